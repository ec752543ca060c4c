// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// Sources, targets and path targets given as vertices of a mesh file, as 3D points or as points
// on its triangles, in the numbering of a soup solver made by make_solver(), and the results back
// per file vertex (fields, paths, the warnings about what is unreachable): shared by dggvtp,
// dggvtp-batch and the Python module.

#ifndef DGGVTP_QUERY_PLACES_H
#define DGGVTP_QUERY_PLACES_H

#include <dggvtp/load_mesh.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace dggvtp {

using Point_3 = Loaded_soup::Point;
using Triangle = std::array<std::uint32_t, 3>;
using Polyline = std::vector<std::array<double, 3>>;

// A vertex of the file, a 3D point (as dggvtp's --source, --target and --path-to give them) or a
// point on a triangle of the soup (as the Python module's face_points give them)
struct Place
{
  bool is_point = false;               // a 3D point: `point`
  bool is_face_point = false;          // a point on a triangle: `triangle`, `barycentric`
  std::size_t vertex = 0;              // 0-based, in the file's order
  std::array<double, 3> point{};       // located at the nearest point of the surface
  std::size_t triangle = 0;            // in soup.triangles, with
  std::array<double, 3> barycentric{}; // the coordinates of its corners, in the triangle's order
};

// whether a query's places (sources, targets, path targets) include points, of either kind: the
// places are then the solver's Face_locations
inline bool has_points(std::initializer_list<const std::vector<Place>*> places)
{
  for(const std::vector<Place>* range : places)
    for(const Place& p : *range)
      if(p.is_point || p.is_face_point)
        return true;
  return false;
}

// whether they include 3D points, which a Point_locator locates
inline bool needs_locator(std::initializer_list<const std::vector<Place>*> places)
{
  for(const std::vector<Place>* range : places)
    for(const Place& p : *range)
      if(p.is_point)
        return true;
  return false;
}

// The nearest surface points to 3D points, by CGAL::Polygon_mesh_processing::locate_with_AABB_tree()
// on a Surface_mesh of the solver's triangles (its face f is triangle f, its vertex i point i),
// built only when a point is given: a run without points keeps its time and memory.
class Point_locator
{
  using Mesh = CGAL::Surface_mesh<Point_3>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<CGAL::Exact_predicates_inexact_constructions_kernel,
                                                 CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;

public:
  Point_locator(const std::vector<Point_3>& points, const std::vector<Triangle>& triangles)
    : m_points(points), m_triangles(triangles)
  {
    if(triangles.empty())
      throw Input_error("the mesh has no face to place a point on");
    if(internal::faces_to_mesh(points, triangles, m_mesh) != 0)
      throw std::logic_error("the solver's triangles do not make a Surface_mesh");
    CGAL::Polygon_mesh_processing::build_AABB_tree(m_mesh, m_tree);
  }

  // the triangle and the barycentric coordinates of its corners, in the triangle's order (the
  // order of the soup solver's Face_location)
  std::pair<std::size_t, std::array<double, 3>> locate(const std::array<double, 3>& p) const
  {
    const Point_3 query(p[0], p[1], p[2]);
    const auto location = CGAL::Polygon_mesh_processing::locate_with_AABB_tree(query, m_tree, m_mesh);
    const std::size_t f = std::size_t(location.first);
    const auto h = halfedge(location.first, m_mesh);
    const Mesh::Vertex_index corners[3] = {source(h, m_mesh), target(h, m_mesh), target(next(h, m_mesh), m_mesh)};
    std::array<double, 3> barycentric{};
    for(int k = 0; k < 3; ++k)
      for(int j = 0; j < 3; ++j)
        if(m_triangles[f][j] == std::size_t(corners[k]))
          barycentric[j] = location.second[k];
    // a point at a corner is that vertex: the closest point to it, a construction, may be a
    // rounding error away (then it would be a source or target inside the face, next to the vertex)
    for(int j = 0; j < 3; ++j)
      if(m_points[m_triangles[f][j]] == query)
        barycentric = {double(j == 0), double(j == 1), double(j == 2)};
    return {f, barycentric};
  }

