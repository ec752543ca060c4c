// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// The exact mode in exact arithmetic (issue 19): a Surface_mesh over CGAL's exact kernel with
// square roots (CORE::Expr), on small meshes whose truth is known in closed form. No rounding
// margin is left (Number_type_math::machine_epsilon() is 0), so the propagation decides every tie
// and every flat vertex exactly; where the truth is algebraic, squares of distances are compared
// with `==` in the exact type.
//
// What exact square-root arithmetic costs: CORE proves a tie (two windows meeting at a vertex, an
// angle sum of exactly 2 pi) by evaluating to a separation bound whose size doubles with each
// distinct square root in the compared numbers. The preparation keeps them few (one root per
// distinct squared length or area, none for a perfect square; angle sums with the face areas as
// their only roots), so meshes of few distinct lengths (integer grids, a subdivided regular
// tetrahedron, a square prism) of a few dozen faces take 0.01-8 s per source. Generic coordinates
// bring a root per edge: a jittered 3 x 3 grid of 18 faces takes 20 s to minutes, a 4 x 4 one moved
// by a rigid motion over 100 s (benchmark/DGG_VTP_3/README.md, "Exact kernel"); those tests stay
// small (6 and 8 faces).

#include "test_utilities.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel_with_sqrt.h>

#include <chrono>
#include <map>

using namespace dggvtp_test;

namespace {

using Exact_kernel = CGAL::Exact_predicates_exact_constructions_kernel_with_sqrt;
using Exact_mesh = CGAL::Surface_mesh<Exact_kernel::Point_3>;
using FT = Exact_kernel::FT;

// exact distances from the i-th vertex, with the time they took
std::vector<FT> exact_distances(const Exact_mesh& mesh, std::size_t source_index, double& seconds,
                                CGAL::DGG_VTP_3::Propagation_statistics* statistics = nullptr)
{
  auto map = get(CGAL::dynamic_vertex_property_t<FT>(), mesh);
  const auto start = std::chrono::steady_clock::now();
  const auto s = CGAL::DGG_VTP_3::compute_geodesic_distances(mesh, map, vertex_list(mesh).at(source_index));
  if(statistics)
    *statistics = s;
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::vector<FT> d;
  for(auto v : vertices(mesh))
    d.push_back(get(map, v));
  return d;
}

std::vector<double> to_doubles(const std::vector<FT>& d)
{
  std::vector<double> r;
  for(const FT& x : d)
    r.push_back(CGAL::to_double(x));
  return r;
}

// the squares of the distances from the source are `squares` exactly
void check_squares(const std::vector<FT>& d, const std::vector<double>& squares, const std::string& what)
{
  BOOST_TEST_REQUIRE(d.size() == squares.size());
  for(std::size_t i = 0; i < d.size(); ++i)
    BOOST_TEST((d[i] * d[i] == FT(squares[i])),
               what << ", vertex " << i << ": " << CGAL::to_double(d[i]) << " squared is not " << squares[i]);
}

// the time of one run, for the log: a test must not fail on a slow or loaded machine (sanitizers)
void report_time(double seconds, const std::string& what)
{
  BOOST_TEST_MESSAGE(what << ": " << seconds << " s");
}

} // namespace

BOOST_AUTO_TEST_SUITE(exact_kernel)

