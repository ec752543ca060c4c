// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// The library's own time for the Python call solver.distances(0, epsilon=1e-4) (see measure.py):
// thread CPU and wall seconds of compute_distances_to_nearest_source (Sequential_tag, as the module
// runs threads=1) on a soup solver built as dggvtp and the module build it. Not built by CMake:
//   g++ -O3 -DNDEBUG -frounding-math -std=gnu++17 -Iinclude -Iloader/include python/measure_propagation.cpp \
//       -o measure_propagation -lgmpxx -lmpfr -lgmp
//   ./measure_propagation MESH [RUNS]

#include <dggvtp/load_mesh.h>

#include <CGAL/DGG_VTP_3.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <optional>
#include <vector>

int main(int argc, char** argv)
{
  using Solver = CGAL::DGG_VTP_3::Triangle_soup_geodesic_distance_solver<CGAL::Exact_predicates_inexact_constructions_kernel>;
  dggvtp::Loaded_soup soup = dggvtp::load_soup(argv[1]);
  std::optional<Solver> solver;
  dggvtp::make_solver(soup, solver);
  const int runs = argc > 2 ? std::atoi(argv[2]) : 5;
  std::vector<double> d(solver->number_of_vertices());
  for(int r = 0; r < runs; ++r)
  {
    timespec a, b;
    const auto w0 = std::chrono::steady_clock::now();
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &a);
    solver->compute_distances_to_nearest_source<CGAL::Sequential_tag>(std::vector<std::size_t>{0}, CGAL::make_property_map(d),
                                                                      CGAL::parameters::accuracy(1e-4));
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &b);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
    std::printf("cpu %.3f wall %.3f\n", (b.tv_sec - a.tv_sec) + 1e-9 * (b.tv_nsec - a.tv_nsec), wall);
    std::fflush(stdout);
  }
}
