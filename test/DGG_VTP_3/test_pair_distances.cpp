// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// Pair queries (compute_pair_distances, issue 59): each pair's propagation searches toward its
// target and stops once the target's distance is final. Against the exact rows of whole fields:
// the value within [exact, (1 + epsilon) exact], the exact mode's to rounding, the lower bound
// within [exact / (1 + epsilon), exact]; the path from the source to the target, as long as the
// value; the same bits on any number of threads; surface points; errors that name the pair.

#include "test_utilities.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

using namespace dggvtp_test;
namespace DP = CGAL::DGG_VTP_3::parameters;

namespace {

using Sm = CGAL::Surface_mesh<Epick::Point_3>;
using Solver = CGAL::DGG_VTP_3::Geodesic_distance_solver<Sm>;
using Sm_vertex = boost::graph_traits<Sm>::vertex_descriptor;
using Path_point = CGAL::DGG_VTP_3::Shortest_path_tree<Solver>::Path_point;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

struct Pair_value
{
  double distance = -1., lower = -1.;
  std::vector<Path_point> path;
};

template <class Tag = CGAL::Sequential_tag, class Pairs, class NP>
std::vector<Pair_value> pair_values(const Solver& solver, const Pairs& pairs, const NP& np, bool paths)
{
  std::vector<Pair_value> out(pairs.size());
  if(paths)
    solver.compute_pair_distances<Tag>(
      pairs, [&](std::size_t k, double d, double lower, const std::vector<Path_point>& path) {
        out.at(k) = Pair_value{d, lower, path};
      }, np);
  else
    solver.compute_pair_distances<Tag>(pairs, [&](std::size_t k, double d, double lower) {
      out.at(k).distance = d;
      out.at(k).lower = lower;
    }, np);
  return out;
}

// every `step`-th source of `name` with every vertex as target, at `epsilon`, against exact rows
void check_pairs(const std::string& name, std::size_t step, double epsilon)
{
  const Sm mesh = make_mesh<Sm>(read_soup(name));
  const Solver solver(mesh);
  const std::vector<Sm_vertex> all = vertex_list(mesh);
  std::vector<std::pair<Sm_vertex, Sm_vertex>> pairs;
  std::vector<std::vector<double>> exact;
  for(std::size_t s = 0; s < all.size(); s += step)
  {
    exact.push_back(solver_distances(solver, mesh, s));
    for(Sm_vertex t : all)
      pairs.emplace_back(all[s], t);
  }
  const std::vector<Pair_value> got = pair_values(solver, pairs, CGAL::parameters::accuracy(epsilon), false);
  std::size_t outside = 0, bad_lower = 0, compared = 0;
  double worst = 0.;
  for(std::size_t k = 0; k < pairs.size(); ++k)
  {
    const double truth = exact[k / all.size()][k % all.size()];
    const double d = got[k].distance, lower = got[k].lower;
    ++compared;
    if(truth == 0.)
    {
      outside += d != 0.;
      continue;
    }
    const double r = (d - truth) / truth;
    worst = (std::max)(worst, r / (std::max)(epsilon, 1e-300));
    // the exact mode's value is the exact row's, to rounding
    if(!(r >= -1e-12 && r <= (epsilon == 0. ? 1e-12 : epsilon)))
      ++outside;
    if(!(lower <= truth * (1. + 1e-12) && lower >= truth / (1. + epsilon) * (1. - 1e-12)))
      ++bad_lower;
  }
  BOOST_TEST_MESSAGE(name << ", epsilon " << epsilon << ": " << compared << " pairs, largest error / epsilon " << worst);
  BOOST_TEST(compared == (all.size() + step - 1) / step * all.size());
  BOOST_TEST(outside == 0u, name << ", epsilon " << epsilon << ": " << outside << " values outside the contract");
  BOOST_TEST(bad_lower == 0u, name << ", epsilon " << epsilon << ": " << bad_lower << " lower bounds not certified");
}

double length_of(const Sm& mesh, const std::vector<Path_point>& path)
{
  double length = 0.;
  for(std::size_t i = 1; i < path.size(); ++i)
  {
    const auto a = CGAL::Polygon_mesh_processing::construct_point(path[i - 1].location, mesh);
    const auto b = CGAL::Polygon_mesh_processing::construct_point(path[i].location, mesh);
    length += std::sqrt(CGAL::squared_distance(a, b));
  }
  return length;
}

// a pair costs a propagation: sources spread over the mesh, each with every vertex as a target
// (the sanitizer builds take fewer)
#ifdef DGG_VTP_3_TEST_FEWER_CONFIGURATIONS
constexpr std::size_t every = 150;
#else
constexpr std::size_t every = 45;
#endif

} // namespace

