// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// The concurrency tags: compute_distances (one propagation, its patches shared among threads) and
// compute_distances_from_each_source (one field per source, the sources shared among threads),
// with Sequential_tag and, when this executable is linked with TBB, Parallel_tag on 1, 2, 4 and 8
// threads (more threads than cores is the point: the work must be shared out differently and
// give the same bits).

#include "test_utilities.h"
#include "without_tbb.h"

#include <CGAL/tags.h>

#include <array>
#include <cstring>
#include <stdexcept>
#include <iterator>
#include <type_traits>

using namespace dggvtp_test;

namespace {

template <class Mesh>
using Field_map = typename boost::property_map<Mesh, CGAL::dynamic_vertex_property_t<typename Distance_map<Mesh>::FT>>::const_type;

template <class Mesh>
std::vector<Field_map<Mesh>> fresh_maps(const Mesh& mesh, std::size_t count)
{
  std::vector<Field_map<Mesh>> maps;
  for(std::size_t k = 0; k < count; ++k)
  {
    maps.push_back(get(CGAL::dynamic_vertex_property_t<typename Distance_map<Mesh>::FT>(), mesh));
    for(auto v : vertices(mesh))
      put(maps.back(), v, typename Distance_map<Mesh>::FT(-1));
  }
  return maps;
}

// the same bits, not merely the same values (a NaN or a -0 would hide behind ==)
template <class FT>
bool same_bits(FT a, FT b) { return std::memcmp(&a, &b, sizeof(FT)) == 0; }

// what the single queries give, one source at a time: the reference of every concurrency variant
template <class Mesh>
struct Single_queries
{
  std::vector<Field_map<Mesh>> fields;
  std::vector<CGAL::DGG_VTP_3::Propagation_statistics> statistics;
};

template <class Mesh, class Solver>
Single_queries<Mesh> single_queries(const Mesh& mesh, const Solver& solver,
                                    const std::vector<Vertex<Mesh>>& sources, double accuracy)
{
  Single_queries<Mesh> result;
  result.fields = fresh_maps(mesh, sources.size());
  for(std::size_t k = 0; k < sources.size(); ++k)
    result.statistics.push_back(
      solver.compute_distances(sources[k], result.fields[k], CGAL::parameters::accuracy(accuracy)));
  return result;
}

// every field of compute_distances_from_each_source (and its statistics) is, bit for bit, the one
// of the single query
template <class ConcurrencyTag, class Mesh, class Solver>
void check_against_single_queries(const Mesh& mesh, const Solver& solver,
                                  const std::vector<Vertex<Mesh>>& sources, double accuracy,
                                  const Single_queries<Mesh>& single, const std::string& what)
{
  const std::vector<Field_map<Mesh>> maps = fresh_maps(mesh, sources.size());
  const std::vector<CGAL::DGG_VTP_3::Propagation_statistics> statistics =
    solver.template compute_distances_from_each_source<ConcurrencyTag>(sources, maps,
                                                                       CGAL::parameters::accuracy(accuracy));
  BOOST_REQUIRE_EQUAL(statistics.size(), sources.size());

  std::size_t differences = 0;
  for(std::size_t k = 0; k < sources.size(); ++k)
  {
    BOOST_TEST(statistics[k].windows_created == single.statistics[k].windows_created, what << ", source " << k);
    BOOST_TEST(statistics[k].vertices_popped == single.statistics[k].vertices_popped, what << ", source " << k);
    for(auto v : vertices(mesh))
      if(!same_bits(get(maps[k], v), get(single.fields[k], v)))
        ++differences;
    BOOST_TEST(get(maps[k], sources[k]) == 0., what << ", source " << k);
  }
  BOOST_TEST(differences == 0u, what << ": " << differences << " distances differ from the single queries");
}

template <class Mesh>
std::vector<Vertex<Mesh>> spread_sources(const Mesh& mesh, std::size_t count)
{
  const std::vector<Vertex<Mesh>> all = vertex_list(mesh);
  std::vector<Vertex<Mesh>> sources;
  for(std::size_t k = 0; k < count; ++k)
    sources.push_back(all[k * all.size() / count]);
  return sources;
}

} // namespace

