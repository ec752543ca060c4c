// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// The certified interval of every distance (issue 45): the lower bound K(v) of the named parameter
// lower_bound_map (and of the rows of compute_distances_from_each_source_set) is at most the exact
// distance, and the distance d(v) at most K(v) + epsilon d(v), at every vertex, for every source
// and accuracy; K = d in the exact mode; the same bits with Parallel_tag; float bounds rounded
// down; a query stopped early (targets, max_distance) still gives valid bounds.

#include "test_utilities.h"
#include "without_tbb.h"

#include <cstring>

using namespace dggvtp_test;

namespace {

namespace DP = CGAL::DGG_VTP_3::parameters;
using Sm = CGAL::Surface_mesh<Epick::Point_3>;

const double epsilons[] = {1., 0.5, 1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-7};

struct Bound_report
{
  double below_exact = 0.;   // max of (K - exact) / exact: positive is a false lower bound
  double width = 0.;         // max of (d - K) / (epsilon d)
  std::size_t certified = 0; // vertices with K = d
  std::size_t bad = 0;       // NaN, K > d, or d or K finite where the exact distance is not, or not where it is
};

// the same bits, not merely the same values (a NaN or a -0 would hide behind ==)
bool same_bits(const std::vector<double>& a, const std::vector<double>& b)
{
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

Bound_report check_bounds(const std::vector<double>& d, const std::vector<double>& k,
                          const std::vector<double>& exact, double epsilon)
{
  Bound_report r;
  for(std::size_t i = 0; i < d.size(); ++i)
  {
    // a vertex the exact field reaches has a finite distance and bound, and one it does not reach
    // neither: an all-infinite field is no interval of a finite one
    const bool reached = std::isfinite(exact[i]);
    if(!(k[i] <= d[i]) || bool(std::isfinite(d[i])) != reached || bool(std::isfinite(k[i])) != reached)
    {
      ++r.bad;
      continue;
    }
    if(!std::isfinite(d[i]))
      continue;
    r.certified += k[i] == d[i];
    if(exact[i] > 0.)
      r.below_exact = (std::max)(r.below_exact, (k[i] - exact[i]) / exact[i]);
    if(d[i] > 0.)
      r.width = (std::max)(r.width, (d[i] - k[i]) / (epsilon > 0. ? epsilon * d[i] : 1.));
  }
  return r;
}

// every source of `file` through compute_distances_from_each_source_set's rows, every accuracy,
// against the exact mode's rows
void check_every_source(const std::string& file)
{
  const Soup soup = read_soup(file);
  const Sm mesh = make_mesh<Sm>(soup);
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Sm> solver(mesh);
  std::vector<std::vector<Sm::Vertex_index>> sets;
  for(auto v : vertices(mesh))
    sets.push_back({v});
  std::vector<std::vector<double>> exact(sets.size());
  std::size_t reached_exactly = 0;
  solver.compute_distances_from_each_source_set(
    sets, [&](std::size_t k, const std::vector<double>& d, const auto&, const auto&, const std::vector<double>& lower) {
      BOOST_TEST((lower == d), file << ": exact mode, source " << k << ": lower bound = distance");
      exact[k] = d;
      for(double x : d)
        reached_exactly += std::isfinite(x);
    });
  // the reference reaches more than the sources themselves
  BOOST_TEST(reached_exactly > sets.size(), file << ": the exact mode reaches " << reached_exactly << " vertices");
  for(double epsilon : epsilons)
  {
    Bound_report all;
    std::size_t reached = 0;
    solver.compute_distances_from_each_source_set(
      sets,
      [&](std::size_t k, const std::vector<double>& d, const auto&, const auto&, const std::vector<double>& lower) {
        const Bound_report r = check_bounds(d, lower, exact[k], epsilon);
        all.below_exact = (std::max)(all.below_exact, r.below_exact);
        all.width = (std::max)(all.width, r.width);
        all.certified += r.certified;
        all.bad += r.bad;
        reached += d.size();
      },
      CGAL::parameters::accuracy(epsilon));
    BOOST_TEST_MESSAGE(file << ", epsilon " << epsilon << ": max (K - exact) / exact " << all.below_exact
                       << ", max (d - K) / (epsilon d) " << all.width << ", certified exact "
                       << double(all.certified) / double(reached));
    BOOST_TEST(all.bad == 0u, file << ", epsilon " << epsilon);
    BOOST_TEST(all.below_exact <= 1e-12, file << ", epsilon " << epsilon);
    BOOST_TEST(all.width <= 1., file << ", epsilon " << epsilon);
  }
}

template <class Mesh, class NamedParameters>
std::pair<std::vector<double>, std::vector<double>> field_and_bounds(const Mesh& mesh, std::size_t source,
                                                                      const NamedParameters& np)
{
  using FT = typename Distance_map<Mesh>::FT;
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh> solver(mesh);
  auto d = get(CGAL::dynamic_vertex_property_t<FT>(), mesh);
  auto k = get(CGAL::dynamic_vertex_property_t<FT>(), mesh);
  solver.compute_distances(vertex_list(mesh).at(source), d, DP::lower_bound_map(k, np));
  return {to_vector(mesh, d), to_vector(mesh, k)};
}

} // namespace

BOOST_AUTO_TEST_SUITE(lower_bounds)

BOOST_AUTO_TEST_CASE(every_source_of_pinion) { check_every_source("pinion.ply"); }

// a mesh with a border and thin triangles: 60 sources
BOOST_AUTO_TEST_CASE(lion_head_sources)
{
  const Soup soup = read_soup("lion_head.ply");
  const Sm mesh = make_mesh<Sm>(soup);
  for(std::size_t s = 0; s < soup.points.size(); s += soup.points.size() / 60)
  {
    const std::vector<double> exact = geodesic_distances(mesh, s);
    for(double epsilon : {1., 1e-2, 1e-4})
    {
      const auto [d, k] = field_and_bounds(mesh, s, CGAL::parameters::accuracy(epsilon));
      const Bound_report r = check_bounds(d, k, exact, epsilon);
      BOOST_TEST(r.bad == 0u);
      BOOST_TEST(r.below_exact <= 1e-12, "source " << s << ", epsilon " << epsilon);
      BOOST_TEST(r.width <= 1., "source " << s << ", epsilon " << epsilon);
    }
  }
}

// the named parameter on the soup solver and with Parallel_tag: the same bits
BOOST_AUTO_TEST_CASE(same_bits_on_every_solver_and_tag)
{
  const Soup soup = read_soup("spot.ply");
  const Sm mesh = make_mesh<Sm>(soup);
  const auto [d, k] = field_and_bounds(mesh, 7, CGAL::parameters::accuracy(1e-2));
  std::vector<Epick::Point_3> points;
  for(const auto& p : soup.points)
    points.emplace_back(p[0], p[1], p[2]);
  const CGAL::DGG_VTP_3::Triangle_soup_geodesic_distance_solver<Epick> soup_solver(points, soup.faces);
  std::vector<double> ds(points.size()), ks(points.size());
  soup_solver.compute_distances(std::size_t(7), CGAL::make_property_map(ds),
                                DP::lower_bound_map(CGAL::make_property_map(ks), CGAL::parameters::accuracy(1e-2)));
  BOOST_TEST(same_bits(ds, d), "the soup solver's distances");
  BOOST_TEST(same_bits(ks, k), "the soup solver's bounds");
  BOOST_TEST((k != d), "epsilon 1e-2 certifies an interval, not every distance");
#ifdef CGAL_LINKED_WITH_TBB
  for(int threads : {1, 2, 4, 8})
    on_threads(threads, [&] {
      // NaN first: a value the run does not write is not the sequential one left over
      ds.assign(points.size(), std::numeric_limits<double>::quiet_NaN());
      ks.assign(points.size(), std::numeric_limits<double>::quiet_NaN());
      soup_solver.compute_distances<CGAL::Parallel_tag>(
        std::size_t(7), CGAL::make_property_map(ds),
        DP::lower_bound_map(CGAL::make_property_map(ks), CGAL::parameters::accuracy(1e-2)));
      BOOST_TEST(same_bits(ds, d), threads << " threads: the distances");
      BOOST_TEST(same_bits(ks, k), threads << " threads: the bounds");
    });
#else
  DGG_VTP_3_REFUSE_WITHOUT_TBB("Parallel_tag against Sequential_tag");
#endif
}

// float: each bound rounded down from the propagation's double, so still below the exact distance
BOOST_AUTO_TEST_CASE(float_rounded_down)
{
  const Soup soup = read_soup("pinion.ply");
  using Sf = CGAL::Surface_mesh<Sc_float::Point_3>;
  const Sf mesh = make_mesh<Sf>(soup);
  for(std::size_t s : {0, 300})
  {
    const std::vector<double> exact = geodesic_distances(make_mesh<Sm>(soup), s);
    for(double epsilon : {0., 1e-3, 1e-7})
    {
      const auto [d, k] = field_and_bounds(mesh, s, CGAL::parameters::accuracy(epsilon));
      for(std::size_t i = 0; i < k.size(); ++i)
      {
        BOOST_TEST(k[i] <= d[i]);
        // the float surface differs from the double one by float's rounding of the coordinates
        BOOST_TEST(k[i] <= exact[i] * (1. + 1e-6) + 1e-12, "vertex " << i);
      }
    }
  }
}

// A query stopped early: the vertices beyond max_distance get +infinity as their distance and
// bound; with targets, a vertex whose distance is not final gets a bound that pending work cannot
// undercut (the limit's key), so every bound stays below the exact distance.
BOOST_AUTO_TEST_CASE(early_termination)
{
  const Soup soup = read_soup("spot.ply");
  const Sm mesh = make_mesh<Sm>(soup);
  const std::vector<double> exact = geodesic_distances(mesh, 11);
  const std::vector<Sm::Vertex_index> all = vertex_list(mesh);
  for(double epsilon : {0., 1e-3, 1.})
  {
    const auto [d, k] = field_and_bounds(mesh, 11, DP::max_distance(0.3, CGAL::parameters::accuracy(epsilon)));
    const auto [dt, kt] = field_and_bounds(
      mesh, 11, DP::targets(std::vector<Sm::Vertex_index>{all[40], all[900]}, CGAL::parameters::accuracy(epsilon)));
    std::size_t within = 0, open = 0;
    for(std::size_t i = 0; i < d.size(); ++i)
    {
      BOOST_TEST((std::isinf(d[i]) == std::isinf(k[i])), "vertex " << i);
      within += std::isfinite(d[i]);
      BOOST_TEST(k[i] <= d[i]);
      if(std::isfinite(k[i]))
        BOOST_TEST(k[i] <= exact[i] * (1. + 1e-12), "max_distance, epsilon " << epsilon << ", vertex " << i);
      BOOST_TEST((std::isinf(dt[i]) == std::isinf(kt[i])), "vertex " << i);
      BOOST_TEST(kt[i] <= dt[i]);
      if(std::isfinite(kt[i]))
        BOOST_TEST(kt[i] <= exact[i] * (1. + 1e-12), "targets, epsilon " << epsilon << ", vertex " << i);
      open += std::isfinite(dt[i]) && kt[i] < dt[i];
    }
    BOOST_TEST(within > 10u);
    BOOST_TEST(within < d.size());
    if(epsilon == 0.)
      BOOST_TEST(open > 0u, "vertices not final get a bound below their distance, even in the exact mode");
  }
}

BOOST_AUTO_TEST_SUITE_END()