  // how far the point at `location` (as locate() gives it) is from `p`
  double distance(const std::array<double, 3>& p, const std::pair<std::size_t, std::array<double, 3>>& location) const
  {
    double squared = 0.;
    for(int c = 0; c < 3; ++c)
    {
      double x = 0.;
      for(int j = 0; j < 3; ++j)
        x += location.second[j] * m_points[m_triangles[location.first][j]][c];
      squared += CGAL::square(x - p[c]);
    }
    return std::sqrt(squared);
  }

  // the length of the diagonal of the mesh's bounding box
  double diagonal() const
  {
    const CGAL::Bbox_3 box = m_tree.bbox();
    return std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                     CGAL::square(box.zmax() - box.zmin()));
  }

private:
  const std::vector<Point_3>& m_points;
  const std::vector<Triangle>& m_triangles;
  Mesh m_mesh;
  Tree m_tree;
};

// The ranges of places of a query: dggvtp's --source, --target and --path-to options
enum class Place_range { source, target, path_target };

// A point taken at the nearest point of the surface farther than 1e-6 times the diagonal of the
// mesh's bounding box from where it was given (users are told: a point off the surface may be a
// mistake)
struct Moved_point
{
  Place_range range;
  std::size_t place; // its number in its range
  std::array<double, 3> point;
  double distance;   // how far it was moved
};

// The places of a query (sources, targets, path targets) in the solver's numbering, as ranges of
// Element: solver vertices, or the solver's Face_locations when a point is given (a range holds one type; a vertex is then the
// corner of one of its triangles, the same source or target bit for bit). A vertex of the file is
// a source or target on each of its copies.
template <class Solver, class Element>
struct Query_places
{
  static constexpr std::size_t no_point = std::size_t(-1);
  // where the target of a --target or --path-to option is: copies of a file vertex, or a point
  struct Target
  {
    std::vector<std::size_t> vertices;
    std::size_t point = no_point; // its number among the query's targets
  };

  std::vector<Element> sources;
  std::vector<std::size_t> source_option; // per source: the number of its option
  // the source vertices that no triangle uses (no location names them), with their option's number
  std::vector<std::pair<std::size_t, std::size_t>> isolated_sources;
  std::vector<Element> targets;           // the query's: those of --target, then of --path-to
  std::vector<Target> target_places, path_places; // per option
  std::vector<Moved_point> moved_points;
};

// Locates the points with `locator` (needed when Element is a Face_location and a 3D point is
// given), on the soup's triangles, so before they are released.
template <class Solver, class Element>
Query_places<Solver, Element> query_places(const Loaded_soup& soup, const Point_locator* locator,
                                            const std::vector<Place>& sources, const std::vector<Place>& targets,
                                            const std::vector<Place>& path_targets)
{
  using FT = typename Solver::FT;
  using Places = Query_places<Solver, Element>;
  constexpr bool by_location = !std::is_same<Element, std::size_t>::value;
  Places q;
  const std::size_t no_corner = std::size_t(-1);
  std::vector<std::size_t> corner; // per solver vertex, in locations: a corner (3 f + k) at it
  if constexpr(by_location)
  {
    corner.assign(soup.file_vertex_of.size(), no_corner);
    for(std::size_t f = 0; f < soup.triangles.size(); ++f)
      for(std::size_t k = 0; k < 3; ++k)
        corner[soup.triangles[f][k]] = 3 * f + k;
  }
  // false for a vertex that no location names
  const auto add_vertex = [&](std::size_t v, std::vector<Element>& range) {
    if constexpr(by_location)
    {
      if(corner[v] == no_corner)
        return false;
      Element e(corner[v] / 3, {FT(0), FT(0), FT(0)});
      e.second[corner[v] % 3] = FT(1);
      range.push_back(e);
    }
    else
      range.push_back(v);
    return true;
  };
  const auto add_point = [&](const Place& p, Place_range kind, std::size_t place, std::vector<Element>& range) {
    if constexpr(by_location)
    {
      if(p.is_face_point)
      {
        const auto& b = p.barycentric;
        range.emplace_back(p.triangle, std::array<FT, 3>{FT(b[0]), FT(b[1]), FT(b[2])});
        return;
      }
      const auto l = locator->locate(p.point);
      range.emplace_back(l.first, std::array<FT, 3>{FT(l.second[0]), FT(l.second[1]), FT(l.second[2])});
      const double moved = locator->distance(p.point, l);
      if(moved > 1e-6 * locator->diagonal())
        q.moved_points.push_back(Moved_point{kind, place, p.point, moved});
    }
  };

  for(std::size_t option = 0; option < sources.size(); ++option)
  {
    const Place& p = sources[option];
    if(p.is_point || p.is_face_point)
    {
      add_point(p, Place_range::source, option, q.sources);
      q.source_option.push_back(option);
    }
    else
      for(std::size_t v : solver_vertices_of(soup, p.vertex))
      {
        if(add_vertex(v, q.sources))
          q.source_option.push_back(option);
        else
          q.isolated_sources.emplace_back(v, option);
      }
  }
  for(const auto& [places, out] : {std::make_pair(&targets, &q.target_places),
                                   std::make_pair(&path_targets, &q.path_places)})
    for(std::size_t k = 0; k < places->size(); ++k)
    {
      const Place& p = (*places)[k];
      typename Places::Target t;
      if(p.is_point || p.is_face_point)
      {
        t.point = q.targets.size();
        add_point(p, places == &targets ? Place_range::target : Place_range::path_target, k, q.targets);
      }
      else
      {
        // an unused vertex needs no waiting for: it is unreached, or a source
        t.vertices = solver_vertices_of(soup, p.vertex);
        for(std::size_t v : t.vertices)
          add_vertex(v, q.targets);
      }
      out->push_back(t);
    }
  return q;
}

