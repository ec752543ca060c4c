// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team
//
// The reference of the benchmarks: CGAL's exact Surface_mesh_shortest_path (Epick, double) from one
// vertex to all vertices, in a process of its own so that its peak memory is its own.
//
// usage: smsp_distances MESH SOURCE OUTPUT STATS
//   MESH    a file CGAL reads as a polygon soup (PLY, OFF, OBJ, ...); vertex i is the i-th vertex of the file
//   SOURCE  0-based index of the source vertex
//   OUTPUT  one line per vertex, file order: the distance printed with %.17g ('-' = stdout)
//   STATS   one JSON object: vertices, faces, source, seconds_load, seconds_prepare,
//           seconds_build_tree, seconds_queries, seconds_propagate (= build_tree + queries), peak_rss_mb

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>

#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Traits = CGAL::Surface_mesh_shortest_path_traits<Kernel, Mesh>;
using Shortest_path = CGAL::Surface_mesh_shortest_path<Traits>;
using Clock = std::chrono::steady_clock;

namespace {

double seconds_since(const Clock::time_point& t0)
{
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

double peak_rss_mb()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.; // Linux: kilobytes
}

} // namespace

int main(int argc, char** argv)
{
  if(argc != 5)
  {
    std::cerr << "usage: smsp_distances MESH SOURCE OUTPUT STATS\n";
    return 1;
  }
  const std::string mesh_file = argv[1], output_file = argv[3], stats_file = argv[4];
  char* end = nullptr;
  const unsigned long long source_index = std::strtoull(argv[2], &end, 10);
  if(end == argv[2] || *end != '\0')
  {
    std::cerr << "error: SOURCE must be a vertex index\n";
    return 1;
  }

  // load: a soup, then a mesh with the soup's vertex order (vertex i = point i)
  Clock::time_point t0 = Clock::now();
  std::vector<Kernel::Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  if(!CGAL::IO::read_polygon_soup(mesh_file, points, polygons) || points.empty())
  {
    std::cerr << "error: cannot read " << mesh_file << "\n";
    return 2;
  }
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  if(num_vertices(mesh) != points.size() || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "error: " << mesh_file << " is not a triangle mesh using all its vertices\n";
    return 2;
  }
  if(source_index >= num_vertices(mesh))
  {
    std::cerr << "error: source " << source_index << " out of range\n";
    return 2;
  }
  const double seconds_load = seconds_since(t0);
  const Mesh::Vertex_index source(static_cast<Mesh::size_type>(source_index));

  t0 = Clock::now();
  Shortest_path shortest_paths(mesh);
  shortest_paths.add_source_point(source);
  const double seconds_prepare = seconds_since(t0);

  t0 = Clock::now();
  shortest_paths.build_sequence_tree();
  const double seconds_build_tree = seconds_since(t0);

  t0 = Clock::now();
  std::vector<double> distances;
  distances.reserve(num_vertices(mesh));
  for(Mesh::Vertex_index v : vertices(mesh))
    distances.push_back(CGAL::to_double(shortest_paths.shortest_distance_to_source_points(v).first));
  const double seconds_queries = seconds_since(t0);

  FILE* out = (output_file == "-") ? stdout : std::fopen(output_file.c_str(), "w");
  if(out == nullptr)
  {
    std::cerr << "error: cannot write " << output_file << "\n";
    return 2;
  }
  for(double x : distances)
  {
    if(std::isfinite(x) && x >= 0.)
      std::fprintf(out, "%.17g\n", x);
    else
      std::fprintf(out, "inf\n"); // SMSP reports a negative distance for unreachable vertices
  }
  if(out != stdout)
    std::fclose(out);

  FILE* stats = std::fopen(stats_file.c_str(), "w");
  if(stats == nullptr)
  {
    std::cerr << "error: cannot write " << stats_file << "\n";
    return 2;
  }
  std::fprintf(stats,
               "{\"program\": \"smsp_distances\", \"vertices\": %zu, \"faces\": %zu, \"source\": %llu, "
               "\"seconds_load\": %.6f, \"seconds_prepare\": %.6f, \"seconds_build_tree\": %.6f, "
               "\"seconds_queries\": %.6f, \"seconds_propagate\": %.6f, \"peak_rss_mb\": %.1f}\n",
               std::size_t(num_vertices(mesh)), std::size_t(num_faces(mesh)), source_index, seconds_load,
               seconds_prepare, seconds_build_tree, seconds_queries, seconds_build_tree + seconds_queries,
               peak_rss_mb());
  std::fclose(stats);
  return 0;
}
