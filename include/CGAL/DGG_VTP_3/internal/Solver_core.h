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

#ifndef CGAL_DGG_VTP_3_INTERNAL_SOLVER_CORE_H
#define CGAL_DGG_VTP_3_INTERNAL_SOLVER_CORE_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/Propagation_statistics.h>
#include <CGAL/DGG_VTP_3/parameters.h>
#include <CGAL/DGG_VTP_3/internal/Effective_concurrency_tag.h>
#include <CGAL/DGG_VTP_3/internal/Element_numbering.h>
#include <CGAL/DGG_VTP_3/internal/Farthest_point_sampling.h>
#include <CGAL/DGG_VTP_3/internal/Patch_partition.h>
#include <CGAL/DGG_VTP_3/internal/Propagation_pool.h>
#include <CGAL/DGG_VTP_3/internal/Propagation_query.h>
#include <CGAL/DGG_VTP_3/internal/Query_builder.h>
#include <CGAL/DGG_VTP_3/internal/Unfolded_mesh.h>
#include <CGAL/DGG_VTP_3/internal/Window_propagation.h>
#include <CGAL/DGG_VTP_3/internal/as_given.h>
#include <CGAL/DGG_VTP_3/internal/for_each_block.h>
#include <CGAL/DGG_VTP_3/internal/nearest_sources.h>
#include <CGAL/DGG_VTP_3/internal/number_type_math.h>
#include <CGAL/DGG_VTP_3/internal/read_prior_field.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/for_each.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <boost/range/irange.hpp>

#include <array>
#include <functional>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <memory>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// What Geodesic_distance_solver and Triangle_soup_geodesic_distance_solver share, all of it: the
// prepared mesh and every query, from the user's sources and named parameters to the user's
// outputs. The solvers differ only by how their user names vertices and faces (`Numbering`, see
// Element_numbering.h); `FT` is the number type of the results.
template <class Numbering, class FT>
class Solver_core
{
public:
  // float input and output, the propagation in double: in float, windows that tie within
  // rounding get trimmed in the wrong order
  using Computation_FT = typename std::conditional<std::is_same<FT, float>::value, double, FT>::type;
  using Mesh = Unfolded_mesh<Computation_FT>;
  using Index = typename Mesh::Index;
  using Query = Propagation_query<Computation_FT>;
  using Propagation = Window_propagation<Computation_FT>;
  using vertex_descriptor = typename Numbering::vertex_descriptor;
  using face_descriptor = typename Numbering::face_descriptor;
  // where a target of a query is: a vertex (true) or the number of a point target
  using Place = std::pair<bool, Index>;

  // The tag the preparation runs with: the named parameter concurrency_tag (Sequential_tag if not
  // given), Sequential_tag for an exact number type. A named parameter, not a template parameter
  // as for the queries: a constructor takes no explicit template arguments, and so the tag goes
  // with the preparation's other options (as CGAL 6's autorefine_triangle_soup() takes it).
  template <class NamedParameters>
  using Preparation_tag = typename Effective_concurrency_tag<
    typename internal_np::Lookup_named_param_def<internal_np::concurrency_tag_t, NamedParameters, Sequential_tag>::type,
    Computation_FT>::type;

  // `order`: how `mesh` renumbered the elements of `numbering` (see unfold_triangles())
  template <class ConcurrencyTag>
  Solver_core(ConcurrencyTag tag, Numbering numbering, Mesh&& mesh, Unfolding_order&& order)
    : m_numbering(std::move(numbering), std::move(order), tag), m_mesh(std::move(mesh)), m_partition(m_mesh, tag)
  {}

  // one per solver and its copies (they share it): its propagations refer to its mesh
  Solver_core(const Solver_core&) = delete;
  Solver_core& operator=(const Solver_core&) = delete;

  // the propagations kept for the next queries freed (see Propagation_pool)
  void release_query_memory() const { m_pool.clear(); }

