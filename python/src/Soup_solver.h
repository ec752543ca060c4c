// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// The solver behind dggvtp.GeodesicSolver, without Python: a Triangle_soup_geodesic_distance_solver
// built from a soup as dggvtp builds it (dggvtp::make_solver, and with repair on the repairs of
// dggvtp --repair: the same bits), answering queries in the numbering of the caller's vertices and
// faces. The Python layer converts the arguments, allocates the result arrays and releases the GIL
// around these calls; every query is const and may run in several threads at once.

#ifndef DGGVTP_PYTHON_SOUP_SOLVER_H
#define DGGVTP_PYTHON_SOUP_SOLVER_H

#include <dggvtp/load_mesh.h>
#include <dggvtp/query_places.h>
#include <dggvtp/repair.h>
#include <dggvtp/sparse_rows.h>
#include <dggvtp/threads.h>

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Simple_cartesian.h>

#include <boost/range/irange.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace dggvtp {
namespace python {

// What a query asks, in the caller's numbering: vertices of V, faces of F
struct Query
{
  std::vector<Place> sources;      // their order numbers the labels
  std::vector<Place> targets;      // target_distances()
  std::vector<Place> path_targets; // shortest_paths()
  double epsilon = 0.;             // accuracy; 0 = exact
  double max_distance = std::numeric_limits<double>::infinity();
  long threads = 0;                // 0 = all cores; 1 = sequential
  std::function<bool()> interrupted; // asked between rounds and rows: true cancels (Propagation_cancelled)
  // distances(): a field of earlier sources that the sources are added to, per vertex of V (null:
  // none): their distances, the number of each vertex's nearest earlier source (-1: unreached)
  // and the certified errors of the distances (the lower bounds being distance - error)
  const double* prior_distances = nullptr;
  const long long* prior_labels = nullptr;
  const double* prior_bounds = nullptr;
};

using Paths = std::vector<std::pair<Polyline, double>>; // from each target to its source, and its length

// The queries of GeodesicSolver, whatever the precision. Each adds to `moved` the points it took
// at the surface far from where they were given, for a warning.
class Solver_interface
{
public:
  virtual ~Solver_interface() = default;
  virtual std::size_t number_of_vertices() const = 0; // of V
  virtual std::size_t number_of_faces() const = 0;    // of F
  virtual std::size_t number_of_triangles() const = 0; // of the solver (after the input policy's repairs)
  virtual const std::vector<std::string>& repairs() const = 0;
  // V (3D) and F as the caller gave them, to build the same solver again (pickle)
  virtual std::pair<std::vector<std::array<double, 3>>, std::vector<std::array<std::uint32_t, 3>>>
  given_mesh() const = 0;
  // per vertex, into `distances` (and, unless null, `labels` and the certified error `bounds`:
  // distance - a lower bound of the exact distance)
  virtual void distances(const Query& query, double* distances, long long* labels, double* bounds,
                         std::vector<Moved_point>& moved) const = 0;
  // per source vertex of `query` (no points), a row of number_of_vertices() into `rows` (and into
  // `bounds` unless null)
  virtual void distances_from_each(const Query& query, double* rows, double* bounds) const = 0;
  // per source vertex of `query` (every vertex if it has none), the vertices within its maximum
  // distance; each row is handed to `row(k, row)` from any thread
  virtual void local_distance_matrix(const Query& query,
                                     const std::function<void(std::size_t, Sparse_row&&)>& row) const = 0;
  // and, unless null, the number of each target's nearest source (-1: unreachable) into `labels`
  virtual std::vector<double> target_distances(const Query& query, std::vector<Moved_point>& moved,
                                               std::vector<long long>* labels) const = 0;
  virtual Paths shortest_paths(const Query& query, std::vector<Moved_point>& moved) const = 0;
  // per pair k (query.sources[k], query.targets[k]: vertices), one propagation toward the target,
  // the pairs in parallel on query.threads, the same bits for any number: its distance into
  // `values`, and, unless null, a certified lower bound of the exact one into `lower` and the path
  // from the source to the target into `paths`
  virtual void pair_distances(const Query& query, double* values, double* lower, Paths* paths) const = 0;
  // farthest-point sampling of `k` vertices from query.sources[0] (a vertex): the samples, the
  // field of them into `distances` and, unless null, the number of each vertex's nearest sample
  // into `labels` and the certified errors of the field into `bounds`
  virtual std::vector<long long> farthest_point_sampling(const Query& query, std::size_t k, double* distances,
                                                         long long* labels, double* bounds) const = 0;
};

template <class Kernel>
class Soup_solver final : public Solver_interface
{
  using Solver = CGAL::DGG_VTP_3::Triangle_soup_geodesic_distance_solver<Kernel>;
  using FT = typename Solver::FT;
  using Location = typename Solver::Face_location;
  using Face = std::array<std::uint32_t, 3>;

public:
  // `faces`: F, in its corner order (the soup's triangles may have lost some); prepared on
  // `threads` threads (0: all cores), the same bits for any number; throws Input_error for a soup
  // the input policy refuses
  Soup_solver(Loaded_soup&& soup, std::vector<Face>&& faces, const Repair_option& repair, long threads)
    : m_soup(std::move(soup)), m_faces(std::move(faces))
  {
    if(repair.on)
    {
      m_given_points = file_points(); // the repairs may move them
      m_record = repair_soup(m_soup, repair);
    }
    try
    {
      with_threads(threads, [&](auto tag) { make_solver<decltype(tag)>(m_soup, m_solver); });
    }
    catch(const std::invalid_argument& e) // the library's documented preconditions
    {
      throw Input_error(with_repair_hint(e.what(), repair));
    }
    m_same_vertices = m_soup.points.size() == m_soup.file_vertices;
    m_merged = m_record.merged_into();
    index_faces();
  }

