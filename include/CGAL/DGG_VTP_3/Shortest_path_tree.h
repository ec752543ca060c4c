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

#ifndef CGAL_DGG_VTP_3_SHORTEST_PATH_TREE_H
#define CGAL_DGG_VTP_3_SHORTEST_PATH_TREE_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/Propagation_statistics.h>
#include <CGAL/DGG_VTP_3/internal/Path_tracer.h>
#include <CGAL/DGG_VTP_3/internal/Point_targets.h>
#include <CGAL/DGG_VTP_3/internal/Propagation_query.h>
#include <CGAL/DGG_VTP_3/internal/Window_propagation.h>
#include <CGAL/DGG_VTP_3/internal/nearest_sources.h>
#include <CGAL/DGG_VTP_3/internal/number_type_math.h>

#include <CGAL/Polygon_mesh_processing/locate.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <iterator>
#include <type_traits>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {

/*!
 * \ingroup PkgDGGVTP3Ref
 *
 * The result of `Geodesic_distance_solver::compute_shortest_path_tree()`: the distances of the
 * vertices (and of the query's targets) and what tracing their shortest paths back to the
 * nearest source needs, per vertex the pseudo-source of its path (a source, a saddle or border
 * vertex in the exact mode, any vertex with DGG-VTP) and the direction the path arrives from.
 * A path is traced in time proportional to the number of faces it crosses; it is made of
 * straight legs (in the unfolding of the faces they cross) from pseudo-source to pseudo-source,
 * and its length is the distance reported for its target. On a soup given copies of points
 * (`copy_of`), a path that goes from one sheet to another through a copy has two points in a row
 * at the copies, one in each sheet.
 *
 * It keeps the prepared mesh of the solver that computed it: it stays valid when that solver is
 * destroyed, assigned or moved, and the mesh need not outlive it either.
 */
template <class Solver>
class Shortest_path_tree
{
  using Core = typename Solver::Core;
  using Computation_FT = typename Core::Computation_FT;
  using Index = typename Core::Index;
  using Tracer = internal::Path_tracer<Computation_FT>;
  using Internal_point = internal::Path_point_internal<Computation_FT>;

public:
  using FT = typename Solver::FT;
  using vertex_descriptor = typename Solver::vertex_descriptor;
  using face_descriptor = typename Solver::face_descriptor;
  using Face_location = typename Solver::Face_location;

  /// a point of a path
  struct Path_point
  {
    /// where the point is: at a vertex, on an edge, inside a face
    enum Simplex { VERTEX, EDGE, FACE };
    Simplex simplex;
    /// the point in a face: for all points but the first, the face the path crosses from the
    /// previous point to this one (so that the faces it crosses are those of its points); an edge
    /// point has one zero coordinate, a vertex two
    Face_location location;
    /// the vertex, for a `VERTEX`
    vertex_descriptor vertex;
  };

  /// the distance of `v` (`+infinity` if unreachable)
  FT distance(vertex_descriptor v) const { return FT(m_distance[m_core->checked_vertex(v)]); }
  /// the distance of the `k`-th target of the query, vertex or point (`+infinity` if unreachable or
  /// beyond the query's maximum distance)
  FT target_distance(std::size_t k) const
  {
    const Place& place = checked_place(k);
    const Computation_FT d = place.first ? m_distance[place.second] : m_targets[place.second].distance;
    return FT(d > m_query.max_distance ? internal::Number_type_math<Computation_FT>::infinity() : d);
  }

  /// what the propagation did
  const Propagation_statistics& statistics() const { return m_statistics; }

  /// the number of the nearest source of `v` in the query's order (`std::size_t(-1)` if unreachable)
  std::size_t nearest_source(vertex_descriptor v) const { return m_nearest[m_core->checked_vertex(v)]; }

  /// the number of the nearest source of the `k`-th target of the query, vertex or point, in the
  /// query's order (`std::size_t(-1)` if unreachable or beyond the query's maximum distance)
  std::size_t target_nearest_source(std::size_t k) const
  {
    const Place& place = checked_place(k);
    if(!(target_distance(k) < internal::Number_type_math<FT>::infinity()))
      return std::size_t(-1);
    if(place.first)
      return m_nearest[place.second];
    // a point's origin is a vertex, or the number of vertices plus its source's number
    const Index origin = m_targets[place.second].origin;
    const Index nv = Index(m_nearest.size());
    return origin < nv ? m_nearest[origin] : origin == no_origin() ? std::size_t(-1) : std::size_t(origin - nv);
  }

