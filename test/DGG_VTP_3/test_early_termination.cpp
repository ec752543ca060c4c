// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// Early termination (targets, max_distance) against the full field, bit for bit, on meshes whose
// edges vary in length by three orders of magnitude, where a stop "a few mean edge lengths beyond
// the targets" has nothing to do with how far a window still to be propagated may reach
// (issue 31: the stop rested on a margin of 8 mean edge lengths).

#include "test_utilities.h"

#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>

#include <cmath>
#include <cstring>

#include <algorithm>
#include <iterator>
#include <limits>

using namespace dggvtp_test;
namespace DP = CGAL::DGG_VTP_3::parameters;

namespace {

// the same bits (a NaN equals a NaN, -0 differs from +0: == would hide both)
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

using Mesh = CGAL::Surface_mesh<Epick::Point_3>;
using Solver = CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh>;
using Location = std::pair<Mesh::Face_index, std::array<double, 3>>;

// A bumpy height field over a grid whose columns widen geometrically, from 1e-3 to about 2, and
// whose rows are 0.05 apart: needles at one end, wide flat triangles at the other, every quad
// split along a random diagonal.
Soup mixed_edge_lengths(std::uint64_t seed)
{
  Random random(seed);
  const std::size_t nx = 56, ny = 24;
  std::vector<double> x(1, 0.);
  for(std::size_t i = 0; i < nx; ++i)
    x.push_back(x.back() + 1e-3 * std::pow(1.15, double(i)));
  Soup soup;
  for(std::size_t j = 0; j <= ny; ++j)
    for(std::size_t i = 0; i <= nx; ++i)
      soup.points.push_back({x[i], 0.05 * double(j), random.uniform(-0.02, 0.02)});
  add_grid_triangles(nx, ny, random, soup);
  return soup;
}

// A short way that the early stop of a margin in mean edge lengths missed: a bridge of three
// flat triangles from s to t whose corners are all about 10 away (edge ab, then ac, cross the
// segment st of length 2), beside an arch of fine triangles, a half cylinder of length pi from s
// to t. t is reached first along the arch (pi), long before any corner of the bridge (10), while
// the window that s sends across ab waits in the list of face abc, none of whose vertices is
// anywhere near: 8 mean edge lengths of the arch beyond pi, the old stop gave t pi instead of 2.
Soup arch_and_bridge()
{
  Soup soup;
  const auto add = [&soup](double x, double y, double z) {
    soup.points.push_back({x, y, z});
    return soup.points.size() - 1;
  };
  const std::size_t s = add(0., 0., 0.), t = add(2., 0., 0.);
  const std::size_t a = add(2. / 3., 10., 0.), b = add(2. / 3., -10., 0.), c = add(4. / 3., -10., 0.);
  soup.faces.push_back({s, b, a});
  soup.faces.push_back({a, b, c});
  soup.faces.push_back({a, c, t});
  // the arch: rows across it at angles theta in (0, pi) of the half circle of radius 1 about
  // (1, 0, 0) in the plane y = 0, fanning into s and t at its ends
  const std::size_t rows = 100, across = 6;
  std::vector<std::vector<std::size_t>> row(rows - 1);
  const double pi = 3.14159265358979323846;
  for(std::size_t i = 1; i < rows; ++i)
    for(std::size_t j = 0; j <= across; ++j)
    {
      const double theta = pi * double(i) / double(rows);
      row[i - 1].push_back(add(1. - std::cos(theta), 0.2 * double(j) / double(across) - 0.1, std::sin(theta)));
    }
  for(std::size_t i = 0; i + 1 < row.size(); ++i)
    for(std::size_t j = 0; j < across; ++j)
    {
      soup.faces.push_back({row[i][j], row[i + 1][j], row[i + 1][j + 1]});
      soup.faces.push_back({row[i][j], row[i + 1][j + 1], row[i][j + 1]});
    }
  for(std::size_t j = 0; j < across; ++j)
  {
    soup.faces.push_back({s, row.front()[j], row.front()[j + 1]});
    soup.faces.push_back({t, row.back()[j + 1], row.back()[j]});
  }
  // one fan around s and t: the arch's end joined to the bridge's long edges
  soup.faces.push_back({s, row.front()[0], b});
  soup.faces.push_back({t, row.back()[0], c});
  CGAL::Polygon_mesh_processing::orient_polygon_soup(soup.points, soup.faces);
  return soup;
}

std::vector<double> full_field(const Solver& solver, const Mesh& mesh, Mesh::Vertex_index source, double accuracy)
{
  auto map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  solver.compute_distances(source, map, CGAL::parameters::accuracy(accuracy));
  return to_vector(mesh, map);
}

template <class Targets>
std::vector<double> target_distances(const Solver& solver, const Mesh& mesh, Mesh::Vertex_index source,
                                     const Targets& targets, double accuracy)
{
  auto map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  std::vector<double> d;
  solver.compute_distances(source, map,
                           DP::target_distances(std::back_inserter(d), DP::targets(targets)).accuracy(accuracy));
  return d;
}

// Many single targets drawn at random, then max_distance at random radii: the same bits as the
// full field (the stop changes when the propagation ends, not what it computes up to then).
void check_against_full_field(const Mesh& mesh, std::uint64_t seed, const std::string& label, int runs = 3)
{
  const Solver solver(mesh);
  const std::vector<Mesh::Vertex_index> vs = vertex_list(mesh);
  Random random(seed);
  for(double accuracy : {0., 1e-1, 1e-3, 1e-5})
    for(int run = 0; run < runs; ++run)
    {
      const Mesh::Vertex_index source = vs[std::size_t(random.uniform() * double(vs.size()))];
      const std::vector<double> all = full_field(solver, mesh, source, accuracy);
      double farthest = 0.;
      for(double d : all)
        farthest = (std::max)(farthest, d);
      std::size_t wrong_targets = 0, wrong_below_limit = 0, wrong_beyond_limit = 0;
      for(int k = 0; k < 25; ++k)
      {
        const std::size_t t = std::size_t(random.uniform() * double(vs.size()));
        const std::vector<double> d = target_distances(solver, mesh, source, std::vector<Mesh::Vertex_index>{vs[t]}, accuracy);
        if(!same_bits(d.at(0), all[t]))
          ++wrong_targets;
      }
      for(int k = 0; k < 6; ++k)
      {
        const double limit = random.uniform(0., 0.8) * farthest;
        auto map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
        solver.compute_distances(source, map, DP::max_distance(limit).accuracy(accuracy));
        const std::vector<double> d = to_vector(mesh, map);
        for(std::size_t i = 0; i < d.size(); ++i)
        {
          if(all[i] <= limit && !same_bits(d[i], all[i]))
            ++wrong_below_limit;
          if(all[i] > limit && d[i] != std::numeric_limits<double>::infinity())
            ++wrong_beyond_limit;
        }
      }
      BOOST_TEST_MESSAGE(label << ", epsilon " << accuracy << ", run " << run);
      BOOST_TEST(wrong_targets == 0u, label << ", epsilon " << accuracy << ": targets off the full field");
      BOOST_TEST(wrong_below_limit == 0u, label << ", epsilon " << accuracy << ": vertices within max_distance off the full field");
      BOOST_TEST(wrong_beyond_limit == 0u, label << ", epsilon " << accuracy << ": vertices beyond max_distance not +inf");
    }
}

} // namespace