  std::size_t number_of_vertices() const { return m_numbering.number_of_vertices(); }
  std::size_t number_of_non_manifold_vertices() const { return m_mesh.number_of_non_manifold_vertices(); }
  const Mesh& mesh() const { return m_mesh; }
  vertex_descriptor vertex(Index v) const { return m_numbering.vertex(v); }
  face_descriptor face(Index f) const { return m_numbering.face(f); }
  Index checked_vertex(vertex_descriptor v, const char* what = "vertex") const { return builder().vertex_index(v, what); }

  // ---------------------------------------------------------------------------------------------
  // Queries
  // ---------------------------------------------------------------------------------------------

  template <class ConcurrencyTag, class SourceRange, class VertexDistanceMap, class NamedParameters>
  Propagation_statistics distances_to_nearest_source(const SourceRange& sources, VertexDistanceMap distances,
                                                     const NamedParameters& np) const
  {
    Set_up s = set_up(sources, np);
    Prior_field<Computation_FT> prior;
    if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::prior_distance_map_t>::value)
    {
      static_assert(parameters::is_default_parameter<NamedParameters, internal_np::nearest_source_map_t>::value ||
                    !parameters::is_default_parameter<NamedParameters, internal_np::prior_nearest_source_map_t>::value,
                    "the named parameter nearest_source_map needs prior_nearest_source_map with a prior field");
      static_assert(takes_whole_fields<NamedParameters>(),
                    "a prior field is a whole field: the named parameters targets and max_distance are not taken with it");
      const Index first_number = read_prior_field(m_numbering, s.accuracy, np, prior);
      for(Index& k : s.query.source_numbers)
        k += first_number;
      s.query.prior = &prior;
      s.query.add_to_field = s.query.record_origins = true;
    }
    const auto lease = scratch();
    Propagation& propagation = lease->propagation;
    propagation.template run<Effective_tag<ConcurrencyTag>>(s.query, s.accuracy);
    write_distances(propagation, distances);
    const std::vector<Computation_FT>& d = propagation.distances();
    if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::target_distances_t>::value)
    {
      auto out = parameters::get_parameter(np, internal_np::target_distances_t());
      const std::vector<Computation_FT> at_points = propagation.point_targets().distances();
      for(const Place& t : s.targets)
      {
        const Computation_FT dt = t.first ? d[t.second] : at_points[t.second];
        *out++ = FT(dt > s.query.max_distance ? Number_type_math<Computation_FT>::infinity() : dt);
      }
    }
    write_bounds_and_labels(propagation, np);
    return propagation.statistics();
  }

  // farthest-point sampling (see internal/Farthest_point_sampling.h): the samples, in order
  template <class ConcurrencyTag, class NamedParameters>
  std::vector<vertex_descriptor> farthest_point_sampling(std::size_t k, const NamedParameters& np) const
  {
    static_assert(takes_whole_fields<NamedParameters>(),
                  "each sample is the farthest vertex of a whole field: the named parameters targets and "
                  "max_distance are not taken");
    const Computation_FT accuracy = checked_accuracy(np);
    const std::size_t nv = number_of_vertices();
    if(k == 0 || k > nv)
      throw std::invalid_argument("the number of samples must be in [1, " + std::to_string(nv) +
                                  "] (the number of vertices); got " + std::to_string(k));
    Index first = 0;
    if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::first_sample_t>::value)
      first = checked_vertex(parameters::get_parameter(np, internal_np::first_sample_t()), "first sample");
    const auto lease = scratch();
    Propagation& propagation = lease->propagation;
    const std::vector<Index> samples =
      internal::farthest_point_sampling<Effective_tag<ConcurrencyTag>>(propagation, first, k, accuracy, progress_of(np),
                                                                       m_numbering.user_numbers(),
                                                                       m_numbering.vertices_of_user_numbers());
    if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::distance_map_t>::value)
      write_distances(propagation, parameters::get_parameter(np, internal_np::distance_map_t()));
    write_bounds_and_labels(propagation, np);
    std::vector<vertex_descriptor> out;
    for(Index v : samples)
      out.push_back(m_numbering.vertex(v));
    return out;
  }

  // One propagation per set of source vertices, each on one thread; `row(k, distances,
  // statistics)` is called as the k-th is done, `distances` indexed by the user's numbers of the
  // vertices, or `row(k, distances, statistics, reached)` if it takes the numbers of the vertices
  // the propagation reached (every other is at +infinity): a row within a maximum distance then
  // costs what it reaches (its vectors are written at those vertices only). Everything is checked
  // before the first propagation.
  template <class ConcurrencyTag, class SourceSetRange, class RowFunction, class NamedParameters>
  void distances_from_each_source_set(const SourceSetRange& source_sets, const RowFunction& row,
                                      const NamedParameters& np) const
  {
    static_assert(parameters::is_default_parameter<NamedParameters, internal_np::targets_t>::value,
                  "one field per source: the named parameter targets is not taken "
                  "(call compute_distances() once per source instead)");
    static_assert(parameters::is_default_parameter<NamedParameters, internal_np::target_distances_t>::value,
                  "one field per source: the named parameter target_distances is not taken "
                  "(call compute_distances() once per source instead)");
    static_assert(parameters::is_default_parameter<NamedParameters, internal_np::nearest_source_map_t>::value,
                  "one field per source: the named parameter nearest_source_map is not taken "
                  "(the nearest source of a vertex is that of its field)");
    static_assert(parameters::is_default_parameter<NamedParameters, internal_np::lower_bound_map_t>::value,
                  "one field per source: the named parameter lower_bound_map is not taken (a row "
                  "function with a fifth parameter receives each field's lower bounds)");
    static_assert(parameters::is_default_parameter<NamedParameters, internal_np::callback_t>::value,
                  "one field per source: the named parameter callback is not taken (the fields are "
                  "handed to the caller one by one: it sees the progress, and may stop by throwing)");
    Query options;
    const Computation_FT accuracy = checked_accuracy(np);
    add_max_distance(np, options);
    // the sets one after the other: those of set k are vertices[begin[k]] to vertices[begin[k + 1] - 1]
    std::vector<Index> vertices;
    std::vector<std::size_t> begin(1, 0);
    for(const auto& set : source_sets)
    {
      for(const auto& v : set)
        vertices.push_back(checked_vertex(v, "source"));
      if(vertices.size() == begin.back())
        throw std::invalid_argument("source set " + std::to_string(begin.size() - 1) + " is empty");
      begin.push_back(vertices.size());
    }
    CGAL::for_each<Effective_tag<ConcurrencyTag>>(boost::irange(std::size_t(0), begin.size() - 1), [&](std::size_t k) {
      Query query = options;
      query.vertex_sources.assign(vertices.begin() + begin[k], vertices.begin() + begin[k + 1]);
      query.source_numbers.assign(query.vertex_sources.size(), 0); // the set is one source
      const auto lease = scratch();
      Propagation& propagation = lease->propagation;
      propagation.template run<Sequential_tag>(query, accuracy);
      constexpr bool with_reached = std::is_invocable<const RowFunction&, std::size_t, const std::vector<FT>&,
                                                      const Propagation_statistics&, const std::vector<Index>&>::value;
      constexpr bool with_bounds =
        std::is_invocable<const RowFunction&, std::size_t, const std::vector<FT>&, const Propagation_statistics&,
                          const std::vector<Index>&, const std::vector<FT>&>::value;
      const User_row hand_over(*lease, propagation, m_numbering, with_bounds);
      if constexpr(with_bounds)
        row(k, lease->distances, propagation.statistics(), lease->reached, lease->bounds);
      else if constexpr(with_reached)
        row(k, lease->distances, propagation.statistics(), lease->reached);
      else
        row(k, lease->distances, propagation.statistics());
      return true;
    });
  }

  template <class ConcurrencyTag, class VertexRange, class VertexDistanceMapRange, class NamedParameters>
  std::vector<Propagation_statistics> distances_from_each_source(const VertexRange& sources,
                                                                 const VertexDistanceMapRange& distance_maps,
                                                                 const NamedParameters& np) const
  {
    std::vector<std::array<vertex_descriptor, 1>> sets;
    for(const vertex_descriptor& v : sources)
      sets.push_back({{v}});
    if(sets.size() != static_cast<std::size_t>(std::distance(std::begin(distance_maps), std::end(distance_maps))))
      throw std::invalid_argument("one distance map per source is needed");
    std::vector<Propagation_statistics> statistics(sets.size());
    distances_from_each_source_set<ConcurrencyTag>(
      sets,
      [&](std::size_t k, const std::vector<FT>& d, const Propagation_statistics& s) {
        const auto& map = *(std::begin(distance_maps) + k);
        for(std::size_t i = 0; i < d.size(); ++i)
          put(map, m_numbering.user_vertex(i), d[i]);
        statistics[k] = s;
      },
      np);
    return statistics;
  }

  // the propagation of compute_shortest_path_tree(), handed with its query and the places of its
  // targets to `make_tree`, whose result is returned
  template <class ConcurrencyTag, class SourceRange, class NamedParameters, class MakeTree>
  auto shortest_path_tree(const SourceRange& sources, const NamedParameters& np, const MakeTree& make_tree) const
  {
    Set_up s = set_up(sources, np);
    s.query.record_origins = s.query.record_arrivals = true;
    const auto lease = scratch();
    lease->propagation.template run<Effective_tag<ConcurrencyTag>>(s.query, s.accuracy);
    return make_tree(lease->propagation, s.query, s.targets);
  }

  // One propagation per pair (source, target) of `pairs` (vertices or surface points), each on one
  // thread, toward its target (see Distance_to_go), and stopped once the target's distance is
  // final; each is handed to `give(k, propagation, query, place, accuracy)` as the k-th is done,
  // `place` that of its target (see distance_at()). With `paths`, the propagations record what
  // tracing the paths needs. Every pair is checked before the first propagation.
  template <class ConcurrencyTag, class PairRange, class NamedParameters, class Give>
  void pairs(const PairRange& pairs, const NamedParameters& np, bool paths, const Give& give) const
  {
    static_assert(parameters::is_default_parameter<NamedParameters, internal_np::targets_t>::value,
                  "each pair has its target: the named parameter targets is not taken");
    static_assert(parameters::is_default_parameter<NamedParameters, internal_np::target_distances_t>::value &&
                    parameters::is_default_parameter<NamedParameters, internal_np::nearest_source_map_t>::value &&
                    parameters::is_default_parameter<NamedParameters, internal_np::lower_bound_map_t>::value,
                  "the pair function receives each pair's distance and lower bound: the named parameters "
                  "target_distances, nearest_source_map and lower_bound_map are not taken");
    static_assert(parameters::is_default_parameter<NamedParameters, internal_np::callback_t>::value,
                  "the pairs are handed to the caller one by one: it sees the progress, and may stop by "
                  "throwing (the named parameter callback is not taken)");
    std::vector<Set_up> set_ups;
    std::size_t k = 0;
    for(const auto& pair : pairs)
    {
      Set_up s;
      s.accuracy = checked_accuracy(np);
      add_max_distance(np, s.query);
      try
      {
        builder().add_sources(std::array<std::decay_t<decltype(pair.first)>, 1>{{pair.first}}, s.query);
        s.targets = builder().add_targets(std::array<std::decay_t<decltype(pair.second)>, 1>{{pair.second}}, s.query);
      }
      catch(const std::invalid_argument& e)
      {
        throw std::invalid_argument("pair " + std::to_string(k) + ": " + e.what());
      }
      ++k;
      s.query.record_origins = s.query.record_arrivals = paths;
      s.query.toward_targets = true;
      set_ups.push_back(std::move(s));
    }
    CGAL::for_each<Effective_tag<ConcurrencyTag>>(boost::irange(std::size_t(0), set_ups.size()), [&](std::size_t i) {
      const auto lease = scratch();
      lease->propagation.template run<Sequential_tag>(set_ups[i].query, set_ups[i].accuracy);
      give(i, lease->propagation, set_ups[i].query, set_ups[i].targets.front(), set_ups[i].accuracy);
      return true;
    });
  }

  // The distance that `propagation` found at its target `place` (+infinity beyond the query's
  // maximum distance), and a certified lower bound of the exact one: the least key of a vertex
  // target, d / (1 + accuracy) at a point (the contract), rounded down.
  std::pair<FT, FT> distance_at(const Propagation& propagation, const Query& query, const Place& place,
                                Computation_FT accuracy) const
  {
    const Computation_FT inf = Number_type_math<Computation_FT>::infinity();
    Computation_FT d = place.first ? propagation.distances()[place.second] : propagation.point_targets().distances()[place.second];
    if(d > query.max_distance)
      d = inf;
    Computation_FT lower = inf;
    if(d < inf)
    {
      if(place.first)
        lower = propagation.lower_bounds()[place.second];
      else
      {
        lower = d / (Computation_FT(1) + accuracy);
        lower -= Tuning<Computation_FT>::rounding_margin(lower);
      }
    }
    return {FT(d), rounded_down(lower)};
  }

