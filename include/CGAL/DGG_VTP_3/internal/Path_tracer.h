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

#ifndef CGAL_DGG_VTP_3_INTERNAL_PATH_TRACER_H
#define CGAL_DGG_VTP_3_INTERNAL_PATH_TRACER_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/Unfolded_mesh.h>
#include <CGAL/DGG_VTP_3/internal/Vertex_copies.h>
#include <CGAL/DGG_VTP_3/internal/Vertex_directions.h>
#include <CGAL/DGG_VTP_3/internal/number_type_math.h>
#include <CGAL/DGG_VTP_3/internal/planar_geometry.h>

#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// A point of a path: at a vertex, on an edge or inside a face, given in the face the path
// crosses next (barycentric coordinates of its corners, as Unfolded_mesh numbers them: zeros
// for the corners whose opposite edge or vertex the point is not on).
template <class FT>
struct Path_point_internal
{
  enum Kind { VERTEX, EDGE, FACE };
  Kind kind;
  std::uint32_t face;
  std::array<FT, 3> barycentric;
  std::uint32_t vertex; // for a VERTEX
};

// Walks straight lines on the surface: a leg of a shortest path goes straight from a vertex (or a
// point of a face) in a given direction across faces, unfolding each onto the last, for a given
// length, and ends at the pseudo-source of the leg. Each edge crossed gives a path point.
template <class FT>
class Path_tracer
{
  using Mesh = Unfolded_mesh<FT>;
  using Index = typename Mesh::Index;
  using Point = Vec2<FT>;
  using Path_point = Path_point_internal<FT>;

public:
  explicit Path_tracer(const Mesh& mesh) : m_mesh(mesh) {}

  // The walk from the source of `corner` along `direction` (in the frame of `corner`), or from the
  // point `p` of the face of `h` (in the frame of `h`), for `length`; it ends at `end_vertex` or,
  // if that is `no_vertex()`, at `end_point`. Appends the edges crossed and the end.
  void walk_from_vertex(Index corner, const Point& direction, FT length, Index end_vertex, const Path_point& end_point,
                        std::vector<Path_point>& out) const
  {
    walk(corner, Point{number<FT>(0), number<FT>(0)}, direction, length, corner, true, end_vertex, end_point, out);
  }
  void walk_from_point(Index h, const Point& p, const Point& direction, FT length, Index end_vertex,
                       const Path_point& end_point, std::vector<Path_point>& out) const
  {
    walk(h, p, direction, length, Mesh::no_halfedge, false, end_vertex, end_point, out);
  }
  static Index no_vertex() { return Index(-1); }

  // vertex `v` as a path point of face `f` if it is one of its corners, else of one of its own faces
  Path_point vertex_point(Index v, Index f) const
  {
    for(int k = 0; k < 3; ++k)
      if(m_mesh.source(3 * f + k) == v)
        return corner_point(f, k);
    const Index c = *m_mesh.corners_begin(v);
    return corner_point(Mesh::face(c), int(c % 3));
  }

  // a point of the face of `h` given in the frame of `h`, as a path point
  Path_point face_point(Index h, const Point& p) const
  {
    const Index f = Mesh::face(h);
    const int k = int(h % 3);
    const Point c = m_mesh.apex(h);
    const FT len = m_mesh.length(h);
    // barycentric coordinates in the frame: p = b1 (len, 0) + b2 c
    const FT b2 = p.y / c.y;
    const FT b1 = (p.x - b2 * c.x) / len;
    Path_point q{Path_point::FACE, f, {number<FT>(0), number<FT>(0), number<FT>(0)}, Index(-1)};
    q.barycentric[(k + 1) % 3] = b1;
    q.barycentric[(k + 2) % 3] = b2;
    q.barycentric[k] = number<FT>(1) - b1 - b2;
    return q;
  }

private:
  // the frame of `to` (a halfedge of the same face as `from`) from the frame of `from`
  void change_frame(Index from, Index to, Point& p, Point& d) const
  {
    while(from != to)
    {
      // into the frame of next(from): its origin is (len, 0), its axis along (apex - (len, 0))
      const FT len = m_mesh.length(from);
      const Point c = m_mesh.apex(from);
      const Point axis = c - Point{len, number<FT>(0)};
      const FT n = m_mesh.length(Mesh::next(from));
      const Point q = p - Point{len, number<FT>(0)};
      p = Point{dot(q, axis) / n, cross(axis, q) / n};
      d = Point{dot(d, axis) / n, cross(axis, d) / n};
      from = Mesh::next(from);
    }
  }