  std::size_t number_of_vertices() const override { return m_soup.file_vertices; }
  std::size_t number_of_faces() const override { return m_faces.size(); }
  std::size_t number_of_triangles() const override { return m_soup.triangles.size(); }
  const std::vector<std::string>& repairs() const override { return m_soup.repairs; }
  std::pair<std::vector<std::array<double, 3>>, std::vector<Face>> given_mesh() const override
  {
    return {m_given_points.empty() ? file_points() : m_given_points, m_faces};
  }

  void distances(const Query& query, double* distances, long long* labels, double* bounds,
                 std::vector<Moved_point>& moved) const override
  {
    namespace DP = CGAL::DGG_VTP_3::parameters;
    with_places(query, moved, [&](const auto& q) {
      Field field(*this, distances);
      std::vector<std::size_t> nearest(labels ? m_solver->number_of_vertices() : 0);
      std::vector<FT> lower(bounds ? m_solver->number_of_vertices() : 0);
      const Prior_field prior(*this, query);
      with_threads(query.threads, [&](auto tag) {
        const auto field_query = [&](const auto& np) {
          if(bounds)
            m_solver->template compute_distances_to_nearest_source<decltype(tag)>(
              q.sources, field.map(), DP::lower_bound_map(CGAL::make_property_map(lower), np));
          else
            m_solver->template compute_distances_to_nearest_source<decltype(tag)>(q.sources, field.map(), np);
        };
        const auto with_labels = [&](const auto& np) {
          if(labels)
            field_query(DP::nearest_source_map(CGAL::make_property_map(nearest), np));
          else
            field_query(np);
        };
        if(!prior.given())
        {
          with_labels(one_query_parameters(query));
          return;
        }
        // a whole field: no max_distance (GeodesicSolver.distances refuses it)
        const auto np = DP::prior_distance_map(
          CGAL::make_property_map(prior.distances),
          DP::prior_lower_bound_map(CGAL::make_property_map(prior.lower),
                                    CGAL::parameters::accuracy(query.epsilon).callback(interruption(query))));
        if(!prior.labels.empty())
          with_labels(DP::prior_nearest_source_map(CGAL::make_property_map(prior.labels), np));
        else // labels need the prior ones (GeodesicSolver.distances says so)
          field_query(np);
      });
      field.finish(labels, prior.labels_of(q, nearest, field.data()));
      if(bounds)
        write_bounds(lower, distances, bounds);
    });
  }