BOOST_AUTO_TEST_SUITE(pair_distances)

// CAD: flat faces, sharp edges, thin triangles; every 45th source to every vertex
BOOST_AUTO_TEST_CASE(pinion_against_exact_rows)
{
  for(double epsilon : {0., 1e-1, 1e-3})
    check_pairs("pinion.ply", every, epsilon);
}

// a smooth closed mesh with a border-free surface and saddles everywhere
BOOST_AUTO_TEST_CASE(spot_against_exact_rows)
{
  for(double epsilon : {0., 1e-2})
    check_pairs("spot.ply", every * 16, epsilon);
}

// the path runs from the source to the target, on the mesh, as long as the value
BOOST_AUTO_TEST_CASE(paths_from_source_to_target)
{
  const Sm mesh = make_mesh<Sm>(read_soup("lion_head.ply"));
  const Solver solver(mesh);
  const std::vector<Sm_vertex> all = vertex_list(mesh);
  std::vector<std::pair<Sm_vertex, Sm_vertex>> pairs;
  for(std::size_t k = 0; k < 20; ++k)
    pairs.emplace_back(all[(k * 4099) % all.size()], all[(k * 7919 + 13) % all.size()]);
  for(double epsilon : {0., 1e-2})
  {
    const std::vector<Pair_value> got = pair_values(solver, pairs, CGAL::parameters::accuracy(epsilon), true);
    const std::vector<Pair_value> bare = pair_values(solver, pairs, CGAL::parameters::accuracy(epsilon), false);
    for(std::size_t k = 0; k < pairs.size(); ++k)
    {
      const Pair_value& p = got[k];
      BOOST_TEST(same_bits(p.distance, bare[k].distance), "pair " << k << ": recording the path changed the value");
      BOOST_REQUIRE(!p.path.empty());
      BOOST_TEST(p.path.front().vertex == pairs[k].first, "pair " << k << ": the path does not start at the source");
      BOOST_TEST(p.path.back().vertex == pairs[k].second, "pair " << k << ": the path does not end at the target");
      BOOST_TEST(length_of(mesh, p.path) == p.distance, boost::test_tools::tolerance(1e-9));
    }
  }
}

#ifdef CGAL_LINKED_WITH_TBB
// the pairs shared among 2, 4 and 8 threads give Sequential_tag's bits
BOOST_AUTO_TEST_CASE(the_same_bits_on_any_number_of_threads)
{
  const Sm mesh = make_mesh<Sm>(read_soup("bunny.ply"));
  const Solver solver(mesh);
  const std::vector<Sm_vertex> all = vertex_list(mesh);
  std::vector<std::pair<Sm_vertex, Sm_vertex>> pairs;
  for(std::size_t k = 0; k < 24; ++k)
    pairs.emplace_back(all[(k * 1543) % all.size()], all[(k * 6151 + 101) % all.size()]);
  for(double epsilon : {0., 1e-1, 1e-4})
  {
    const auto np = CGAL::parameters::accuracy(epsilon);
    const std::vector<Pair_value> expected = pair_values(solver, pairs, np, false);
    for(int threads : {2, 4, 8})
      on_threads(threads, [&] {
        const std::vector<Pair_value> got = pair_values<CGAL::Parallel_tag>(solver, pairs, np, false);
        std::size_t differ = 0;
        for(std::size_t k = 0; k < pairs.size(); ++k)
          differ += !same_bits(got[k].distance, expected[k].distance) || !same_bits(got[k].lower, expected[k].lower);
        BOOST_TEST(differ == 0u, "epsilon " << epsilon << ", " << threads << " threads: " << differ << " pairs differ");
      });
  }
}
#endif