BOOST_AUTO_TEST_SUITE(early_termination)

BOOST_AUTO_TEST_CASE(targets_and_max_distance_match_the_full_field_on_mixed_edge_lengths)
{
  for(std::uint64_t seed : {3u, 17u})
    check_against_full_field(make_mesh<Mesh>(mixed_edge_lengths(seed)), seed, "mixed edges, seed " + std::to_string(seed));
}

BOOST_AUTO_TEST_CASE(target_behind_a_bridge_of_large_faces)
{
  const Mesh mesh = make_mesh<Mesh>(arch_and_bridge());
  const Solver solver(mesh);
  const std::vector<Mesh::Vertex_index> vs = vertex_list(mesh);
  for(double accuracy : {0., 1e-3})
  {
    const std::vector<double> all = full_field(solver, mesh, vs[0], accuracy);
    BOOST_TEST(all[1] == 2., boost::test_tools::tolerance(1e-12 + accuracy));
    const std::vector<double> d = target_distances(solver, mesh, vs[0], std::vector<Mesh::Vertex_index>{vs[1]}, accuracy);
    BOOST_TEST(d.at(0) == all[1], "epsilon " << accuracy);
    auto map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
    solver.compute_distances(vs[0], map, DP::max_distance(2.5).accuracy(accuracy));
    BOOST_TEST(get(map, vs[1]) == all[1], "epsilon " << accuracy);
  }
  check_against_full_field(mesh, 11, "arch and bridge");
}

BOOST_AUTO_TEST_CASE(targets_and_max_distance_match_the_full_field_on_blade)
{
  check_against_full_field(make_mesh<Mesh>(read_soup("blade.ply")), 5, "blade.ply", 1);
}

// Point targets: their distances are those of a run that stops only after the farthest vertex,
// i.e. after every window has been propagated.
BOOST_AUTO_TEST_CASE(point_targets_match_a_run_to_the_end)
{
  const Mesh mesh = make_mesh<Mesh>(mixed_edge_lengths(29));
  const Solver solver(mesh);
  const std::vector<Mesh::Vertex_index> vs = vertex_list(mesh);
  const std::vector<Mesh::Face_index> fs(faces(mesh).begin(), faces(mesh).end());
  Random random(29);
  for(double accuracy : {0., 1e-3})
  {
    const Mesh::Vertex_index source = vs[vs.size() / 3];
    const std::vector<double> all = full_field(solver, mesh, source, accuracy);
    const std::size_t farthest = std::size_t(std::max_element(all.begin(), all.end()) - all.begin());
    for(int k = 0; k < 20; ++k)
    {
      const double a = random.uniform(0.05, 0.9), b = random.uniform(0.05, 0.95 - a);
      const Location point(fs[std::size_t(random.uniform() * double(fs.size()))], {a, b, 1. - a - b});
      const std::vector<double> early = target_distances(solver, mesh, source, std::vector<Location>{point}, accuracy);
      auto map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
      std::vector<double> late;
      solver.compute_distances(source, map,
                               DP::target_distances(std::back_inserter(late),
                                                    DP::targets(std::vector<Location>{point, CGAL::Polygon_mesh_processing::locate_vertex<double>(vs[farthest], mesh)}))
                                 .accuracy(accuracy));
      BOOST_TEST(early.at(0) == late.at(0), "point target " << k << ", epsilon " << accuracy);
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()