  // one sequential propagation per row (the rows shared among the threads), from every copy of
  // the source vertex, as dggvtp-batch computes its rows
  void distances_from_each(const Query& query, double* rows, double* bounds) const override
  {
    const std::size_t n = number_of_vertices();
    with_threads(query.threads, [&](auto tag) {
      CGAL::for_each<decltype(tag)>(boost::irange(std::size_t(0), query.sources.size()), [&](std::size_t k) {
        stop_if_interrupted(query);
        Query one = query;
        one.sources.assign(1, query.sources[k]);
        one.threads = 1;
        std::vector<Moved_point> none; // vertices only
        distances(one, rows + k * n, nullptr, bounds ? bounds + k * n : nullptr, none);
        return true;
      });
    });
  }

  // one sequential propagation per row, the rows shared among the threads, each made sparse as it
  // is done (dggvtp-batch --max-distance's rows); a vertex that a repair removed has an empty row
  void local_distance_matrix(const Query& query,
                             const std::function<void(std::size_t, Sparse_row&&)>& row) const override
  {
    const bool every_vertex = query.sources.empty();
    std::vector<std::size_t> computed, file_vertices; // the rows that are not removed vertices, and their sources
    for(std::size_t k = 0; k < (every_vertex ? number_of_vertices() : query.sources.size()); ++k)
    {
      const std::size_t v = every_vertex ? k : query.sources[k].vertex;
      const auto lost = m_record.lost.find(v);
      if(every_vertex && lost != m_record.lost.end() && lost->second == Repair_record::removed)
        row(k, Sparse_row());
      else
      {
        computed.push_back(k);
        file_vertices.push_back(m_record.file_vertex(v, "source")); // a merged vertex: the one at its place
      }
    }
    const auto done = [&](std::size_t k, const std::vector<FT>& d, const CGAL::DGG_VTP_3::Propagation_statistics&,
                          const auto& reached) {
      stop_if_interrupted(query);
      Sparse_row r;
      sparse_row(m_soup, d, reached, &m_merged, r);
      row(computed[k], std::move(r));
    };
    const auto sets = solver_vertex_sets(m_soup, file_vertices);
    with_threads(query.threads, [&](auto tag) {
      m_solver->template compute_distances_from_each_source_set<decltype(tag)>(sets, done, named_parameters(query));
    });
  }

  // with labels, from the shortest path tree, which knows each target's nearest source
  std::vector<double> target_distances(const Query& query, std::vector<Moved_point>& moved,
                                       std::vector<long long>* labels) const override
  {
    std::vector<double> out;
    with_places(query, moved, [&](const auto& q) {
      namespace DP = CGAL::DGG_VTP_3::parameters;
      std::vector<FT> d(m_solver->number_of_vertices());
      std::vector<FT> at_targets;
      std::vector<std::size_t> nearest(labels ? d.size() : 0), target_nearest;
      with_threads(query.threads, [&](auto tag) {
        const auto np = DP::targets(q.targets, one_query_parameters(query));
        if(!labels)
        {
          m_solver->template compute_distances_to_nearest_source<decltype(tag)>(
            q.sources, CGAL::make_property_map(d), DP::target_distances(std::back_inserter(at_targets), np));
          return;
        }
        const auto tree = m_solver->template compute_shortest_path_tree<decltype(tag)>(q.sources, np);
        for(std::size_t v = 0; v < d.size(); ++v) // beyond max_distance unreached, as in the field
          if(tree.distance(v) <= FT(query.max_distance))
          {
            d[v] = tree.distance(v);
            nearest[v] = tree.nearest_source(v);
          }
          else
          {
            d[v] = std::numeric_limits<FT>::infinity();
            nearest[v] = std::size_t(-1);
          }
        for(std::size_t k = 0; k < q.targets.size(); ++k)
        {
          at_targets.push_back(tree.target_distance(k));
          target_nearest.push_back(tree.target_nearest_source(k));
        }
      });
      const std::vector<long long> label = finish_sources(q, nearest, d.data());
      for(const auto& t : q.target_places)
      {
        const std::size_t v = t.vertices.empty() ? 0 : nearest_copy(t.vertices, d);
        out.push_back(double(t.vertices.empty() ? at_targets[t.point] : d[v]));
        if(labels)
          labels->push_back(!t.vertices.empty() ? label[v]
                            : target_nearest[t.point] == std::size_t(-1)
                              ? -1
                              : static_cast<long long>(q.source_option[target_nearest[t.point]]));
      }
    });
    return out;
  }

