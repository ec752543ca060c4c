// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team
//
// compute_distances_from_each_source on 1 thread (Sequential_tag) against Parallel_tag on T
// threads, in the same process, alternating the two REPEAT times:
//
//   many_sources MESH SOURCES EPSILON THREADS REPEAT
//
// prints one JSON object: the medians, their ratio, and whether every field of the parallel runs
// is bit for bit the sequential one. Sources are spread evenly over the vertices (vertex k*n/SOURCES).

#include <dggvtp/load_mesh.h>

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/tags.h>

#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;
using Field = Mesh::Property_map<vertex_descriptor, double>;

namespace {

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 6)
  {
    std::cerr << "usage: many_sources MESH SOURCES EPSILON THREADS REPEAT\n";
    return 1;
  }
  try
  {
    dggvtp::Loaded_soup soup = dggvtp::load_soup(argv[1]);
    Mesh mesh = dggvtp::make_triangle_mesh<Kernel>(soup);
    const std::size_t count = std::stoul(argv[2]);
    const double epsilon = std::stod(argv[3]);
    const int threads = std::stoi(argv[4]);
    const int repeat = (std::max)(1, std::stoi(argv[5]));
    // TBB aborts on a parallelism of 0, and no source would time nothing
    if(count == 0 || threads < 1)
    {
      std::cerr << "error: SOURCES and THREADS must be at least 1\n";
      return 1;
    }

    std::vector<vertex_descriptor> sources;
    for(std::size_t k = 0; k < count; ++k)
      sources.push_back(vertex_descriptor(static_cast<Mesh::size_type>(k * num_vertices(mesh) / count)));
    std::vector<Field> sequential, parallel;
    for(std::size_t k = 0; k < count; ++k)
    {
      sequential.push_back(mesh.add_property_map<vertex_descriptor, double>("s" + std::to_string(k)).first);
      parallel.push_back(mesh.add_property_map<vertex_descriptor, double>("p" + std::to_string(k)).first);
    }

    const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh> solver(mesh);
    const auto np = CGAL::parameters::accuracy(epsilon);
    std::vector<double> seconds_sequential, seconds_parallel;
    for(int r = 0; r < repeat; ++r)
    {
      auto t0 = std::chrono::steady_clock::now();
      solver.compute_distances_from_each_source<CGAL::Sequential_tag>(sources, sequential, np);
      seconds_sequential.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
      t0 = std::chrono::steady_clock::now();
      solver.compute_distances_from_each_source<CGAL::Parallel_tag>(sources, parallel, np);
      seconds_parallel.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }

    std::size_t differences = 0;
    for(std::size_t k = 0; k < count; ++k)
      for(vertex_descriptor v : vertices(mesh))
        if(get(sequential[k], v) != get(parallel[k], v))
          ++differences;
    const double s = median(seconds_sequential), p = median(seconds_parallel);
    std::printf("{\"sources\": %zu, \"epsilon\": %g, \"threads\": %d, \"repeat\": %d, "
                "\"seconds_sequential\": %.4f, \"seconds_parallel\": %.4f, \"speedup\": %.3f, "
                "\"differing_distances\": %zu}\n",
                count, epsilon, threads, repeat, s, p, s / p, differences);
    return differences == 0 ? 0 : 3;
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  }
}
