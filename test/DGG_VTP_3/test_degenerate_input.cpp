// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// Inputs the documentation rejects with std::invalid_argument: invalid sources, invalid
// accuracies, faces that are not triangles, non-finite coordinates, degenerate triangles,
// coordinates whose squares overflow, slivers and cones so thin that windows would wrap around
// them for hours. And inputs it accepts however hostile they look (needles,
// caps, 1e12 and 1e-12 scales, borders, pinched vertices, meshes without faces): finite
// distances, never a NaN, in both modes (guards against the crashes and NaNs of the MMP-derived
// codes on scanned meshes: libigl / geometry-central / pygeodesic / tvb-gdist
// `p->start() < p->stop()`, CGAL Surface_mesh_shortest_path on an isolated vertex).

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
  BOOST_CHECK_THROW(CGAL::DGG_VTP_3::compute_geodesic_distances(mesh, map, *vertices(mesh).begin()),
                    std::invalid_argument);
}


// distances from the i-th vertex, exact (accuracy 0) or DGG-VTP; every one checked not NaN
template <class Mesh>
std::vector<double> checked_distances(const Mesh& mesh, std::size_t source_index, double accuracy)
{
  const std::vector<double> d =
    geodesic_distances(mesh, source_index, nullptr, CGAL::parameters::accuracy(accuracy));
  for(std::size_t i = 0; i < d.size(); ++i)
    BOOST_TEST(!std::isnan(d[i]), "vertex " << i << " (accuracy " << accuracy << ") is NaN");
  return d;
}

// both modes against `truth` (inf where unreachable), to `tolerance` relative, plus epsilon for
// DGG-VTP
template <class Mesh>
void check_both_modes(const Mesh& mesh, std::size_t source_index, const std::vector<double>& truth,
                      double tolerance)
{
  for(double accuracy : {0., 1e-4})
  {
    const std::vector<double> d = checked_distances(mesh, source_index, accuracy);
    BOOST_REQUIRE_EQUAL(d.size(), truth.size());
    for(std::size_t i = 0; i < d.size(); ++i)
    {
      if(std::isinf(truth[i]))
        BOOST_TEST(std::isinf(d[i]), "vertex " << i << ": " << d[i] << ", expected inf");
      else
        BOOST_TEST(std::abs(d[i] - truth[i]) <= (tolerance + accuracy) * truth[i] + 1e-300,
                   "vertex " << i << " (accuracy " << accuracy << "): " << d[i] << ", expected " << truth[i]);
    }
  }
}

Soup scaled(Soup soup, double factor)
{
  for(auto& p : soup.points)
    for(double& c : p)
      c *= factor;
  return soup;
}

// an L-shaped flat mesh: the unit squares [0,2]x[0,1] and [0,1]x[1,2], with the reflex border
// corner 4 at (1, 1)
Soup l_shape()
{
  Soup soup;
  soup.points = {{0., 0., 0.}, {1., 0., 0.}, {2., 0., 0.}, {0., 1., 0.}, {1., 1., 0.}, {2., 1., 0.},
                 {0., 2., 0.}, {1., 2., 0.}};
  soup.faces = {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}, {3, 4, 7}, {3, 7, 6}};
  return soup;
}

