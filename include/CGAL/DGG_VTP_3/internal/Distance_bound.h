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

#include <CGAL/DGG_VTP_3/internal/Key_ratio.h>
#include <CGAL/DGG_VTP_3/internal/number_type_math.h>
#include <CGAL/DGG_VTP_3/internal/planar_geometry.h>

#include <algorithm>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// The distance bound d_max of a window (paper, Algorithm 1, line 22), as this package certifies
// it. All decisions of DGG-VTP compare keys (see Key_ratio in Tuning.h): a window of pseudo-source
// s at distance sigma_s has the key sigma_s / rho + |sq| at a point q beyond it (rho = 1 + eps).
// A CH-relay vertex c of the window, at a = |sc| on one of its boundary rays, has a distance
// F(c) <= sigma_s + a (the window lit it) and emits all around: its key at q is at most
// sigma_s / rho + a / rho + |cq|. Where that is below the window's key,
//
//   G_c(q) = a / rho + |cq| - |sq| < 0,
//
// the relay's offer dominates the window's, and the window may stop there without loss (the
// argument of the manual: a dominated offer never holds the bound (1 + eps) d on its own).
// Along a ray from s, |cq| grows no faster than |sq|: G_c only decreases, so a window whose
// interval is dominated everywhere stays dominated beyond it. At distance r from s, c dominates
// the rays that make an angle t with its own when cos t >= lambda + a k / r (lambda = 1 / rho,
// k = (1 - lambda^2) / 2: squaring G_c < 0). The bound is the smallest r from which the rays
// dominated by the two relays together cover the beam (closed form below); beyond it the
// window stops. The relays' segments to the interval run inside the window's beam, which holds
// no vertex: they are paths on the surface.
//
// `source`: the window's unfolded pseudo-source; [b0, b1] its interval on the x axis;
// `relay_left` / `relay_right`: a, the distance from the pseudo-source to the CH-relay vertex on
// the ray through b0 / b1, or 0 where that ray goes through no known vertex; `keys`: the key
// ratio. Returns +infinity where the relays cannot cover the beam (rho = 1, the exact mode: never).
template <class FT>
FT distance_bound(const Vec2<FT>& source, FT b0, FT b1, FT relay_left, FT relay_right, const Key_ratio<FT>& keys)
{
  using Math = Number_type_math<FT>;
  const FT inf = Math::infinity();
  if(!keys.stops() || !(relay_left > FT(0) || relay_right > FT(0)))
    return inf;
  const FT zero = number<FT>(0), one = number<FT>(1), two = number<FT>(2);
  const FT lambda = keys.lambda(), one_minus_lambda = keys.one_minus_lambda(), k = keys.k();
  const Vec2<FT> r0{b0 - source.x, -source.y};
  const Vec2<FT> r1{b1 - source.x, -source.y};
  // Most beams are too wide for their relays (1 - cos(opening) >= 4 k): since 1 - cos >= sin^2 / 2,
  // a test without square roots finds most of them
  const FT norms2 = dot(r0, r0) * dot(r1, r1);
  const FT cross01 = cross(r0, r1);
  if(!(norms2 > FT(0)) || cross01 * cross01 >= number<FT>(8) * k * norms2)
    return inf;
  const FT norms = Math::sqrt(norms2);
  const FT cos_opening = dot(r0, r1) / norms;
  const FT sin_opening = cross01 / norms;
  // 1 - cos without cancellation: narrow beams are the usual case
  const FT one_minus_cos = cos_opening > FT(0) ? sin_opening * sin_opening / (one + cos_opening) : one - cos_opening;
  if(!(relay_left > FT(0) && relay_right > FT(0)))
  {
    // one relay covers the whole opening: cos(opening) >= lambda + a k / r
    const FT a = (std::max)(relay_left, relay_right);
    const FT slack = one_minus_lambda - one_minus_cos; // cos(opening) - lambda
    return slack > FT(0) ? a * k / slack : inf;
  }
  // Two relays: with u = lambda + a_l x and v = lambda + a_r x (x = k / r), the cosines of the
  // angles t_l and t_r each relay dominates, t_l + t_r = opening is
  //   u^2 + v^2 - 2 u v cos(opening) = sin^2(opening),
  // a quadratic P x^2 + Q x + R = 0 with R < 0 exactly when the beam is narrower than what two
  // relays at infinity dominate (2 arccos lambda). Its positive root bounds x: below it the
  // relays' angles together exceed the opening (or one of them alone does), as long as each
  // relay dominates some rays at all (u, v <= 1, x <= (1 - lambda) / a).
  const FT al = relay_left, ar = relay_right;
  const FT R = one_minus_cos * (one_minus_cos - two * two * k);
  if(!(R < FT(0)))
    return inf;
  const FT P = (al - ar) * (al - ar) + two * al * ar * one_minus_cos;
  const FT Q = two * lambda * (al + ar) * one_minus_cos;
  const FT disc = Q * Q - two * two * P * R;
  const FT x_root = -two * R / (Q + Math::sqrt((std::max)(zero, disc)));
  const FT x = (std::min)(x_root, one_minus_lambda / (std::max)(al, ar));
  return x > FT(0) ? k / x : inf;
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
