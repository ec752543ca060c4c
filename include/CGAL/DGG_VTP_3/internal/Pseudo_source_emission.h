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

#ifndef CGAL_DGG_VTP_3_INTERNAL_PSEUDO_SOURCE_EMISSION_H
#define CGAL_DGG_VTP_3_INTERNAL_PSEUDO_SOURCE_EMISSION_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/Key_ratio.h>
#include <CGAL/DGG_VTP_3/internal/Surface_point.h>
#include <CGAL/DGG_VTP_3/internal/Tuning.h>
#include <CGAL/DGG_VTP_3/internal/Unfolded_mesh.h>
#include <CGAL/DGG_VTP_3/internal/Vertex_copies.h>
#include <CGAL/DGG_VTP_3/internal/Vertex_directions.h>
#include <CGAL/DGG_VTP_3/internal/Window_construction.h>
#include <CGAL/DGG_VTP_3/internal/number_type_math.h>
#include <CGAL/DGG_VTP_3/internal/planar_geometry.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// Positions at a vertex (see direction_position()) of the directions back along the shortest
// paths found so far; a range when several paths tie.
template <class FT>
struct Incoming_directions
{
  FT low = number<FT>(0);
  FT high = number<FT>(0);
};

// What a pseudo-source sends out (paper, Algorithm 1, lines 2-7 and 11-13): from a vertex, for
// each corner it lights, the distances of the corner's two other vertices along its edges and a
// full-edge window across the edge opposite it; from a source inside a face, the same from the
// point. Which corners a vertex lights depends on why it is a pseudo-source: all of them for a
// source, a singular vertex or a pseudo-source of DGG-VTP (see Pseudo_source_states), its shadow
// for a saddle of the exact algorithm.
//
// A pseudo-source of DGG-VTP lights all its corners rather than the paper's fan: its windows are
// needed wherever its key may be the least, which near the vertex is in every direction (the
// manual's argument rests on it), and pairwise trimming cuts them back to the paper's fan, the
// directions nearly straight ahead of the path that reached it, within a face or two.
//
// What is sent goes to `out`, the propagation on the pseudo-source's patch:
//   out.relax(vertex, distance, key, corner, direction, origin)  a path reaches a vertex (see
//                                                                 Window_propagation::relax)
//   out.add_window(halfedge, window)                         a window enters a window list
//   out.count_pseudo_source()                                one more pseudo-source emits
template <class FT>
class Pseudo_source_emission
{
  using Mesh = Unfolded_mesh<FT>;
  using Index = typename Mesh::Index;
  using Point = Vec2<FT>;
  using T = Tuning<FT>;

public:
  // `keys`: the key ratio of the windows
  Pseudo_source_emission(const Mesh& mesh, const Key_ratio<FT>& keys)
    : m_mesh(mesh)
    , m_keys(keys)
    , m_shadow_widening(small_turn(T::shadow_widening()))
  {}

  // for the next propagation
  void set_keys(const Key_ratio<FT>& keys) { m_keys = keys; }

  // lines 3-7: vertex `v` at distance `dv` lights all its corners. Each neighbour is the end of two
  // corners' edges, and DGG-VTP relaxes it from the first (that corner's target): the second would
  // give the same distance, which only the exact mode's shadows tell from it by its direction.
  // The neighbours are all relaxed before the windows leave, so that the ICH rule trims each window
  // against both ends of its edge.
  template <class Out>
  void all_around(Index v, FT dv, Out& out) const
  {
    out.count_pseudo_source();
    const bool each_neighbour_once = !m_keys.is_exact();
    for(const Index* c = m_mesh.corners_begin(v); c != m_mesh.corners_end(v); ++c)
      relax_ends(v, dv, *c, out, !each_neighbour_once || m_mesh.opposite(Mesh::prev(*c)) == Mesh::no_halfedge);
    for(const Index* c = m_mesh.corners_begin(v); c != m_mesh.corners_end(v); ++c)
      window_across(v, dv, *c, out);
  }

  // a vertex at distance `dv` and least key `key`: its copies (see Vertex_copies.h) are the same
  // point, reached through it at no cost (no corner: a step of length zero)
  template <class Out>
  void to_copies(Index v, FT dv, FT key, Out& out) const
  {
    for(Index u = m_mesh.next_copy(v); u != v; u = m_mesh.next_copy(u))
      out.relax(u, dv, key, Mesh::no_halfedge, Point{number<FT>(0), number<FT>(0)}, v);
  }

