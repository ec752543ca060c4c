// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// Analytic truth: flat patches (geodesic = Euclidean distance) and the lateral surface of a
// prism (a flat cylinder: distance by unrolling, the shorter way around).

#include "test_utilities.h"

using namespace dggvtp_test;

namespace {

const Rigid_motion skew_motion({1., 2., 3.}, 0.7, {0.3, -1.2, 2.5});

template <class Config>
void check_flat_patch(const Soup& soup, std::size_t source_index, const std::string& what)
{
  using Mesh = typename Config::Mesh;
  const Mesh mesh = make_mesh<Mesh>(soup);
  CGAL::DGG_VTP_3::Propagation_statistics statistics;
  const std::vector<double> d = geodesic_distances(mesh, source_index, &statistics);
  check_distances(d, euclidean_distances(mesh, source_index), source_index, Config::tolerance,
                  what + " " + config_name<Config>() + ", source " + std::to_string(source_index));
  BOOST_TEST(statistics.vertices_reached == num_vertices(mesh));
  BOOST_TEST(statistics.pseudo_sources >= 1u);
  BOOST_TEST(statistics.windows_peak <= statistics.windows_created);
}

// 21 x 21 points, jittered, random diagonals, in the unit square
Soup jittered_square() { return flat_patch(20, 20, 0.05, 0.05, 0.15, 20260101, skew_motion); }

// 101 x 6 points, cells 0.01 x 1 (aspect ratio 1:100), interior points jittered along x
Soup skinny_strip() { return flat_patch(100, 5, 0.01, 1., 0.3, 20260102, skew_motion); }

} // namespace

BOOST_AUTO_TEST_SUITE(analytic)

BOOST_AUTO_TEST_CASE_TEMPLATE(flat_patch_interior_source, Config, Analytic_configurations)
{
  const Soup soup = jittered_square();
  check_flat_patch<Config>(soup, 10 * 21 + 10, "flat patch");  // the centre
  check_flat_patch<Config>(soup, 4 * 21 + 15, "flat patch");   // off centre
}

BOOST_AUTO_TEST_CASE_TEMPLATE(flat_patch_boundary_source, Config, Analytic_configurations)
{
  const Soup soup = jittered_square();
  check_flat_patch<Config>(soup, 7, "flat patch");             // on the border y = 0
  check_flat_patch<Config>(soup, 20 * 21 + 20, "flat patch");  // a corner
}

// In float this case is at the edge of the configuration's tolerance: the relative error of an
// unfolded triangle's height is about (float epsilon) x (aspect ratio). Measured: 1.15e-5 with
// the triangles unfolded in float (fails), 6.9e-6 when the constructor unfolds them in double.
BOOST_AUTO_TEST_CASE_TEMPLATE(skinny_triangles, Config, Analytic_configurations)
{
  const Soup soup = skinny_strip();
  check_flat_patch<Config>(soup, 2 * 101 + 37, "skinny strip");  // interior
  check_flat_patch<Config>(soup, 101 + 100, "skinny strip");     // on the border x = 1
  check_flat_patch<Config>(soup, 0, "skinny strip");             // a corner
}

BOOST_AUTO_TEST_CASE_TEMPLATE(prism_lateral_surface, Config, Analytic_configurations)
{
  using Mesh = typename Config::Mesh;
  // 7 sides cut in 4, 13 rings over a height of 3 (about half the perimeter), so that many
  // shortest paths wrap around the seam of the unrolled strip
  const Prism prism = dggvtp_test::prism_lateral_surface(7, 4, 13, 3., 20260103);
  const Mesh mesh = make_mesh<Mesh>(prism.soup);
  BOOST_TEST_MESSAGE("prism: " << num_vertices(mesh) << " vertices, perimeter " << prism.perimeter);
  const std::size_t n = prism.per_ring;
  const std::size_t sources[] = {6 * n + 0,    // interior, on a vertical edge of the prism
                                 5 * n + 17,   // interior, inside a side
                                 0 * n + 9,    // bottom border
                                 12 * n + 4};  // top border, on a vertical edge
  for(std::size_t s : sources)
  {
    BOOST_TEST(prism.wrapped(s) > 0u);  // the test covers paths across the seam
    const std::vector<double> d = geodesic_distances(mesh, s);
    check_distances(d, prism.distances(s), s, Config::tolerance,
                    "prism " + config_name<Config>() + ", source " + std::to_string(s));
  }
}

BOOST_AUTO_TEST_SUITE_END()