// a cone 1 high over a triangle of circumradius r (apex angle about 3 sqrt(3) r), closed by a fan
// at the centre of its base
Soup cone(double r)
{
  Soup soup;
  const double h = r * std::sqrt(3.) / 2.;
  soup.points = {{0., 0., 1.}, {r, 0., 0.}, {-r / 2., h, 0.}, {-r / 2., -h, 0.}, {0., 0., 0.}};
  soup.faces = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {4, 2, 1}, {4, 3, 2}, {4, 1, 3}};
  return soup;
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
  BOOST_CHECK_THROW(CGAL::DGG_VTP_3::compute_geodesic_distances(mesh, map, Mesh::null_vertex()),
                    std::invalid_argument);
  BOOST_CHECK_THROW(CGAL::DGG_VTP_3::compute_geodesic_distances(mesh, map, Mesh::Vertex_index(4)),
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
  // above maximal_accuracy (1) the fans wrapped around and lost vertices (issue 31: spot at 10)
  for(double accuracy : {-1e-3, -inf, nan, inf, 1.0000001, 4.5, 10., 50.})
  {
    BOOST_CHECK_THROW(solver.compute_distances(v, map, CGAL::parameters::accuracy(accuracy)), std::invalid_argument);
    BOOST_CHECK_THROW(CGAL::DGG_VTP_3::compute_geodesic_distances(mesh, map, v, CGAL::parameters::accuracy(accuracy)),
                      std::invalid_argument);
  }
  // the message names the named parameter and gives the value as given, not std::to_string's -0.000000
  try
  {
    solver.compute_distances(v, map, CGAL::parameters::accuracy(-1e-9));
    BOOST_ERROR("accuracy -1e-9 accepted");
  }
  catch(const std::invalid_argument& e)
  {
    const std::string what = e.what();
    BOOST_TEST(what.find("accuracy") != std::string::npos, what);
    BOOST_TEST(what.find("[0, 1]") != std::string::npos, what);
    BOOST_TEST(what.find("-1e-09") != std::string::npos, what);
  }
  // 0 is the exact algorithm, the default; 1 the largest accuracy supported
  BOOST_CHECK_NO_THROW(solver.compute_distances(v, map, CGAL::parameters::accuracy(0.)));
  BOOST_CHECK_NO_THROW(solver.compute_distances(v, map, CGAL::parameters::accuracy(CGAL::DGG_VTP_3::maximal_accuracy)));
}

