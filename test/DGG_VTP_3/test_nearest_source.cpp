// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// compute_distances_to_nearest_source: the distance field of several sources at once.

#include "test_utilities.h"

#include <cstring>

using namespace dggvtp_test;

namespace {

// the number of elements whose bits differ (a NaN equals a NaN, -0 differs from +0: == would hide
// both), every element when the sizes differ
std::size_t bit_differences(const std::vector<double>& a, const std::vector<double>& b)
{
  if(a.size() != b.size())
    return (std::max)(a.size(), b.size());
  std::size_t count = 0;
  for(std::size_t i = 0; i < a.size(); ++i)
    count += std::memcmp(&a[i], &b[i], sizeof(double)) != 0;
  return count;
}

} // namespace

BOOST_AUTO_TEST_SUITE(nearest_source)

// on a flat patch the field is the minimum of the Euclidean distances to the sources
BOOST_AUTO_TEST_CASE_TEMPLATE(flat_patch_two_sources, Config, All_configurations)
{
  using Mesh = typename Config::Mesh;
  const Mesh mesh = make_mesh<Mesh>(flat_patch(16, 12, 1., 1., 0.15, 11, Rigid_motion({0.2, 0.4, -0.9}, 0.5, {0., 1., 2.})));
  const std::size_t a = 3, b = 150;
  const std::vector<double> da = euclidean_distances(mesh, a);
  const std::vector<double> db = euclidean_distances(mesh, b);
  std::vector<double> truth(da.size());
  for(std::size_t i = 0; i < da.size(); ++i)
    truth[i] = (std::min)(da[i], db[i]);

  CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh> solver(mesh);
  auto map = get(CGAL::dynamic_vertex_property_t<typename Distance_map<Mesh>::FT>(), mesh);
  const auto vertices = vertex_list(mesh);
  solver.compute_distances_to_nearest_source(std::vector<Vertex<Mesh>>{vertices[a], vertices[b]}, map);
  const std::vector<double> d = to_vector(mesh, map);
  BOOST_TEST(d[b] == 0.);
  check_distances(d, truth, a, Config::tolerance, "two sources, " + config_name<Config>());
}

// the free function with a range of sources is compute_distances_to_nearest_source, bit for bit
BOOST_AUTO_TEST_CASE_TEMPLATE(free_function_with_sources, Config, All_configurations)
{
  using Mesh = typename Config::Mesh;
  const Mesh mesh = make_mesh<Mesh>(read_soup("pinion.ply"));
  const auto vertices = vertex_list(mesh);
  const std::vector<Vertex<Mesh>> sources{vertices[7], vertices[300], vertices[611]};
  for(double accuracy : {0., 1e-5})
  {
    auto from_function = get(CGAL::dynamic_vertex_property_t<typename Distance_map<Mesh>::FT>(), mesh);
    auto from_class = get(CGAL::dynamic_vertex_property_t<typename Distance_map<Mesh>::FT>(), mesh);
    const auto np = CGAL::parameters::accuracy(accuracy);
    const auto a = CGAL::DGG_VTP_3::compute_geodesic_distances(mesh, from_function, sources, np);
    const auto b = CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh>(mesh).compute_distances_to_nearest_source(
      sources, from_class, np);
    const std::size_t differ = bit_differences(to_vector(mesh, from_function), to_vector(mesh, from_class));
    BOOST_TEST(differ == 0u, config_name<Config>() << ", accuracy " << accuracy << ": " << differ
                                                   << " distances differ in their bits");
    BOOST_TEST(a.windows_created == b.windows_created);
    for(const auto& s : sources)
      BOOST_TEST(double(get(from_function, s)) == 0.);
  }
}

BOOST_AUTO_TEST_CASE(no_source_is_an_error)
{
  using Mesh = CGAL::Surface_mesh<Epick::Point_3>;
  const Mesh mesh = make_mesh<Mesh>(read_soup("pinion.ply"));
  CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh> solver(mesh);
  auto map = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  BOOST_CHECK_THROW(solver.compute_distances_to_nearest_source(std::vector<Mesh::Vertex_index>(), map),
                    std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
