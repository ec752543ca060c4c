// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// What the documentation promises: results on meshes with borders and several components,
// +infinity where no path reaches, the class and the free function agreeing, reusable const
// solvers, and the named parameters.

#include "test_utilities.h"

#include <boost/property_map/property_map.hpp>

#include <cstring>
#include <map>
#include <thread>

using namespace dggvtp_test;

namespace {

bool is_plus_infinity(double d) { return std::isinf(d) && d > 0; }

// two disjoint flat patches: vertices [0, 36) and [36, 72)
Soup two_components()
{
  Soup a = flat_patch(5, 5, 0.2, 0.2, 0.1, 7, Rigid_motion({0., 0., 1.}, 0., {0., 0., 0.}));
  const Soup b = flat_patch(5, 5, 0.2, 0.2, 0.1, 8, Rigid_motion({1., 0., 0.}, 0.5, {3., 0., 0.}));
  const std::size_t offset = a.points.size();
  a.points.insert(a.points.end(), b.points.begin(), b.points.end());
  for(auto f : b.faces)
  {
    for(auto& i : f)
      i += offset;
    a.faces.push_back(f);
  }
  return a;
}

Soup small_patch() { return flat_patch(8, 6, 0.125, 0.125, 0.15, 11, Rigid_motion({1., -1., 2.}, 0.4, {0., 1., 0.})); }

// reads the mesh's points scaled by a factor
template <class Mesh>
struct Scaled_point_map
{
  using Point = typename boost::property_traits<
                  typename boost::property_map<Mesh, CGAL::vertex_point_t>::const_type>::value_type;
  using key_type = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using value_type = Point;
  using reference = Point;
  using category = boost::readable_property_map_tag;

  const Mesh* mesh;
  double factor;

  friend Point get(const Scaled_point_map& m, key_type v)
  {
    using FT = typename CGAL::Kernel_traits<Point>::Kernel::FT;
    const Point& p = get(CGAL::vertex_point, *m.mesh, v);
    return Point(p.x() * FT(m.factor), p.y() * FT(m.factor), p.z() * FT(m.factor));
  }
};

} // namespace

BOOST_AUTO_TEST_SUITE(documented_behaviour)