BOOST_AUTO_TEST_SUITE(concurrency)

BOOST_AUTO_TEST_CASE(parallel_if_available_follows_tbb)
{
#ifdef CGAL_LINKED_WITH_TBB
  BOOST_TEST((std::is_same<CGAL::Parallel_if_available_tag, CGAL::Parallel_tag>::value));
#else
  BOOST_TEST((std::is_same<CGAL::Parallel_if_available_tag, CGAL::Sequential_tag>::value));
#endif
}

// exact mode and DGG-VTP, on a closed mesh (pinion) and one with border (lion_head)
BOOST_AUTO_TEST_CASE_TEMPLATE(each_source_equals_single_queries, Config, All_configurations)
{
  using Mesh = typename Config::Mesh;
  for(const char* name : {"pinion.ply", "lion_head.ply"})
  {
    const Mesh mesh = make_mesh<Mesh>(read_soup(name));
    const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh> solver(mesh);
    const std::vector<Vertex<Mesh>> sources = spread_sources(mesh, 5);
    for(double accuracy : {0., 1e-5})
    {
      const std::string what = std::string(name) + ", " + config_name<Config>() + ", accuracy " + std::to_string(accuracy);
      const Single_queries<Mesh> single = single_queries(mesh, solver, sources, accuracy);
      check_against_single_queries<CGAL::Sequential_tag>(mesh, solver, sources, accuracy, single, what + ", sequential");
#ifdef CGAL_LINKED_WITH_TBB
      for(int threads : {1, 2, 4, 8})
        on_threads(threads, [&] {
          check_against_single_queries<CGAL::Parallel_tag>(mesh, solver, sources, accuracy, single,
                                                           what + ", " + std::to_string(threads) + " threads");
        });
#else
      DGG_VTP_3_REFUSE_WITHOUT_TBB("compute_distances_from_each_source with Parallel_tag against single queries");
#endif
    }
  }
}

// without a tag, compute_distances_from_each_source runs sequentially, as CGAL's tagged functions do
BOOST_AUTO_TEST_CASE(each_source_defaults_to_sequential)
{
  using Mesh = Sm_d::Mesh;
  const Mesh mesh = make_mesh<Mesh>(read_soup("pinion.ply"));
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh> solver(mesh);
  const std::vector<Vertex<Mesh>> sources = spread_sources(mesh, 3);
  const Single_queries<Mesh> single = single_queries(mesh, solver, sources, 0.);
  const std::vector<Field_map<Mesh>> maps = fresh_maps(mesh, sources.size());
  BOOST_REQUIRE_EQUAL(solver.compute_distances_from_each_source(sources, maps).size(), sources.size());
  std::size_t differences = 0;
  for(std::size_t k = 0; k < sources.size(); ++k)
    for(auto v : vertices(mesh))
      if(!same_bits(get(maps[k], v), get(single.fields[k], v)))
        ++differences;
  BOOST_TEST(differences == 0u);
}

