// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One solver, prepared once for a plain Polyhedron_3 (no ids to initialise), queried for several
// sources and, with DGG-VTP, for a distance field within a relative error of 1e-6.

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>

#include <boost/unordered_map.hpp>

#include <iostream>
#include <iterator>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Polyhedron_3<Kernel>;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : CGAL::data_file_path("meshes/elephant.off");
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "cannot read a triangle mesh from " << file << "\n";
    return 1;
  }
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh> solver(mesh);

  boost::unordered_map<vertex_descriptor, double> storage;
  auto distance = boost::make_assoc_property_map(storage);
  const auto first = vertices(mesh).begin();
  for(vertex_descriptor source : {*first, *std::next(first, num_vertices(mesh) / 2)})
  {
    const auto exact = solver.compute_distances(source, distance);
    double exact_sum = 0.;
    for(vertex_descriptor v : vertices(mesh))
      exact_sum += get(distance, v);

    const auto approximate = solver.compute_distances(source, distance, CGAL::parameters::accuracy(1e-6));
    double approximate_sum = 0.;
    for(vertex_descriptor v : vertices(mesh))
      approximate_sum += get(distance, v);

    std::cout << "mean distance from a source: exact " << exact_sum / num_vertices(mesh) << " ("
              << exact.windows_created << " windows), DGG-VTP 1e-6 " << approximate_sum / num_vertices(mesh)
              << " (" << approximate.windows_created << " windows)\n";
    if(!(approximate_sum >= exact_sum * (1. - 1e-12) && approximate_sum <= exact_sum * (1. + 1e-6)))
      return 1;
  }
  return 0;
}
