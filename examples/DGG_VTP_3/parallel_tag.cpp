// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team
//
// The concurrency tag, as in Polygon_mesh_processing: with CGAL::Parallel_tag one propagation is
// shared among TBB's threads (compute_distances), or the sources are (one field per source,
// compute_distances_from_each_source), and the distances are the same bits as sequentially.
// Parallel_tag needs a program linked with TBB the way CGAL does it, through the CMake target
// CGAL::TBB_support (CMakeLists.txt here: find_package(TBB), include(CGAL_TBB_support)); without
// it, Parallel_tag does not compile and Parallel_if_available_tag runs sequentially.

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <tbb/task_arena.h>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using vertex_descriptor = Mesh::Vertex_index;
using Distance_map = Mesh::Property_map<vertex_descriptor, double>;

template <class Function>
double seconds_of(Function f)
{
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : DGG_VTP_3_DATA_DIR "/bunny.ply";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Invalid input: " << filename << " is not a triangle mesh." << std::endl;
    return EXIT_FAILURE;
  }
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh> solver(mesh);
  std::cout << tbb::this_task_arena::max_concurrency() << " threads" << std::endl;

  // one propagation, on one thread and on all
  const vertex_descriptor source = *vertices(mesh).begin();
  Distance_map sequential = mesh.add_property_map<vertex_descriptor, double>("v:sequential").first;
  Distance_map parallel = mesh.add_property_map<vertex_descriptor, double>("v:parallel").first;
  const double t1 = seconds_of([&] { solver.compute_distances<CGAL::Sequential_tag>(source, sequential); });
  const double tp = seconds_of([&] { solver.compute_distances<CGAL::Parallel_tag>(source, parallel); });
  bool same = true;
  for(vertex_descriptor v : vertices(mesh))
    same = same && sequential[v] == parallel[v];
  std::cout << "one propagation: " << t1 << " s sequential, " << tp << " s parallel" << std::endl;

  // four sources, one field each, the sources shared among the threads
  std::vector<vertex_descriptor> sources;
  for(std::size_t k = 0; k < 4; ++k)
    sources.push_back(vertex_descriptor(static_cast<Mesh::size_type>(k * num_vertices(mesh) / 4)));
  std::vector<Distance_map> fields;
  for(std::size_t k = 0; k < sources.size(); ++k)
    fields.push_back(mesh.add_property_map<vertex_descriptor, double>("v:field_" + std::to_string(k)).first);
  const double tf = seconds_of([&] { solver.compute_distances_from_each_source<CGAL::Parallel_tag>(sources, fields); });
  std::cout << sources.size() << " sources, one field each: " << tf << " s parallel" << std::endl;
  for(std::size_t k = 0; k < sources.size(); ++k)
  {
    solver.compute_distances(sources[k], sequential);
    for(vertex_descriptor v : vertices(mesh))
      same = same && sequential[v] == fields[k][v];
  }

  std::cout << (same ? "the same distances, bit for bit" : "the distances differ") << std::endl;
  return same ? EXIT_SUCCESS : EXIT_FAILURE;
}
