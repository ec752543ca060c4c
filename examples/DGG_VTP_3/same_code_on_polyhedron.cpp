// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team
//
// Generic code over any CGAL triangle mesh: one function template, run on a Surface_mesh and on
// a plain Polyhedron_3 (no vertex or face ids to set up: the solver numbers them itself), with
// distances in a dynamic property map. Both give the same distances.

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

// the distances from the first vertex of the file to every vertex, in the file's order
template <class TriangleMesh>
std::vector<double> distances_from_first_vertex(const std::string& filename)
{
  TriangleMesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
    return {};
  auto distance = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  CGAL::DGG_VTP_3::compute_geodesic_distances(mesh, distance, *vertices(mesh).begin());
  std::vector<double> result;
  for(auto v : vertices(mesh))
    result.push_back(get(distance, v));
  return result;
}

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : DGG_VTP_3_DATA_DIR "/spot.ply";
  const std::vector<double> on_surface_mesh = distances_from_first_vertex<CGAL::Surface_mesh<Kernel::Point_3>>(filename);
  const std::vector<double> on_polyhedron = distances_from_first_vertex<CGAL::Polyhedron_3<Kernel>>(filename);
  if(on_surface_mesh.empty() || on_surface_mesh.size() != on_polyhedron.size())
  {
    std::cerr << "Invalid input: " << filename << " is not a triangle mesh." << std::endl;
    return EXIT_FAILURE;
  }
  double largest = 0.;
  for(std::size_t i = 0; i < on_surface_mesh.size(); ++i)
    largest = (std::max)(largest, std::abs(on_surface_mesh[i] - on_polyhedron[i]) / (std::max)(on_polyhedron[i], 1e-300));
  std::cout << on_surface_mesh.size() << " vertices; largest relative difference between Surface_mesh and "
            << "Polyhedron_3: " << largest << std::endl;
  return largest <= 1e-12 ? EXIT_SUCCESS : EXIT_FAILURE;
}
