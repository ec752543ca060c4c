// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

#ifndef CGAL_DGG_VTP_3_INTERNAL_PSEUDO_SOURCE_EMISSION_H
#define CGAL_DGG_VTP_3_INTERNAL_PSEUDO_SOURCE_EMISSION_H

#include <CGAL/DGG_VTP_3/internal/Surface_point.h>
#include <CGAL/DGG_VTP_3/internal/Tuning.h>
#include <CGAL/DGG_VTP_3/internal/Unfolded_mesh.h>
#include <CGAL/DGG_VTP_3/internal/Window_construction.h>
#include <CGAL/DGG_VTP_3/internal/number_type_math.h>
#include <CGAL/DGG_VTP_3/internal/planar_geometry.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// Polar angles at a vertex (see Unfolded_mesh::corner_start_angle) of the directions back along
// the shortest paths found so far; a range when several paths tie.
template <class FT>
struct Incoming_directions
{
  FT low = FT(0);
  FT high = FT(0);
};

// What a pseudo-source sends out (paper, Algorithm 1, lines 2-7 and 11-13): from a vertex, for
// each corner it lights, the distances of the corner's two other vertices along its edges and a
// full-edge window across the edge opposite it; from a source inside a face, the same from the
// point. Which corners a vertex lights depends on why it is a pseudo-source: all of them for a
// source or a singular vertex, its shadow for a saddle of the exact algorithm, its fan in
// DGG-VTP.
//
// What is sent goes to `out`, the propagation on the pseudo-source's patch:
//   out.relax(vertex, distance, corner, direction, origin)  a path reaches a vertex (see
//                                                            Window_propagation::relax)
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
  // `bound_epsilon`: epsilon of the windows' distance bound (0: exact, no bound);
  // `fan_half_width`: radians added on both sides of a fan
  Pseudo_source_emission(const Mesh& mesh, FT bound_epsilon, FT fan_half_width)
    : m_mesh(mesh), m_bound_epsilon(bound_epsilon), m_fan_half_width(fan_half_width)
  {}

  // lines 3-7: vertex `v` at distance `dv` lights all its corners
  template <class Out>
  void all_around(Index v, FT dv, Out& out) const
  {
    out.count_pseudo_source();
    for(const Index* c = m_mesh.corners_begin(v); c != m_mesh.corners_end(v); ++c)
      across_corner(v, dv, *c, out);
  }

  // Lines 11-13 of the exact algorithm: a shortest path bends at a saddle only if it turns by at
  // least pi on both sides, so a saddle emits windows only into the faces that meet the cone
  // [back + pi, back + angle_sum - pi] of the directions it arrived from, widened by a small
  // angle for rounding (emitting more is always safe: windows are real paths, pruned later).
  template <class Out>
  void in_shadow(Index v, FT dv, const Incoming_directions<FT>& in, Out& out) const
  {
    const FT theta = m_mesh.angle_sum(v);
    const FT widen = T::shadow_widening();
    in_cone(v, dv, in, T::pi() - widen, theta - T::pi() + widen, out);
  }

  // Lines 11-12 of DGG-VTP: every vertex is a pseudo-source, but only inside its fan, the
  // directions nearly straight ahead of the geodesic that reached it (paper, Fig. 5): the
  // straight continuations on the two sides, back + pi and back + angle_sum - pi, widened by the
  // fan half-width on both sides (for a convex vertex they swap places).
  template <class Out>
  void in_fan(Index v, FT dv, const Incoming_directions<FT>& in, Out& out) const
  {
    const FT theta = m_mesh.angle_sum(v);
    const FT left = T::pi(), right = theta - T::pi();
    in_cone(v, dv, in, (std::min)(left, right) - m_fan_half_width, (std::max)(left, right) + m_fan_half_width,
            out);
  }

  // Lines 2-7 for a source inside a face (or on an edge, then in both faces): it reaches the
  // face's corners straight and sends a full-edge window across each edge it is not on.
  // `out_in_face(f)` is the `out` of the patch of face f.
  template <class OutInFace>
  void from_surface_point(const Surface_point<FT>& s, Index origin, OutInFace&& out_in_face) const
  {
    Surface_point<FT> other{Index(-1), {FT(0), FT(0), FT(0)}};
    for(int k = 0; k < 3; ++k)
      if(s.barycentric[k] == FT(0))
      {
        const Surface_point<FT> across = same_point_across_edge(m_mesh, s, k);
        if(across.face != Index(-1))
          other = across;
      }
    // the two faces of an edge point in the same order however the point was given
    if(other.face != Index(-1) && other.face < s.face)
      from_point_in_face(other, origin, out_in_face(other.face));
    from_point_in_face(s, origin, out_in_face(s.face));
    if(other.face != Index(-1) && other.face > s.face)
      from_point_in_face(other, origin, out_in_face(other.face));
  }

private:
  // windows into the faces that meet [back + from, back + to] for some recorded arrival
  // direction back (a union of cones sliding with back)
  template <class Out>
  void in_cone(Index v, FT dv, const Incoming_directions<FT>& in, FT from_back, FT to_back, Out& out) const
  {
    const FT theta = m_mesh.angle_sum(v);
    FT from = in.low + from_back;
    const FT width = (in.high + to_back) - from;
    if(!(width < theta))
    {
      all_around(v, dv, out);
      return;
    }
    if(width < FT(0))
      return;
    from = Number_type_math<FT>::fmod(from, theta);
    if(from < FT(0))
      from += theta;
    // the cone is [from, from + width] on the circle of length theta; corners in turning order
    out.count_pseudo_source();
    for(const Index* c = m_mesh.corners_begin(v); c != m_mesh.corners_end(v); ++c)
    {
      const FT start = m_mesh.corner_start_angle(*c);
      const FT end = start + m_mesh.corner_angle(*c);
      const bool meets = (end >= from && start <= from + width) ||
                         (end + theta >= from && start + theta <= from + width);
      if(meets)
        across_corner(v, dv, *c, out);
    }
  }

  // a full-edge window on the edge opposite `v` in the face of corner `h`, and the distances of
  // the corner's two other vertices along its edges
  template <class Out>
  void across_corner(Index v, FT dv, Index h, Out& out) const
  {
    const Index across = Mesh::next(h);
    const Index prev = Mesh::prev(h);
    // from target(h) back along its corner's last edge, from source(prev) back along prev
    out.relax(m_mesh.target(h), dv + m_mesh.length(h), across, m_mesh.apex(across), v);
    out.relax(m_mesh.source(prev), dv + m_mesh.length(prev), prev, Point{FT(1), FT(0)}, v);
    const Index t = m_mesh.opposite(across);
    if(t != Mesh::no_halfedge)
      out.add_window(t, window_across_corner(m_mesh, h, dv, m_bound_epsilon, v));
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
      out.relax(m_mesh.source(e), to_source, e, q, origin);
      const Index t = m_mesh.opposite(e);
      if(b[(k + 2) % 3] != FT(0) && t != Mesh::no_halfedge) // not on this edge
        out.add_window(t, window_from_point(m_mesh, e, q, FT(0), length(q - Point{m_mesh.length(e), FT(0)}),
                                            to_source, m_bound_epsilon, origin));
    }
  }

  const Mesh& m_mesh;
  const FT m_bound_epsilon;  // epsilon of the distance bound (0: exact, no bound)
  const FT m_fan_half_width; // radians added on both sides of a fan
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_PSEUDO_SOURCE_EMISSION_H
