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

#ifndef CGAL_DGG_VTP_3_INTERNAL_POINT_TARGETS_H
#define CGAL_DGG_VTP_3_INTERNAL_POINT_TARGETS_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/Key_ratio.h>
#include <CGAL/DGG_VTP_3/internal/Propagation_query.h>
#include <CGAL/DGG_VTP_3/internal/Surface_point.h>
#include <CGAL/DGG_VTP_3/internal/Unfolded_mesh.h>
#include <CGAL/DGG_VTP_3/internal/Window.h>
#include <CGAL/DGG_VTP_3/internal/number_type_math.h>
#include <CGAL/DGG_VTP_3/internal/planar_geometry.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// The distances of points of faces, computed during a propagation: the shortest path to a point
// of face f enters f through one of its edges, carried by a window crossing f, or comes from one
// of f's corners (a pseudo-source there) or from a source in f. So the exact distance is the
// smallest of what the windows crossing f give at the point, D(corner) + |corner point| and
// |source point|; the windows are looked at as they cross, so nothing is kept. A point on an edge
// belongs to both faces; each face keeps its own best value (a patch writes only its faces), and
// the two are combined at the end.
template <class FT>
class Point_targets
{
  using Mesh = Unfolded_mesh<FT>;
  using Index = typename Mesh::Index;
  using Point = Vec2<FT>;

public:
  Point_targets() = default;

