// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// Exactly regular flat grids: every vertex lies on lines from the source through other vertices,
// so the windows on either side of such a vertex meet exactly along a ray of a shortest path, and
// their ends and crossings tie to the last bit in exact arithmetic but not in floating point.
// Rounding there once lost those paths: distances up to 0.14% too long on a 21 x 21 grid, while a
// jittered grid (test_analytic) was right. The truth is the Euclidean distance.

#include "test_utilities.h"

using namespace dggvtp_test;

namespace {

// n x n vertices at integer coordinates in the plane z = 0, vertex (i, j) of index j * n + i,
// each square (a, b, c, d) = ((i, j), (i + 1, j), (i, j + 1), (i + 1, j + 1)) split along the
// diagonal a-d or b-c
Soup grid_soup(std::size_t n, bool diagonal_ad)
{
  Soup soup;
  for(std::size_t j = 0; j < n; ++j)
    for(std::size_t i = 0; i < n; ++i)
      soup.points.push_back({double(i), double(j), 0.});
  for(std::size_t j = 0; j + 1 < n; ++j)
    for(std::size_t i = 0; i + 1 < n; ++i)
    {
      const std::size_t a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      if(diagonal_ad)
      {
        soup.faces.push_back({a, b, d});
        soup.faces.push_back({a, d, c});
      }
      else
      {
        soup.faces.push_back({a, b, c});
        soup.faces.push_back({b, d, c});
      }
    }
  return soup;
}

struct Grid_case
{
  std::size_t n;
  bool diagonal_ad;
};
const Grid_case grids[] = {{21, true}, {21, false}, {30, true}, {30, false}};

// the centre, a corner, an interior vertex off every symmetry axis
std::vector<std::size_t> grid_sources(std::size_t n) { return {(n / 2) * n + n / 2, 0, 7 * n + 3}; }

std::string grid_label(const Grid_case& g, std::size_t source)
{
  return std::to_string(g.n) + " x " + std::to_string(g.n) + " grid, diagonal " + (g.diagonal_ad ? "a-d" : "b-c") +
         ", source " + std::to_string(source);
}

// The lateral surface of a prism over a regular n-gon of side 1, rings of height 1 from 0 to
// `rings` - 1, each square split along a diagonal: a regular grid wrapped around a cylinder, as a
// CAD exporter triangulates one. Vertex (i, j) of index j * n + i.
Soup prism_soup(std::size_t n, std::size_t rings)
{
  Soup soup;
  const double radius = 0.5 / std::sin(CGAL_PI / double(n));
  for(std::size_t j = 0; j < rings; ++j)
    for(std::size_t i = 0; i < n; ++i)
      soup.points.push_back({radius * std::cos(2 * CGAL_PI * double(i) / double(n)),
                             radius * std::sin(2 * CGAL_PI * double(i) / double(n)), double(j)});
  for(std::size_t j = 0; j + 1 < rings; ++j)
    for(std::size_t i = 0; i < n; ++i)
    {
      const std::size_t a = j * n + i, b = j * n + (i + 1) % n, c = a + n, d = b + n;
      soup.faces.push_back({a, b, d});
      soup.faces.push_back({a, d, c});
    }
  return soup;
}

// on the prism, unrolled: the shorter way round
std::vector<double> prism_distances(std::size_t n, std::size_t rings, std::size_t source)
{
  std::vector<double> d(n * rings);
  for(std::size_t v = 0; v < d.size(); ++v)
  {
    const double around = double((v % n + n - source % n) % n);
    const double dz = double(v / n) - double(source / n);
    d[v] = std::sqrt((std::min)(around, double(n) - around) * (std::min)(around, double(n) - around) + dz * dz);
  }
  return d;
}

} // namespace

BOOST_AUTO_TEST_SUITE(regular_grid)

// The same grid wrapped around a prism (as a CAD exporter triangulates a bore): paths along and
// around it through collinear vertices, the unrolled distance the truth. (The generated coupling,
// whose bore lost such a path to a tie rule, is checked against Surface_mesh_shortest_path in
// test/DGG_VTP_3_adversary: this prism alone did not lose it.)
BOOST_AUTO_TEST_CASE_TEMPLATE(prism_exact_distances, Config, Analytic_configurations)
{
  using Mesh = typename Config::Mesh;
  const std::size_t n = 40, rings = 16;
  const Mesh mesh = make_mesh<Mesh>(prism_soup(n, rings));
  for(std::size_t s : {std::size_t(0), 7 * n + 3})
    check_distances(geodesic_distances(mesh, s), prism_distances(n, rings, s), s, Config::tolerance,
                    "prism, source " + std::to_string(s) + ", " + config_name<Config>());
}

BOOST_AUTO_TEST_CASE_TEMPLATE(exact_distances, Config, Analytic_configurations)
{
  using Mesh = typename Config::Mesh;
  for(const Grid_case& g : grids)
  {
    const Mesh mesh = make_mesh<Mesh>(grid_soup(g.n, g.diagonal_ad));
    for(std::size_t s : grid_sources(g.n))
      check_distances(geodesic_distances(mesh, s), euclidean_distances(mesh, s), s, Config::tolerance,
                      grid_label(g, s) + ", " + config_name<Config>());
  }
}

// DGG-VTP's contract: within epsilon above the truth, never below it beyond rounding
BOOST_AUTO_TEST_CASE(accuracy_contract)
{
  using Mesh = Sm_d::Mesh;
  for(const Grid_case& g : grids)
  {
    const Mesh mesh = make_mesh<Mesh>(grid_soup(g.n, g.diagonal_ad));
    for(std::size_t s : grid_sources(g.n))
    {
      const std::vector<double> truth = euclidean_distances(mesh, s);
      for(double epsilon : {1e-3, 1e-6})
      {
        const std::vector<double> d = geodesic_distances(mesh, s, nullptr, CGAL::parameters::accuracy(epsilon));
        double above = 0., below = 0.;
        std::size_t outside = 0; // written so that a NaN counts
        for(std::size_t i = 0; i < d.size(); ++i)
          if(i != s)
          {
            const double e = (d[i] - truth[i]) / truth[i];
            above = (std::max)(above, e);
            below = (std::min)(below, e);
            outside += !(e <= epsilon && e >= -1e-12);
          }
        const std::string label = grid_label(g, s) + ", epsilon " + std::to_string(epsilon);
        BOOST_TEST_MESSAGE(label << ": max relative error " << above << ", min " << below);
        BOOST_TEST(outside == 0u, label << ": " << outside << " vertices outside [-1e-12, epsilon] (or NaN); max "
                                        << above << ", min " << below);
        BOOST_TEST(d[s] == 0.);
      }
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()
