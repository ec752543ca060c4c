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

#ifndef CGAL_DGG_VTP_3_INTERNAL_WINDOW_CONSTRUCTION_H
#define CGAL_DGG_VTP_3_INTERNAL_WINDOW_CONSTRUCTION_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/Distance_bound.h>
#include <CGAL/DGG_VTP_3/internal/Key_ratio.h>
#include <CGAL/DGG_VTP_3/internal/Unfolded_mesh.h>
#include <CGAL/DGG_VTP_3/internal/Window.h>
#include <CGAL/DGG_VTP_3/internal/number_type_math.h>
#include <CGAL/DGG_VTP_3/internal/planar_geometry.h>

#include <cstdint>
#include <limits>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// Where windows come from: a pseudo-source lighting the edge opposite one of its corners, and a
// window crossing the face of its halfedge (a -> b, apex c) into its two children.

// The full-edge window that a pseudo-source at `p` (in the frame of halfedge `e`, inside its face),
// at distance `sigma`, sends across the edge of `e`, in the frame of the neighbouring halfedge
// (the caller checks that there is one). Where windows stop (`keys.stops()`) its CH-relay
// vertices are the ends of the edge (paper, Algorithm 1, line 3), at distances `relay_left` (from
// the target of `e`, the start of the neighbouring halfedge) and `relay_right`, and its distance
// bound follows from them (with_bound()); elsewhere it has neither, as take_relay() gives none.
template <class FT>
inline Window<FT> window_from_point(const Unfolded_mesh<FT>& mesh, typename Unfolded_mesh<FT>::Index e,
                                    const Vec2<FT>& p, FT sigma, FT relay_left, FT relay_right,
                                    const Key_ratio<FT>& keys, std::uint32_t origin)
{
  const FT len = mesh.length(e);
  const bool stops = keys.stops();
  Window<FT> w;
  w.b0 = number<FT>(0);
  w.b1 = len;
  w.source = Vec2<FT>{len - p.x, -p.y}; // the same triangle seen from the other side
  w.sigma = keys.key(sigma);
  w.relay_left = stops ? relay_left : number<FT>(0);
  w.relay_right = stops ? relay_right : number<FT>(0);
  w.relay_left_vertex = mesh.target(e);
  w.relay_right_vertex = mesh.source(e);
  // the bound waits for with_bound(), once the ICH rule has trimmed the window: most of a
  // pseudo-source's windows die at once
  w.d_max = stops ? std::numeric_limits<float>::quiet_NaN() : std::numeric_limits<float>::infinity();
  w.origin = origin;
  return w;
}

// The window that a pseudo-source vertex at distance `sigma`, at the corner of halfedge `h`,
// sends across the edge opposite it.
template <class FT>
inline Window<FT> window_across_corner(const Unfolded_mesh<FT>& mesh, typename Unfolded_mesh<FT>::Index h, FT sigma,
                                       const Key_ratio<FT>& keys, std::uint32_t origin)
{
  using Mesh = Unfolded_mesh<FT>;
  const auto across = Mesh::next(h); // the edge opposite the pseudo-source; its apex
  return window_from_point(mesh, across, mesh.apex(across), sigma, mesh.length(Mesh::prev(h)), mesh.length(h),
                           keys, origin);
}

// The child of `w` on edge (a, c), in the frame of the neighbouring halfedge a -> c (of length
// `len`), from the rays of `w` through [b0, min(end, x)], `x` being where the ray to c crosses
// the base. False if that is empty.
template <class FT>
inline bool left_child(const Window<FT>& w, const Vec2<FT>& c, FT x, FT end, FT len, Window<FT>& child)
{
  const Vec2<FT> a{number<FT>(0), number<FT>(0)};
  const FT u0 = ray_segment_parameter(w.source, Vec2<FT>{w.b0, number<FT>(0)}, a, c);
  const FT u1 = x < end ? number<FT>(1) : ray_segment_parameter(w.source, Vec2<FT>{end, number<FT>(0)}, a, c);
  if(!(u0 < u1))
    return false;
  child = w;
  child.b0 = u0 * len;
  child.b1 = u1 * len;
  child.source = to_neighbour_frame(w.source, a, c, len);
  return true;
}

// The child of `w` on edge (b, c), in the frame of the neighbouring halfedge c -> b (of length
// `len`), from the rays of `w` through [max(start, x), b1]; `b` = (base length, 0).
template <class FT>
inline bool right_child(const Window<FT>& w, const Vec2<FT>& b, const Vec2<FT>& c, FT x, FT start, FT len, Window<FT>& child)
{
  const FT v0 = start < x ? number<FT>(0) : ray_segment_parameter(w.source, Vec2<FT>{start, number<FT>(0)}, c, b);
  const FT v1 = ray_segment_parameter(w.source, Vec2<FT>{w.b1, number<FT>(0)}, c, b);
  if(!(v0 < v1))
    return false;
  child = w;
  child.b0 = v0 * len;
  child.b1 = v1 * len;
  child.source = to_neighbour_frame(w.source, c, b - c, len);
  return true;
}

// A child whose boundary ray grazes vertex `v`, at `distance` from the pseudo-source, takes it
// as its CH-relay vertex on that side (paper, Algorithm 1, line 22): `relay` and `relay_vertex`
// are the child's fields of that side. Only windows that may stop have relays.
template <class FT>
inline void take_relay(Window<FT>& child, FT& relay, std::uint32_t& relay_vertex, FT distance, std::uint32_t v,
                       const Key_ratio<FT>& keys)
{
  if(!keys.stops())
    return;
  relay = distance;
  relay_vertex = v;
  child.d_max = std::numeric_limits<float>::quiet_NaN();
}

// The distance bound follows the relays a window has now; a bound of relays it no longer has is
// not kept, even if smaller: their segments to the window may leave its beam.
template <class FT>
inline const Window<FT>& with_bound(Window<FT>& w, const Key_ratio<FT>& keys)
{
  if(w.bound_is_stale())
    w.set_bound(distance_bound(w.source, w.b0, w.b1, w.relay_left, w.relay_right, keys));
  return w;
}

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_WINDOW_CONSTRUCTION_H
