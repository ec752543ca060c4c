// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team
//
// One Geodesic_distance_solver, prepared once for a plain Polyhedron_3 (no vertex ids to
// initialise), queried for several sources at once: one distance field per source, each in a
// boost::unordered_map. With Parallel_if_available_tag the sources are shared among TBB's threads
// when the program is linked with TBB (CGAL::TBB_support), and computed one after the other
// otherwise; the distances are the same either way.

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>

#include <boost/property_map/property_map.hpp>
#include <boost/unordered_map.hpp>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Polyhedron_3<Kernel>;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;
using Solver = CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh>;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/elephant.off");

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Invalid input: " << filename << " is not a triangle mesh." << std::endl;
    return EXIT_FAILURE;
  }

  // the intrinsic geometry is computed once, here ...
  const Solver solver(mesh);

  // ... and reused by every query: three sources spread over the vertex range
  const std::size_t n = num_vertices(mesh);
  std::vector<vertex_descriptor> sources;
  for(std::size_t k = 0; k < 3; ++k)
    sources.push_back(*std::next(vertices(mesh).begin(), k * n / 3));

  using Storage = boost::unordered_map<vertex_descriptor, double>;
  std::vector<Storage> storage(sources.size());
  std::vector<boost::associative_property_map<Storage> > distances;
  for(Storage& s : storage)
    distances.emplace_back(s);

  const std::vector<CGAL::DGG_VTP_3::Propagation_statistics> statistics =
    solver.compute_distances_from_each_source<CGAL::Parallel_if_available_tag>(sources, distances);

  for(std::size_t k = 0; k < sources.size(); ++k)
  {
    double sum = 0., max_distance = 0.;
    for(vertex_descriptor v : vertices(mesh))
    {
      sum += get(distances[k], v);
      max_distance = (std::max)(max_distance, get(distances[k], v));
    }
    std::cout << "source at (" << sources[k]->point() << "): mean distance " << sum / n
              << ", max distance " << max_distance << ", " << statistics[k].vertices_reached
              << " vertices reached, " << statistics[k].windows_created << " windows" << std::endl;

    if(get(distances[k], sources[k]) != 0. || !(max_distance > 0.))
      return EXIT_FAILURE;
  }

  return EXIT_SUCCESS;
}
