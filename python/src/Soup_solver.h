// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// The solver behind dggvtp.GeodesicSolver, without Python: a Triangle_soup_geodesic_distance_solver
// built from a soup as dggvtp builds it (dggvtp::make_solver: the same repairs, the same bits),
// answering queries in the numbering of the caller's vertices. The Python layer converts the
// arguments, allocates the result arrays and releases the GIL around these calls; every query is
// const and may run in several threads at once.

#ifndef DGGVTP_PYTHON_SOUP_SOLVER_H
#define DGGVTP_PYTHON_SOUP_SOLVER_H

#include <dggvtp/load_mesh.h>
#include <dggvtp/query_places.h>

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Simple_cartesian.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace dggvtp {
namespace python {

// What a query asks, in the caller's (the file's) vertex numbering
struct Query
{
  std::vector<Place> sources;      // their order numbers the labels
  std::vector<Place> targets;      // target_distances()
  std::vector<Place> path_targets; // shortest_path(): one
  double epsilon = 0.;             // accuracy; 0 = exact
  double max_distance = std::numeric_limits<double>::infinity();
  long threads = 1;                // 0 = all cores; 1 = sequential

  bool has_points() const { return dggvtp::has_points({&sources, &targets, &path_targets}); }
};

// The queries of GeodesicSolver, whatever the precision
class Solver_interface
{
public:
  virtual ~Solver_interface() = default;
  virtual std::size_t number_of_vertices() const = 0; // of the caller's mesh
  virtual std::size_t number_of_faces() const = 0;    // triangles of the solver (after repairs)
  virtual const std::vector<std::string>& repairs() const = 0;
  // per vertex, into `distances` (and `labels` unless null)
  virtual void distances(const Query& query, double* distances, long long* labels) const = 0;
  // per source vertex of `query` (no points), a row of number_of_vertices() into `rows`
  virtual void distances_from_each(const Query& query, double* rows) const = 0;
  virtual std::vector<double> target_distances(const Query& query) const = 0;
  virtual Polyline shortest_path(const Query& query) const = 0;
};

// Runs `f` with the concurrency tag and the TBB thread limit of `threads` (1: sequential). TBB's
// limit is process-wide: concurrent calls share the smallest one.
template <class F>
void with_threads(long threads, F f)
{
  if(threads == 1)
  {
    f(CGAL::Sequential_tag());
    return;
  }
#ifdef CGAL_LINKED_WITH_TBB
  std::optional<tbb::global_control> limit;
  if(threads > 0)
    limit.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
#endif
  f(CGAL::Parallel_if_available_tag());
}

template <class Kernel>
class Soup_solver final : public Solver_interface
{
  using Solver = CGAL::DGG_VTP_3::Triangle_soup_geodesic_distance_solver<Kernel>;
  using FT = typename Solver::FT;
  using Location = typename Solver::Face_location;

public:
  // throws Input_error or std::invalid_argument for a soup the input policy refuses
  explicit Soup_solver(Loaded_soup&& soup) : m_soup(std::move(soup))
  {
    make_solver(m_soup, m_solver);
    // no repair appended a copy of a vertex: the solver's vertices are the caller's
    m_same_vertices = m_soup.points.size() == m_soup.file_vertices;
  }

  std::size_t number_of_vertices() const override { return m_soup.file_vertices; }
  std::size_t number_of_faces() const override { return m_soup.triangles.size(); }
  const std::vector<std::string>& repairs() const override { return m_soup.repairs; }

  void distances(const Query& query, double* distances, long long* labels) const override
  {
    with_places(query, [&](const auto& q) {
      Field field(*this, distances);
      std::vector<std::size_t> nearest(labels ? m_solver->number_of_vertices() : 0);
      with_threads(query.threads, [&](auto tag) {
        using Tag = decltype(tag);
        const auto np = named_parameters(query);
        if(labels)
          m_solver->template compute_distances_to_nearest_source<Tag>(
            q.sources, field.map(), CGAL::DGG_VTP_3::parameters::nearest_source_map(CGAL::make_property_map(nearest), np));
        else
          m_solver->template compute_distances_to_nearest_source<Tag>(q.sources, field.map(), np);
      });
      const std::vector<long long> label = finish_sources(q, nearest, field.data());
      field.finish(labels, label);
    });
  }

  // one sequential propagation per row (the rows shared among the threads), from every copy of
  // the source vertex, as dggvtp-batch computes its rows
  void distances_from_each(const Query& query, double* rows) const override
  {
    const std::size_t n = number_of_vertices();
    with_threads(query.threads, [&](auto tag) {
      CGAL::for_each<decltype(tag)>(std::vector<std::size_t>(boost::counting_iterator<std::size_t>(0),
                                                             boost::counting_iterator<std::size_t>(query.sources.size())),
                                    [&](std::size_t k) {
        Query one = query;
        one.sources.assign(1, query.sources[k]);
        one.threads = 1;
        distances(one, rows + k * n, nullptr);
        return true;
      });
    });
  }

  std::vector<double> target_distances(const Query& query) const override
  {
    std::vector<double> out;
    with_places(query, [&](const auto& q) {
      std::vector<FT> d(m_solver->number_of_vertices());
      std::vector<FT> at_targets;
      with_threads(query.threads, [&](auto tag) {
        namespace DP = CGAL::DGG_VTP_3::parameters;
        m_solver->template compute_distances_to_nearest_source<decltype(tag)>(
          q.sources, CGAL::make_property_map(d),
          DP::target_distances(std::back_inserter(at_targets), DP::targets(q.targets, named_parameters(query))));
      });
      finish_sources(q, std::vector<std::size_t>(), d.data());
      for(const auto& t : q.target_places)
        out.push_back(double(t.vertices.empty() ? at_targets[t.point] : d[nearest_copy(t.vertices, d)]));
    });
    return out;
  }

  Polyline shortest_path(const Query& query) const override
  {
    Polyline line;
    with_places(query, [&](const auto& q) {
      using Tree = decltype(m_solver->compute_shortest_path_tree(q.sources));
      std::optional<Tree> tree;
      with_threads(query.threads, [&](auto tag) {
        tree.emplace(m_solver->template compute_shortest_path_tree<decltype(tag)>(
          q.sources, CGAL::DGG_VTP_3::parameters::targets(q.targets, named_parameters(query))));
      });
      std::vector<typename Tree::Path_point> path;
      const auto& t = q.path_places.front();
      if(t.vertices.empty())
        tree->shortest_path_to_target(t.point, std::back_inserter(path));
      else
      {
        std::vector<FT> d(m_solver->number_of_vertices());
        for(std::size_t v = 0; v < d.size(); ++v)
          d[v] = tree->distance(v);
        tree->shortest_path(nearest_copy(t.vertices, d), std::back_inserter(path));
      }
      line = polyline_of(path, m_soup.points, m_soup.triangles).first;
    });
    return line;
  }

private:
  // The distances of one propagation per solver vertex, then per caller vertex: in double on a
  // soup without copies, the library writes straight into the caller's array.
  class Field
  {
  public:
    Field(const Soup_solver& s, double* out) : m_s(s), m_out(out)
    {
      if(!direct())
        m_scratch.resize(s.m_solver->number_of_vertices());
    }
    bool direct() const { return std::is_same<FT, double>::value && m_s.m_same_vertices; }
    FT* data()
    {
      if constexpr(std::is_same<FT, double>::value)
        if(direct())
          return m_out;
      return m_scratch.data();
    }
    auto map() { return CGAL::make_property_map(data()); }
    // the caller's distances (and labels, from those per solver vertex)
    void finish(long long* labels, const std::vector<long long>& label)
    {
      if(direct())
      {
        std::copy(label.begin(), label.end(), labels);
        return;
      }
      const std::vector<double> d = file_vertex_distances(m_s.m_soup, m_scratch);
      std::copy(d.begin(), d.end(), m_out);
      if(labels)
      {
        const std::vector<long long> l = file_vertex_labels(m_s.m_soup, m_scratch, label);
        std::copy(l.begin(), l.end(), labels);
      }
    }

  private:
    const Soup_solver& m_s;
    double* m_out;
    std::vector<FT> m_scratch; // per solver vertex, unless direct()
  };

  static auto named_parameters(const Query& query)
  {
    return CGAL::DGG_VTP_3::parameters::max_distance(query.max_distance).accuracy(query.epsilon);
  }

  // Runs `f` with the query's places in the solver's numbering: vertices, or Face_locations when a
  // point is given (located on the solver's triangles, as dggvtp locates them).
  template <class F>
  void with_places(const Query& query, F f) const
  {
    if(!query.has_points())
      return run_with(query_places<Solver, std::size_t>(m_soup, nullptr, query.sources, query.targets,
                                                        query.path_targets), f);
    std::unique_lock<std::mutex> lock(m_locator_mutex); // its first query builds a search tree
    if(!m_locator)
      m_locator = std::make_unique<Point_locator>(m_soup.points, m_soup.triangles);
    auto q = query_places<Solver, Location>(m_soup, m_locator.get(), query.sources, query.targets, query.path_targets);
    lock.unlock();
    run_with(q, f);
  }

  template <class Places, class F>
  static void run_with(const Places& q, F f)
  {
    if(q.sources.empty()) // as dggvtp says it
      throw Input_error("every source is a vertex that no face uses: no point of the surface can be reached");
    f(q);
  }

  Loaded_soup m_soup; // kept: the copies' file vertices, and the triangles to locate points on
  std::optional<Solver> m_solver;
  bool m_same_vertices = true;
  mutable std::mutex m_locator_mutex;
  mutable std::unique_ptr<Point_locator> m_locator; // made by the first query with a point
};

inline std::unique_ptr<Solver_interface> make_soup_solver(Loaded_soup&& soup, const std::string& precision)
{
  if(precision == "float")
    return std::make_unique<Soup_solver<CGAL::Simple_cartesian<float>>>(std::move(soup));
  return std::make_unique<Soup_solver<CGAL::Exact_predicates_inexact_constructions_kernel>>(std::move(soup));
}

} // namespace python
} // namespace dggvtp

#endif // DGGVTP_PYTHON_SOUP_SOLVER_H