// One propagation: Parallel_tag gives the distances and statistics of Sequential_tag, bit for bit,
// for any number of threads. The meshes have 8 (lion_head) and 36 (bunny) patches of faces, so
// that windows, distances and faces entering the region cross from patch to patch; the results
// stay within the accuracy of the exact mode's.
BOOST_AUTO_TEST_CASE_TEMPLATE(one_propagation_is_the_same_for_any_thread_count, Config, All_configurations)
{
  using Mesh = typename Config::Mesh;
  using FT = typename Distance_map<Mesh>::FT;
  for(const char* name : {"lion_head.ply", "bunny.ply"})
  {
    const Mesh mesh = make_mesh<Mesh>(read_soup(name));
    const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh> solver(mesh);
    const Vertex<Mesh> source = spread_sources(mesh, 3)[1];
    const Field_map<Mesh> exact = fresh_maps(mesh, 1).front();
    solver.compute_distances(source, exact);
    for(double accuracy : {0., 1e-6})
    {
      const std::string what = std::string(name) + ", " + config_name<Config>() + ", accuracy " + std::to_string(accuracy);
      const Field_map<Mesh> sequential = fresh_maps(mesh, 1).front();
      const CGAL::DGG_VTP_3::Propagation_statistics expected =
        solver.template compute_distances<CGAL::Sequential_tag>(source, sequential, CGAL::parameters::accuracy(accuracy));
      // within the accuracy of the exact mode: [e, e (1 + epsilon)] to the relative 1e-12 of the
      // propagation's double, as the rest of the suite checks; a float result is rounded once to
      // float from that double, and so is the exact one it is compared with: 2^-24 each way
      const double u = std::is_same<FT, float>::value ? std::ldexp(1., -24) : 0.;
      const double rounding = 1e-12;
      std::size_t outside = 0;
      for(auto v : vertices(mesh))
      {
        const double e = double(get(exact, v)), d = double(get(sequential, v));
        if(!(d >= e * (1. - u) / (1. + u) * (1. - rounding) && d <= e * (1. + accuracy) * (1. + u) / (1. - u) * (1. + rounding)))
          ++outside;
      }
      BOOST_TEST(outside == 0u, what << ": " << outside << " distances outside the accuracy");
#ifdef CGAL_LINKED_WITH_TBB
      for(int threads : {1, 2, 4, 8})
        on_threads(threads, [&] {
          const Field_map<Mesh> parallel = fresh_maps(mesh, 1).front();
          const CGAL::DGG_VTP_3::Propagation_statistics statistics =
            solver.template compute_distances<CGAL::Parallel_tag>(source, parallel, CGAL::parameters::accuracy(accuracy));
          std::size_t differences = 0;
          for(auto v : vertices(mesh))
            if(!same_bits(get(parallel, v), get(sequential, v)))
              ++differences;
          BOOST_TEST(differences == 0u, what << ", " << threads << " threads: " << differences << " distances differ");
          BOOST_TEST(statistics.windows_created == expected.windows_created, what << ", " << threads << " threads");
          BOOST_TEST(statistics.windows_peak == expected.windows_peak, what << ", " << threads << " threads");
          BOOST_TEST(statistics.vertices_popped == expected.vertices_popped, what << ", " << threads << " threads");
        });
#else
      DGG_VTP_3_REFUSE_WITHOUT_TBB("compute_distances with Parallel_tag against Sequential_tag");
#endif
    }
  }
}

// the checks come before any propagation: nothing is written when one of them fails
// Surface-point sources, point targets, early termination and nearest-source labels: the same bits
// for any number of threads too (bunny: 36 patches, the sources' first windows cross patches)
BOOST_AUTO_TEST_CASE(surface_points_and_early_stop_are_the_same_for_any_thread_count)
{
  using Mesh = Sm_d::Mesh;
  namespace DP = CGAL::DGG_VTP_3::parameters;
  using Location = std::pair<Mesh::Face_index, std::array<double, 3>>;
  const Mesh mesh = make_mesh<Mesh>(read_soup("bunny.ply"));
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh> solver(mesh);
  const std::vector<Location> sources = {Location(Mesh::Face_index(100), {0.2, 0.3, 0.5}),
                                         Location(Mesh::Face_index(40000), {0.5, 0.5, 0.})};
  const std::vector<Location> targets = {Location(Mesh::Face_index(7000), {0.1, 0.6, 0.3}),
                                         Location(Mesh::Face_index(30000), {0.3, 0.3, 0.4})};
  for(double accuracy : {0., 1e-6})
  {
    const auto run = [&](auto tag, std::vector<double>& at_targets, std::vector<std::size_t>& labels) {
      auto d = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
      auto l = get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh);
      at_targets.clear();
      solver.template compute_distances_to_nearest_source<decltype(tag)>(
        sources, d, DP::nearest_source_map(l, DP::target_distances(std::back_inserter(at_targets),
                                                                    DP::targets(targets))).accuracy(accuracy));
      labels.clear();
      std::vector<double> out;
      for(auto v : vertices(mesh))
      {
        out.push_back(get(d, v));
        labels.push_back(get(l, v));
      }
      return out;
    };
    std::vector<double> expected_targets, got_targets;
    std::vector<std::size_t> expected_labels, got_labels;
    const std::vector<double> expected = run(CGAL::Sequential_tag(), expected_targets, expected_labels);
    BOOST_TEST(expected_targets.size() == targets.size());
#ifdef CGAL_LINKED_WITH_TBB
    for(int threads : {1, 2, 4, 8})
      on_threads(threads, [&] {
        const std::vector<double> got = run(CGAL::Parallel_tag(), got_targets, got_labels);
        std::size_t differences = 0;
        for(std::size_t i = 0; i < got.size(); ++i)
          differences += !same_bits(got[i], expected[i]);
        BOOST_TEST(differences == 0u, threads << " threads, accuracy " << accuracy);
        BOOST_TEST(got_labels == expected_labels, boost::test_tools::per_element());
        for(std::size_t k = 0; k < targets.size(); ++k)
          BOOST_TEST(same_bits(got_targets[k], expected_targets[k]));
      });
#else
    DGG_VTP_3_REFUSE_WITHOUT_TBB("surface points and targets with Parallel_tag against Sequential_tag");
#endif
  }
}

