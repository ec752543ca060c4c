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

#ifndef CGAL_DGG_VTP_3_INTERNAL_PLANAR_GEOMETRY_H
#define CGAL_DGG_VTP_3_INTERNAL_PLANAR_GEOMETRY_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/number_type_math.h>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// Windows live in the 2D frame of a halfedge (origin at its source vertex, x axis along it,
// its face above). A tiny struct in the computation number type keeps the hot loops free of
// kernel dispatch: everything here is the unfolding of one triangle onto the plane.
template <class FT>
struct Vec2
{
  FT x;
  FT y;
};

template <class FT> inline Vec2<FT> operator-(const Vec2<FT>& a, const Vec2<FT>& b) { return {a.x - b.x, a.y - b.y}; }
template <class FT> inline FT dot(const Vec2<FT>& a, const Vec2<FT>& b) { return a.x * b.x + a.y * b.y; }
template <class FT> inline FT cross(const Vec2<FT>& a, const Vec2<FT>& b) { return a.x * b.y - a.y * b.x; }
template <class FT> inline FT length(const Vec2<FT>& a) { return Number_type_math<FT>::sqrt(dot(a, a)); }

template <class FT>
inline FT clamp01(FT t)
{
  // also maps NaN to 0: a degenerate ray can never push a window off its edge
  return t > FT(0) ? (t < FT(1) ? t : number<FT>(1)) : number<FT>(0);
}

// Parameter in [0, 1] along segment [A, B] where the line through `s` and `p` crosses it.
// Rays that miss the segment (possible only through rounding) are clamped to its ends.
template <class FT>
inline FT ray_segment_parameter(const Vec2<FT>& s, const Vec2<FT>& p,
                                const Vec2<FT>& A, const Vec2<FT>& B)
{
  const Vec2<FT> r = p - s;
  const FT den = cross(r, B - A);
  if(!(den != FT(0)))
    return number<FT>(0);
  return clamp01(cross(r, s - A) / den);
}

// Abscissa where the line from `s` (below the x axis) to `c` (above it) crosses the x axis:
// the point of the base edge through which a window lights the apex `c`.
template <class FT>
inline FT x_axis_crossing(const Vec2<FT>& s, const Vec2<FT>& c)
{
  return s.x - s.y * (c.x - s.x) / (c.y - s.y);
}

// A point given in the frame of halfedge (a -> b) of a triangle, expressed in the frame of the
// opposite halfedge of edge (origin -> origin + axis) of the same triangle, whose face is the
// neighbour: translate, rotate onto `axis`, and flip so that the triangle lies below.
template <class FT>
inline Vec2<FT> to_neighbour_frame(const Vec2<FT>& p, const Vec2<FT>& origin,
                                   const Vec2<FT>& axis, FT axis_length)
{
  const Vec2<FT> q = p - origin;
  return {dot(q, axis) / axis_length, cross(axis, q) / axis_length};
}

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_PLANAR_GEOMETRY_H
