// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team
//
// Two helpers of the DGG-VTP sweep (dgg_sweep.py), on a mesh loaded exactly as dggvtp loads it
// (vertex i is the i-th vertex of the file):
//
//   mesh_baseline MESH sources K
//     prints up to K distinct source vertices, one per line: vertex 0, a border vertex, the
//     vertex of largest and of smallest angle sum, vertex n/2, then evenly spaced vertices.
//   mesh_baseline MESH dijkstra SOURCE REPEAT
//     Boost.Graph's Dijkstra over the mesh edges (edge lengths computed beforehand), REPEAT
//     times; prints {"seconds_dijkstra": median, "max_distance": ...}. The floor DGG-VTP races:
//     the same priority-queue walk over the vertices with no geometry at all.

#include <dggvtp/load_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <boost/property_map/function_property_map.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <set>
#include <string>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;
using edge_descriptor = boost::graph_traits<Mesh>::edge_descriptor;

namespace {

double corner_angle(const Kernel::Point_3& p, const Kernel::Point_3& q, const Kernel::Point_3& r)
{
  const Kernel::Vector_3 a = q - p, b = r - p;
  return std::atan2(std::sqrt(CGAL::cross_product(a, b).squared_length()), a * b);
}

std::vector<std::size_t> pick_sources(const Mesh& mesh, std::size_t file_vertices, std::size_t k)
{
  std::vector<double> angle_sum(num_vertices(mesh), 0.);
  for(auto f : faces(mesh))
  {
    auto h = halfedge(f, mesh);
    for(int i = 0; i < 3; ++i, h = next(h, mesh))
      angle_sum[target(h, mesh)] += corner_angle(mesh.point(target(h, mesh)), mesh.point(source(h, mesh)),
                                                 mesh.point(target(next(h, mesh), mesh)));
  }
  std::vector<std::size_t> picks{0};
  for(auto v : vertices(mesh))
    if(std::size_t(v) < file_vertices && is_border(v, mesh))
    {
      picks.push_back(std::size_t(v));
      break;
    }
  std::size_t largest = 0, smallest = 0;
  for(std::size_t i = 0; i < file_vertices; ++i)
  {
    if(angle_sum[i] > angle_sum[largest])
      largest = i;
    if(angle_sum[i] < angle_sum[smallest] && angle_sum[i] > 0.)
      smallest = i;
  }
  picks.push_back(largest);
  picks.push_back(smallest);
  picks.push_back(file_vertices / 2);
  for(std::size_t i = 1; picks.size() < 4 * k && i < 4 * k; ++i)
    picks.push_back(i * file_vertices / (4 * k));
  std::vector<std::size_t> out;
  std::set<std::size_t> seen;
  for(std::size_t p : picks)
    if(out.size() < k && p < file_vertices && seen.insert(p).second)
      out.push_back(p);
  return out;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 4)
  {
    std::cerr << "usage: mesh_baseline MESH sources K | mesh_baseline MESH dijkstra SOURCE REPEAT\n";
    return 1;
  }
  try
  {
    dggvtp::Loaded_soup soup = dggvtp::load_soup(argv[1]);
    const std::size_t file_vertices = soup.file_vertices;
    const Mesh mesh = dggvtp::make_triangle_mesh<Kernel>(soup);
    const std::string what = argv[2];
    if(what == "sources")
    {
      for(std::size_t s : pick_sources(mesh, file_vertices, std::stoul(argv[3])))
        std::cout << s << '\n';
      return 0;
    }
    if(what != "dijkstra" || argc < 5)
    {
      std::cerr << "usage: mesh_baseline MESH sources K | mesh_baseline MESH dijkstra SOURCE REPEAT\n";
      return 1;
    }
    const vertex_descriptor s(static_cast<Mesh::size_type>(std::stoul(argv[3])));
    const int repeat = std::max(1, std::stoi(argv[4]));
    std::vector<double> weight(num_edges(mesh));
    for(auto e : edges(mesh))
      weight[std::size_t(e)] = std::sqrt(CGAL::squared_distance(mesh.point(source(e, mesh)), mesh.point(target(e, mesh))));
    std::vector<double> distance(num_vertices(mesh));
    std::vector<double> seconds;
    for(int r = 0; r < repeat; ++r)
    {
      const auto t0 = std::chrono::steady_clock::now();
      boost::dijkstra_shortest_paths(
        mesh, s,
        boost::distance_map(boost::make_iterator_property_map(distance.begin(), get(boost::vertex_index, mesh)))
          .weight_map(boost::make_function_property_map<edge_descriptor>(
            [&weight](edge_descriptor e) { return weight[std::size_t(e)]; }))
          .vertex_index_map(get(boost::vertex_index, mesh)));
      seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    std::sort(seconds.begin(), seconds.end());
    double max_distance = 0.;
    for(double d : distance)
      if(d < std::numeric_limits<double>::max())
        max_distance = std::max(max_distance, d);
    std::printf("{\"seconds_dijkstra\": %.6f, \"max_distance\": %.17g}\n", seconds[seconds.size() / 2], max_distance);
    return 0;
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  }
}