  Path_point corner_point(Index f, int k) const
  {
    Path_point q{Path_point::VERTEX, f, {number<FT>(0), number<FT>(0), number<FT>(0)}, m_mesh.source(3 * f + Index(k))};
    q.barycentric[k] = number<FT>(1);
    return q;
  }

  // The walk from `p` in the face of `h`, entered through the edge of `entry` (none: from inside
  // the face; `h` itself and `from_corner`: from its source, leaving through the opposite edge).
  // Returns whether it ends where it should: at `end_vertex`, in a face of it, or in or beside
  // the face of `end_point`. Across an edge of copies (see Vertex_copies.h) the leg goes on in
  // the sheet where it does, the first if none.
  bool walk(Index h, Point p, Point d, FT length, Index entry, bool from_corner, Index end_vertex,
            const Path_point& end_point, std::vector<Path_point>& out) const
  {
    using Math = Number_type_math<FT>;
    d = Point{d.x / length_of(d), d.y / length_of(d)};
    const FT tolerance = number<FT>(1024) * Math::machine_epsilon();
    for(std::size_t steps = 0; steps <= 3 * m_mesh.number_of_faces(); ++steps)
    {
      // the edge of the face of h the ray leaves through: the nearest crossing ahead
      FT best_t = Math::infinity();
      Index exit = Mesh::no_halfedge;
      FT exit_u(0);
      const Point corner[3] = {Point{number<FT>(0), number<FT>(0)}, Point{m_mesh.length(h), number<FT>(0)}, m_mesh.apex(h)};
      for(int i = 0; i < 3; ++i)
      {
        const Index e = Mesh::face(h) * 3 + Index((h + i) % 3);
        if(e == entry || (from_corner && e == Mesh::prev(entry)))
          continue;
        const Point a = corner[i], b = corner[(i + 1) % 3];
        // p + t d = a + u (b - a)
        const Point ab = b - a;
        const FT den = cross(d, ab);
        if(!(den != FT(0)))
          continue;
        const Point ap = a - p;
        const FT t = cross(ap, ab) / den;
        const FT u = cross(ap, d) / den;
        if(t > -tolerance * length && u >= -tolerance && u <= FT(1) + tolerance && t < best_t)
        {
          best_t = t;
          exit = e;
          exit_u = u;
        }
      }
      const Index f = Mesh::face(h);
      if(exit == Mesh::no_halfedge || best_t >= length * (number<FT>(1) - tolerance))
        break; // the leg ends in this face
      const FT u = exit_u < FT(0) ? number<FT>(0) : (exit_u > FT(1) ? number<FT>(1) : exit_u);
      Point q = Point{p.x + best_t * d.x, p.y + best_t * d.y};
      length -= best_t;
      if(u <= tolerance || u >= FT(1) - tolerance)
      {
        // through a vertex w: a leg goes there only where it goes straight on (a flat vertex, or
        // along a straight border), so it continues in the opposite direction, turned by pi one
        // way round, or at a border the other way round if that leaves the fan, or along the
        // fan's first edge if both do
        const int kw = u <= tolerance ? int(exit % 3) : int((exit + 1) % 3);
        const Index cw = 3 * f + Index(kw);
        const Index w = m_mesh.source(cw);
        out.push_back(corner_point(f, kw));
        if(w == end_vertex)
          return true;
        Point back{-d.x, -d.y}, at{q.x, q.y};
        change_frame(h, cw, at, back);
        const Point straight{number<FT>(1), number<FT>(0)};
        const Corner_direction<FT, Index> arrival{cw, 0, back.y < FT(0) ? straight : back};
        Corner_direction<FT, Index> on = arrival;
        if(!turn_direction(m_mesh, on, true, straight))
        {
          on = arrival;
          if(!turn_direction(m_mesh, on, false, straight))
            on = Corner_direction<FT, Index>{*m_mesh.corners_begin(w), 0, straight};
        }
        h = on.corner;
        p = Point{number<FT>(0), number<FT>(0)};
        d = Point{on.vector.x / length_of(on.vector), on.vector.y / length_of(on.vector)};
        entry = h;
        from_corner = true;
        continue;
      }
      const Index o = m_mesh.opposite(exit);
      Path_point x{Path_point::EDGE, f, {number<FT>(0), number<FT>(0), number<FT>(0)}, Index(-1)};
      x.barycentric[exit % 3] = number<FT>(1) - u;
      x.barycentric[(exit + 1) % 3] = u;
      out.push_back(x);
      if(!m_mesh.has_face_across(exit))
        break; // onto the border: only rounding puts a leg there
      // continue in the neighbour: the crossing and the direction in the frame of `exit`, then
      // in the frame of its opposite halfedge (the same edge the other way, the face below), or of
      // a twin along the same way (the face below is then its face mirrored)
      change_frame(h, exit, q, d);
      const FT len = m_mesh.length(exit);
      const auto across = [&](Index g, Point& pg, Point& dg) {
        const bool mirrored = !same_point(m_mesh, m_mesh.source(g), m_mesh.target(exit));
        pg = mirrored ? Point{q.x, -q.y} : Point{len - q.x, -q.y};
        dg = mirrored ? Point{d.x, -d.y} : Point{-d.x, -d.y};
      };
      if(m_mesh.next_twin(exit) != exit)
      {
        std::vector<Path_point> first;
        bool tried = false;
        const auto try_sheet = [&](Index g) {
          std::vector<Path_point> rest;
          Point pg, dg;
          across(g, pg, dg);
          const bool arrived = walk(g, pg, dg, length, g, false, end_vertex, end_point, rest);
          if(!tried)
            first = rest;
          tried = true;
          if(arrived)
            out.insert(out.end(), rest.begin(), rest.end());
          return arrived;
        };
        if(o != Mesh::no_halfedge && try_sheet(o))
          return true;
        for(Index g = m_mesh.next_twin(exit); g != exit; g = m_mesh.next_twin(g))
          if(g != o && try_sheet(g))
            return true;
        out.insert(out.end(), first.begin(), first.end());
        return false;
      }
      across(o, p, d);
      h = o;
      entry = o;
      from_corner = false;
    }
    out.push_back(end_vertex != no_vertex() ? vertex_point(end_vertex, Mesh::face(h)) : end_point);
    return ends_beside(Mesh::face(h), end_vertex, end_point);
  }

  // whether face `f` has `end_vertex` as a corner, or is the face of `end_point` or next to it
  bool ends_beside(Index f, Index end_vertex, const Path_point& end_point) const
  {
    if(end_vertex != no_vertex())
      return m_mesh.source(3 * f) == end_vertex || m_mesh.source(3 * f + 1) == end_vertex ||
             m_mesh.source(3 * f + 2) == end_vertex;
    for(Index e = 3 * end_point.face; e < 3 * end_point.face + 3; ++e)
    {
      if(m_mesh.opposite(e) != Mesh::no_halfedge && Mesh::face(m_mesh.opposite(e)) == f)
        return true;
      for(Index g = m_mesh.next_twin(e); g != e; g = m_mesh.next_twin(g))
        if(Mesh::face(g) == f)
          return true;
    }
    return f == end_point.face;
  }

  static FT length_of(const Point& v) { return internal::length(v); }

  const Mesh& m_mesh;
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_PATH_TRACER_H