  /// writes the shortest path from `target` to its nearest source into `out`, as `Path_point`s,
  /// from the target to the source; nothing if it is unreachable
  template <class OutputIterator>
  OutputIterator shortest_path(vertex_descriptor target, OutputIterator out) const
  {
    return to_user(path_from_vertex(m_core->checked_vertex(target)), out);
  }

  /// the same for the `k`-th target of the query, vertex or point
  template <class OutputIterator>
  OutputIterator shortest_path_to_target(std::size_t k, OutputIterator out) const
  {
    const Place& place = checked_place(k);
    if(place.first)
      return to_user(path_from_vertex(place.second), out);
    const Target& a = m_targets[place.second];
    std::vector<Internal_point> path;
    if(a.origin != no_origin() && a.distance < internal::Number_type_math<Computation_FT>::infinity() &&
       a.distance <= m_query.max_distance) // farther points are unreached, as farther vertices
    {
      const Tracer tracer(m_core->mesh());
      const Index h = a.frame;
      const int c = int(h % 3);
      const auto apex = m_core->mesh().apex(h);
      const internal::Vec2<Computation_FT> q{a.barycentric[(c + 1) % 3] * m_core->mesh().length(h) +
                                               a.barycentric[(c + 2) % 3] * apex.x,
                                             a.barycentric[(c + 2) % 3] * apex.y};
      Internal_point start{Internal_point::FACE, h / 3, a.barycentric, Index(-1)};
      int zeros = 0;
      for(const auto& b : a.barycentric)
        zeros += b == Computation_FT(0);
      start.kind = zeros == 0 ? Internal_point::FACE : Internal_point::EDGE;
      path.push_back(start);
      const Leg leg = leg_to(a.origin, a.distance);
      tracer.walk_from_point(h, q, a.direction, leg.length, leg.vertex, leg.end, path);
      if(leg.vertex != Tracer::no_vertex() && !leg.is_source)
        trace_from(leg.vertex, path);
    }
    return to_user(path, out);
  }

  /// the 3D points of a path given as `Path_point`s, in the same order (the mesh given to the solver)
  template <class TriangleMesh, class PathPointRange, class OutputIterator>
  static OutputIterator points(const TriangleMesh& tm, const PathPointRange& path, OutputIterator out)
  {
    for(const Path_point& p : path)
      *out++ = CGAL::Polygon_mesh_processing::construct_point(p.location, tm);
    return out;
  }

private:
  friend Solver;
  using Propagation = typename Core::Propagation;
  using Arrival = typename Propagation::Arrival;
  using Target = typename internal::Point_targets<Computation_FT>::Arrival;
  using Place = typename Core::Place;

  static Index no_origin() { return Propagation::no_origin(); }

  Shortest_path_tree(std::shared_ptr<const Core> core, Propagation& propagation, const typename Core::Query& query,
                     const std::vector<Place>& places)
    : m_core(std::move(core))
    , m_distance(propagation.distances())
    , m_origin(propagation.origins())
    , m_nearest(internal::nearest_sources(m_origin, no_origin()))
    , m_arrival(propagation.arrivals())
    , m_places(places)
    , m_query(query)
    , m_statistics(propagation.statistics())
  {
    propagation.point_targets().combine(m_targets);
  }

  const Place& checked_place(std::size_t k) const
  {
    if(k >= m_places.size())
      throw std::invalid_argument("no such target in the query");
    return m_places[k];
  }

  // the path from vertex `v` back to its nearest source; empty if unreachable
  std::vector<Internal_point> path_from_vertex(Index v) const
  {
    std::vector<Internal_point> path;
    if(m_origin[v] != no_origin() && m_distance[v] < internal::Number_type_math<Computation_FT>::infinity())
    {
      path.push_back(Tracer(m_core->mesh()).vertex_point(v, first_face(v)));
      trace_from(v, path);
    }
    return path;
  }

  Index first_face(Index v) const { return *m_core->mesh().corners_begin(v) / 3; }

  // where a leg ending at `origin` (from a point at distance `from`) ends, and how long it is
  struct Leg
  {
    Computation_FT length;
    Index vertex;        // the vertex it ends at, or no_vertex()
    Internal_point end;  // the source point it ends at, if not a vertex
    bool is_source;      // it ends at a source: the path is complete
  };
  Leg leg_to(Index origin, Computation_FT from) const
  {
    const Index nv = Index(m_distance.size());
    if(origin < nv)
      return Leg{from - m_distance[origin], origin, Internal_point{}, false};
    const std::size_t number = origin - nv;
    for(std::size_t k = 0; k < m_query.vertex_sources.size(); ++k)
      if(m_query.source_numbers[k] == number)
        return Leg{from, m_query.vertex_sources[k], Internal_point{}, true};
    for(std::size_t k = 0; k < m_query.point_sources.size(); ++k)
      if(m_query.source_numbers[m_query.vertex_sources.size() + k] == number)
      {
        const auto& s = m_query.point_sources[k];
        int zeros = 0;
        for(const auto& b : s.barycentric)
          zeros += b == Computation_FT(0);
        return Leg{from, Tracer::no_vertex(),
                   Internal_point{zeros == 0 ? Internal_point::FACE : Internal_point::EDGE, s.face, s.barycentric, Index(-1)},
                   true};
      }
    return Leg{from, Tracer::no_vertex(), Internal_point{}, true};
  }

