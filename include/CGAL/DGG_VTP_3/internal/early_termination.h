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

#ifndef CGAL_DGG_VTP_3_INTERNAL_EARLY_TERMINATION_H
#define CGAL_DGG_VTP_3_INTERNAL_EARLY_TERMINATION_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/Point_targets.h>
#include <CGAL/DGG_VTP_3/internal/Propagation_query.h>
#include <CGAL/DGG_VTP_3/internal/number_type_math.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// Early termination: the vertices nearer than the query's largest distance of interest (its
// maximum distance, or the largest distance of its targets found so far, +inf while one is
// unreached) are final once no vertex within a few mean edge lengths beyond it is left to pop
// (`band`, a round's width: twice that absorbs what windows crossing the last faces still
// bring). Returns how far vertices still need to be popped (+inf: all of them). `distance`: the
// vertices' distances found so far.
template <class FT>
FT early_termination_limit(const Propagation_query<FT>& query, const Point_targets<FT>& point_targets,
                           const std::vector<FT>& distance, FT band)
{
  FT limit = query.max_distance;
  if(!query.vertex_targets.empty() || !point_targets.empty())
  {
    FT targets = point_targets.empty() ? number<FT>(0) : point_targets.largest();
    for(std::uint32_t v : query.vertex_targets)
      targets = (std::max)(targets, distance[v]);
    limit = (std::min)(limit, targets);
  }
  return limit < Number_type_math<FT>::infinity() ? limit + number<FT>(2) * band : limit;
}

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_EARLY_TERMINATION_H