// Completes a propagation's result from the sources `q`, per solver vertex: `d` gets 0 at the
// source vertices no triangle uses (no propagation starts there), and the labels (returned; empty
// when `nearest` is) are the number of each vertex's nearest source place, from `nearest` (the
// library's nearest_source_map, a number in q.sources), or -1 where unreached.
template <class Places, class FT>
std::vector<long long> finish_sources(const Places& q, const std::vector<std::size_t>& nearest, FT* d)
{
  std::vector<long long> label(nearest.size(), -1);
  for(std::size_t v = 0; v < nearest.size(); ++v)
    if(nearest[v] != std::size_t(-1))
      label[v] = static_cast<long long>(q.source_option[nearest[v]]);
  for(const auto& [v, option] : q.isolated_sources)
  {
    d[v] = FT(0);
    if(!label.empty())
      label[v] = static_cast<long long>(option);
  }
  return label;
}

// The labels of a farthest-point sampling: per solver vertex, the number of its nearest sample
// (the library's nearest_source_map), or -1 where unreached.
inline std::vector<long long> sample_labels(const std::vector<std::size_t>& nearest)
{
  std::vector<long long> label(nearest.size());
  std::transform(nearest.begin(), nearest.end(), label.begin(),
                 [](std::size_t k) { return k == std::size_t(-1) ? -1LL : static_cast<long long>(k); });
  return label;
}

// Per file vertex, the label (given per solver vertex) of its copy nearest to the sources, the
// copy whose distance file_vertex_distances() reports; -1 where unreached.
template <class FT>
std::vector<long long> file_vertex_labels(const Loaded_soup& soup, const std::vector<FT>& d,
                                          const std::vector<long long>& label)
{
  std::vector<long long> out(soup.file_vertices, -1);
  std::vector<FT> best(soup.file_vertices, std::numeric_limits<FT>::infinity());
  for(std::size_t v = 0; v < d.size(); ++v)
  {
    const std::size_t f = soup.file_vertex_of[v];
    if(d[v] < best[f])
    {
      best[f] = d[v];
      out[f] = label[v];
    }
  }
  return out;
}

// the copy of a target's file vertex nearest to the sources
template <class FT>
std::size_t nearest_copy(const std::vector<std::size_t>& copies, const std::vector<FT>& d)
{
  std::size_t best = copies.front();
  for(std::size_t v : copies)
    if(d[v] < d[best])
      best = v;
  return best;
}