  // the legs from vertex `v` back to a source
  void trace_from(Index v, std::vector<Internal_point>& path) const
  {
    const Tracer tracer(m_core->mesh());
    for(std::size_t steps = 0; steps <= m_distance.size(); ++steps)
    {
      const Index o = m_origin[v];
      if(o == no_origin() || (o >= m_distance.size() && leg_to(o, m_distance[v]).vertex == v))
        return; // v is the source
      if(m_arrival[v].corner == Core::Mesh::no_halfedge) // from a copy of v, the same point (a step of length 0)
      {
        path.push_back(tracer.vertex_point(o, first_face(o)));
        v = o;
        continue;
      }
      const Leg leg = leg_to(o, m_distance[v]);
      tracer.walk_from_vertex(m_arrival[v].corner, m_arrival[v].direction, leg.length, leg.vertex, leg.end, path);
      if(leg.is_source || leg.vertex == Tracer::no_vertex())
        return;
      v = leg.vertex;
    }
  }

  template <class OutputIterator>
  OutputIterator to_user(const std::vector<Internal_point>& path, OutputIterator out) const
  {
    for(const Internal_point& p : path)
    {
      Path_point q;
      q.simplex = p.kind == Internal_point::VERTEX ? Path_point::VERTEX
                : p.kind == Internal_point::EDGE ? Path_point::EDGE : Path_point::FACE;
      q.location.first = m_core->face(p.face);
      for(int k = 0; k < 3; ++k)
        q.location.second[k] = FT(p.barycentric[k]);
      q.vertex = p.kind == Internal_point::VERTEX ? m_core->vertex(p.vertex) : vertex_descriptor();
      *out++ = q;
    }
    return out;
  }

  std::shared_ptr<const Core> m_core;     // the solver's mesh and numbering
  std::vector<Computation_FT> m_distance; // per vertex
  std::vector<Index> m_origin;            // per vertex: the pseudo-source of its path
  std::vector<std::size_t> m_nearest;     // per vertex: the number of its nearest source, or -1
  std::vector<Arrival> m_arrival;         // per vertex: the corner and direction its path arrives from
  std::vector<Target> m_targets;          // per point target of the query: how its path arrives
  std::vector<Place> m_places;            // per target of the query, in its order: where it is
  internal::Propagation_query<Computation_FT> m_query; // the sources
  Propagation_statistics m_statistics;    // what the propagation did
};

namespace internal {

// The pairs of the solvers' compute_pair_distances(), on their Solver_core `core`; `make_tree` makes
// the Shortest_path_tree of a propagation, its query and the place of its target, for the path.
template <class ConcurrencyTag, class Core, class PairRange, class PairFunction, class NamedParameters, class MakeTree>
void pair_distances(const Core& core, const PairRange& pairs, const PairFunction& pair, const NamedParameters& np,
                    const MakeTree& make_tree)
{
  using Tree = decltype(make_tree(std::declval<typename Core::Propagation&>(), std::declval<const typename Core::Query&>(),
                                  std::declval<const std::vector<typename Core::Place>&>()));
  using Path_point = typename Tree::Path_point;
  using FT = typename Tree::FT;
  constexpr bool with_path =
    std::is_invocable<const PairFunction&, std::size_t, FT, FT, const std::vector<Path_point>&>::value;
  core.template pairs<ConcurrencyTag>(pairs, np, with_path, [&](std::size_t k, auto& propagation, const auto& query,
                                                                 const auto& place, const auto& accuracy) {
    const std::pair<FT, FT> d = core.distance_at(propagation, query, place, accuracy);
    if constexpr(with_path)
    {
      std::vector<Path_point> path;
      make_tree(propagation, query, std::vector<typename Core::Place>(1, place)).shortest_path_to_target(0, std::back_inserter(path));
      std::reverse(path.begin(), path.end()); // from the source
      pair(k, d.first, d.second, path);
    }
    else
      pair(k, d.first, d.second);
  });
}

} // namespace internal

} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_SHORTEST_PATH_TREE_H
