// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team
//
// Several sources at once: one propagation gives every vertex its distance to the nearest source
// and, with the named parameter nearest_source_map, which source that is (its number in the
// range of sources): a geodesic Voronoi partition of the vertices.

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using vertex_descriptor = Mesh::Vertex_index;
namespace DP = CGAL::DGG_VTP_3::parameters;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : DGG_VTP_3_DATA_DIR "/spot.ply";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Invalid input: " << filename << " is not a triangle mesh." << std::endl;
    return EXIT_FAILURE;
  }
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh> solver(mesh);
  std::vector<vertex_descriptor> sources;
  for(std::size_t k = 0; k < 4; ++k)
    sources.push_back(vertex_descriptor(static_cast<Mesh::size_type>(k * num_vertices(mesh) / 4)));

  auto distance = mesh.add_property_map<vertex_descriptor, double>("v:distance").first;
  auto nearest = mesh.add_property_map<vertex_descriptor, std::size_t>("v:nearest_source").first;
  solver.compute_distances_to_nearest_source(sources, distance, DP::nearest_source_map(nearest));

  // the same from each source alone: the nearest source is the one at the smallest distance
  auto alone = mesh.add_property_map<vertex_descriptor, double>("v:alone").first;
  std::vector<std::vector<double>> fields(sources.size());
  for(std::size_t k = 0; k < sources.size(); ++k)
  {
    solver.compute_distances(sources[k], alone);
    for(vertex_descriptor v : vertices(mesh))
      fields[k].push_back(alone[v]);
  }
  std::vector<std::size_t> region_size(sources.size(), 0);
  bool right = true;
  for(vertex_descriptor v : vertices(mesh))
  {
    const std::size_t k = nearest[v];
    if(k >= sources.size())
      return EXIT_FAILURE; // every vertex of this mesh is reachable
    ++region_size[k];
    double smallest = fields[0][v];
    for(const std::vector<double>& field : fields)
      smallest = (std::min)(smallest, field[v]);
    // within rounding: sources at the same distance are a tie, either is right
    right = right && std::abs(distance[v] - smallest) <= 1e-12 * smallest &&
            std::abs(fields[k][v] - smallest) <= 1e-12 * smallest;
  }
  for(std::size_t k = 0; k < sources.size(); ++k)
    std::cout << "source " << k << " (vertex " << sources[k] << "): nearest to " << region_size[k] << " vertices"
              << std::endl;
  std::cout << (right ? "every vertex labelled with its nearest source" : "wrong labels or distances") << std::endl;
  return right ? EXIT_SUCCESS : EXIT_FAILURE;
}
