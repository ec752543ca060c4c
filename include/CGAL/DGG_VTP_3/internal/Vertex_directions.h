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

#ifndef CGAL_DGG_VTP_3_INTERNAL_VERTEX_DIRECTIONS_H
#define CGAL_DGG_VTP_3_INTERNAL_VERTEX_DIRECTIONS_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/planar_geometry.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// Directions around a vertex without angles. The decisions that depend on them (is this vertex a
// saddle, which faces does its shadow meet, which way does a path go on through it)
// are sign tests on unfolded vectors: no atan2 and no pi, so that they are exact in an exact
// number type, and free of the rounding of angle sums at 2 pi and pi in the others.
//
// A direction leaving vertex v is a vector in the frame of one of v's corners (Unfolded_mesh: the
// corner's first edge along +x, its apex above), inside the corner. Turning on, the next corner's
// first edge is this corner's last one (Unfolded_mesh::next_in_turn).

// A number that grows with the angle of `t` (t.y >= 0) from +x as the angle does, from 0 to 2
// at pi: rational in t, so comparing two of them compares two angles exactly.
template <class FT>
FT pseudo_angle(const Vec2<FT>& t)
{
  if(t.x >= FT(0))
    return t.y / (t.x + t.y);
  return number<FT>(2) - t.y / (t.y - t.x);
}

// a vector of pseudo-angle p in [0, 2)
template <class FT>
Vec2<FT> vector_of_pseudo_angle(const FT& p)
{
  return p <= FT(1) ? Vec2<FT>{number<FT>(1) - p, p} : Vec2<FT>{number<FT>(1) - p, number<FT>(2) - p};
}

// the rotation by a small angle s >= 0, as (cos s, sin s); exactly (1, 0) for s = 0. The cosine
// and sine are taken in double: s is a widening margin, whose rounding does not matter
template <class FT>
Vec2<FT> small_turn(const FT& s)
{
  if(!(s > FT(0)))
    return Vec2<FT>{number<FT>(1), number<FT>(0)};
  const double a = CGAL::to_double(s);
  return Vec2<FT>{number<FT>(std::cos(a)), number<FT>(std::sin(a))};
}

// A sum of corner angles (each in (0, pi)), kept as a vector at the sum (the product of the
// corners' vectors as complex numbers, of any positive length) and the number of half turns
// made: the sum is in [half_turns pi, (half_turns + 1) pi).
template <class FT>
struct Angle_sum
{
  Vec2<FT> at{number<FT>(1), number<FT>(0)};
  int half_turns = 0;

  // angle in [0, pi) modulo 2 pi
  static bool upper(const Vec2<FT>& e) { return e.y > FT(0) || (e.y == FT(0) && e.x > FT(0)); }

  // adds the angle of `u` (in (0, pi)): a half turn is crossed when the side changes
  void add(const Vec2<FT>& u)
  {
    const Vec2<FT> next{at.x * u.x - at.y * u.y, at.x * u.y + at.y * u.x};
    if(upper(next) != upper(at))
      ++half_turns;
    at = next;
  }

  // -1, 0 or 1 as the sum is below, at or above half_turns_b pi + the angle of b, b a vector on
  // the side that half_turns_b says
  int compare(int half_turns_b, const Vec2<FT>& b) const
  {
    if(half_turns != half_turns_b)
      return half_turns < half_turns_b ? -1 : 1;
    const FT c = cross(b, at);
    return c > FT(0) ? 1 : (c < FT(0) ? -1 : 0);
  }
};

// A direction at a vertex during a turn: the corner, its rank in turning order counted on past the
// last corner (or back before the first) as the turn goes around, and the vector in its frame.
template <class FT, class Index>
struct Corner_direction
{
  Index corner;
  std::int64_t rank;
  Vec2<FT> vector;
};

