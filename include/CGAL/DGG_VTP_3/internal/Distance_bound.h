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

#ifndef CGAL_DGG_VTP_3_INTERNAL_DISTANCE_BOUND_H
#define CGAL_DGG_VTP_3_INTERNAL_DISTANCE_BOUND_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/number_type_math.h>
#include <CGAL/DGG_VTP_3/internal/planar_geometry.h>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// How far a window may travel from its pseudo-source before the paths through its CH-relay
// vertices approximate every longer geodesic it carries within a factor (1 + eps): the paper's
// Theorem 2 (Adikusuma et al.), Eq. (1). `source` is the window's unfolded pseudo-source,
// [b0, b1] its interval on the x axis, `relay_left` / `relay_right` the distances from the
// pseudo-source to the CH-relay vertices on the rays through b0 / b1.
// Returns +infinity where the theorem gives no bound (rays opening by 60 degrees or more, which
// makes l0 - d <= 0, or no relay yet).
template <class FT>
FT distance_bound(const Vec2<FT>& source, FT b0, FT b1, FT relay_left, FT relay_right, FT eps)
{
  const FT inf = Number_type_math<FT>::infinity();
  const FT l0 = (std::max)(relay_left, relay_right);
  const FT l1 = (std::min)(relay_left, relay_right);
  if(!(l1 > FT(0)))
    return inf;
  const Vec2<FT> r0{b0 - source.x, -source.y};
  const Vec2<FT> r1{b1 - source.x, -source.y};
  const FT cos_opening = dot(r0, r1) / (length(r0) * length(r1));
  using Math = Number_type_math<FT>;
  // c2: the point of the shorter relay's ray at distance l0; d = |c0 c2|
  const FT d = l0 * Math::sqrt((std::max)(number<FT>(0), number<FT>(2) - number<FT>(2) * cos_opening));
  if(!(d < l0))
    return inf;
  const FT alpha = l1 / l0;
  FT beta(1);
  if(alpha > FT(0.99))
    beta = number<FT>(0.5);
  else
  {
    const FT q = number<FT>(1) / (number<FT>(1) - alpha);
    const FT disc = q * q - q - number<FT>(2) * eps * l0 * (l0 - d) / (d * d);
    if(disc >= FT(0))
    {
      const FT mu = q - Math::sqrt(disc);
      if(mu > FT(0) && mu < FT(1))
        beta = mu;
    }
  }
  const FT spread = (number<FT>(1) - beta) * d;
  return l0 + spread * spread / (number<FT>(2) * eps * (l0 - d));
}

// Distance from the pseudo-source to the nearest point of the window's interval.
template <class FT>
FT distance_to_interval(const Vec2<FT>& source, FT b0, FT b1)
{
  const FT x = source.x < b0 ? b0 : (source.x > b1 ? b1 : source.x);
  return length(Vec2<FT>{x - source.x, -source.y});
}

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_DISTANCE_BOUND_H
