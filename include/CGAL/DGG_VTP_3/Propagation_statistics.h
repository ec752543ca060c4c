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

#ifndef CGAL_DGG_VTP_3_PROPAGATION_STATISTICS_H
#define CGAL_DGG_VTP_3_PROPAGATION_STATISTICS_H

#include <CGAL/license/DGG_VTP_3.h>

#include <cstddef>

namespace CGAL {
namespace DGG_VTP_3 {

/// \ingroup PkgDGGVTP3Ref
/// What one distance computation did; returned by every query so that callers can report or
/// compare runs without the library printing anything.
struct Propagation_statistics
{
  std::size_t windows_created = 0;  ///< windows stored in a window list, in total
  std::size_t windows_peak = 0;     ///< largest number of windows alive at the same time (an upper bound: over the propagation's rounds, the sum of each patch's largest number in the round)
  std::size_t pseudo_sources = 0;   ///< vertices that emitted windows (the source included)
  std::size_t vertices_popped = 0;  ///< vertices taken from the priority queue (a vertex whose distance drops after being popped counts again)
  std::size_t vertices_reached = 0; ///< vertices with a finite distance
};

} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_PROPAGATION_STATISTICS_H