// A shortest path of a Shortest_path_tree (Path_points: barycentric coordinates in the soup's
// triangles) as 3D points, and its length (+infinity for no path: unreached)
template <class Path_point>
std::pair<Polyline, double> polyline_of(const std::vector<Path_point>& path, const std::vector<Point_3>& points,
                                        const std::vector<Triangle>& triangles)
{
  Polyline line;
  double length = path.empty() ? std::numeric_limits<double>::infinity() : 0.;
  for(const Path_point& p : path)
  {
    std::array<double, 3> x{0., 0., 0.};
    for(int k = 0; k < 3; ++k)
      for(int c = 0; c < 3; ++c)
        x[c] += double(p.location.second[k]) * points[triangles[p.location.first][k]][c];
    if(!line.empty())
      length += std::sqrt(CGAL::square(x[0] - line.back()[0]) + CGAL::square(x[1] - line.back()[1]) +
                          CGAL::square(x[2] - line.back()[2]));
    line.push_back(x);
  }
  return {std::move(line), length};
}

// The shortest paths of the path targets of `q` in `tree` (`d`: its distances per solver vertex),
// each as a polyline over the soup's points and triangles, from the target to its nearest source,
// with its length (+infinity for no path: unreached)
template <class Tree, class Places, class FT>
std::vector<std::pair<Polyline, double>> trace_paths(const Tree& tree, const Places& q, const std::vector<FT>& d,
                                                     const std::vector<Point_3>& points,
                                                     const std::vector<Triangle>& triangles)
{
  std::vector<std::pair<Polyline, double>> out;
  for(const auto& t : q.path_places)
  {
    std::vector<typename Tree::Path_point> path;
    if(t.vertices.empty())
      tree.shortest_path_to_target(t.point, std::back_inserter(path));
    else
      tree.shortest_path(nearest_copy(t.vertices, d), std::back_inserter(path));
    out.push_back(polyline_of(path, points, triangles));
  }
  return out;
}

// how many of the values in [first, last) are +infinity
template <class Iterator>
std::size_t count_infinite(Iterator first, Iterator last)
{
  std::size_t n = 0;
  for(; first != last; ++first)
    n += std::isinf(*first) ? 1 : 0;
  return n;
}

template <class Range>
std::size_t count_infinite(const Range& values)
{
  return count_infinite(std::begin(values), std::end(values));
}

// The rows (fields of one source each) that leave vertices unreachable (inf), counted as they are
// computed, from any thread, for one warning (unreachable_rows_warning())
struct Unreachable_rows
{
  std::atomic<std::size_t> rows{0}; // rows with an inf
  std::atomic<std::size_t> most{0}; // the most infs in one row

  template <class Iterator>
  void add(Iterator first, Iterator last)
  {
    const std::size_t n = count_infinite(first, last);
    if(n == 0)
      return;
    ++rows;
    for(std::size_t m = most.load(); m < n && !most.compare_exchange_weak(m, n);)
    {
    }
  }
};

// The warning for `unreachable` of `total` `what` ("vertices", "targets and paths") that no path on
// the surface reaches from the sources; empty when there is none. Beyond a maximum distance they
// are unreached by request: no warning then (the callers' business).
inline std::string unreachable_warning(std::size_t unreachable, std::size_t total, const std::string& what)
{
  if(unreachable == 0)
    return std::string();
  return std::to_string(unreachable) + " of " + std::to_string(total) + " " + what +
         " are unreachable from the sources (inf): in other connected components than the sources', or used by no face";
}

// The same for `rows` of `computed` fields of one source each (dggvtp-batch's rows), `most` being
// the most unreachable vertices of one row, of `vertices`
inline std::string unreachable_rows_warning(std::size_t rows, std::size_t computed, std::size_t most,
                                            std::size_t vertices)
{
  if(rows == 0)
    return std::string();
  return std::to_string(rows) + " of the " + std::to_string(computed) +
         " rows computed leave vertices unreachable (inf), up to " + std::to_string(most) + " of " +
         std::to_string(vertices) + " in a row: in other connected components than the row's source, or used by no face";
}

} // namespace dggvtp

#endif // DGGVTP_QUERY_PLACES_H
