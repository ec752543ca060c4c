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

#ifndef CGAL_DGG_VTP_3_INTERNAL_NEAREST_SOURCES_H
#define CGAL_DGG_VTP_3_INTERNAL_NEAREST_SOURCES_H

#include <CGAL/license/DGG_VTP_3.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// Per vertex, the number of the source its path starts from, std::size_t(-1) if none: the
// propagation records per vertex the pseudo-source of its path (`origin`: a vertex, the source of
// number k as nv + k, or `no_origin`), which is a source, or a vertex whose own path starts from a
// source, and so on. Each chain is walked once.
template <class Index>
std::vector<std::size_t> nearest_sources(const std::vector<Index>& origin, Index no_origin)
{
  const Index nv = Index(origin.size());
  const std::size_t unknown = std::size_t(-2), none = std::size_t(-1);
  std::vector<std::size_t> nearest(nv, unknown);
  std::vector<Index> chain;
  for(Index v = 0; v < nv; ++v)
  {
    Index u = v;
    while(u < nv && nearest[u] == unknown)
    {
      chain.push_back(u);
      nearest[u] = none; // a cycle (rounding could make one) ends here, unlabelled
      u = origin[u];
    }
    const std::size_t label = u < nv ? nearest[u] : u == no_origin ? none : std::size_t(u - nv);
    for(Index c : chain)
      nearest[c] = label;
    chain.clear();
  }
  return nearest;
}

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_NEAREST_SOURCES_H
