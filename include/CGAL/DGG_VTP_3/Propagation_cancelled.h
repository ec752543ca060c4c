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

#ifndef CGAL_DGG_VTP_3_PROPAGATION_CANCELLED_H
#define CGAL_DGG_VTP_3_PROPAGATION_CANCELLED_H

#include <CGAL/license/DGG_VTP_3.h>

#include <exception>

namespace CGAL {
namespace DGG_VTP_3 {

/// \ingroup PkgDGGVTP3Ref
/// Thrown by a query whose `callback` named parameter returned `false`. The query has no result
/// (its outputs may be partly written); the solver is unchanged, and answers the next query as if
/// this one had never been asked.
struct Propagation_cancelled : std::exception
{
  const char* what() const noexcept override { return "the propagation was cancelled by its callback"; }
};

} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_PROPAGATION_CANCELLED_H