// the named parameters reach every propagation: with max_distance, each field is the one of
// compute_distances with it, bit for bit, farther vertices at +infinity (issue 31: they were dropped)
BOOST_AUTO_TEST_CASE(each_source_honours_max_distance)
{
  using Mesh = Sm_d::Mesh;
  const Mesh mesh = make_mesh<Mesh>(read_soup("pinion.ply"));
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh> solver(mesh);
  const std::vector<Vertex<Mesh>> sources = spread_sources(mesh, 3);
  for(double accuracy : {0., 1e-4})
  {
    const auto np = CGAL::DGG_VTP_3::parameters::max_distance(0.3).accuracy(accuracy);
    const std::vector<Field_map<Mesh>> maps = fresh_maps(mesh, sources.size());
    const std::vector<Field_map<Mesh>> parallel_maps = fresh_maps(mesh, sources.size());
    solver.compute_distances_from_each_source(sources, maps, np);
    solver.compute_distances_from_each_source<CGAL::Parallel_if_available_tag>(sources, parallel_maps, np);
    for(std::size_t k = 0; k < sources.size(); ++k)
    {
      const Field_map<Mesh> single = fresh_maps(mesh, 1).front();
      solver.compute_distances(sources[k], single, np);
      std::size_t differences = 0, beyond = 0, within = 0;
      for(auto v : vertices(mesh))
      {
        differences += !same_bits(get(maps[k], v), get(single, v)) || !same_bits(get(parallel_maps[k], v), get(single, v));
        beyond += get(maps[k], v) == std::numeric_limits<double>::infinity();
        within += get(maps[k], v) <= 0.3;
      }
      BOOST_TEST(differences == 0u, "source " << k << ", accuracy " << accuracy);
      BOOST_TEST(beyond > 0u, "source " << k << ": no vertex beyond the maximum distance");
      BOOST_TEST(beyond + within == num_vertices(mesh), "source " << k);
    }
  }
}

// compute_distances_from_each_source_set: row k is, bit for bit, the field of
// compute_distances_to_nearest_source from set k (a set of several vertices is one source), with
// its statistics, each row handed over once, whatever the tag and the number of threads; in
// float and double, on the mesh solver and the soup solver
template <class Solver, class Vertex, class Check>
void check_source_sets(const Solver& solver, const std::vector<std::vector<Vertex>>& sets, double accuracy,
                       const Check& check_row, const std::string& what)
{
  using FT = typename Solver::FT;
  std::vector<std::vector<FT>> rows(sets.size());
  std::vector<CGAL::DGG_VTP_3::Propagation_statistics> statistics(sets.size());
  std::vector<int> calls(sets.size(), 0);
  const int runs = 5; // sequential, then 1, 2, 4 and 8 threads
  const auto row = [&](std::size_t k, const std::vector<FT>& d, const CGAL::DGG_VTP_3::Propagation_statistics& s) {
    rows.at(k) = d;
    statistics.at(k) = s;
    ++calls.at(k); // each k from one thread only
  };
  const auto np = CGAL::parameters::accuracy(accuracy);
  solver.compute_distances_from_each_source_set(sets, row, np);
  for(std::size_t k = 0; k < sets.size(); ++k)
    check_row(sets[k], rows[k], statistics[k], what + ", sequential, set " + std::to_string(k));
#ifdef CGAL_LINKED_WITH_TBB
  for(int threads : {1, 2, 4, 8})
    on_threads(threads, [&] {
      solver.template compute_distances_from_each_source_set<CGAL::Parallel_tag>(sets, row, np);
      for(std::size_t k = 0; k < sets.size(); ++k)
        check_row(sets[k], rows[k], statistics[k], what + ", " + std::to_string(threads) + " threads, set " + std::to_string(k));
    });
#else
  DGG_VTP_3_REFUSE_WITHOUT_TBB("compute_distances_from_each_source_set with Parallel_tag against Sequential_tag");
#endif
  for(std::size_t k = 0; k < sets.size(); ++k)
    BOOST_TEST(calls[k] == runs, what << ", set " << k);
}