// The position of a direction among those at a vertex, one number for ordering and storing: the
// rank of its corner plus half its pseudo-angle there, so in [rank, rank + 1). `t` is given in the
// frame of `corner`; a direction that rounding put outside the corner counts as on its nearest
// edge, and one on the corner's last edge as on the next corner's first edge.
template <class Mesh, class FT>
FT direction_position(const Mesh& mesh, typename Mesh::Index corner, const Vec2<FT>& t)
{
  if(!(t.y > FT(0)))
    return number<FT>(mesh.corner_rank(corner));
  const Vec2<FT> a = mesh.apex(corner);
  if(!(cross(t, a) > FT(0)))
  {
    const typename Mesh::Index n = mesh.next_in_turn(corner);
    if(n != Mesh::no_halfedge)
      return number<FT>(mesh.corner_rank(n));
    return number<FT>(mesh.corner_rank(corner)) + pseudo_angle(a) / number<FT>(2);
  }
  return number<FT>(mesh.corner_rank(corner)) + pseudo_angle(t) / number<FT>(2);
}

// the direction at vertex `v` at a position that direction_position() gave
template <class Mesh, class FT>
Corner_direction<FT, typename Mesh::Index> direction_at(const Mesh& mesh, typename Mesh::Index v, const FT& position)
{
  using Index = typename Mesh::Index;
  Index rank = Index((std::max)(0., std::floor(CGAL::to_double(position))));
  while(rank > 0 && FT(rank) > position) // to_double() may round up to the next integer
    --rank;
  return {mesh.corner_of_rank(v, rank), std::int64_t(rank), vector_of_pseudo_angle(number<FT>(2) * (position - number<FT>(rank)))};
}

// The turns of the shadows of saddles and of straight paths through vertices: by pi - s (s given
// by its rotation `turn_s`, see small_turn()), counterclockwise or clockwise, from a direction at
// a vertex. Returns false if the turn leaves the vertex's fan of faces at a border. The result is
// on the first edge of the next corner rather than on the last edge of its own corner, so that
// one direction has one representation.
template <class Mesh, class FT>
bool turn_direction(const Mesh& mesh, Corner_direction<FT, typename Mesh::Index>& d, bool counterclockwise,
                    const Vec2<FT>& turn_s)
{
  using Index = typename Mesh::Index;
  using Point = Vec2<FT>;
  // Clockwise turns work in each corner's mirror image across its bisector, where the last edge
  // is +x and the first edge along the last edge's direction (Unfolded_mesh::last_edge_direction),
  // so that one loop serves both ways. Only directions matter: an exact type's vectors, not unit,
  // just scale.
  const auto mirror = [](const Point& t, const Point& u) { return Point{dot(t, u), cross(t, u)}; };
  // T, given as a vector in the current corner's (working) frame whose angle from +x in [0, 2 pi)
  // is the turn still to make, reached corner by corner
  const auto walk = [&](Point t) {
    for(;;)
    {
      const Point u = mesh.last_edge_direction(d.corner);
      if(t.y >= FT(0) && cross(t, u) >= FT(0))
        break;
      const Index n = counterclockwise ? mesh.next_in_turn(d.corner) : mesh.previous_in_turn(d.corner);
      if(n == Mesh::no_halfedge)
        return false;
      t = Point{dot(t, u), cross(u, t)}; // the same direction from the neighbour's first edge
      d.corner = n;
      d.rank += counterclockwise ? 1 : -1;
    }
    d.vector = counterclockwise ? t : mirror(t, mesh.last_edge_direction(d.corner));
    if(cross(d.vector, mesh.apex(d.corner)) == FT(0))
    {
      const Index n = mesh.next_in_turn(d.corner);
      if(n != Mesh::no_halfedge)
      {
        d.corner = n;
        ++d.rank;
        d.vector = Point{number<FT>(1), number<FT>(0)};
      }
    }
    return true;
  };
  const Point t = counterclockwise ? d.vector : mirror(d.vector, mesh.last_edge_direction(d.corner));
  return walk(Point{-(t.x * turn_s.x + t.y * turn_s.y), -(t.y * turn_s.x - t.x * turn_s.y)});
}

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_VERTEX_DIRECTIONS_H
