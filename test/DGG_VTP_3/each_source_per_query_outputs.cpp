// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// Must NOT compile: compute_distances_from_each_source refuses the named parameters whose output
// belongs to one query (tests each_source_refuses_*: with DGG_VTP_3_TARGETS, targets; with
// DGG_VTP_3_TARGET_DISTANCES, target_distances; with DGG_VTP_3_NEAREST_SOURCE_MAP,
// nearest_source_map; with DGG_VTP_3_CALLBACK, callback), with a static_assert that says so.

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <functional>
#include <iterator>
#include <vector>

using Mesh = CGAL::Surface_mesh<CGAL::Epick::Point_3>;

int main()
{
  const Mesh mesh;
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh> solver(mesh);
  const std::vector<Mesh::Vertex_index> sources;
  const std::vector<Mesh::Property_map<Mesh::Vertex_index, double>> fields;
#if defined(DGG_VTP_3_TARGETS)
  solver.compute_distances_from_each_source(sources, fields, CGAL::DGG_VTP_3::parameters::targets(sources));
#elif defined(DGG_VTP_3_TARGET_DISTANCES)
  std::vector<double> at_targets;
  solver.compute_distances_from_each_source(sources, fields,
                                            CGAL::DGG_VTP_3::parameters::target_distances(std::back_inserter(at_targets)));
#elif defined(DGG_VTP_3_NEAREST_SOURCE_MAP)
  const Mesh::Property_map<Mesh::Vertex_index, std::size_t> labels;
  solver.compute_distances_from_each_source(sources, fields, CGAL::DGG_VTP_3::parameters::nearest_source_map(labels));
#elif defined(DGG_VTP_3_CALLBACK)
  const std::function<bool(double)> progress = [](double) { return true; };
  solver.compute_distances_from_each_source(sources, fields, CGAL::parameters::callback(progress));
#else
  solver.compute_distances_from_each_source(sources, fields); // compiles: the control
#endif
}