// 5 x 5 integer points in the plane z = 0 (32 faces), random diagonals: the geodesic distance is
// the Euclidean one, so its square is an integer, exactly. The 9 interior vertices are flat (angle
// sum 2 pi exactly): no pseudo-source in exact arithmetic, while double leans towards saddles there.
BOOST_AUTO_TEST_CASE(flat_patch_squares_are_exact)
{
  const Soup soup = flat_patch(4, 4, 1., 1., 0., 20260119, Rigid_motion({0., 0., 1.}, 0., {0., 0., 0.}));
  const Exact_mesh mesh = make_mesh<Exact_mesh>(soup);
  BOOST_TEST_REQUIRE(num_faces(mesh) == 32u);
  for(std::size_t s : {std::size_t(12), std::size_t(0), std::size_t(7)}) // the middle, a corner, a border vertex
  {
    double seconds = 0.;
    CGAL::DGG_VTP_3::Propagation_statistics exact, in_double;
    const std::vector<FT> d = exact_distances(mesh, s, seconds, &exact);
    report_time(seconds, "flat patch, source " + std::to_string(s));
    const auto& p = soup.points[s];
    std::vector<double> squares;
    for(const auto& q : soup.points)
      squares.push_back((q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]));
    check_squares(d, squares, "flat patch, source " + std::to_string(s));
    geodesic_distances(make_mesh<Sm_d::Mesh>(soup), s, &in_double);
    // in exact arithmetic the pseudo-sources are the 16 border vertices and the source (one of
    // them emitting twice, at most: a later window may shorten it); in double every interior
    // vertex is one too
    BOOST_TEST(exact.pseudo_sources <= 17u, "source " << s << ": " << exact.pseudo_sources << " exactly");
    BOOST_TEST(in_double.pseudo_sources >= exact.pseudo_sources + 8,
               "source " << s << ": " << exact.pseudo_sources << " exactly, " << in_double.pseudo_sources << " in double");
  }
}

// Without infinity in the type, an unreached vertex gets the largest double
BOOST_AUTO_TEST_CASE(unreached_is_largest_double)
{
  Soup soup;
  soup.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}};
  soup.faces = {{0, 1, 2}, {3, 4, 5}};
  const Exact_mesh mesh = make_mesh<Exact_mesh>(soup);
  double seconds = 0.;
  const std::vector<FT> d = exact_distances(mesh, 0, seconds);
  BOOST_TEST((d[1] == FT(1)));
  BOOST_TEST((d[2] == FT(1)));
  for(std::size_t i = 3; i < 6; ++i)
    BOOST_TEST((d[i] == FT((std::numeric_limits<double>::max)())));
  BOOST_TEST((CGAL::DGG_VTP_3::internal::Number_type_math<FT>::machine_epsilon() == FT(0)));
}

// The same patch moved by a rigid motion (irrational coordinates after rounding to double):
// within 1e-14 of the Euclidean distances computed in double.
BOOST_AUTO_TEST_CASE(flat_patch_moved)
{
  const Soup soup = flat_patch(2, 2, 0.5, 0.5, 0.1, 20260120, Rigid_motion({1., 2., 3.}, 0.7, {0.3, -1.2, 2.5}));
  const Exact_mesh mesh = make_mesh<Exact_mesh>(soup);
  double seconds = 0.;
  const std::vector<double> d = to_doubles(exact_distances(mesh, 3, seconds));
  report_time(seconds, "moved flat patch");
  check_distances(d, euclidean_distances(mesh, 3), 3, 1e-14, "moved flat patch, exact kernel");
}

// The lateral surface of a triangular prism (6 faces), unrolled: within 1e-14 of the closed form
BOOST_AUTO_TEST_CASE(prism_lateral_surface)
{
  const Prism prism = dggvtp_test::prism_lateral_surface(3, 1, 2, 1.5, 20260121);
  const Exact_mesh mesh = make_mesh<Exact_mesh>(prism.soup);
  BOOST_TEST_REQUIRE(num_faces(mesh) == 6u);
  const std::size_t s = prism.per_ring + 1;
  double seconds = 0.;
  const std::vector<double> d = to_doubles(exact_distances(mesh, s, seconds));
  report_time(seconds, "prism, source " + std::to_string(s));
  check_distances(d, prism.distances(s), s, 1e-14, "prism, exact kernel, source " + std::to_string(s));
}

