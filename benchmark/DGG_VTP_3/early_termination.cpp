// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team
//
// Early termination against the full field, in one process, the variants alternating REPEAT
// times (medians):
//
//   early_termination MESH EPSILON REPEAT [FRACTION]
//
// The source is a point inside face 0 (barycentric 0.2, 0.3, 0.5). The mesh's diameter D is the
// diagonal of its bounding box; the target is the centre of a face of the vertex whose distance
// from the source is nearest FRACTION * D (default 0.1). Prints a Markdown table row per variant:
// the full field; targets = {that point, that vertex}; max_distance = FRACTION * D; with the
// query's time, its ratio to the full field's, the windows, the vertices popped, and the vertex's
// distance (the full field's in every variant: checked, exit status 3 otherwise).

#include <dggvtp/load_mesh.h>

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/locate.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Solver = CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh>;
namespace DP = CGAL::DGG_VTP_3::parameters;

namespace {

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 4)
  {
    std::cerr << "usage: early_termination MESH EPSILON REPEAT [FRACTION]\n";
    return 1;
  }
  try
  {
    dggvtp::Loaded_soup soup = dggvtp::load_soup(argv[1]);
    Mesh mesh = dggvtp::make_triangle_mesh<Kernel>(soup);
    const double epsilon = std::stod(argv[2]);
    const int repeat = (std::max)(1, std::stoi(argv[3]));
    const double fraction = argc > 4 ? std::stod(argv[4]) : 0.1;
    const Solver solver(mesh);
    auto distance = mesh.add_property_map<Mesh::Vertex_index, double>("v:d").first;
    const Solver::Face_location source(*faces(mesh).begin(), {0.2, 0.3, 0.5});

    // the target: near the vertex at FRACTION * D from the source
    const CGAL::Bbox_3 box = CGAL::bbox_3(mesh.points().begin(), mesh.points().end());
    const double diameter = std::sqrt(std::pow(box.xmax() - box.xmin(), 2) + std::pow(box.ymax() - box.ymin(), 2) +
                                      std::pow(box.zmax() - box.zmin(), 2));
    const double cutoff = fraction * diameter;
    solver.compute_distances(source, distance, CGAL::parameters::accuracy(epsilon));
    Mesh::Vertex_index nearest;
    double gap = std::numeric_limits<double>::infinity();
    for(auto v : vertices(mesh))
      if(std::abs(get(distance, v) - cutoff) < gap)
      {
        gap = std::abs(get(distance, v) - cutoff);
        nearest = v;
      }
    const Solver::Face_location target(face(halfedge(nearest, mesh), mesh), {1. / 3., 1. / 3., 1. / 3.});
    const std::vector<Solver::Face_location> targets(1, target);
    const Solver::Face_location at_nearest = CGAL::Polygon_mesh_processing::locate_vertex<double>(nearest, mesh);

    // three variants, alternating: the full field; targets = {the point, the vertex}; max_distance
    std::vector<double> seconds[3];
    CGAL::DGG_VTP_3::Propagation_statistics statistics[3];
    double at_vertex[3] = {0., 0., 0.}, at_point = 0.;
    for(int r = 0; r < repeat; ++r)
      for(int k = 0; k < 3; ++k)
      {
        std::vector<double> at;
        const std::vector<Solver::Face_location> both = {target, at_nearest};
        const auto t0 = std::chrono::steady_clock::now();
        if(k == 0)
          statistics[k] = solver.compute_distances(source, distance, CGAL::parameters::accuracy(epsilon));
        else if(k == 1)
          statistics[k] = solver.compute_distances(
            source, distance, DP::target_distances(std::back_inserter(at), DP::targets(both)).accuracy(epsilon));
        else
          statistics[k] = solver.compute_distances(source, distance, DP::max_distance(cutoff).accuracy(epsilon));
        seconds[k].push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        at_vertex[k] = k == 1 ? at[1] : get(distance, nearest);
        if(k == 1)
          at_point = at[0];
      }
    const std::string mode = epsilon > 0. ? "1e" + std::to_string(int(std::lround(std::log10(epsilon)))) : "exact";
    const double full = median(seconds[0]);
    const char* names[3] = {"full field", "targets: a point and a vertex", "max_distance"};
    std::printf("| mode | cutoff (%.2g x bbox diagonal) | variant | seconds (median of %d) | full / this | windows created "
                "| vertices popped | distance at the vertex |\n|---|---:|---|---:|---:|---:|---:|---:|\n", fraction, repeat);
    for(int k = 0; k < 3; ++k)
    {
      const double t = median(seconds[k]);
      std::printf("| %s | %.4g | %s | %.3f | %.1f | %zu | %zu | %.17g |\n", mode.c_str(), cutoff, names[k], t, full / t,
                  statistics[k].windows_created, statistics[k].vertices_popped, at_vertex[k]);
    }
    std::printf("\ntarget point: %.17g (%zu vertices)\n", at_point, num_vertices(mesh));
    // the vertex's distance is the full field's in every variant (max_distance: unless beyond)
    const bool same = at_vertex[1] == at_vertex[0] && (at_vertex[2] == at_vertex[0] || (at_vertex[0] > cutoff && std::isinf(at_vertex[2])));
    return same ? 0 : 3;
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  }
}
