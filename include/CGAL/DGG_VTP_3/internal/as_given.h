// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// All rights reserved.
//
// This file is part of DGG_VTP_3, a package written for CGAL (www.cgal.org).
//
// $URL$
// $Id$
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : DGG-VTP for CGAL team

#ifndef CGAL_DGG_VTP_3_INTERNAL_AS_GIVEN_H
#define CGAL_DGG_VTP_3_INTERNAL_AS_GIVEN_H

#include <CGAL/license/DGG_VTP_3.h>

#include <charconv>
#include <string>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// A number in an error message as the user gave it: the shortest text that reads back as `x`
// (-1e-09, not std::to_string's -0.000000).
inline std::string as_given(double x)
{
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof(text), x).ptr);
}

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_AS_GIVEN_H
