// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The reference of the benchmarks: CGAL's exact Surface_mesh_shortest_path from one vertex, in a
// process of its own so that its peak memory is its own.
// usage: smsp_distances MESH SOURCE OUTPUT STATS

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Traits = CGAL::Surface_mesh_shortest_path_traits<Kernel, Mesh>;

int main(int argc, char** argv)
{
  if(argc != 5)
  {
    std::cerr << "usage: smsp_distances MESH SOURCE OUTPUT STATS\n";
    return 1;
  }
  std::vector<Kernel::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_soup(argv[1], points, polygons))
  {
    std::cerr << "error: cannot read " << argv[1] << "\n";
    return 2;
  }
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh); // vertex i = point i
  const Mesh::Vertex_index source(static_cast<Mesh::size_type>(std::stoul(argv[2])));

  const auto t0 = std::chrono::steady_clock::now();
  CGAL::Surface_mesh_shortest_path<Traits> shortest_paths(mesh);
  shortest_paths.add_source_point(source);
  shortest_paths.build_sequence_tree();
  std::vector<double> d;
  for(Mesh::Vertex_index v : vertices(mesh))
    d.push_back(shortest_paths.shortest_distance_to_source_points(v).first);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  FILE* out = std::fopen(argv[3], "w");
  for(double x : d)
    std::fprintf(out, "%.17g\n", x);
  std::fclose(out);
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  FILE* stats = std::fopen(argv[4], "w");
  std::fprintf(stats, "{\"vertices\": %zu, \"seconds_propagate\": %.6f, \"peak_rss_mb\": %.1f}\n",
               d.size(), seconds, double(usage.ru_maxrss) / 1024.);
  std::fclose(stats);
  return 0;
}