  // the paths of one propagation, which stops once they are final
  Paths shortest_paths(const Query& query, std::vector<Moved_point>& moved) const override
  {
    Paths paths;
    with_places(query, moved, [&](const auto& q) {
      using Tree = decltype(m_solver->compute_shortest_path_tree(q.sources));
      std::optional<Tree> tree;
      with_threads(query.threads, [&](auto tag) {
        tree.emplace(m_solver->template compute_shortest_path_tree<decltype(tag)>(
          q.sources, CGAL::DGG_VTP_3::parameters::targets(q.targets, one_query_parameters(query))));
      });
      std::vector<FT> d(m_solver->number_of_vertices());
      for(std::size_t v = 0; v < d.size(); ++v)
        d[v] = tree->distance(v);
      paths = trace_paths(*tree, q, d, m_soup.points, m_soup.triangles);
    });
    return paths;
  }

  void pair_distances(const Query& query, double* values, double* lower, Paths* paths) const override
  {
    const std::size_t n = query.sources.size();
    if(paths)
      paths->assign(n, {});
    if(!m_same_vertices)
    {
      // a vertex split into copies is several solver vertices: each pair runs as target_distances()
      // and shortest_paths() run it, and its lower bound is the contract's
      with_threads(query.threads, [&](auto tag) {
        CGAL::for_each<decltype(tag)>(boost::irange(std::size_t(0), n), [&](std::size_t k) {
          stop_if_interrupted(query);
          Query one = query;
          one.sources.assign(1, query.sources[k]);
          one.targets.assign(1, query.targets[k]);
          one.threads = 1;
          std::vector<Moved_point> none; // vertices only
          values[k] = target_distances(one, none, nullptr).front();
          if(lower)
            lower[k] = contract_lower_bound(values[k], query.epsilon);
          if(paths)
          {
            one.path_targets = one.targets;
            (*paths)[k] = shortest_paths(one, none).front();
            std::reverse((*paths)[k].first.begin(), (*paths)[k].first.end());
          }
          return true;
        });
      });
      return;
    }
    std::vector<std::pair<std::size_t, std::size_t>> pairs(n);
    for(std::size_t k = 0; k < n; ++k)
      pairs[k] = {solver_place(query.sources[k], "source").vertex, solver_place(query.targets[k], "target").vertex};
    const auto np = named_parameters(query);
    const auto write = [&](std::size_t k, FT d, FT low) {
      stop_if_interrupted(query);
      values[k] = double(d);
      if(lower)
        lower[k] = double(low) <= double(d) ? double(low) : std::nextafter(double(d), 0.);
    };
    with_threads(query.threads, [&](auto tag) {
      if(!paths)
        return m_solver->template compute_pair_distances<decltype(tag)>(pairs, write, np);
      m_solver->template compute_pair_distances<decltype(tag)>(
        pairs,
        [&](std::size_t k, FT d, FT low, const auto& path) {
          write(k, d, low);
          (*paths)[k] = polyline_of(path, m_soup.points, m_soup.triangles);
        },
        np);
    });
  }