private:
  // A propagation of this mesh for one query, kept for the next one (see Propagation_pool), and
  // the vectors that hand its field over in the user's numbering (distances_from_each_source_set():
  // +infinity but during a hand-over, their memory taken at the first)
  struct Scratch
  {
    Scratch(const Mesh& mesh, const Patch_partition<Computation_FT>& partition) : propagation(mesh, partition) {}
    bool reusable() const { return propagation.reusable(); }
    Propagation propagation;
    std::vector<FT> distances, bounds; // per user's number of a vertex
    std::vector<Index> reached;        // the user's numbers of the vertices the run reached
  };
  typename Propagation_pool<Scratch>::Lease scratch() const
  {
    return m_pool.take([this] { return std::make_unique<Scratch>(m_mesh, m_partition); });
  }

  // The field of `propagation` in `scratch`'s vectors, in the user's numbering, at the vertices it
  // reached (and their bounds if `bounds`), for as long as it lives: they are back at +infinity
  // after, even if the row threw.
  class User_row
  {
  public:
    User_row(Scratch& scratch, const Propagation& propagation, const Unfolded_numbering<Numbering>& numbering, bool bounds)
      : m_scratch(scratch)
    {
      const FT inf = FT(Number_type_math<Computation_FT>::infinity());
      const std::size_t n = propagation.distances().size();
      if(m_scratch.distances.size() != n)
        m_scratch.distances.assign(n, inf);
      if(bounds && m_scratch.bounds.size() != n)
        m_scratch.bounds.assign(n, inf);
      m_scratch.reached.clear();
      for(Index v : propagation.reached())
      {
        const Index u = Index(numbering.user_number(v));
        m_scratch.reached.push_back(u);
        m_scratch.distances[u] = FT(propagation.distances()[v]);
        if(bounds)
          m_scratch.bounds[u] = rounded_down(propagation.lower_bounds()[v]);
      }
    }
    ~User_row()
    {
      const FT inf = FT(Number_type_math<Computation_FT>::infinity());
      for(Index u : m_scratch.reached)
      {
        m_scratch.distances[u] = inf;
        if(!m_scratch.bounds.empty())
          m_scratch.bounds[u] = inf;
      }
    }
    User_row(const User_row&) = delete;
    User_row& operator=(const User_row&) = delete;

  private:
    Scratch& m_scratch;
  };

  template <class ConcurrencyTag>
  using Effective_tag = typename Effective_concurrency_tag<ConcurrencyTag, Computation_FT>::type;

  Query_builder<Unfolded_numbering<Numbering>, Mesh, Computation_FT> builder() const
  {
    return Query_builder<Unfolded_numbering<Numbering>, Mesh, Computation_FT>(m_numbering, m_mesh);
  }

  // a query of sources and named parameters, checked
  struct Set_up
  {
    Query query;
    Computation_FT accuracy;
    std::vector<Place> targets; // per target, in the order of the named parameter
  };

  template <class SourceRange, class NamedParameters>
  Set_up set_up(const SourceRange& sources, const NamedParameters& np) const
  {
    Set_up s;
    s.accuracy = checked_accuracy(np);
    builder().add_sources(sources, s.query);
    if(s.query.vertex_sources.empty() && s.query.point_sources.empty())
      throw std::invalid_argument("no source given");
    add_max_distance(np, s.query);
    s.query.record_origins =
      !parameters::is_default_parameter<NamedParameters, internal_np::nearest_source_map_t>::value;
    if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::targets_t>::value)
      s.targets = builder().add_targets(parameters::get_parameter(np, internal_np::targets_t()), s.query);
    s.query.progress = progress_of(np);
    return s;
  }

  // the named parameter callback, which may be given empty
  template <class NamedParameters>
  static std::function<bool(double)> progress_of(const NamedParameters& np)
  {
    if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::callback_t>::value)
      return parameters::get_parameter(np, internal_np::callback);
    else
      return {};
  }

  // whether the named parameters ask for no less than whole fields (no targets, no maximum distance)
  template <class NamedParameters>
  static constexpr bool takes_whole_fields()
  {
    return parameters::is_default_parameter<NamedParameters, internal_np::targets_t>::value &&
           parameters::is_default_parameter<NamedParameters, internal_np::max_distance_t>::value;
  }

  template <class VertexDistanceMap>
  void write_distances(const Propagation& propagation, VertexDistanceMap distances) const
  {
    const std::vector<Computation_FT>& d = propagation.distances();
    for(std::size_t i = 0; i < d.size(); ++i)
      put(distances, m_numbering.vertex(i), FT(d[i]));
  }

  // the named parameters lower_bound_map and nearest_source_map, of the field `propagation` holds
  template <class NamedParameters>
  void write_bounds_and_labels(const Propagation& propagation, const NamedParameters& np) const
  {
    const std::vector<Computation_FT>& d = propagation.distances();
    if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::lower_bound_map_t>::value)
    {
      auto bounds = parameters::get_parameter(np, internal_np::lower_bound_map_t());
      const std::vector<Computation_FT>& k = propagation.lower_bounds();
      for(std::size_t i = 0; i < k.size(); ++i)
        put(bounds, m_numbering.vertex(i), rounded_down(k[i]));
    }
    if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::nearest_source_map_t>::value)
    {
      auto labels = parameters::get_parameter(np, internal_np::nearest_source_map_t());
      const std::vector<std::size_t> nearest = nearest_sources(propagation.origins(), Propagation::no_origin());
      for(std::size_t i = 0; i < d.size(); ++i)
        put(labels, m_numbering.vertex(i),
            d[i] < Number_type_math<Computation_FT>::infinity() ? nearest[i] : std::size_t(-1));
    }
  }

  // a lower bound in the user's number type: a float one rounded down, never above the bound
  static FT rounded_down(const Computation_FT& x)
  {
    FT y = FT(x);
    if constexpr(!std::is_same<FT, Computation_FT>::value)
      if(Computation_FT(y) > x)
        y = std::nextafter(y, -std::numeric_limits<FT>::infinity());
    return y;
  }

  template <class NamedParameters>
  static Computation_FT checked_accuracy(const NamedParameters& np)
  {
    const double accuracy = parameters::choose_parameter(parameters::get_parameter(np, internal_np::accuracy), 0.);
    if(!(accuracy >= 0. && accuracy <= maximal_accuracy))
      throw std::invalid_argument("the accuracy must be a number in [0, 1] (0: exact); got " + as_given(accuracy));
    return number<Computation_FT>(accuracy);
  }

  template <class NamedParameters>
  static void add_max_distance(const NamedParameters& np, Query& query)
  {
    const double max_distance = parameters::choose_parameter(
      parameters::get_parameter(np, internal_np::max_distance_t()), std::numeric_limits<double>::infinity());
    if(!(max_distance >= 0.))
      throw std::invalid_argument("the maximum distance must be a number >= 0; got " + as_given(max_distance));
    query.max_distance = max_distance < std::numeric_limits<double>::infinity()
                           ? number<Computation_FT>(max_distance)
                           : Number_type_math<Computation_FT>::infinity();
  }

  Unfolded_numbering<Numbering> m_numbering; // the user's vertices and faces <-> those of m_mesh
  Mesh m_mesh;                            // intrinsic geometry and combinatorics
  Patch_partition<Computation_FT> m_partition; // the faces cut into patches for the propagation's rounds
  mutable Propagation_pool<Scratch> m_pool; // the propagations of the queries, between them
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_SOLVER_CORE_H
