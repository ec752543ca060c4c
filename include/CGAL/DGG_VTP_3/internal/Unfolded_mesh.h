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

#ifndef CGAL_DGG_VTP_3_INTERNAL_UNFOLDED_MESH_H
#define CGAL_DGG_VTP_3_INTERNAL_UNFOLDED_MESH_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/Default_init_allocator.h>
#include <CGAL/DGG_VTP_3/internal/Tuning.h>
#include <CGAL/DGG_VTP_3/internal/Vertex_directions.h>
#include <CGAL/DGG_VTP_3/internal/for_each_block.h>
#include <CGAL/DGG_VTP_3/internal/mesh_combinatorics.h>
#include <CGAL/DGG_VTP_3/internal/number_type_math.h>
#include <CGAL/DGG_VTP_3/internal/planar_geometry.h>

#include <CGAL/number_type_config.h>
#include <CGAL/number_utils.h>

#include <cmath>
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <utility>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// How the unfolding renumbered the user's elements (see unfold_triangles()): face i of the mesh is
// the user's face faces[i], vertex i the user's vertex vertices[i].
struct Unfolding_order
{
  std::vector<std::uint32_t> faces, vertices;
};

// Everything the propagation needs to know about the mesh, computed once per mesh: the intrinsic
// geometry (edge lengths, each triangle unfolded onto each of its edges) and the combinatorics, in
// flat arrays indexed by "corner halfedges" `3 * f + k` (face `f`, corner `k`), so that a query
// never touches the user's mesh data structure again.
//
// Halfedge `3f+k` goes from corner `k` to corner `k+1` of face `f`; its frame has corner `k` at the
// origin, corner `k+1` at `(length, 0)` and corner `k+2`, the apex, at `apex` (with `apex.y > 0`).
template <class FT>
class Unfolded_mesh
{
public:
  using Index = std::uint32_t;
  static constexpr Index no_halfedge = Index(-1);

  std::size_t number_of_vertices() const { return m_vertex_corners_begin.size() - 1; }
  std::size_t number_of_faces() const { return m_corner_vertex.size() / 3; }
  std::size_t number_of_halfedges() const { return m_corner_vertex.size(); }

  static Index face(Index h) { return h / 3; }
  static Index next(Index h) { return h % 3 == 2 ? h - 2 : h + 1; }
  static Index prev(Index h) { return h % 3 == 0 ? h + 2 : h - 1; }

  // source vertex of halfedge `h` (= the vertex at corner `h`)
  Index source(Index h) const { return m_corner_vertex[h]; }
  Index target(Index h) const { return m_corner_vertex[next(h)]; }
  // the same edge seen from the neighbouring face, or `no_halfedge` on the border
  Index opposite(Index h) const { return m_opposite[h]; }
  FT length(Index h) const { return m_length[h]; }
  Vec2<FT> apex(Index h) const { return {m_apex_x[h], m_twice_area[face(h)] / m_length[h]}; }
  // A vector along the last edge of the corner of `h`, in its frame: its angle is the corner's
  // angle, and only its direction is used (angle sums, turns). In the inexact types it is the unit
  // vector, so that products of many stay in range. In an exact type it is (ab . ac, twice the
  // area), with the face's area as its only square root: CORE proves a tie (an angle sum of
  // exactly 2 pi at a flat vertex) at a cost that doubles with every distinct root involved, and
  // the unit vector would bring in the two edge lengths too (a vertex of six faces: 6 roots
  // instead of 12).
  Vec2<FT> last_edge_direction(Index h) const
  {
    if constexpr(Number_type_math<FT>::is_exact)
      return {m_corner_dot[h], m_twice_area[face(h)]};
    else
    {
      const Vec2<FT> a = apex(h);
      const FT l = m_length[prev(h)];
      return {a.x / l, a.y / l};
    }
  }

  // the corners at vertex `v`: halfedges `h` with `source(h) == v`, in turning order (counterclockwise
  // seen from the faces' front, starting after the border if there is one) unless `v` is
  // non-manifold
  const Index* corners_begin(Index v) const { return m_vertex_corners.data() + m_vertex_corners_begin[v]; }
  const Index* corners_end(Index v) const { return m_vertex_corners.data() + m_vertex_corners_begin[v + 1]; }
  // the position of corner `h` among its vertex's corners (a search among a few: the exact mode's
  // shadows alone ask, and an array of them would cost 4 bytes a halfedge), and the corner at a position
  Index corner_rank(Index h) const
  {
    const Index* first = corners_begin(source(h));
    return Index(std::find(first, corners_end(source(h)), h) - first);
  }
  Index corner_of_rank(Index v, Index rank) const { return corners_begin(v)[rank]; }

