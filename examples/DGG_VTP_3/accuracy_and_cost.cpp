// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team
//
// Choosing the accuracy epsilon of DGG-VTP: the same source in the exact mode (accuracy 0) and at
// a few epsilons, with the largest relative error each one makes against the exact distances and
// what it costs. Every distance of DGG-VTP is the length of a path on the surface, so it is never
// below the exact one; epsilon bounds how far above. Take the largest epsilon whose error the
// application tolerates: the windows then stop sooner.

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <string>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using vertex_descriptor = Mesh::Vertex_index;
using Distance_map = Mesh::Property_map<vertex_descriptor, double>;

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
  const vertex_descriptor source = *vertices(mesh).begin();

  // the time and the windows of one query with this accuracy (0: exact)
  const auto run = [&](double accuracy, Distance_map distance) {
    const auto start = std::chrono::steady_clock::now();
    const CGAL::DGG_VTP_3::Propagation_statistics stats =
      solver.compute_distances(source, distance, CGAL::parameters::accuracy(accuracy));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << "accuracy " << accuracy << ": " << seconds << " s, " << stats.windows_created << " windows";
    return seconds;
  };

  Distance_map exact = mesh.add_property_map<vertex_descriptor, double>("v:exact").first;
  Distance_map approximate = mesh.add_property_map<vertex_descriptor, double>("v:approximate").first;
  const double seconds_exact = run(0., exact);
  std::cout << std::endl;

  bool within = true;
  for(double epsilon : {1e-2, 1e-4, 1e-6})
  {
    const double seconds = run(epsilon, approximate);
    double largest = 0.;
    for(vertex_descriptor v : vertices(mesh))
    {
      if(exact[v] == 0.)
        continue;
      const double error = (approximate[v] - exact[v]) / exact[v];
      largest = (std::max)(largest, error);
      // never shorter than the exact distance, beyond rounding
      within = within && error > -1e-12;
    }
    std::cout << ", largest relative error " << largest << " (" << largest / epsilon << " epsilon), "
              << seconds_exact / seconds << " times as fast as exact" << std::endl;
    within = within && largest <= epsilon;
  }
  return within ? EXIT_SUCCESS : EXIT_FAILURE;
}
