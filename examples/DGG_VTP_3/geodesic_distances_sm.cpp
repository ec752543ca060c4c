// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Exact geodesic distances from one vertex of a Surface_mesh, with the one-shot function.

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <iostream>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using vertex_descriptor = Mesh::Vertex_index;

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : CGAL::data_file_path("meshes/elephant.off");
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "cannot read a triangle mesh from " << file << "\n";
    return 1;
  }
  auto distance = mesh.add_property_map<vertex_descriptor, double>("v:distance", 0.).first;
  const vertex_descriptor source = *vertices(mesh).begin();

  CGAL::DGG_VTP_3::compute_geodesic_distances(mesh, source, distance);

  vertex_descriptor farthest = source;
  for(vertex_descriptor v : vertices(mesh))
    if(distance[v] > distance[farthest])
      farthest = v;
  std::cout << "geodesic distance from " << source << " to " << farthest << " (the farthest vertex): "
            << distance[farthest] << "\n";
  return distance[farthest] > 0. ? 0 : 1;
}
