// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// Must NOT compile: Parallel_tag without TBB (CGAL_LINKED_WITH_TBB undefined) is a compile-time
// error with a clear message, as in Polygon_mesh_processing (tests parallel_tag_needs_tbb: the
// many-sources query, and with DGG_VTP_3_ONE_PROPAGATION defined, a single propagation).

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <vector>

using Mesh = CGAL::Surface_mesh<CGAL::Epick::Point_3>;

int main()
{
  const Mesh mesh;
  const CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh> solver(mesh);
  const std::vector<Mesh::Vertex_index> sources;
#ifdef DGG_VTP_3_ONE_PROPAGATION
  std::vector<double> distances;
  solver.compute_distances_to_nearest_source<CGAL::Parallel_tag>(sources, CGAL::make_property_map(distances));
#else
  const std::vector<Mesh::Property_map<Mesh::Vertex_index, double>> fields;
  solver.compute_distances_from_each_source<CGAL::Parallel_tag>(sources, fields);
#endif
}