template <class Kernel>
void check_source_sets_on(const std::string& name)
{
  using FT = typename Kernel::FT;
  using Mesh = CGAL::Surface_mesh<typename Kernel::Point_3>;
  const Soup soup = read_soup(name);
  const Mesh mesh = make_mesh<Mesh>(soup);
  const std::vector<Vertex<Mesh>> all = vertex_list(mesh);
  const std::size_t n = all.size();
  const std::vector<std::vector<std::size_t>> index_sets{{0}, {n / 3, 2 * n / 3}, {n / 5, n / 2, n - 1}, {7}};
  for(double accuracy : {0., 1e-4})
  {
    const std::string what = name + ", accuracy " + std::to_string(accuracy);
    // the mesh solver: sets of vertex descriptors, rows indexed by the vertex index map
    const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh> solver(mesh);
    std::vector<std::vector<Vertex<Mesh>>> sets;
    for(const auto& set : index_sets)
    {
      sets.emplace_back();
      for(std::size_t i : set)
        sets.back().push_back(all[i]);
    }
    check_source_sets(solver, sets, accuracy,
      [&](const std::vector<Vertex<Mesh>>& set, const std::vector<FT>& row,
          const CGAL::DGG_VTP_3::Propagation_statistics& statistics, const std::string& context) {
        std::vector<FT> expected(n);
        const auto s = solver.compute_distances_to_nearest_source(set, CGAL::make_property_map(expected),
                                                                  CGAL::parameters::accuracy(accuracy));
        BOOST_REQUIRE_EQUAL(row.size(), n);
        std::size_t differences = 0;
        for(std::size_t i = 0; i < n; ++i)
          differences += !same_bits(row[get(CGAL::get(CGAL::vertex_index, mesh), all[i])], expected[i]);
        BOOST_TEST(differences == 0u, context << ": " << differences << " distances differ");
        BOOST_TEST(statistics.windows_created == s.windows_created, context);
        BOOST_TEST(statistics.vertices_popped == s.vertices_popped, context);
      },
      what + ", Surface_mesh");
    // the soup solver: sets of point indices
    std::vector<typename Kernel::Point_3> points;
    for(const auto& p : soup.points)
      points.emplace_back(FT(p[0]), FT(p[1]), FT(p[2]));
    const CGAL::DGG_VTP_3::Triangle_soup_geodesic_distance_solver<Kernel> soup_solver(points, soup.faces);
    check_source_sets(soup_solver, index_sets, accuracy,
      [&](const std::vector<std::size_t>& set, const std::vector<FT>& row,
          const CGAL::DGG_VTP_3::Propagation_statistics& statistics, const std::string& context) {
        std::vector<FT> expected(n);
        const auto s = soup_solver.compute_distances_to_nearest_source(set, CGAL::make_property_map(expected),
                                                                       CGAL::parameters::accuracy(accuracy));
        std::size_t differences = 0;
        for(std::size_t i = 0; i < n; ++i)
          differences += !same_bits(row.at(i), expected[i]);
        BOOST_TEST(differences == 0u, context << ": " << differences << " distances differ");
        BOOST_TEST(statistics.windows_created == s.windows_created, context);
      },
      what + ", soup");
  }
}