  std::vector<long long> farthest_point_sampling(const Query& query, std::size_t k, double* distances,
                                                 long long* labels, double* bounds) const override
  {
    namespace DP = CGAL::DGG_VTP_3::parameters;
    const std::size_t first = solver_place(query.sources.at(0), "first sample").vertex;
    Field field(*this, distances);
    std::vector<std::size_t> nearest(m_solver->number_of_vertices()), samples;
    std::vector<FT> lower(bounds ? m_solver->number_of_vertices() : 0);
    with_threads(query.threads, [&](auto tag) {
      const auto np = DP::first_sample(
        first, DP::distance_map(field.map(), DP::nearest_source_map(CGAL::make_property_map(nearest),
                                                                    CGAL::parameters::accuracy(query.epsilon)
                                                                      .callback(interruption(query)))));
      if(bounds)
        m_solver->template farthest_point_sampling<decltype(tag)>(
          k, std::back_inserter(samples), DP::lower_bound_map(CGAL::make_property_map(lower), np));
      else
        m_solver->template farthest_point_sampling<decltype(tag)>(k, std::back_inserter(samples), np);
    });
    field.finish(labels, labels ? sample_labels(nearest) : std::vector<long long>());
    if(bounds)
      write_bounds(lower, distances, bounds);
    std::vector<long long> out;
    for(std::size_t v : samples)
      out.push_back(static_cast<long long>(m_soup.file_vertex_of[v]));
    return out;
  }

private:
  // a certified lower bound of an exact distance that `d` is within the contract of accuracy
  // `epsilon` of: d / (1 + epsilon), less the rounding (as the library's for points)
  static double contract_lower_bound(double d, double epsilon)
  {
    const double lower = d / (1. + epsilon);
    return std::isinf(lower) ? lower : lower - 64. * std::numeric_limits<double>::epsilon() * lower;
  }

  // the file vertex of solver vertex `v`
  std::size_t file_vertex(std::size_t v) const { return m_soup.file_vertex_of.empty() ? v : m_soup.file_vertex_of[v]; }

  // per caller vertex, the certified errors of `distances` (the caller's), given the lower bounds
  // per solver vertex
  void write_bounds(const std::vector<FT>& lower, const double* distances, double* bounds) const
  {
    std::vector<double> lower_file = file_vertex_distances(m_soup, lower);
    m_record.apply(lower_file.data(), nullptr);
    const std::vector<double> errors =
      certified_errors(std::vector<double>(distances, distances + number_of_vertices()), lower_file);
    std::copy(errors.begin(), errors.end(), bounds);
  }

  // A query's prior field (Query::prior_*) per solver vertex, as the library's prior_* named
  // parameters take it; a vertex takes the values of its file vertex (the copies of a split
  // vertex are one point: they have its distance). The labels of the new sources follow the
  // largest prior label.
  struct Prior_field
  {
    std::vector<FT> distances, lower;
    std::vector<std::size_t> labels; // empty without prior labels
    long long first_new_label = 0;   // the caller's label of the first new source
    std::size_t first_new_number = 0; // the library's number of it (past the solver vertices' largest)

    Prior_field(const Soup_solver& s, const Query& query)
    {
      if(!query.prior_distances)
        return;
      const std::size_t n = s.m_solver->number_of_vertices();
      distances.resize(n);
      lower.resize(n);
      for(std::size_t v = 0; v < n; ++v)
      {
        const std::size_t f = s.file_vertex(v);
        const double d = query.prior_distances[f];
        distances[v] = FT(d);
        // the error of an unreached vertex is inf: its lower bound too
        lower[v] = !query.prior_bounds ? distances[v] / (FT(1) + FT(query.epsilon))
                   : std::isinf(d) ? FT(d) : FT(d - query.prior_bounds[f]);
      }
      if(!query.prior_labels)
        return;
      labels.resize(n);
      for(std::size_t v = 0; v < n; ++v)
      {
        const long long l = query.prior_labels[s.file_vertex(v)];
        labels[v] = l < 0 ? std::size_t(-1) : std::size_t(l);
        if(l >= 0 && !std::isinf(double(distances[v]))) // as the library numbers the new sources
          first_new_number = (std::max)(first_new_number, std::size_t(l) + 1);
      }
      for(std::size_t f = 0; f < s.number_of_vertices(); ++f)
        first_new_label = (std::max)(first_new_label, query.prior_labels[f] + 1);
    }
    bool given() const { return !distances.empty(); }

