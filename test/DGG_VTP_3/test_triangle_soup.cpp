// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// Triangle_soup_geodesic_distance_solver: the same distances, bit for bit, and the same
// propagation as the solver of the Surface_mesh made from the soup (with the corners in the same
// order); its own input checks (indices,
// triangles, orientation, edges of more than two triangles) and the common ones; pinched vertices
// kept and counted.

#include "test_utilities.h"

#include <CGAL/DGG_VTP_3/Triangle_soup_geodesic_distance_solver.h>

#include <cstring>
#include <stdexcept>

using namespace dggvtp_test;

namespace {

template <class Kernel>
std::vector<typename Kernel::Point_3> kernel_points(const Soup& soup)
{
  using FT = typename Kernel::FT;
  std::vector<typename Kernel::Point_3> points;
  for(const auto& p : soup.points)
    points.emplace_back(FT(p[0]), FT(p[1]), FT(p[2]));
  return points;
}

template <class Kernel>
void check_same_as_surface_mesh(const std::string& name, std::size_t source, double accuracy)
{
  using Mesh = CGAL::Surface_mesh<typename Kernel::Point_3>;
  using FT = typename Kernel::FT;
  const Soup soup = read_soup(name);
  const Mesh mesh = make_mesh<Mesh>(soup);
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh> mesh_solver(mesh);
  auto mesh_map = get(CGAL::dynamic_vertex_property_t<FT>(), mesh);
  const auto mesh_statistics =
    mesh_solver.compute_distances(vertex_list(mesh).at(source), mesh_map, CGAL::parameters::accuracy(accuracy));

  // Surface_mesh's halfedge(f) starts at the third vertex of the polygon it was made from
  std::vector<std::array<std::size_t, 3>> rotated;
  for(const auto& t : soup.faces)
    rotated.push_back({t[2], t[0], t[1]});
  const CGAL::DGG_VTP_3::Triangle_soup_geodesic_distance_solver<Kernel> soup_solver(kernel_points<Kernel>(soup),
                                                                                   rotated);
  std::vector<FT> d(soup.points.size());
  const auto soup_statistics =
    soup_solver.compute_distances(source, CGAL::make_property_map(d), CGAL::parameters::accuracy(accuracy));

  BOOST_TEST_CONTEXT(name << " source " << source << " accuracy " << accuracy)
  {
    BOOST_CHECK_EQUAL(soup_statistics.windows_created, mesh_statistics.windows_created);
    BOOST_CHECK_EQUAL(soup_statistics.vertices_reached, mesh_statistics.vertices_reached);
    std::size_t differ = 0, i = 0;
    for(auto v : vertices(mesh))
    {
      const FT a = get(mesh_map, v), b = d[i++];
      differ += std::memcmp(&a, &b, sizeof(FT)) != 0; // bits: == would take -0 for 0 and miss a NaN
    }
    BOOST_CHECK_EQUAL(differ, 0u);
  }
}

Soup two_triangles()
{
  Soup soup;
  soup.points = {{0., 0., 0.}, {1., 0., 0.}, {0., 1., 0.}, {1., 1., 0.}};
  soup.faces = {{0, 1, 2}, {2, 1, 3}};
  return soup;
}

template <class Faces>
void require_refused(const Soup& soup, const Faces& faces, const std::string& words)
{
  try
  {
    CGAL::DGG_VTP_3::Triangle_soup_geodesic_distance_solver<Epick> solver(kernel_points<Epick>(soup), faces);
    BOOST_ERROR("accepted, expected: " << words);
  }
  catch(const std::invalid_argument& e)
  {
    BOOST_CHECK_MESSAGE(std::string(e.what()).find(words) != std::string::npos, e.what());
  }
}

} // namespace

BOOST_AUTO_TEST_SUITE(triangle_soup)

BOOST_AUTO_TEST_CASE(same_bits_as_the_surface_mesh_solver)
{
  for(const char* name : {"spot.ply", "pinion.ply"})
    for(double accuracy : {0., 1e-4})
    {
      check_same_as_surface_mesh<Epick>(name, 0, accuracy);
      check_same_as_surface_mesh<CGAL::Simple_cartesian<float>>(name, 17, accuracy);
    }
}