  // `points` must not be at a vertex (such a target is the vertex)
  Point_targets(const Mesh& mesh, const std::vector<Surface_point<FT>>& points)
    : m_count(points.size())
  {
    if(points.empty())
      return;
    std::vector<std::pair<Index, Entry>> entries;
    for(std::size_t t = 0; t < points.size(); ++t)
    {
      const Surface_point<FT>& q = points[t];
      entries.emplace_back(q.face, Entry{Index(t), q.barycentric, infinity(), Index(-1), Index(-1), Point{number<FT>(0), number<FT>(0)}});
      std::vector<Surface_point<FT>> across;
      for(int k = 0; k < 3; ++k)
        if(q.barycentric[k] == FT(0))
          same_point_across_edge(mesh, q, k, across);
      for(const Surface_point<FT>& other : across)
        entries.emplace_back(other.face, Entry{Index(t), other.barycentric, infinity(), Index(-1), Index(-1),
                                               Point{number<FT>(0), number<FT>(0)}});
    }
    std::stable_sort(entries.begin(), entries.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    m_faces.reserve(entries.size());
    m_entries.reserve(entries.size());
    for(const auto& e : entries)
    {
      m_faces.push_back(e.first);
      m_entries.push_back(e.second);
    }
  }

  bool empty() const { return m_count == 0; }
  // a search among the targets' faces, not an array of the mesh's: a query costs what it reaches
  bool in_face(Index f) const { return std::binary_search(m_faces.begin(), m_faces.end(), f); }

  // the windows of the list of halfedge `h` cross its face: each gives its distance to the
  // targets of the face inside its beam (`keys`: the windows' key ratio)
  void cross(const Mesh& mesh, Index h, const std::vector<Window<FT>>& windows, const Key_ratio<FT>& keys)
  {
    const Index f = Mesh::face(h);
    const int k = int(h % 3);
    const Point c = mesh.apex(h);
    const FT len = mesh.length(h);
    for(auto it = std::lower_bound(m_faces.begin(), m_faces.end(), f); it != m_faces.end() && *it == f; ++it)
    {
      Entry& e = m_entries[it - m_faces.begin()];
      const Point q{e.barycentric[(k + 1) % 3] * len + e.barycentric[(k + 2) % 3] * c.x,
                    e.barycentric[(k + 2) % 3] * c.y};
      for(const Window<FT>& w : windows)
      {
        // inside the beam: between the rays through b0 (on the left) and b1
        const Point r = q - w.source;
        if(cross_product(Point{w.b1 - w.source.x, -w.source.y}, r) < FT(0) ||
           cross_product(r, Point{w.b0 - w.source.x, -w.source.y}) < FT(0))
          continue;
        const FT d = keys.distance(w.sigma) + length(r);
        if(d < e.best)
          e.set(d, w.origin, h, w.source - q);
      }
    }
  }

  // the largest of the targets' distances found so far, by the windows seen and by the corners'
  // distances `vertex_distance` (+inf while one is unreached)
  FT largest_bound(const Mesh& mesh, const std::vector<FT>& vertex_distance) const
  {
    std::vector<FT> bound(m_count, infinity());
    for(std::size_t i = 0; i < m_entries.size(); ++i)
    {
      const Entry& e = m_entries[i];
      FT& b = bound[e.target];
      b = (std::min)(b, e.best);
      const Index f = m_faces[i];
      const Point corner[3] = {Point{number<FT>(0), number<FT>(0)}, Point{mesh.length(3 * f), number<FT>(0)}, mesh.apex(3 * f)};
      const Point q = position(e.barycentric, corner);
      for(int k = 0; k < 3; ++k)
        b = (std::min)(b, vertex_distance[mesh.source(3 * f + k)] + length(q - corner[k]));
    }
    FT largest(0);
    for(const FT& b : bound)
      largest = (std::max)(largest, b);
    return largest;
  }

  // The distances of the targets, after the propagation, with what the corners and the source
  // points give.
  void finish(const Mesh& mesh, const std::vector<FT>& vertex_distance, const Propagation_query<FT>& query)
  {
    const Index nv = Index(vertex_distance.size());
    const std::vector<Surface_point<FT>>& sources = query.point_sources;
    for(std::size_t i = 0; i < m_entries.size(); ++i)
    {
      Entry& e = m_entries[i];
      const Index f = m_faces[i];
      const Point corner[3] = {Point{number<FT>(0), number<FT>(0)}, Point{mesh.length(3 * f), number<FT>(0)}, mesh.apex(3 * f)};
      const Point q = position(e.barycentric, corner);
      for(int k = 0; k < 3; ++k)
      {
        const Index v = mesh.source(3 * f + k);
        const FT d = vertex_distance[v] + length(q - corner[k]);
        if(d < e.best)
          e.set(d, v, 3 * f, corner[k] - q);
      }
      for(std::size_t s = 0; s < sources.size(); ++s)
        if(sources[s].face == f)
        {
          const Point source = position(sources[s].barycentric, corner);
          const FT d = length(q - source);
          if(d < e.best)
            e.set(d, nv + query.source_numbers[query.vertex_sources.size() + s], 3 * f, source - q);
        }
    }
  }

  // how the shortest path found reaches a target: its length, its pseudo-source (a vertex, or the
  // number of vertices + the number of a source), and the direction it arrives from, in the frame
  // of a halfedge of the target's face
  struct Arrival
  {
    FT distance;
    Index origin;
    Index frame;
    Point direction;
    std::array<FT, 3> barycentric; // the target in the frame's face
  };

  // per target: how its shortest path arrives
  void combine(std::vector<Arrival>& arrivals) const
  {
    arrivals.assign(m_count, Arrival{infinity(), Index(-1), Index(-1), Point{number<FT>(0), number<FT>(0)}, {number<FT>(0), number<FT>(0), number<FT>(0)}});
    for(const Entry& e : m_entries)
      if(e.best < arrivals[e.target].distance)
        arrivals[e.target] = Arrival{e.best, e.origin, e.frame, e.direction, e.barycentric};
  }

  // per target: its distance
  std::vector<FT> distances() const
  {
    std::vector<Arrival> arrivals;
    combine(arrivals);
    std::vector<FT> d;
    for(const Arrival& a : arrivals)
      d.push_back(a.distance);
    return d;
  }

private:
  static FT infinity() { return Number_type_math<FT>::infinity(); }
  static FT cross_product(const Point& a, const Point& b) { return internal::cross(a, b); }
  static Point position(const std::array<FT, 3>& b, const Point* corner)
  {
    return Point{b[0] * corner[0].x + b[1] * corner[1].x + b[2] * corner[2].x,
                 b[0] * corner[0].y + b[1] * corner[1].y + b[2] * corner[2].y};
  }

  struct Entry
  {
    Index target;                   // its number among the targets
    std::array<FT, 3> barycentric;  // in this face
    FT best;                        // the shortest distance found through this face
    Index origin;                   // the pseudo-source of that path
    Index frame;                    // a halfedge of the face, the frame of `direction`
    Point direction;                // where that path arrives from
    void set(FT d, Index o, Index h, const Point& towards)
    {
      best = d;
      origin = o;
      frame = h;
      direction = towards;
    }
  };
  std::size_t m_count = 0;
  std::vector<Index> m_faces;       // per entry, sorted: its face
  std::vector<Entry> m_entries;
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_POINT_TARGETS_H