  // the corner after `h` in turning order at source(h): its first edge is the last edge of `h`'s
  // corner; the one before; `no_halfedge` past a border
  Index next_in_turn(Index h) const { return m_opposite[prev(h)]; }
  Index previous_in_turn(Index h) const { return m_opposite[h] == no_halfedge ? no_halfedge : next(m_opposite[h]); }
  // on the border, or where several umbrellas meet: geodesics may turn there at any angle
  bool is_singular(Index v) const { return m_singular[v] != 0; }
  // geodesics may bend there: saddle (angle sum above 2*pi), border or non-manifold vertex
  bool is_exact_pseudo_source(Index v) const { return m_exact_pseudo_source[v] != 0; }

  // the position of vertex `v` in space, rounded to float: for lower bounds of distances, which
  // allow for the rounding (see Distance_to_go)
  const float* position(Index v) const { return m_position.data() + 3 * std::size_t(v); }

  // vertices where several fans of faces meet (kept: geodesics may pass through them)
  std::size_t number_of_non_manifold_vertices() const { return m_non_manifold_vertices; }

  // Copies of one point, sheets split apart where they met (see link_copies()): the next vertex
  // at the point of `v`, round a cycle (`v` itself if none); the next halfedge along the edge of
  // `h` in another sheet, round a cycle (`h` itself if none). A window leaving a face across the
  // edge of `h` enters the faces of opposite(h) and of these (see for_each_face_across()).
  Index next_copy(Index v) const { return m_next_copy.empty() ? v : m_next_copy[v]; }
  Index next_twin(Index h) const { return m_next_twin.empty() ? h : m_next_twin[h]; }
  bool has_twins() const { return !m_next_twin.empty(); }
  bool has_face_across(Index h) const { return m_opposite[h] != no_halfedge || next_twin(h) != h; }

  template <class ConcurrencyTag, class FT_>
  friend Unfolding_order unfold_triangles(std::vector<FT_> xyz, Uninitialized_vector<std::uint32_t> corner_vertex,
                                          Uninitialized_vector<std::uint32_t> opposite, Unfolded_mesh<FT_>& out);
  template <class FT_>
  friend void link_copies(const std::vector<std::uint32_t>& group, Unfolded_mesh<FT_>& mesh);

private:
  Uninitialized_vector<Index> m_corner_vertex; // 3F: vertex at each corner
  Uninitialized_vector<Index> m_opposite;   // 3F: opposite corner halfedge, or no_halfedge
  Uninitialized_vector<FT> m_length;        // 3F: length of each halfedge
  Uninitialized_vector<FT> m_apex_x;        // 3F: abscissa of the apex in each halfedge's frame
  Uninitialized_vector<FT> m_twice_area;    // F: twice the area (the apex's height times the length)
  std::vector<FT> m_corner_dot;             // 3F in exact types (else empty): ab . ac at each corner
  std::vector<Index> m_vertex_corners_begin;// V+1: CSR offsets into m_vertex_corners
  Uninitialized_vector<Index> m_vertex_corners; // 3F: corners grouped by vertex, in turning order
  std::vector<float> m_position;            // 3V: the vertices' coordinates, rounded to float
  std::vector<char> m_singular;             // V: border or non-manifold vertex
  std::vector<char> m_exact_pseudo_source;  // V: pseudo-source of the exact (VTP) propagation
  std::size_t m_non_manifold_vertices = 0;
  std::vector<Index> m_next_copy;           // V, or empty where no vertex has a copy
  std::vector<Index> m_next_twin;           // 3F, or empty where no edge has a copy
};

// Halfedges are numbered 3 f + k in 32 bits, the largest number meaning "none": throws
// std::invalid_argument for a mesh whose faces or vertices do not fit.
template <class FT>
void check_index_range(std::size_t number_of_vertices, std::size_t number_of_faces)
{
  const std::size_t most = std::size_t(Unfolded_mesh<FT>::no_halfedge) / 3 - 1;
  if(number_of_faces > most || number_of_vertices > most)
    throw std::invalid_argument("the mesh is too large: " + std::to_string(number_of_faces) + " faces and " +
                                std::to_string(number_of_vertices) + " vertices, at most " + std::to_string(most) +
                                " of each are supported (32-bit indices)");
}

inline std::string to_short_string(double x)
{
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.3g", x);
  return buffer;
}

