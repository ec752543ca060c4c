// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team
//
// Stopping early. With max_distance the propagation stops at that distance: nearer vertices get
// their distance, farther ones +infinity. With targets it stops as soon as the distances of the
// targets are final, and target_distances receives them; the cost then depends on how far the
// targets are, not on the size of the mesh.

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using vertex_descriptor = Mesh::Vertex_index;
namespace DP = CGAL::DGG_VTP_3::parameters;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : DGG_VTP_3_DATA_DIR "/spot.ply";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Invalid input: " << filename << " is not a triangle mesh." << std::endl;
    return EXIT_FAILURE;
  }
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh> solver(mesh);
  const vertex_descriptor source = *vertices(mesh).begin();
  const auto close = [](double a, double b) { return std::abs(a - b) <= 1e-12 * b; };

  // the whole field, for comparison
  auto full = mesh.add_property_map<vertex_descriptor, double>("v:full").first;
  const CGAL::DGG_VTP_3::Propagation_statistics all = solver.compute_distances(source, full);
  double farthest = 0.;
  for(vertex_descriptor v : vertices(mesh))
    farthest = (std::max)(farthest, full[v]);
  bool right = true;

  // up to a third of the way to the farthest vertex
  const double limit = farthest / 3;
  auto limited = mesh.add_property_map<vertex_descriptor, double>("v:limited").first;
  const CGAL::DGG_VTP_3::Propagation_statistics near =
    solver.compute_distances(source, limited, DP::max_distance(limit));
  for(vertex_descriptor v : vertices(mesh))
  {
    if(full[v] < limit * (1 - 1e-12))
      right = right && close(limited[v], full[v]);
    else if(full[v] > limit * (1 + 1e-12))
      right = right && limited[v] == std::numeric_limits<double>::infinity();
  }
  std::cout << "max_distance " << limit << ": " << near.vertices_reached << " of " << all.vertices_reached
            << " vertices reached, " << near.windows_created << " windows instead of " << all.windows_created
            << std::endl;

  // three targets at about a tenth, a quarter and half of the farthest distance
  std::vector<vertex_descriptor> targets;
  for(double fraction : {0.1, 0.25, 0.5})
  {
    vertex_descriptor best = source;
    for(vertex_descriptor v : vertices(mesh))
      if(std::abs(full[v] - fraction * farthest) < std::abs(full[best] - fraction * farthest))
        best = v;
    targets.push_back(best);
  }
  std::vector<double> at_targets;
  auto upper_bounds = mesh.add_property_map<vertex_descriptor, double>("v:upper_bounds").first;
  const CGAL::DGG_VTP_3::Propagation_statistics to_targets = solver.compute_distances(
    source, upper_bounds, DP::target_distances(std::back_inserter(at_targets), DP::targets(targets)));
  for(std::size_t k = 0; k < targets.size(); ++k)
  {
    std::cout << "target " << targets[k] << ": distance " << at_targets[k] << std::endl;
    right = right && close(at_targets[k], full[targets[k]]);
  }
  std::cout << "targets: " << to_targets.windows_created << " windows instead of " << all.windows_created
            << std::endl;
  return right && at_targets.size() == targets.size() ? EXIT_SUCCESS : EXIT_FAILURE;
}