// faces and vertices are numbered in 32 bits (3 per face for the halfedges): a mesh beyond that
// is refused with a message, not numbered modulo 2^32 (such a mesh needs ~100 GB, so the check is
// called with the sizes alone)
BOOST_AUTO_TEST_CASE(too_many_faces_for_32_bit_indices)
{
  using CGAL::DGG_VTP_3::internal::check_index_range;
  const std::size_t most = (std::size_t(1) << 32) / 3 - 1; // (2^32 - 1) / 3 - 1
  BOOST_CHECK_NO_THROW(check_index_range<double>(most, most));
  BOOST_CHECK_THROW(check_index_range<double>(3, most + 1), std::invalid_argument);
  BOOST_CHECK_THROW(check_index_range<double>(most + 1, 3), std::invalid_argument);
  BOOST_CHECK_THROW(check_index_range<double>(3, std::size_t(1) << 33), std::invalid_argument);
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

// |x| = 1e200: the squared edge lengths overflow (in float the coordinates themselves do)
BOOST_AUTO_TEST_CASE_TEMPLATE(coordinates_too_large_to_square, Config, All_configurations)
{
  require_constructor_throws(make_mesh<typename Config::Mesh>(scaled(tetrahedron(), 1e200)));
}

// the unit tetrahedron scaled by 1e12 and by 1e-12: the distances scale with it
BOOST_AUTO_TEST_CASE_TEMPLATE(huge_and_tiny_coordinates, Config, All_configurations)
{
  const double s2 = std::sqrt(2.);
  for(double factor : {1e12, 1e-12})
  {
    BOOST_TEST_MESSAGE("scale " << factor);
    const auto mesh = make_mesh<typename Config::Mesh>(scaled(tetrahedron(), factor));
    check_both_modes(mesh, 0, {0., factor, factor, factor}, Config::tolerance);
    check_both_modes(mesh, 1, {factor, 0., s2 * factor, s2 * factor}, Config::tolerance);
  }
}

// A needle (edges 1, 1 and 1e-9) and a cap (an angle of pi - 2e-9) in flat meshes, crossed by
// the paths: Euclidean distances, to the accuracy the sliver's conditioning allows.
BOOST_AUTO_TEST_CASE_TEMPLATE(needle_triangle, Config, All_configurations)
{
  Soup soup;
  soup.points = {{0., 0., 0.}, {1., 0., 0.}, {1., 1e-9, 0.}, {0., 1., 0.}, {1., 1., 0.}};
  soup.faces = {{0, 1, 2}, {0, 2, 4}, {0, 4, 3}};
  const auto mesh = make_mesh<typename Config::Mesh>(soup);
  check_both_modes(mesh, 3, euclidean_distances(mesh, 3), 1e-6);
  check_both_modes(mesh, 2, euclidean_distances(mesh, 2), 1e-6);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(cap_triangle, Config, All_configurations)
{
  Soup soup;
  soup.points = {{0., 0., 0.}, {2., 0., 0.}, {1., 1e-9, 0.}, {1., 1., 0.}, {1., -1., 0.}};
  soup.faces = {{0, 1, 2}, {0, 2, 3}, {2, 1, 3}, {0, 4, 1}};
  const auto mesh = make_mesh<typename Config::Mesh>(soup);
  for(std::size_t source : {0, 2, 3, 4})
    check_both_modes(mesh, source, euclidean_distances(mesh, source), 1e-6);
}

// Windows wrap around a needle-thin tube or cone about length / height (pi / apex angle) times
// before the ICH rule prunes them: such meshes are refused (the tetrahedron 1 long and 1e-12 wide
// that the fuzzer found kept the propagation busy for hours).
BOOST_AUTO_TEST_CASE_TEMPLATE(slivers_and_sharp_cones_are_refused, Config, All_configurations)
{
  Soup tube;
  tube.points = {{0., 0., 0.}, {1e-12, 1., 0.}, {0., 1e-12, 0.}, {0., 0., 1e-12}};
  tube.faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  require_constructor_throws(make_mesh<typename Config::Mesh>(tube));
  require_constructor_throws(make_mesh<typename Config::Mesh>(cone(1e-5))); // apex angle 5.2e-5
}

// just inside the limit (apex angle 1.04e-4): accepted, and the wrapping stays cheap
BOOST_AUTO_TEST_CASE_TEMPLATE(cone_at_the_limit, Config, All_configurations)
{
  const double r = 2e-5;
  const auto mesh = make_mesh<typename Config::Mesh>(cone(r));
  check_both_modes(mesh, 1, {std::sqrt(1. + r * r), 0., r * std::sqrt(3.), r * std::sqrt(3.), r}, 1e-6);
  CGAL::DGG_VTP_3::Propagation_statistics stats;
  geodesic_distances(mesh, 1, &stats);
  BOOST_TEST(stats.windows_created < 1000000u);
}

// a source on the border; the paths to 6 and 7 touch the reflex border corner 4
BOOST_AUTO_TEST_CASE_TEMPLATE(source_on_border, Config, All_configurations)
{
  const auto mesh = make_mesh<typename Config::Mesh>(l_shape());
  const double s2 = std::sqrt(2.);
  check_both_modes(mesh, 2, {2., 1., 0., std::sqrt(5.), s2, 1., 2. * s2, 1. + s2}, Config::tolerance);
  check_both_modes(mesh, 4, {s2, 1., s2, 1., 0., 1., s2, 1.}, Config::tolerance);
}

// two fans meeting at vertex 0 only (a Surface_mesh can hold it): paths pass through it
BOOST_AUTO_TEST_CASE(pinched_vertex)
{
  Soup soup;
  soup.points = {{0., 0., 0.}, {1., 0., 0.}, {0., 1., 0.}, {-1., 0., 0.}, {0., -1., 0.}};
  soup.faces = {{0, 1, 2}, {0, 3, 4}};
  const auto mesh = make_mesh<Sm_d::Mesh>(soup);
  check_both_modes(mesh, 1, {1., 0., std::sqrt(2.), 2., 2.}, Sm_d::tolerance);
  check_both_modes(mesh, 0, {0., 1., 1., 1., 1.}, Sm_d::tolerance);
}

// vertices and no face: the source at 0, every other vertex unreachable
BOOST_AUTO_TEST_CASE_TEMPLATE(no_faces, Config, All_configurations)
{
  Soup soup;
  soup.points = {{0., 0., 0.}, {1., 0., 0.}, {1., 0., 0.}};
  const auto mesh = make_mesh<typename Config::Mesh>(soup);
  const double inf = std::numeric_limits<double>::infinity();
  check_both_modes(mesh, 1, {inf, 0., inf}, Config::tolerance);
}

// an empty mesh: nothing to ask; an empty source range: an error
BOOST_AUTO_TEST_CASE(empty_mesh_and_no_source)
{
  using Mesh = Sm_d::Mesh;
  const Mesh empty;
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh> empty_solver(empty);
  BOOST_TEST(empty_solver.number_of_vertices() == 0u);
  auto empty_map = get(CGAL::dynamic_vertex_property_t<double>(), empty);
  BOOST_CHECK_THROW(empty_solver.compute_distances(Mesh::Vertex_index(0), empty_map), std::invalid_argument);

  const Mesh mesh = make_mesh<Mesh>(tetrahedron());
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh> solver(mesh);
  auto map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  BOOST_CHECK_THROW(solver.compute_distances_to_nearest_source(std::vector<Mesh::Vertex_index>(), map),
                    std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
