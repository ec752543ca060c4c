// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// Inputs the documentation rejects with std::invalid_argument: invalid sources, invalid
// accuracies, faces that are not triangles, non-finite coordinates, degenerate triangles.

#include "test_utilities.h"

#include <stdexcept>

using namespace dggvtp_test;

namespace {

Soup tetrahedron()
{
  Soup soup;
  soup.points = {{0., 0., 0.}, {1., 0., 0.}, {0., 1., 0.}, {0., 0., 1.}};
  soup.faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  return soup;
}

// a unit square as one quad and two triangles beside it
Soup quad_and_triangles()
{
  Soup soup;
  soup.points = {{0., 0., 0.}, {1., 0., 0.}, {1., 1., 0.}, {0., 1., 0.}, {2., 0., 0.}, {2., 1., 0.}};
  soup.faces = {{0, 1, 2, 3}, {1, 4, 5}, {1, 5, 2}};
  return soup;
}

template <class Mesh>
void set_point(Mesh& mesh, std::size_t i, double x, double y, double z)
{
  using Point = typename boost::property_traits<
                  typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type;
  using FT = typename CGAL::Kernel_traits<Point>::Kernel::FT;
  put(get(CGAL::vertex_point, mesh), vertex_list(mesh).at(i), Point(FT(x), FT(y), FT(z)));
}

template <class Mesh>
void require_constructor_throws(const Mesh& mesh)
{
  using Solver = CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh>;
  BOOST_CHECK_THROW(Solver{mesh}, std::invalid_argument);
  auto map = get(CGAL::dynamic_vertex_property_t<typename Solver::FT>(), mesh);
  BOOST_CHECK_THROW(CGAL::DGG_VTP_3::compute_geodesic_distances(mesh, *vertices(mesh).begin(), map),
                    std::invalid_argument);
}

} // namespace

BOOST_AUTO_TEST_SUITE(degenerate_input)

// Surface_mesh: the null vertex, an index past the end, a removed vertex
BOOST_AUTO_TEST_CASE(invalid_source_surface_mesh)
{
  using Mesh = Sm_d::Mesh;
  Mesh mesh = make_mesh<Mesh>(tetrahedron());
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh> solver(mesh);
  auto map = mesh.add_property_map<Mesh::Vertex_index, double>("v:distance", 0.).first;
  BOOST_CHECK_THROW(solver.compute_distances(Mesh::null_vertex(), map), std::invalid_argument);
  BOOST_CHECK_THROW(solver.compute_distances(Mesh::Vertex_index(4), map), std::invalid_argument);
  BOOST_CHECK_THROW(solver.compute_distances(Mesh::Vertex_index(1000), map), std::invalid_argument);
  BOOST_CHECK_THROW(CGAL::DGG_VTP_3::compute_geodesic_distances(mesh, Mesh::null_vertex(), map),
                    std::invalid_argument);
  BOOST_CHECK_THROW(CGAL::DGG_VTP_3::compute_geodesic_distances(mesh, Mesh::Vertex_index(4), map),
                    std::invalid_argument);
  // still usable after the exceptions
  BOOST_CHECK_NO_THROW(solver.compute_distances(Mesh::Vertex_index(0), map));
  BOOST_TEST(map[Mesh::Vertex_index(3)] == 1., boost::test_tools::tolerance(Sm_d::tolerance));
}

// Polyhedron_3: a vertex of another polyhedron
BOOST_AUTO_TEST_CASE(invalid_source_polyhedron)
{
  using Mesh = Ph_d::Mesh;
  const Mesh mesh = make_mesh<Mesh>(tetrahedron());
  const Mesh other = make_mesh<Mesh>(tetrahedron());
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh> solver(mesh);
  auto map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  for(auto v : vertices(other))
    BOOST_CHECK_THROW(solver.compute_distances(v, map), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(invalid_accuracy, Config, All_configurations)
{
  using Mesh = typename Config::Mesh;
  const Mesh mesh = make_mesh<Mesh>(tetrahedron());
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh> solver(mesh);
  auto map = get(CGAL::dynamic_vertex_property_t<typename Config::Kernel::FT>(), mesh);
  const auto v = *vertices(mesh).begin();
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for(double accuracy : {-1e-3, -inf, nan, inf})
  {
    BOOST_CHECK_THROW(solver.compute_distances(v, map, CGAL::parameters::accuracy(accuracy)), std::invalid_argument);
    BOOST_CHECK_THROW(CGAL::DGG_VTP_3::compute_geodesic_distances(mesh, v, map, CGAL::parameters::accuracy(accuracy)),
                      std::invalid_argument);
  }
  // 0 is the exact algorithm, the default
  BOOST_CHECK_NO_THROW(solver.compute_distances(v, map, CGAL::parameters::accuracy(0.)));
}

BOOST_AUTO_TEST_CASE_TEMPLATE(quad_face, Config, All_configurations)
{
  require_constructor_throws(make_mesh<typename Config::Mesh>(quad_and_triangles()));
}

BOOST_AUTO_TEST_CASE_TEMPLATE(non_finite_coordinate, Config, All_configurations)
{
  using Mesh = typename Config::Mesh;
  for(double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
  {
    Mesh mesh = make_mesh<Mesh>(tetrahedron());
    set_point(mesh, 2, 0., bad, 0.);
    require_constructor_throws(mesh);
  }
}

// three collinear corners: zero area, no zero length edge
BOOST_AUTO_TEST_CASE_TEMPLATE(zero_area_triangle, Config, All_configurations)
{
  using Mesh = typename Config::Mesh;
  Soup soup;
  soup.points = {{0., 0., 0.}, {2., 0., 0.}, {1., 0., 0.}, {1., 1., 0.}};
  soup.faces = {{0, 2, 3}, {2, 1, 3}, {0, 1, 2}};  // the last one is flat: 0, 1, 2 are collinear
  require_constructor_throws(make_mesh<Mesh>(soup));
}

// two corners at the same place: a zero length edge
BOOST_AUTO_TEST_CASE_TEMPLATE(zero_length_edge, Config, All_configurations)
{
  using Mesh = typename Config::Mesh;
  Mesh mesh = make_mesh<Mesh>(tetrahedron());
  set_point(mesh, 3, 1., 0., 0.);  // onto vertex 1
  require_constructor_throws(mesh);
}

BOOST_AUTO_TEST_SUITE_END()