// A patch with a border (an open mesh) is a valid input: the analytic suite checks the numbers;
// here the border vertices themselves are the sources and every vertex is reached.
BOOST_AUTO_TEST_CASE_TEMPLATE(open_mesh_border_sources, Config, All_configurations)
{
  using Mesh = typename Config::Mesh;
  const Mesh mesh = make_mesh<Mesh>(small_patch());
  const auto vs = vertex_list(mesh);
  for(std::size_t s = 0; s < vs.size(); ++s)
  {
    if(!CGAL::is_border(vs[s], mesh))
      continue;
    CGAL::DGG_VTP_3::Propagation_statistics statistics;
    const std::vector<double> d = geodesic_distances(mesh, s, &statistics);
    const Error_report r = relative_error(d, euclidean_distances(mesh, s), s);
    BOOST_TEST(r.max_relative <= Config::tolerance, "source " << s << ": " << r.max_relative);
    BOOST_TEST(r.at_source <= source_tolerance);
    BOOST_TEST(statistics.vertices_reached == vs.size());
  }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(other_component_is_infinite, Config, Analytic_configurations)
{
  using Mesh = typename Config::Mesh;
  const Mesh mesh = make_mesh<Mesh>(two_components());
  for(std::size_t s : {std::size_t(14), std::size_t(36 + 20)})
  {
    CGAL::DGG_VTP_3::Propagation_statistics statistics;
    const std::vector<double> d = geodesic_distances(mesh, s, &statistics);
    const std::vector<double> truth = euclidean_distances(mesh, s);
    const bool first = s < 36;
    std::size_t finite = 0;
    double max_relative = 0.;
    for(std::size_t i = 0; i < d.size(); ++i)
    {
      if((i < 36) == first)
      {
        ++finite;
        BOOST_TEST(std::isfinite(d[i]));
        if(i != s)
          max_relative = (std::max)(max_relative, std::abs(d[i] - truth[i]) / truth[i]);
      }
      else
        BOOST_TEST(is_plus_infinity(d[i]), "vertex " << i << ": " << d[i]);
    }
    BOOST_TEST(max_relative <= Config::tolerance);
    BOOST_TEST(d[s] <= source_tolerance);
    BOOST_TEST(statistics.vertices_reached == finite);
  }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(isolated_vertex, Config, All_configurations)
{
  using Mesh = typename Config::Mesh;
  using Point = typename Config::Kernel::Point_3;
  Mesh mesh = make_mesh<Mesh>(small_patch());
  const std::size_t n = num_vertices(mesh);
  const auto isolated = add_vertex(mesh);
  put(get(CGAL::vertex_point, mesh), isolated, Point(0.5, 0.5, 7.));
  BOOST_REQUIRE_EQUAL(num_vertices(mesh), n + 1);
  BOOST_REQUIRE(vertex_list(mesh).back() == isolated);

  // unreached from the patch
  CGAL::DGG_VTP_3::Propagation_statistics statistics;
  std::vector<double> d = geodesic_distances(mesh, 3, &statistics);
  BOOST_TEST(is_plus_infinity(d[n]), d[n]);
  const std::vector<double> truth = euclidean_distances(mesh, 3);
  const Error_report r = relative_error(std::vector<double>(d.begin(), d.end() - 1),
                                        std::vector<double>(truth.begin(), truth.end() - 1), 3);
  BOOST_TEST(r.max_relative <= Config::tolerance);
  BOOST_TEST(statistics.vertices_reached == n);

  // as the source: 0 at itself, +infinity elsewhere
  d = geodesic_distances(mesh, n, &statistics);
  BOOST_TEST(d[n] == 0.);
  for(std::size_t i = 0; i < n; ++i)
    BOOST_TEST(is_plus_infinity(d[i]), "vertex " << i << ": " << d[i]);
  BOOST_TEST(statistics.vertices_reached == 1u);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(free_function_equals_class, Config, All_configurations)
{
  using Mesh = typename Config::Mesh;
  const Mesh mesh = make_mesh<Mesh>(dggvtp_test::prism_lateral_surface(5, 3, 6, 2., 99).soup);
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh> solver(mesh);
  BOOST_TEST(solver.number_of_vertices() == num_vertices(mesh));
  for(std::size_t s : {std::size_t(0), std::size_t(37), std::size_t(num_vertices(mesh) - 1)})
  {
    CGAL::DGG_VTP_3::Propagation_statistics a, b;
    const std::vector<double> from_function = geodesic_distances(mesh, s, &a);
    const std::vector<double> from_class = solver_distances(solver, mesh, s, &b);
    BOOST_REQUIRE_EQUAL(from_function.size(), from_class.size());
    BOOST_TEST(std::memcmp(from_function.data(), from_class.data(), from_class.size() * sizeof(double)) == 0,
               "bit-identical");
    BOOST_TEST(a.windows_created == b.windows_created);
    BOOST_TEST(a.windows_peak == b.windows_peak);
    BOOST_TEST(a.pseudo_sources == b.pseudo_sources);
    BOOST_TEST(a.vertices_popped == b.vertices_popped);
    BOOST_TEST(a.vertices_reached == b.vertices_reached);
  }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(solver_reuse, Config, All_configurations)
{
  using Mesh = typename Config::Mesh;
  using Solver = CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh>;
  const Mesh mesh = make_mesh<Mesh>(read_soup("pinion.ply"));
  const Solver reused(mesh);
  const std::size_t sources[] = {5, 400, 5, 123};  // 5 twice: a query must not depend on the last
  for(std::size_t s : sources)
  {
    const std::vector<double> again = solver_distances(reused, mesh, s);
    const Solver fresh(mesh);
    const std::vector<double> first_time = solver_distances(fresh, mesh, s);
    BOOST_TEST(again == first_time, boost::test_tools::per_element());
  }
}

// const queries from two threads at once give what sequential queries give
BOOST_AUTO_TEST_CASE_TEMPLATE(concurrent_queries, Config, All_configurations)
{
  using Mesh = typename Config::Mesh;
  using Solver = CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh>;
  const Mesh mesh = make_mesh<Mesh>(read_soup("pinion.ply"));
  const Solver solver(mesh);
  const auto vs = vertex_list(mesh);
  const std::size_t sources[] = {17, 321};
  std::vector<double> sequential[2], parallel[2];
  for(int k = 0; k < 2; ++k)
    sequential[k] = solver_distances(solver, mesh, sources[k]);
  // std::map storage so that the two threads share nothing but the solver and the mesh
  std::map<typename Solver::vertex_descriptor, typename Solver::FT> storage[2];
  {
    std::thread threads[2];
    for(int k = 0; k < 2; ++k)
      threads[k] = std::thread([&, k] {
        solver.compute_distances(vs[sources[k]], boost::make_assoc_property_map(storage[k]));
      });
    for(auto& t : threads)
      t.join();
  }
  for(int k = 0; k < 2; ++k)
  {
    for(auto v : vs)
      parallel[k].push_back(double(storage[k].at(v)));
    BOOST_TEST(parallel[k] == sequential[k], boost::test_tools::per_element());
  }
}

// the constructor copies what it needs: the solver answers after the mesh is gone
BOOST_AUTO_TEST_CASE(solver_outlives_mesh)
{
  using Mesh = Sm_d::Mesh;
  using Solver = CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh>;
  const Mesh mesh = make_mesh<Mesh>(small_patch());
  auto copy = std::make_unique<Mesh>(mesh);
  const Solver solver(*copy);
  copy.reset();
  const std::vector<double> d = solver_distances(solver, mesh, 20);
  const std::vector<double> expected = geodesic_distances(mesh, 20);
  BOOST_TEST(d == expected, boost::test_tools::per_element());
}

// a vertex point map that scales the points by 2 doubles every distance
BOOST_AUTO_TEST_CASE_TEMPLATE(named_parameter_vertex_point_map, Config, All_configurations)
{
  using Mesh = typename Config::Mesh;
  const Mesh mesh = make_mesh<Mesh>(read_soup("spot.ply"));
  const std::vector<double> d = geodesic_distances(mesh, 100);
  const std::vector<double> d2 = geodesic_distances(
    mesh, 100, nullptr, CGAL::parameters::vertex_point_map(Scaled_point_map<Mesh>{&mesh, 2.}));
  std::vector<double> half;
  for(double x : d2)
    half.push_back(x / 2);
  check_distances(half, d, 100, Config::tolerance, "spot " + config_name<Config>() + " scaled by 2 (d/2 vs d)");

  // the class with the same map
  using Solver = CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh>;
  const Solver solver(mesh, CGAL::parameters::vertex_point_map(Scaled_point_map<Mesh>{&mesh, 2.}));
  BOOST_TEST(solver_distances(solver, mesh, 100) == d2, boost::test_tools::per_element());
}

// geom_traits given explicitly, to the function and to the class, changes nothing
BOOST_AUTO_TEST_CASE_TEMPLATE(named_parameter_geom_traits, Config, All_configurations)
{
  using Mesh = typename Config::Mesh;
  using Kernel = typename Config::Kernel;
  const Mesh mesh = make_mesh<Mesh>(small_patch());
  const std::vector<double> d = geodesic_distances(mesh, 30);
  BOOST_TEST(geodesic_distances(mesh, 30, nullptr, CGAL::parameters::geom_traits(Kernel())) == d,
             boost::test_tools::per_element());
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh, Kernel> solver(mesh, CGAL::parameters::geom_traits(Kernel()));
  BOOST_TEST(solver_distances(solver, mesh, 30) == d, boost::test_tools::per_element());
}

// user-given vertex and face index maps (here: reversed orders) give the same distances up to
// rounding (the internal numbering changes the order of the propagation)
BOOST_AUTO_TEST_CASE_TEMPLATE(named_parameter_index_maps, Config, All_configurations)
{
  using Mesh = typename Config::Mesh;
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<Mesh>::face_descriptor;
  const Mesh mesh = make_mesh<Mesh>(dggvtp_test::prism_lateral_surface(7, 3, 8, 2.5, 5).soup);
  std::map<vertex_descriptor, std::size_t> vertex_ids;
  std::map<face_descriptor, std::size_t> face_ids;
  std::size_t i = num_vertices(mesh);
  for(auto v : vertices(mesh))
    vertex_ids[v] = --i;
  i = num_faces(mesh);
  for(auto f : faces(mesh))
    face_ids[f] = --i;
  const auto vim = boost::make_assoc_property_map(vertex_ids);
  const auto fim = boost::make_assoc_property_map(face_ids);
  const std::vector<double> d = geodesic_distances(mesh, 12);
  const std::vector<double> d_maps = geodesic_distances(
    mesh, 12, nullptr, CGAL::parameters::vertex_index_map(vim).face_index_map(fim));
  check_distances(d_maps, d, 12, Config::tolerance, "prism " + config_name<Config>() + " with reversed index maps");

  // the class, with the index map types as template arguments
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh, CGAL::Default, std::decay_t<decltype(vim)>,
                                                  std::decay_t<decltype(fim)>>
    solver(mesh, CGAL::parameters::vertex_index_map(vim).face_index_map(fim));
  BOOST_TEST(solver_distances(solver, mesh, 12) == d_maps, boost::test_tools::per_element());
}

BOOST_AUTO_TEST_SUITE_END()