// A regular tetrahedron with each face cut in 4 (16 faces, 10 vertices), from a corner of it: every
// vertex is on a face through the source, so the geodesic distance is the Euclidean one, whose
// square is an integer or a half-integer here. Windows go round the whole surface and meet at the
// far corners in exact ties.
BOOST_AUTO_TEST_CASE(subdivided_tetrahedron)
{
  Soup soup;
  soup.points = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> middle_of;
  const auto middle = [&](std::size_t a, std::size_t b) {
    const auto key = std::minmax(a, b);
    if(!middle_of.count(key))
    {
      const auto &p = soup.points[a], &q = soup.points[b];
      middle_of[key] = soup.points.size();
      soup.points.push_back({(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2});
    }
    return middle_of[key];
  };
  for(const auto& f : std::vector<std::array<std::size_t, 3>>{{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}})
  {
    const std::size_t a = f[0], b = f[1], c = f[2], ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
    soup.faces.insert(soup.faces.end(), {{a, ab, ca}, {ab, b, bc}, {ca, bc, c}, {ab, bc, ca}});
  }
  const Exact_mesh mesh = make_mesh<Exact_mesh>(soup);
  BOOST_TEST_REQUIRE(num_faces(mesh) == 16u);
  double seconds = 0.;
  const std::vector<FT> d = exact_distances(mesh, 0, seconds);
  report_time(seconds, "subdivided tetrahedron");
  std::vector<double> squares;
  for(const auto& q : soup.points)
    squares.push_back((q[0] - 1) * (q[0] - 1) + (q[1] - 1) * (q[1] - 1) + (q[2] - 1) * (q[2] - 1));
  check_squares(d, squares, "subdivided tetrahedron");
}

// The lateral surface of the unit square prism, 2 segments per side and 3 rings (32 faces),
// unrolled: a strip of circumference 4 where the square of every distance is a multiple of 1/4,
// exactly; among them paths that cross the seam and that bend over the prism's edges.
BOOST_AUTO_TEST_CASE(square_prism_squares_are_exact)
{
  Prism prism;
  prism.per_ring = 8;
  prism.perimeter = 4.;
  const double corner_x[5] = {0., 1., 1., 0., 0.}, corner_y[5] = {0., 0., 1., 1., 0.};
  for(int ring = 0; ring < 3; ++ring)
    for(int side = 0; side < 4; ++side)
      for(int k = 0; k < 2; ++k)
      {
        const double t = 0.5 * k;
        prism.soup.points.push_back({corner_x[side] + t * (corner_x[side + 1] - corner_x[side]),
                                     corner_y[side] + t * (corner_y[side + 1] - corner_y[side]), double(ring)});
        prism.arc.push_back(side + t);
        prism.height.push_back(ring);
      }
  Random random(20260122);
  for(std::size_t ring = 0; ring < 2; ++ring)
    for(std::size_t k = 0; k < 8; ++k)
    {
      const std::size_t a = 8 * ring + k, b = 8 * ring + (k + 1) % 8, c = b + 8, e = a + 8;
      if(random.coin())
        prism.soup.faces.insert(prism.soup.faces.end(), {{a, b, c}, {a, c, e}});
      else
        prism.soup.faces.insert(prism.soup.faces.end(), {{a, b, e}, {b, c, e}});
    }
  const Exact_mesh mesh = make_mesh<Exact_mesh>(prism.soup);
  BOOST_TEST_REQUIRE(num_faces(mesh) == 32u);
  const std::size_t s = 1; // the middle of a side, on the bottom border
  BOOST_TEST_REQUIRE(prism.wrapped(s) > 0u);
  double seconds = 0.;
  const std::vector<FT> d = exact_distances(mesh, s, seconds);
  report_time(seconds, "square prism");
  std::vector<double> squares; // multiples of 1/4 below 17: exact in double
  for(std::size_t i = 0; i < prism.arc.size(); ++i)
  {
    const double ds = std::abs(prism.arc[i] - prism.arc[s]), dh = prism.height[i] - prism.height[s];
    const double across = (std::min)(ds, prism.perimeter - ds);
    squares.push_back(across * across + dh * dh);
  }
  check_squares(d, squares, "square prism");
}

BOOST_AUTO_TEST_SUITE_END()
