// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// Cross-check against CGAL's exact Surface_mesh_shortest_path on the bundled meshes. The
// reference is always computed on a Surface_mesh<Epick::Point_3> built from the same polygon soup
// (SMSP does not compile for a Polyhedron_3 without ids), and vertex i of every mesh is soup
// point i, so the configurations are compared vertex by vertex.

#include "test_utilities.h"

#include <CGAL/Surface_mesh_shortest_path.h>

#include <chrono>

using namespace dggvtp_test;

namespace {

using Reference_mesh = CGAL::Surface_mesh<Epick::Point_3>;

std::vector<double> smsp_distances(const Reference_mesh& mesh, std::size_t source_index)
{
  using Traits = CGAL::Surface_mesh_shortest_path_traits<Epick, Reference_mesh>;
  CGAL::Surface_mesh_shortest_path<Traits> smsp(mesh);
  smsp.add_source_point(vertex_list(mesh).at(source_index));
  smsp.build_sequence_tree();
  std::vector<double> d;
  for(auto v : vertices(mesh))
    d.push_back(smsp.shortest_distance_to_source_points(v).first);
  return d;
}

template <class Config>
void cross_check(const std::string& file, bool with_border_source)
{
  using Mesh = typename Config::Mesh;
  const Soup soup = read_soup(file);
  const Reference_mesh reference = make_mesh<Reference_mesh>(soup);
  const Mesh mesh = make_mesh<Mesh>(soup);
  std::vector<std::size_t> sources = {0, num_vertices(reference) / 2};
  if(with_border_source)
  {
    std::size_t i = 0;
    for(auto v : vertices(reference))
    {
      if(CGAL::is_border(v, reference))
        break;
      ++i;
    }
    BOOST_REQUIRE(i < num_vertices(reference));
    sources.push_back(i);
  }
  for(std::size_t s : sources)
  {
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    const std::vector<double> truth = smsp_distances(reference, s);
    const auto t1 = Clock::now();
    CGAL::DGG_VTP_3::Propagation_statistics statistics;
    const std::vector<double> d = geodesic_distances(mesh, s, &statistics);
    const auto t2 = Clock::now();
    BOOST_TEST_MESSAGE(file << " " << config_name<Config>() << ", source " << s << ": SMSP "
                       << std::chrono::duration<double>(t1 - t0).count() << " s, DGG_VTP_3 "
                       << std::chrono::duration<double>(t2 - t1).count() << " s, "
                       << statistics.windows_created << " windows created, peak " << statistics.windows_peak
                       << ", " << statistics.pseudo_sources << " pseudo-sources");
    check_distances(d, truth, s, Config::tolerance, file + " " + config_name<Config>() + ", source " + std::to_string(s));
    BOOST_TEST(statistics.vertices_reached == num_vertices(mesh));
  }
}

} // namespace

BOOST_AUTO_TEST_SUITE(cross_check_smsp)

// closed, genus 0
BOOST_AUTO_TEST_CASE_TEMPLATE(spot, Config, All_configurations)
{
  cross_check<Config>("spot.ply", false);
}

// closed, genus 1
BOOST_AUTO_TEST_CASE_TEMPLATE(pinion, Config, All_configurations)
{
  cross_check<Config>("pinion.ply", false);
}

// open, one boundary loop; a source on the border too
BOOST_AUTO_TEST_CASE_TEMPLATE(lion_head, Config, All_configurations)
{
  cross_check<Config>("lion_head.ply", true);
}

BOOST_AUTO_TEST_SUITE_END()
