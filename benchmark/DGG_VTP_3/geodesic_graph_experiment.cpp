// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team
//
// The deciding experiment of the certified geodesic graph (issue 54; the design note's section 7):
// one direct-only propagation (internal/Geodesic_graph_build.h) from every vertex, whose reached
// vertices are the vertex's out-edges, weighted with the distances found:
//
//   geodesic_graph_experiment MESH EPSILON OUT.npz [THREADS]
//
// writes the directed graph as a CSR matrix (scipy.sparse.load_npz reads it; row x holds the
// out-edges of x, without x) and prints one JSON object: out-degrees (mean, largest, at which
// vertex, 99th percentile), windows per run, seconds of the runs and of as many runs within
// distance 0 (a query's set-up, to subtract), microseconds per vertex, peak RSS.
// geodesic_graph_experiment.py checks Dijkstra on the graph against exact rows.

#include <dggvtp/load_mesh.h>
#include <dggvtp/npz.h>
#include <dggvtp/threads.h>

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/DGG_VTP_3/internal/Geodesic_graph_build.h>
#include <CGAL/DGG_VTP_3/internal/unfold_input.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <limits>
#include <stdexcept>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Solver = CGAL::DGG_VTP_3::Triangle_soup_geodesic_distance_solver<Kernel>;

namespace {

struct Row
{
  std::vector<std::uint32_t> columns;
  std::vector<double> values;
};

// VmHWM: getrusage's ru_maxrss keeps the parent's peak across fork and exec (the Python script's)
double peak_rss_mb()
{
  std::ifstream status("/proc/self/status");
  std::string key;
  double kb = 0.;
  while(status >> key)
    if(key == "VmHWM:" && status >> kb)
      break;
  return kb / 1024.;
}

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 4)
  {
    std::cerr << "usage: geodesic_graph_experiment MESH EPSILON OUT.npz [THREADS]\n";
    return 1;
  }
  try
  {
    dggvtp::Loaded_soup soup = dggvtp::load_soup(argv[1]);
    const double epsilon = std::stod(argv[2]);
    const long threads = argc > 4 ? std::stol(argv[4]) : 1;
    if(!(epsilon > 0. && epsilon <= 1.) || threads < 1)
    {
      std::cerr << "error: EPSILON must be in (0, 1] and THREADS at least 1\n";
      return 1;
    }
    std::optional<Solver> solver;
    dggvtp::make_solver(soup, solver);
    const std::size_t n = solver->number_of_vertices();
    for(std::size_t v = 0; v < n; ++v)
      if(soup.file_vertex_of[v] != v)
      {
        std::cerr << "error: the mesh was repaired or has copies of vertices; this experiment takes clean meshes\n";
        return 1;
      }

    // the build runs on a mesh prepared as the solver's is (no class of the package has them)
    namespace I = CGAL::DGG_VTP_3::internal;
    I::Unfolded_mesh<double> mesh;
    std::optional<I::Patch_partition<double>> partition;
    I::Unfolding_order order;
    dggvtp::with_threads(threads, [&](auto tag) {
      order = I::unfold_triangle_soup<decltype(tag)>(soup.points, soup.triangles,
                                                     CGAL::Identity_property_map<Kernel::Point_3>(), Kernel(), mesh);
      partition.emplace(mesh, tag);
    });
    std::vector<std::uint32_t> all(n);
    for(std::size_t v = 0; v < n; ++v)
      all[v] = std::uint32_t(v);
    std::vector<Row> rows(n);
    std::vector<std::size_t> windows(n);
    auto t0 = std::chrono::steady_clock::now();
    dggvtp::with_threads(threads, [&](auto tag) {
      I::geodesic_graph_build_runs<decltype(tag)>(mesh, *partition, all, 0. + epsilon, [&](std::size_t k, const auto& reached,
                                                                                         const auto& w, const auto& statistics) {
        Row& r = rows[order.vertices[k]]; // in the file's numbering
        for(const auto v : reached)
          if(v != all[k] && w[v] < std::numeric_limits<double>::infinity())
          {
            r.columns.push_back(order.vertices[v]);
            r.values.push_back(w[v]);
          }
        windows[order.vertices[k]] = statistics.windows_created;
      });
    });
    const double seconds_runs = seconds_since(t0);

    // the set-up of as many queries, each within distance 0 (its source alone)
    std::vector<std::array<std::size_t, 1>> sets(n);
    for(std::size_t v = 0; v < n; ++v)
      sets[v] = {{v}};
    t0 = std::chrono::steady_clock::now();
    dggvtp::with_threads(threads, [&](auto tag) {
      solver->template compute_distances_from_each_source_set<decltype(tag)>(
        sets, [](std::size_t, const std::vector<double>&, const CGAL::DGG_VTP_3::Propagation_statistics&,
                 const std::vector<std::uint32_t>&) {},
        CGAL::DGG_VTP_3::parameters::max_distance(0.).accuracy(epsilon));
    });
    const double seconds_set_up = seconds_since(t0);

    std::vector<std::size_t> degree(n);
    std::size_t edges = 0, most = 0;
    for(std::size_t v = 0; v < n; ++v)
    {
      degree[v] = rows[v].columns.size();
      edges += degree[v];
      if(degree[v] > degree[most])
        most = v;
    }
    std::vector<std::size_t> sorted = degree;
    std::sort(sorted.begin(), sorted.end());
    std::size_t windows_total = 0;
    for(std::size_t w : windows)
      windows_total += w;

    std::ofstream out(argv[3], std::ios::binary);
    dggvtp::write_csr_npz(rows, n, dggvtp::Npy_dtype::float64,
                          [&out](const char* bytes, std::size_t size) { out.write(bytes, std::streamsize(size)); });
    out.close();
    if(!out)
      throw std::runtime_error(std::string("cannot write ") + argv[3]);

    std::printf("{\"vertices\": %zu, \"epsilon\": %g, \"threads\": %ld, \"edges\": %zu, \"mean_degree\": %.2f, "
                "\"max_degree\": %zu, \"max_degree_at\": %zu, \"p99_degree\": %zu, \"windows_per_vertex\": %.1f, "
                "\"max_windows\": %zu, \"seconds_runs\": %.3f, \"seconds_set_up\": %.3f, \"us_per_vertex\": %.1f, "
                "\"peak_rss_mb\": %.1f}\n",
                n, epsilon, threads, edges, double(edges) / double(n), degree[most], most, sorted[(99 * n) / 100],
                double(windows_total) / double(n), *std::max_element(windows.begin(), windows.end()), seconds_runs,
                seconds_set_up, 1e6 * (seconds_runs - seconds_set_up) * double(threads) / double(n),
                peak_rss_mb());
    return 0;
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  }
}
