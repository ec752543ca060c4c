// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team
//
// Exact geodesic distances from one vertex of a Surface_mesh to all its vertices, with the
// one-shot free function and a property map of the mesh.

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <string>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : DGG_VTP_3_DATA_DIR "/spot.ply";

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Invalid input: " << filename << " is not a triangle mesh." << std::endl;
    return EXIT_FAILURE;
  }

  // one distance per vertex, stored in the mesh; unreachable vertices get +infinity
  Mesh::Property_map<vertex_descriptor, double> distance =
    mesh.add_property_map<vertex_descriptor, double>("v:geodesic_distance", 0.).first;

  const vertex_descriptor source = *(vertices(mesh).begin());
  const CGAL::DGG_VTP_3::Propagation_statistics stats =
    CGAL::DGG_VTP_3::compute_geodesic_distances(mesh, distance, source);

  std::cout << num_vertices(mesh) << " vertices, " << stats.windows_created << " windows" << std::endl;

  // a few vertices: every num_vertices/4 vertex
  const Mesh::size_type step = (std::max)(Mesh::size_type(1), Mesh::size_type(num_vertices(mesh) / 4));
  for(Mesh::size_type i = 0; i < num_vertices(mesh); i += step)
  {
    const vertex_descriptor v(i);
    std::cout << "distance from " << source << " to " << v << ": " << distance[v] << std::endl;
  }

  vertex_descriptor farthest = source;
  for(vertex_descriptor v : vertices(mesh))
    if(distance[v] > distance[farthest])
      farthest = v;
  std::cout << "farthest vertex: " << farthest << " at distance " << distance[farthest] << std::endl;

  return (distance[source] == 0. && distance[farthest] > 0.) ? EXIT_SUCCESS : EXIT_FAILURE;
}
