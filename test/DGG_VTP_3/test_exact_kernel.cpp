// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// The exact mode in exact arithmetic (issue 19): a Surface_mesh over CGAL's exact kernel with
// square roots (CORE::Expr), on tiny meshes whose truth is known in closed form. No rounding margin
// is left (Number_type_math::machine_epsilon() is 0), so the propagation decides every tie and
// every flat vertex exactly; where the truth is algebraic, squares of distances are compared
// with `==` in the exact type. Exact square-root arithmetic is slow: deciding a tie (and windows
// whose edges end at vertices make many) costs more with each square root the compared numbers
// carry, so these meshes have 6 to 8 faces (measured: a regular tetrahedron, 4 faces but windows
// that come round, takes 46 s per source; a 3 x 3 grid of 18 faces 47 s).

#include "test_utilities.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel_with_sqrt.h>

#include <chrono>

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

// the budget for one run
void check_time(double seconds, const std::string& what)
{
  BOOST_TEST_MESSAGE(what << ": " << seconds << " s");
  BOOST_TEST(seconds <= 60., what << " took " << seconds << " s");
}

} // namespace

BOOST_AUTO_TEST_SUITE(exact_kernel)

// 3 x 3 integer points in the plane z = 0, random diagonals: the geodesic distance is the
// Euclidean one, so its square is an integer, exactly. The middle vertex is flat (angle sum 2 pi
// exactly): no pseudo-source in exact arithmetic, while double leans towards saddles there.
BOOST_AUTO_TEST_CASE(flat_patch_squares_are_exact)
{
  const Soup soup = flat_patch(2, 2, 1., 1., 0., 20260119, Rigid_motion({0., 0., 1.}, 0., {0., 0., 0.}));
  const Exact_mesh mesh = make_mesh<Exact_mesh>(soup);
  for(std::size_t s : {std::size_t(4), std::size_t(0)}) // the middle, a corner
  {
    double seconds = 0.;
    CGAL::DGG_VTP_3::Propagation_statistics exact, in_double;
    const std::vector<FT> d = exact_distances(mesh, s, seconds, &exact);
    check_time(seconds, "flat patch, source " + std::to_string(s));
    const auto& p = soup.points[s];
    for(std::size_t i = 0; i < d.size(); ++i)
    {
      const auto& q = soup.points[i];
      const double square = (q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]);
      BOOST_TEST((d[i] * d[i] == FT(square)), "source " << s << ", vertex " << i << ": " << CGAL::to_double(d[i])
                                                        << " squared is not " << square);
    }
    geodesic_distances(make_mesh<Sm_d::Mesh>(soup), s, &in_double);
    // from the middle it is the source (a pseudo-source either way); from a corner it is reached
    BOOST_TEST(exact.pseudo_sources + (s == 4 ? 0 : 1) == in_double.pseudo_sources);
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
  check_time(seconds, "moved flat patch");
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
  check_time(seconds, "prism, source " + std::to_string(s));
  check_distances(d, prism.distances(s), s, 1e-14, "prism, exact kernel, source " + std::to_string(s));
}

BOOST_AUTO_TEST_SUITE_END()
