// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team
//
// The cost of geodesic paths: one query from vertex 0, as distances only or as a shortest path
// tree, then the paths to TARGETS vertices spread over the mesh (vertex k * n / TARGETS):
//
//   paths MESH EPSILON distances|tree TARGETS
//
// prints one JSON object: the query's time, the peak RSS of the process (run the two modes as two
// processes to compare memory), and, for a tree, the median time per path, the median number of
// path points, and the largest |path length - distance| / distance.

#include <dggvtp/load_mesh.h>

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Solver = CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh>;
using Tree = CGAL::DGG_VTP_3::Shortest_path_tree<Solver>;

namespace {

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0. : v[v.size() / 2];
}

double peak_rss_mb()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 5 || (std::string(argv[3]) != "distances" && std::string(argv[3]) != "tree"))
  {
    std::cerr << "usage: paths MESH EPSILON distances|tree TARGETS\n";
    return 1;
  }
  try
  {
    dggvtp::Loaded_soup soup = dggvtp::load_soup(argv[1]);
    const Mesh mesh = dggvtp::make_triangle_mesh<Kernel>(soup);
    const double epsilon = std::stod(argv[2]);
    const bool tree_mode = std::string(argv[3]) == "tree";
    const std::size_t count = std::stoul(argv[4]);
    const Solver solver(mesh);
    const std::vector<Mesh::Vertex_index> sources(1, *vertices(mesh).begin());
    const auto np = CGAL::parameters::accuracy(epsilon);
    const auto t0 = std::chrono::steady_clock::now();
    if(!tree_mode)
    {
      std::vector<double> d(num_vertices(mesh));
      solver.compute_distances_to_nearest_source(sources, CGAL::make_property_map(d), np);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::printf("{\"mode\": \"distances\", \"epsilon\": %g, \"seconds_query\": %.3f, \"peak_rss_mb\": %.1f}\n",
                  epsilon, seconds, peak_rss_mb());
      return 0;
    }
    const Tree tree = solver.compute_shortest_path_tree(sources, np);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::vector<double> per_path, points;
    double worst = 0.;
    std::vector<Tree::Path_point> path;
    std::vector<Kernel::Point_3> xyz;
    for(std::size_t k = 0; k < count; ++k)
    {
      const Mesh::Vertex_index v(static_cast<Mesh::size_type>(k * num_vertices(mesh) / count));
      path.clear();
      const auto t1 = std::chrono::steady_clock::now();
      tree.shortest_path(v, std::back_inserter(path));
      per_path.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count());
      points.push_back(double(path.size()));
      xyz.clear();
      Tree::points(mesh, path, std::back_inserter(xyz));
      double length = 0.;
      for(std::size_t i = 1; i < xyz.size(); ++i)
        length += std::sqrt(CGAL::squared_distance(xyz[i - 1], xyz[i]));
      const double d = tree.distance(v);
      if(d > 0.)
        worst = (std::max)(worst, std::abs(length - d) / d);
    }
    std::printf("{\"mode\": \"tree\", \"epsilon\": %g, \"seconds_query\": %.3f, \"peak_rss_mb\": %.1f, "
                "\"paths\": %zu, \"median_seconds_per_path\": %.3g, \"median_points_per_path\": %.0f, "
                "\"max_relative_length_error\": %.3g}\n",
                epsilon, seconds, peak_rss_mb(), count, median(per_path), median(points), worst);
    return worst <= 1e-12 ? 0 : 3;
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  }
}