  // Lines 11-13 of the exact algorithm: a shortest path bends at a saddle only if it turns by at
  // least pi on both sides, so a saddle emits windows only into the faces that meet the cone
  // [back + pi, back + angle_sum - pi] of the directions it arrived from, widened by a small
  // angle for rounding (emitting more is always safe: windows are real paths, pruned later).
  // The cone runs from the first recorded arrival direction in.low turned by pi counterclockwise
  // to the last, in.high, turned by pi clockwise: a union of cones sliding with the arrival
  // direction. Corners are compared by rank, counted on around the vertex, then pseudo-angle.
  template <class Out>
  void in_shadow(Index v, FT dv, const Incoming_directions<FT>& in, Out& out) const
  {
    Corner_direction<FT, Index> from = direction_at(m_mesh, v, in.low), to = direction_at(m_mesh, v, in.high);
    const std::int64_t k = m_mesh.corners_end(v) - m_mesh.corners_begin(v);
    // a closed fan: turns never leave it
    turn_direction(m_mesh, from, true, m_shadow_widening);
    turn_direction(m_mesh, to, false, m_shadow_widening);
    // the cone's ends, one turn apart on the side where the continuations end
    const std::int64_t from_rank = from.rank, to_rank = to.rank + k;
    const FT from_angle = pseudo_angle(from.vector), to_angle = pseudo_angle(to.vector);
    if(to_rank > from_rank + k || (to_rank == from_rank + k && !(to_angle < from_angle)))
    {
      all_around(v, dv, out);
      return;
    }
    if(to_rank < from_rank || (to_rank == from_rank && to_angle < from_angle))
      return;
    out.count_pseudo_source();
    // a corner that both ends meet is lit once
    for(std::int64_t r = from_rank; r <= (std::min)(to_rank, from_rank + k - 1); ++r)
    {
      const Index h = m_mesh.corner_of_rank(v, Index(((r % k) + k) % k));
      relax_ends(v, dv, h, out, true);
      window_across(v, dv, h, out);
    }
  }

  // Lines 2-7 for a source inside a face (or on an edge, then in all its faces): it reaches the
  // face's corners straight and sends a full-edge window across each edge it is not on.
  // `out_in_face(f)` is the `out` of the patch of face f.
  template <class OutInFace>
  void from_surface_point(const Surface_point<FT>& s, Index origin, OutInFace&& out_in_face) const
  {
    std::vector<Surface_point<FT>> at(1, s);
    for(int k = 0; k < 3; ++k)
      if(s.barycentric[k] == FT(0))
        same_point_across_edge(m_mesh, s, k, at);
    // the faces of an edge point in the same order however the point was given
    std::sort(at.begin(), at.end(), [](const Surface_point<FT>& a, const Surface_point<FT>& b) { return a.face < b.face; });
    for(const Surface_point<FT>& p : at)
      from_point_in_face(p, origin, out_in_face(p.face));
  }

private:
  // the distances of the other two vertices of the face of corner `h` at `v` (at distance `dv`),
  // along the corner's edges: of its target, and of the source of its last edge if `both_ends`
  template <class Out>
  void relax_ends(Index v, FT dv, Index h, Out& out, bool both_ends) const
  {
    const Index across = Mesh::next(h);
    const Index prev = Mesh::prev(h);
    // from target(h) back along its corner's last edge, from source(prev) back along prev
    const FT key = m_keys.key(dv);
    out.relax(m_mesh.target(h), dv + m_mesh.length(h), key + m_mesh.length(h), across, m_mesh.apex(across), v);
    if(both_ends)
      out.relax(m_mesh.source(prev), dv + m_mesh.length(prev), key + m_mesh.length(prev), prev,
                Point{number<FT>(1), number<FT>(0)}, v);
  }

  // a full-edge window from `v` on the edge opposite it in the face of corner `h`
  template <class Out>
  void window_across(Index v, FT dv, Index h, Out& out) const
  {
    const Index across = Mesh::next(h);
    if(m_mesh.has_face_across(across))
      for_each_face_across(m_mesh, across, window_across_corner(m_mesh, h, dv, m_keys, v),
                           [&out](Index t, const Window<FT>& w) { out.add_window(t, w); });
  }

  template <class Out>
  void from_point_in_face(const Surface_point<FT>& s, Index origin, Out&& out) const
  {
    const Index f = s.face;
    const std::array<FT, 3>& b = s.barycentric;
    out.count_pseudo_source();
    for(int k = 0; k < 3; ++k)
    {
      // in the frame of halfedge e = 3f + k: its source at the origin, its target at (len, 0)
      const Index e = 3 * f + k;
      const Point c = m_mesh.apex(e);
      const Point q{b[(k + 1) % 3] * m_mesh.length(e) + b[(k + 2) % 3] * c.x, b[(k + 2) % 3] * c.y};
      const FT to_source = length(q);
      out.relax(m_mesh.source(e), to_source, to_source, e, q, origin);
      if(b[(k + 2) % 3] != FT(0) && m_mesh.has_face_across(e)) // not on this edge
        for_each_face_across(m_mesh, e,
                             window_from_point(m_mesh, e, q, number<FT>(0), length(q - Point{m_mesh.length(e), number<FT>(0)}),
                                               to_source, m_keys, origin),
                             [&out](Index t, const Window<FT>& w) { out.add_window(t, w); });
    }
  }

  const Mesh& m_mesh;
  Key_ratio<FT> m_keys;          // the key ratio of the windows
  const Point m_shadow_widening; // the turn added on both sides of a shadow, for rounding
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_PSEUDO_SOURCE_EMISSION_H