// The square roots of the preparation. An exact number type (CORE::Expr) bounds the cost of
// proving two numbers equal by the product of the degrees of the distinct roots they are built
// from, and a tie on a symmetric mesh (a tetrahedron, a prism) compares numbers built from every
// edge length and face area: one root per distinct radicand, and none for a radicand that is the
// square of a double (integer lengths: 3, 4, 5), keeps that product small (a regular
// tetrahedron: 2 roots instead of 16). Other number types just take the root.
template <class FT, bool exact = Number_type_math<FT>::is_exact>
class Shared_square_roots
{
public:
  FT operator()(const FT& x) { return Number_type_math<FT>::sqrt(x); }
};

template <class FT>
class Shared_square_roots<FT, true>
{
public:
  FT operator()(const FT& x)
  {
    auto it = m_roots.find(x);
    if(it == m_roots.end())
    {
      const FT r = Number_type_math<FT>::sqrt(x);
      const FT nearest(CGAL::to_double(r));
      it = m_roots.emplace(x, nearest * nearest == x ? nearest : r).first;
    }
    return it->second;
  }

private:
  std::map<FT, FT> m_roots;
};

// Fills the mesh from the coordinates of the vertices (3 per vertex), the vertex at each corner
// and the opposite of each halfedge (`no_halfedge` on the border), vertices and faces in the
// user's order; checks the geometry. With no opposites given (a triangle soup), each halfedge a->b
// is matched with the one halfedge b->a, if any. The mesh numbers its faces along a space-filling
// curve and its vertices as those faces first use them; returns both orders (see
// Unfolding_order). Errors name faces and vertices by the user's numbers. Each step is a loop over faces or vertices whose iterations write only their own
// face's or vertex's data, run as `ConcurrencyTag` says (for_each_block()): the mesh is the same bit
// for bit whatever the tag and the number of threads (it must be `Sequential_tag` for an exact `FT`,
// whose numbers share their representations between copies).
template <class ConcurrencyTag, class FT>
Unfolding_order unfold_triangles(std::vector<FT> xyz, Uninitialized_vector<std::uint32_t> corner_vertex,
                                 Uninitialized_vector<std::uint32_t> opposite, Unfolded_mesh<FT>& out)
{
  using Index = typename Unfolded_mesh<FT>::Index;
  constexpr Index no_halfedge = Unfolded_mesh<FT>::no_halfedge;
  const std::size_t nv = xyz.size() / 3;
  const std::size_t nf = corner_vertex.size() / 3;
  double extent = 0.;
  const std::vector<Index> order = faces_in_space_order<ConcurrencyTag>(xyz, corner_vertex, extent);
  // otherwise every edge would be refused as too short for a mesh "inf across"
  if(!std::isfinite(extent))
    throw std::invalid_argument("the vertices span more than the largest finite double: "
                                "scale the mesh down (distances scale with it)");
  reorder_faces<ConcurrencyTag>(order, corner_vertex, opposite);
  const std::vector<Index> vertex_order = reorder_vertices<ConcurrencyTag>(corner_vertex, xyz);
  out.m_corner_vertex.swap(corner_vertex);
  // corners around each vertex (CSR); the faces' spatial order makes walking them cache-friendly
  group_corners_by_vertex<ConcurrencyTag>(out.m_corner_vertex, nv, out.m_vertex_corners_begin, out.m_vertex_corners);
  if(opposite.empty())
    opposite = matched_halfedges<ConcurrencyTag>(out.m_corner_vertex, out.m_vertex_corners_begin, out.m_vertex_corners,
                                                 order, vertex_order);
  out.m_opposite.swap(opposite);
  out.m_length.resize(3 * nf);
  out.m_apex_x.resize(3 * nf);
  out.m_twice_area.resize(nf);
  if constexpr(Number_type_math<FT>::is_exact)
    out.m_corner_dot.resize(3 * nf);

  // unfold each triangle onto each of its three edges; the area comes from the two shortest edges
  // (errors name the face by the user's index)
  const double shortest_accepted = CGAL::to_double(Tuning<FT>::min_relative_edge()) * extent;
  Shared_square_roots<FT> root; // keeps its roots only in an exact type, whose loops run on one thread
  for_each_block<ConcurrencyTag>(nf, [&](std::size_t f0, std::size_t f1) {
    for(std::size_t fi = f0; fi < f1; ++fi)
    {
      const std::size_t user_face = order[fi];
      FT p[3][3];
      for(int k = 0; k < 3; ++k)
        for(int c = 0; c < 3; ++c)
          p[k][c] = xyz[3 * out.m_corner_vertex[3 * fi + k] + c];
      const auto degenerate = [user_face] {
        return std::invalid_argument("face " + std::to_string(user_face) + " is degenerate (zero length edge or zero area)");
      };
      const auto too_large = [user_face] {
        return std::invalid_argument("face " + std::to_string(user_face) +
                                     " is too large for the number type (its squared edge lengths or area overflow): "
                                     "scale the mesh down (distances scale with it)");
      };
      FT twice_area(0), longest(0);
      for(int k = 0; k < 3; ++k)
      {
        const FT* a = p[k];
        const FT* b = p[(k + 1) % 3];
        const FT* c = p[(k + 2) % 3];
        const FT ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const FT ac[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const FT len = root(ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2]);
        const Index hi = Index(3 * fi + k);
        out.m_length[hi] = len;
        const FT corner_dot = ab[0] * ac[0] + ab[1] * ac[1] + ab[2] * ac[2];
        out.m_apex_x[hi] = corner_dot / len;
        if constexpr(Number_type_math<FT>::is_exact)
          out.m_corner_dot[hi] = corner_dot;
        if(!CGAL::is_finite(len))
          throw too_large();
        if(!(len > FT(0)) || !CGAL::is_finite(out.m_apex_x[hi]))
          throw degenerate();
        if(CGAL::to_double(len) < shortest_accepted)
          throw std::invalid_argument("face " + std::to_string(user_face) + " has an edge of length " +
                                      to_short_string(CGAL::to_double(len)) + " in a mesh " + to_short_string(extent) +
                                      " across: distances on this mesh cannot tell so short an edge from rounding (at least " +
                                      to_short_string(CGAL::to_double(Tuning<FT>::min_relative_edge())) +
                                      " times the mesh's size is accepted)");
        // the edge after the longest one and the one before it meet at the corner opposite it
        if(len > longest)
        {
          longest = len;
          const FT* o = p[(k + 2) % 3];
          const FT u[3] = {a[0] - o[0], a[1] - o[1], a[2] - o[2]};
          const FT v[3] = {b[0] - o[0], b[1] - o[1], b[2] - o[2]};
          const FT n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
          twice_area = root(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        }
      }
      out.m_twice_area[fi] = twice_area;
      if(!CGAL::is_finite(twice_area))
        throw too_large();
      if(!(twice_area > FT(0)) || !CGAL::is_finite(twice_area / longest))
        throw degenerate();
      // longest / height on it = longest^2 / (2 area)
      if(longest > Tuning<FT>::max_sliver_ratio() * (twice_area / longest))
        throw std::invalid_argument("face " + std::to_string(user_face) + " is a sliver: an edge " +
                                    to_short_string(CGAL::to_double(longest * longest / twice_area)) +
                                    " times longer than the height on it (at most " +
                                    to_short_string(CGAL::to_double(Tuning<FT>::max_sliver_ratio())) + " is accepted)");
    }
  });
  out.m_position.resize(xyz.size());
  for_each_block<ConcurrencyTag>(xyz.size(), [&](std::size_t i0, std::size_t i1) {
    for(std::size_t i = i0; i < i1; ++i)
      out.m_position[i] = float(CGAL::to_double(xyz[i]));
  });
  xyz = std::vector<FT>(); // its memory is the peak's

  // border vertices, on one thread: the halfedges in order are a stream, a vertex's corners are not
  out.m_singular.assign(nv, 0);
  for(Index h = 0; h < 3 * nf; ++h)
    if(out.m_opposite[h] == no_halfedge)
    {
      out.m_singular[out.source(h)] = 1;
      out.m_singular[out.target(h)] = 1;
    }
  // angles are summed as turns (Angle_sum of each corner's last_edge_direction), never in radians

  // Put the corners of each vertex in turning order (corner h, then the corner across the edge
  // prev(h)), starting after the border if there is one, and sum the angles of each closed fan.
  // A vertex whose corners are not one fan (several umbrellas meet there) is singular.
  std::vector<Angle_sum<FT>> angle_sum(nv);
  // Each vertex at its first corner (the smallest, marked before the loop puts any in turning
  // order), so in the faces' spatial order: its corners' faces are then near each other in memory.
  std::vector<char> is_first(3 * nf, 0);
  for_each_block<ConcurrencyTag>(nv, [&](std::size_t v0, std::size_t v1) {
    for(Index v = Index(v0); v < v1; ++v)
      if(out.corners_begin(v) != out.corners_end(v))
        is_first[*out.corners_begin(v)] = 1;
  });
  std::atomic<std::size_t> non_manifold(0);
  for_each_block<ConcurrencyTag>(3 * nf, [&](std::size_t h0, std::size_t h1) {
    std::vector<Index> ordered;
    std::size_t pinched = 0;
    for(Index corner = Index(h0); corner < h1; ++corner)
    {
      if(!is_first[corner])
        continue;
      const Index v = out.source(corner);
      Index* first = out.m_vertex_corners.data() + out.m_vertex_corners_begin[v];
      Index* last = out.m_vertex_corners.data() + out.m_vertex_corners_begin[v + 1];
      Index start = *first;
      for(Index* c = first; c != last; ++c)
        if(out.m_opposite[*c] == no_halfedge)
          start = *c;
      ordered.clear();
      Index h = start;
      do
      {
        ordered.push_back(h);
        angle_sum[v].add(out.last_edge_direction(h));
        const Index across = out.m_opposite[Unfolded_mesh<FT>::prev(h)];
        if(across == no_halfedge)
          break;
        h = across;
      }
      while(h != start && ordered.size() <= std::size_t(last - first));
      if(ordered.size() == std::size_t(last - first))
        std::copy(ordered.begin(), ordered.end(), first);
      else
      {
        out.m_singular[v] = 1;
        ++pinched;
      }
    }
    non_manifold += pinched; // a count: the same whatever the order of the blocks
  });
  out.m_non_manifold_vertices = non_manifold;

  // Windows wrap around the tip of a closed fan (a cone) about pi / angle times before the ICH
  // rule prunes them, so a needle-sharp cone would make the propagation run for hours. A regular
  // vertex is one closed fan, its angle sum; at a singular one (border, or several fans meeting
  // there), each fan that closes is walked: a sharp cone may be joined to other faces.
  {
    const FT min_angle = Tuning<FT>::min_cone_angle();
    const Vec2<FT> min_turn = small_turn(min_angle);
    const auto check_cone = [&](std::size_t v, const Angle_sum<FT>& angle) {
      if(angle.compare(0, min_turn) < 0)
        throw std::invalid_argument("vertex " + std::to_string(vertex_order[v]) + " is the tip of a cone of angle " +
                                    to_short_string(std::atan2(CGAL::to_double(angle.at.y), CGAL::to_double(angle.at.x))) +
                                    " radians (at least " + to_short_string(CGAL::to_double(min_angle)) +
                                    " is accepted)");
    };
    std::vector<char> walked(3 * nf, 0); // a fan's corners are all at its vertex: one block's
    for_each_block<ConcurrencyTag>(nv, [&](std::size_t v0, std::size_t v1) {
      for(std::size_t v = v0; v < v1; ++v)
      {
        if(!out.m_singular[v])
        {
          if(out.corners_begin(Index(v)) != out.corners_end(Index(v)))
            check_cone(v, angle_sum[v]);
          continue;
        }
        for(const Index* first = out.corners_begin(Index(v)); first != out.corners_end(Index(v)); ++first)
        {
          if(walked[*first])
            continue;
          Angle_sum<FT> angle;
          Index h = *first;
          while(h != no_halfedge && !walked[h])
          {
            walked[h] = 1;
            angle.add(out.last_edge_direction(h));
            h = out.m_opposite[Unfolded_mesh<FT>::prev(h)];
          }
          if(h == *first)
            check_cone(v, angle);
        }
      }
    });
  }

  // A flat vertex computed as slightly above 2*pi is harmless as a pseudo-source (its windows
  // are real paths, pruned like any other); one computed slightly below relies on the windows of
  // either side meeting exactly along the straight line through it, which rounding blurs. So
  // the test leans towards saddles, by a relative flat_tolerance() of 2 pi (none when exact).
  const double below = 2 * CGAL_PI * CGAL::to_double(Tuning<FT>::flat_tolerance());
  const bool exactly = !(below > 0.);
  const Vec2<FT> two_pi_less = exactly ? Vec2<FT>{number<FT>(1), number<FT>(0)} : Vec2<FT>{number<FT>(std::cos(below)), number<FT>(-std::sin(below))};
  out.m_exact_pseudo_source.assign(nv, 0);
  for_each_block<ConcurrencyTag>(nv, [&](std::size_t v0, std::size_t v1) {
    for(std::size_t v = v0; v < v1; ++v)
      out.m_exact_pseudo_source[v] = out.m_singular[v] || angle_sum[v].compare(exactly ? 2 : 1, two_pi_less) > 0;
  });
  return Unfolding_order{order, vertex_order};
}

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_UNFOLDED_MESH_H