    // the labels per solver vertex, the library's nearest sources (`nearest`) as the caller numbers
    // them: the prior labels, then the new sources' numbers in the query after first_new_label
    template <class Places>
    std::vector<long long> labels_of(const Places& q, std::vector<std::size_t>& nearest, FT* d) const
    {
      if(labels.empty())
        return finish_sources(q, nearest, d);
      std::vector<long long> prior(nearest.size(), -1);
      for(std::size_t v = 0; v < nearest.size(); ++v)
        if(nearest[v] != std::size_t(-1) && nearest[v] < first_new_number)
        {
          prior[v] = static_cast<long long>(nearest[v]);
          nearest[v] = std::size_t(-1);
        }
        else if(nearest[v] != std::size_t(-1))
          nearest[v] -= first_new_number;
      std::vector<long long> label = finish_sources(q, nearest, d);
      for(std::size_t v = 0; v < label.size(); ++v)
        label[v] = prior[v] >= 0 ? prior[v] : label[v] < 0 ? -1 : label[v] + first_new_label;
      return label;
    }
  };

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
        std::copy(label.begin(), label.end(), labels);
      else
      {
        const std::vector<double> d = file_vertex_distances(m_s.m_soup, m_scratch);
        std::copy(d.begin(), d.end(), m_out);
        if(labels)
        {
          const std::vector<long long> l = file_vertex_labels(m_s.m_soup, m_scratch, label);
          std::copy(l.begin(), l.end(), labels);
        }
      }
      m_s.m_record.apply(m_out, labels);
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
  // ... of a query of one propagation, which asks query.interrupted between its rounds
  static auto one_query_parameters(const Query& query) { return named_parameters(query).callback(interruption(query)); }
  static std::function<bool(double)> interruption(const Query& query)
  {
    return [&query](double) { return !(query.interrupted && query.interrupted()); };
  }
  // between the rows of many propagations
  static void stop_if_interrupted(const Query& query)
  {
    if(query.interrupted && query.interrupted())
      throw CGAL::DGG_VTP_3::Propagation_cancelled();
  }

  // Where F's faces are among the solver's triangles: face f is triangle f while the input policy
  // keeps them all in F's order (it may turn or split them); after repairs, triangles are found by
  // their file vertices.
  void index_faces()
  {
    const auto corners = [](const auto& corners_of, std::size_t i) {
      Face c{};
      for(int k = 0; k < 3; ++k)
        c[k] = std::uint32_t(corners_of(i, k));
      std::sort(c.begin(), c.end());
      return c;
    };
    const auto of_triangle = [this](std::size_t t, int k) { return m_soup.file_vertex_of[m_soup.triangles[t][k]]; };
    const auto of_face = [this](std::size_t f, int k) { return m_faces[f][k]; };
    m_faces_are_triangles = m_faces.size() == m_soup.triangles.size();
    for(std::size_t f = 0; m_faces_are_triangles && f < m_faces.size(); ++f)
      m_faces_are_triangles = corners(of_face, f) == corners(of_triangle, f);
    if(m_faces_are_triangles)
      return;
    std::map<Face, std::size_t> triangle_at;
    for(std::size_t t = 0; t < m_soup.triangles.size(); ++t)
      triangle_at.emplace(corners(of_triangle, t), t);
    m_triangle_of_face.assign(m_faces.size(), no_triangle);
    for(std::size_t f = 0; f < m_faces.size(); ++f)
      if(const auto t = triangle_at.find(corners(of_face, f)); t != triangle_at.end())
        m_triangle_of_face[f] = t->second;
  }

  // The place `p` in the solver's numbering: a vertex a repair merged is the vertex at its place;
  // a point on face f of F is on its triangle (its coordinates in the triangle's corner order), or,
  // where the repairs left no triangle with f's corners, the 3D point it makes, located.
  Place solver_place(Place p, const char* what) const
  {
    if(!p.is_point && !p.is_face_point)
      p.vertex = m_record.file_vertex(p.vertex, what);
    if(!p.is_face_point)
      return p;
    const Face& face = m_faces[p.triangle];
    const std::size_t t = m_faces_are_triangles ? p.triangle : m_triangle_of_face[p.triangle];
    if(t == no_triangle)
    {
      p.is_face_point = false;
      p.is_point = true;
      p.point = {0., 0., 0.};
      for(int k = 0; k < 3; ++k)
        for(int c = 0; c < 3; ++c)
          p.point[c] += p.barycentric[k] * m_soup.points[face[k]][c];
      return p;
    }
    std::array<double, 3> b{};
    for(int j = 0; j < 3; ++j)
      for(int k = 0; k < 3; ++k)
        if(m_soup.file_vertex_of[m_soup.triangles[t][j]] == face[k])
          b[j] = p.barycentric[k];
    p.triangle = t;
    p.barycentric = b;
    return p;
  }