// surface points as sources and targets: the values of a query with the point as target, which
// the pair query must give within the contract (the exact mode's to rounding)
BOOST_AUTO_TEST_CASE(points_on_faces)
{
  const Sm mesh = make_mesh<Sm>(read_soup("spot.ply"));
  const Solver solver(mesh);
  const std::vector<Solver::Face_location> points = {
    {Sm::Face_index(10), {{0.2, 0.3, 0.5}}}, {Sm::Face_index(3000), {{0.6, 0.4, 0.}}},
    {Sm::Face_index(5000), {{1. / 3, 1. / 3, 1. / 3}}}};
  std::vector<std::pair<Solver::Face_location, Solver::Face_location>> pairs;
  for(const auto& a : points)
    for(const auto& b : points)
      pairs.emplace_back(a, b);
  for(double epsilon : {0., 1e-2})
  {
    const std::vector<Pair_value> got = pair_values(solver, pairs, CGAL::parameters::accuracy(epsilon), false);
    for(std::size_t k = 0; k < pairs.size(); ++k)
    {
      std::vector<double> truth;
      auto map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
      solver.compute_distances(pairs[k].first, map, DP::targets(std::vector<Solver::Face_location>{pairs[k].second},
                                                                DP::target_distances(std::back_inserter(truth))));
      const double t = truth.at(0), d = got[k].distance;
      if(t == 0.)
        BOOST_TEST(d == 0.);
      else
      {
        // both within the contract of the exact distance: within (1 + epsilon) of each other
        BOOST_TEST(d >= t / (1. + epsilon) * (1. - 1e-12), "pair " << k);
        BOOST_TEST(d <= t * (1. + epsilon) * (1. + 1e-12), "pair " << k);
        BOOST_TEST(got[k].lower <= d);
      }
    }
  }
}

// beyond the maximum distance, a pair is unreachable; a pair of no vertex of the mesh is refused
// before any propagation, by its number
BOOST_AUTO_TEST_CASE(max_distance_and_errors)
{
  const Sm mesh = make_mesh<Sm>(read_soup("pinion.ply"));
  const Solver solver(mesh);
  const std::vector<Sm_vertex> all = vertex_list(mesh);
  std::vector<std::pair<Sm_vertex, Sm_vertex>> pairs = {{all[0], all[1]}, {all[0], all[600]}};
  const std::vector<double> exact = solver_distances(solver, mesh, 0);
  const double limit = (exact[1] + exact[600]) / 2.;
  BOOST_REQUIRE(exact[1] < limit && limit < exact[600]);
  const std::vector<Pair_value> got = pair_values(solver, pairs, DP::max_distance(limit), false);
  BOOST_TEST(got[0].distance == exact[1], boost::test_tools::tolerance(1e-12));
  BOOST_TEST(got[1].distance == std::numeric_limits<double>::infinity());
  BOOST_TEST(got[1].lower == std::numeric_limits<double>::infinity());
  pairs.emplace_back(all[2], Sm_vertex(100000));
  int calls = 0;
  try
  {
    solver.compute_pair_distances(pairs, [&](std::size_t, double, double) { ++calls; });
    BOOST_ERROR("a pair out of the mesh was accepted");
  }
  catch(const std::invalid_argument& e)
  {
    BOOST_TEST(std::string(e.what()).find("pair 2") != std::string::npos, e.what());
  }
  BOOST_TEST(calls == 0, "a pair was computed before the bad one was refused");
}

BOOST_AUTO_TEST_SUITE_END()
