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

#include <CGAL/DGG_VTP_3/internal/number_type_math.h>
#include <CGAL/DGG_VTP_3/internal/planar_geometry.h>

#include <CGAL/number_utils.h>

#include <cmath>
#include <cstdint>
#include <limits>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// A window (paper, Fig. 2a): the interval [b0, b1] of a halfedge's edge lit straight from a
// pseudo-source, expressed in that halfedge's frame. The window travels into the halfedge's face.
//
// Its values are keys (see Tuning::key_ratio): `sigma` is the pseudo-source's distance divided by
// the key ratio rho (see Key_ratio), so that every rule compares `sigma + |p - source|`; the
// geodesic distance the window gives a point is `rho sigma + |p - source|`. In the exact mode rho
// is 1 and the two are the same.
//
// DGG-VTP (paper, Theorem 2) adds the CH-relay vertices and the distance bound; in the exact
// mode they stay at their neutral values (no relay, no bound).
template <class FT>
struct Window
{
  FT b0;               // start of the interval, distance from the halfedge's source
  FT b1;               // end of the interval, b0 <= b1 <= edge length
  Vec2<FT> source;     // unfolded pseudo-source, below the edge (source.y <= 0)
  FT sigma;            // key of the pseudo-source: its geodesic distance / rho
  FT relay_left;       // distance from the pseudo-source to the CH-relay vertex on the ray through b0 (0: none)
  FT relay_right;      // distance from the pseudo-source to the CH-relay vertex on the ray through b1 (0: none)
  // The distance bound, rounded up to a float (the window stops later, which is always safe):
  // the window stops where it would go farther; +inf: never; NaN: to recompute (a relay changed).
  // A float, so that a window of double keeps the 72 bytes of the exact algorithm's (at 80, the
  // exact mode was 9% slower on bunny_1M: the lists and their sorting move whole windows).
  float d_max;
  std::uint32_t origin; // its pseudo-source: a vertex, or (number of vertices + k) for the k-th source
  std::uint32_t relay_left_vertex;  // the CH-relay vertex on the ray through b0, if relay_left > 0
  std::uint32_t relay_right_vertex; // the CH-relay vertex on the ray through b1, if relay_right > 0

  FT distance_to(const Vec2<FT>& p) const { return sigma + length(p - source); }
  FT distance_to_base_point(FT x) const { return sigma + length(Vec2<FT>{x - source.x, -source.y}); }

  // the window goes no farther than the distance bound from its pseudo-source at `distance`
  bool beyond_bound(FT distance) const
  {
    return d_max < std::numeric_limits<float>::infinity() && distance > number<FT>(double(d_max));
  }
  bool bound_is_stale() const { return d_max != d_max; }
  void set_bound(FT bound)
  {
    const double d = CGAL::to_double(bound);
    // float(d) may round down, to_double may have: one float step up covers both
    d_max = d < double((std::numeric_limits<float>::max)())
              ? std::nextafter(float(d), std::numeric_limits<float>::infinity())
              : std::numeric_limits<float>::infinity();
  }

  // Pruning moves an end of the interval: its boundary ray no longer goes through the relay
  // vertex of that side, whose segments to the window might now leave its beam.
  void cut_start(FT t)
  {
    b0 = t;
    drop_relay(relay_left);
  }
  void cut_end(FT t)
  {
    b1 = t;
    drop_relay(relay_right);
  }

  // the relay vertex `relay` (of this window) is no longer on its boundary ray
  void drop_relay(FT& relay)
  {
    if(relay > FT(0))
    {
      relay = number<FT>(0);
      d_max = std::numeric_limits<float>::quiet_NaN();
    }
  }
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_WINDOW_H