  // Runs `f` with the query's places in the solver's numbering: vertices, or Face_locations when a
  // point is given (3D points located on the solver's triangles, as dggvtp locates them).
  template <class F>
  void with_places(const Query& query, std::vector<Moved_point>& moved, F f) const
  {
    std::vector<Place> sources, targets, path_targets;
    for(const auto& [from, to, what] : {std::make_tuple(&query.sources, &sources, "source"),
                                        std::make_tuple(&query.targets, &targets, "target"),
                                        std::make_tuple(&query.path_targets, &path_targets, "target")})
      for(const Place& p : *from)
        to->push_back(solver_place(p, what));
    if(!has_points({&sources, &targets, &path_targets}))
      return run_with(query_places<Solver, std::size_t>(m_soup, nullptr, sources, targets, path_targets), f);
    std::unique_lock<std::mutex> lock(m_locator_mutex); // its first query builds a search tree
    if(!m_locator && needs_locator({&sources, &targets, &path_targets}))
      m_locator = std::make_unique<Point_locator>(m_soup.points, m_soup.triangles);
    auto q = query_places<Solver, Location>(m_soup, m_locator.get(), sources, targets, path_targets);
    lock.unlock();
    moved.insert(moved.end(), q.moved_points.begin(), q.moved_points.end());
    run_with(q, f);
  }

  template <class Places, class F>
  static void run_with(const Places& q, F f)
  {
    if(q.sources.empty()) // as dggvtp says it
      throw Input_error("every source is a vertex that no face uses: no point of the surface can be reached");
    f(q);
  }

  std::vector<std::array<double, 3>> file_points() const
  {
    std::vector<std::array<double, 3>> out(m_soup.file_vertices);
    for(std::size_t i = 0; i < out.size(); ++i)
      out[i] = {m_soup.points[i].x(), m_soup.points[i].y(), m_soup.points[i].z()};
    return out;
  }

  static constexpr std::size_t no_triangle = std::size_t(-1);

  Loaded_soup m_soup;         // kept: the copies' file vertices, the triangles to locate points on
  std::vector<Face> m_faces;  // F, for points on its faces
  bool m_faces_are_triangles = true;          // face f of F is triangle f of the soup
  std::vector<std::size_t> m_triangle_of_face; // or else this (no_triangle: none)
  Repair_record m_record;     // what repair=True did to V's vertices
  std::vector<std::array<double, 3>> m_given_points; // V before repair=True (else the soup's points)
  std::map<std::size_t, std::vector<std::size_t>> m_merged; // m_record's merged vertices, by stand-in
  std::optional<Solver> m_solver;
  bool m_same_vertices = true;
  mutable std::mutex m_locator_mutex;
  mutable std::unique_ptr<Point_locator> m_locator; // made by the first query with a 3D point
};

inline std::unique_ptr<Solver_interface> make_soup_solver(Loaded_soup&& soup, std::vector<std::array<std::uint32_t, 3>>&& faces,
                                                          const std::string& precision, const Repair_option& repair,
                                                          long threads)
{
  if(precision == "float")
    return std::make_unique<Soup_solver<CGAL::Simple_cartesian<float>>>(std::move(soup), std::move(faces), repair,
                                                                        threads);
  return std::make_unique<Soup_solver<CGAL::Exact_predicates_inexact_constructions_kernel>>(std::move(soup),
                                                                                            std::move(faces), repair,
                                                                                            threads);
}

} // namespace python
} // namespace dggvtp

#endif // DGGVTP_PYTHON_SOUP_SOLVER_H
