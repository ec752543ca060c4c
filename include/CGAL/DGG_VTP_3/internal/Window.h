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

#ifndef CGAL_DGG_VTP_3_INTERNAL_WINDOW_H
#define CGAL_DGG_VTP_3_INTERNAL_WINDOW_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/planar_geometry.h>

#include <cstdint>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// A window (paper, Fig. 2a): the interval [b0, b1] of a halfedge's edge lit straight from a
// pseudo-source, expressed in that halfedge's frame. The geodesic distance of a point `p` of the
// interval is `sigma + |p - source|`. The window travels into the halfedge's face.
//
// DGG-VTP (paper, Theorem 2) adds the CH-relay distances and the distance bound; in the exact
// mode they stay at their neutral values (no relay, no bound).
template <class FT>
struct Window
{
  FT b0;               // start of the interval, distance from the halfedge's source
  FT b1;               // end of the interval, b0 <= b1 <= edge length
  Vec2<FT> source;     // unfolded pseudo-source, below the edge (source.y <= 0)
  FT sigma;            // geodesic distance of the pseudo-source
  FT relay_left;       // distance from the pseudo-source to the CH-relay vertex of the b0 side
  FT relay_right;      // distance from the pseudo-source to the CH-relay vertex of the b1 side
  FT d_max;            // distance bound: the window stops where it would go farther (+inf: never)
  std::uint32_t origin; // its pseudo-source: a vertex, or (number of vertices + k) for the k-th source

  FT distance_to(const Vec2<FT>& p) const { return sigma + length(p - source); }
  FT distance_to_base_point(FT x) const { return sigma + length(Vec2<FT>{x - source.x, -source.y}); }
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_WINDOW_H