BOOST_AUTO_TEST_CASE(flat_square_and_surface_point_source)
{
  const Soup soup = two_triangles();
  const CGAL::DGG_VTP_3::Triangle_soup_geodesic_distance_solver<Epick> solver(kernel_points<Epick>(soup), soup.faces);
  std::vector<double> d(4);
  solver.compute_distances(std::size_t(0), CGAL::make_property_map(d));
  BOOST_CHECK_EQUAL(d[0], 0.);
  BOOST_CHECK_CLOSE(d[3], std::sqrt(2.), 1e-12);
  // the centre of the square: on the shared edge, halfway
  const std::pair<std::size_t, std::array<double, 3>> centre(0, {0., 0.5, 0.5});
  solver.compute_distances(centre, CGAL::make_property_map(d));
  for(double x : d)
    BOOST_CHECK_CLOSE(x, std::sqrt(0.5), 1e-12);
}

BOOST_AUTO_TEST_CASE(refused_soups)
{
  Soup soup = two_triangles();
  require_refused(soup, std::vector<std::vector<std::size_t>>{{0, 1, 2}, {2, 1, 4}}, "refers to vertex 4");
  require_refused(soup, std::vector<std::vector<int>>{{0, 1, 2}, {2, 1, -1}}, "refers to vertex -1");
  require_refused(soup, std::vector<std::vector<std::size_t>>{{0, 1, 2, 3}}, "not a triangle");
  require_refused(soup, std::vector<std::vector<std::size_t>>{{0, 1}}, "not a triangle");
  require_refused(soup, std::vector<std::vector<std::size_t>>{{0, 1, 2}, {1, 2, 3}}, "orientations disagree");
  soup.points.push_back({1., -1., 0.5});
  require_refused(soup, std::vector<std::vector<std::size_t>>{{0, 1, 2}, {2, 1, 3}, {1, 2, 4}}, "both go from");
  soup.points[3][1] = std::nan("");
  require_refused(soup, std::vector<std::array<std::size_t, 3>>{{{0, 1, 2}}, {{2, 1, 3}}}, "not finite");
  soup.points[3] = {0.5, 0.5, 0.};
  require_refused(soup, std::vector<std::array<std::size_t, 3>>{{{0, 1, 2}}, {{2, 1, 3}}}, "degenerate");
  // coordinates that a double holds but whose squares or spans overflow (the fuzzer's NaN cell)
  Soup huge = two_triangles();
  for(auto& p : huge.points)
    for(double& x : p)
      x *= 1e200;
  require_refused(huge, huge.faces, "too large for the number type");
  huge.points = {{-1.7e308, 0., 0.}, {-1.7e308, 1e300, 0.}, {-1.7e308, 0., 1e300},
                 {1.7e308, 0., 0.},  {1.7e308, 1e300, 0.},  {1.7e308, 0., 1e300}};
  require_refused(huge, std::vector<std::array<std::size_t, 3>>{{{0, 1, 2}}, {{3, 4, 5}}},
                  "span more than the largest finite double");
}

BOOST_AUTO_TEST_CASE(pinched_vertex_is_kept)
{
  // two triangles touching at vertex 0 only, and a point no triangle uses
  Soup soup;
  soup.points = {{0., 0., 0.}, {1., 0., 0.}, {0., 1., 0.}, {-1., 0., 0.}, {0., -1., 0.}, {5., 5., 5.}};
  soup.faces = {{0, 1, 2}, {0, 3, 4}};
  const CGAL::DGG_VTP_3::Triangle_soup_geodesic_distance_solver<Epick> solver(kernel_points<Epick>(soup), soup.faces);
  BOOST_CHECK_EQUAL(solver.number_of_non_manifold_vertices(), 1u);
  std::vector<double> d(6);
  solver.compute_distances(std::size_t(1), CGAL::make_property_map(d));
  BOOST_CHECK_CLOSE(d[3], 2., 1e-12);
  BOOST_CHECK_CLOSE(d[4], 1. + std::sqrt(1.), 1e-12);
  BOOST_CHECK(std::isinf(d[5]));
}

BOOST_AUTO_TEST_SUITE_END()
