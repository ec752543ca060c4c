// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team
//
// A downstream program, built against the package the way a user builds it (see CMakeLists.txt
// here): exact distances from one vertex of a mesh, checked where the answer is known without
// the package. Between the ends of an edge the shortest path is the edge itself (no path is
// shorter than the straight segment, and the edge is a path on the surface).
//
// usage: consumer MESH

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <cstdlib>
#include <iostream>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using vertex_descriptor = Mesh::Vertex_index;

int main(int argc, char** argv)
{
  Mesh mesh;
  if(argc != 2 || !CGAL::IO::read_polygon_mesh(argv[1], mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "usage: consumer MESH (a triangle mesh)" << std::endl;
    return EXIT_FAILURE;
  }
  auto distance = mesh.add_property_map<vertex_descriptor, double>("v:distance", 0.).first;
  const vertex_descriptor source = *vertices(mesh).begin();
  CGAL::DGG_VTP_3::compute_geodesic_distances(mesh, distance, source);

  int neighbours = 0;
  for(vertex_descriptor v : CGAL::vertices_around_target(mesh.halfedge(source), mesh))
  {
    const double edge = std::sqrt(CGAL::squared_distance(mesh.point(source), mesh.point(v)));
    if(!(std::abs(distance[v] - edge) <= 1e-12 * edge))
    {
      std::cerr << "vertex " << v << ": distance " << distance[v] << ", edge length " << edge << std::endl;
      return EXIT_FAILURE;
    }
    ++neighbours;
  }
  double farthest = 0.;
  for(vertex_descriptor v : vertices(mesh))
    farthest = (std::max)(farthest, distance[v]);
  std::cout << num_vertices(mesh) << " vertices; " << neighbours << " neighbours of the source at their edge's "
            << "length; farthest vertex at " << farthest << std::endl;
  return (neighbours > 0 && distance[source] == 0. && std::isfinite(farthest) && farthest > 0.) ? EXIT_SUCCESS
                                                                                                  : EXIT_FAILURE;
}