BOOST_AUTO_TEST_CASE(each_source_set_equals_nearest_source_queries)
{
  check_source_sets_on<Epick>("lion_head.ply");
  check_source_sets_on<Sc_float>("pinion.ply");
}

// source sets: bad sets are refused before the first row; an exception of the row function ends
// the query and reaches the caller
BOOST_AUTO_TEST_CASE(each_source_set_errors)
{
  using Mesh = Sm_d::Mesh;
  const Mesh mesh = make_mesh<Mesh>(read_soup("pinion.ply"));
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh> solver(mesh);
  const std::vector<Vertex<Mesh>> all = vertex_list(mesh);
  std::size_t rows = 0;
  const auto count = [&](std::size_t, const std::vector<double>&, const CGAL::DGG_VTP_3::Propagation_statistics&) {
    ++rows;
  };
  const std::vector<std::vector<Vertex<Mesh>>> with_empty{{all[0]}, {}};
  BOOST_CHECK_THROW(solver.compute_distances_from_each_source_set(with_empty, count), std::invalid_argument);
  const std::vector<std::vector<Vertex<Mesh>>> with_stranger{
    {all[0]}, {all[1], Mesh::Vertex_index(static_cast<Mesh::size_type>(all.size() + 3))}};
  BOOST_CHECK_THROW(solver.compute_distances_from_each_source_set(with_stranger, count), std::invalid_argument);
  const std::vector<std::vector<Vertex<Mesh>>> good{{all[0]}, {all[1]}};
  BOOST_CHECK_THROW(solver.compute_distances_from_each_source_set(good, count, CGAL::parameters::accuracy(-1.)),
                    std::invalid_argument);
  BOOST_TEST(rows == 0u);
  const auto failing = [](std::size_t, const std::vector<double>&, const CGAL::DGG_VTP_3::Propagation_statistics&) {
    throw std::runtime_error("row refused");
  };
  BOOST_CHECK_THROW(solver.compute_distances_from_each_source_set<CGAL::Parallel_if_available_tag>(good, failing),
                    std::runtime_error);
  solver.compute_distances_from_each_source_set(std::vector<std::vector<Vertex<Mesh>>>(), count);
  BOOST_TEST(rows == 0u);
}

BOOST_AUTO_TEST_CASE(bad_arguments_are_refused_before_any_work)
{
  using Mesh = CGAL::Surface_mesh<Epick::Point_3>;
  const Mesh mesh = make_mesh<Mesh>(read_soup("pinion.ply"));
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh> solver(mesh);
  std::vector<Vertex<Mesh>> sources = spread_sources(mesh, 3);

  const std::vector<Field_map<Mesh>> too_few = fresh_maps(mesh, 2);
  BOOST_CHECK_THROW(solver.compute_distances_from_each_source<CGAL::Parallel_if_available_tag>(sources, too_few),
                    std::invalid_argument);

  sources.push_back(Mesh::Vertex_index(static_cast<Mesh::size_type>(num_vertices(mesh) + 7)));
  const std::vector<Field_map<Mesh>> maps = fresh_maps(mesh, sources.size());
  BOOST_CHECK_THROW(solver.compute_distances_from_each_source<CGAL::Parallel_if_available_tag>(sources, maps),
                    std::invalid_argument);
  sources.pop_back();
  BOOST_CHECK_THROW(solver.compute_distances_from_each_source<CGAL::Parallel_if_available_tag>(
                      sources, fresh_maps(mesh, sources.size()), CGAL::parameters::accuracy(-1e-6)),
                    std::invalid_argument);
  BOOST_CHECK_THROW(solver.compute_distances_from_each_source<CGAL::Parallel_if_available_tag>(
                      sources, maps, CGAL::DGG_VTP_3::parameters::max_distance(-1.)),
                    std::invalid_argument);
  for(const Field_map<Mesh>& map : maps)
    BOOST_TEST(get(map, sources.front()) == -1.);

  const std::vector<Field_map<Mesh>> none;
  BOOST_TEST(solver.compute_distances_from_each_source<CGAL::Parallel_if_available_tag>(
               std::vector<Vertex<Mesh>>(), none).empty());
}

BOOST_AUTO_TEST_SUITE_END()
