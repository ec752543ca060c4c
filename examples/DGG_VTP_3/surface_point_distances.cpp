// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team
//
// Sources and targets anywhere on the surface, not only at vertices: 3D points are located on the
// mesh with Polygon_mesh_processing (an AABB tree for several points), and the locations, a face
// and barycentric coordinates, are what the solver takes. The distance at a target point inside a
// face is computed there, not interpolated from the face's corners.

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
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
using Point_3 = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point_3>;
using Solver = CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh>;
namespace PMP = CGAL::Polygon_mesh_processing;
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

  // 3D points near the surface: the centroids of a few faces, moved a little off it
  std::vector<Point_3> points;
  for(std::size_t k = 0; k < 4; ++k)
  {
    const Mesh::Halfedge_index h = halfedge(Mesh::Face_index(static_cast<Mesh::size_type>(k * num_faces(mesh) / 4)), mesh);
    points.push_back(CGAL::centroid(mesh.point(source(h, mesh)), mesh.point(target(h, mesh)),
                                    mesh.point(target(next(h, mesh), mesh))) + Kernel::Vector_3(1e-4, 1e-4, 1e-4));
  }
  // their nearest points of the surface
  CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<Mesh>>> tree;
  PMP::build_AABB_tree(mesh, tree);
  std::vector<Solver::Face_location> locations;
  for(const Point_3& p : points)
    locations.push_back(PMP::locate_with_AABB_tree(p, tree, mesh));
  const Solver::Face_location source_location = locations[0];
  const std::vector<Solver::Face_location> targets(locations.begin() + 1, locations.end());

  const Solver solver(mesh);
  auto distance = mesh.add_property_map<Mesh::Vertex_index, double>("v:distance").first;
  solver.compute_distances(source_location, distance);
  // the same query, stopped once the targets are final (the vertices then hold upper bounds)
  auto upper_bound = mesh.add_property_map<Mesh::Vertex_index, double>("v:upper_bound").first;
  std::vector<double> at_targets;
  solver.compute_distances(source_location, upper_bound,
                           DP::target_distances(std::back_inserter(at_targets), DP::targets(targets)));

  // Checks that need no other solver. Inside the source's face, the straight segment is the
  // shortest path; and no path is shorter than the straight segment through space, nor longer
  // than the one through the nearest corner of the target's face.
  const Point_3 s = PMP::construct_point(source_location, mesh);
  bool right = true;
  for(Mesh::Vertex_index c : vertices_around_face(halfedge(source_location.first, mesh), mesh))
  {
    const double straight = std::sqrt(CGAL::squared_distance(s, mesh.point(c)));
    right = right && std::abs(distance[c] - straight) <= 1e-12 * straight;
  }
  for(std::size_t k = 0; k < targets.size(); ++k)
  {
    const Point_3 t = PMP::construct_point(targets[k], mesh);
    double through_a_corner = std::numeric_limits<double>::infinity();
    for(Mesh::Vertex_index c : vertices_around_face(halfedge(targets[k].first, mesh), mesh))
      through_a_corner = (std::min)(through_a_corner, distance[c] + std::sqrt(CGAL::squared_distance(mesh.point(c), t)));
    const double through_space = std::sqrt(CGAL::squared_distance(s, t));
    std::cout << "target " << k << " at (" << t << "): distance " << at_targets[k] << ", straight line "
              << through_space << ", through a corner " << through_a_corner << std::endl;
    right = right && at_targets[k] >= through_space * (1 - 1e-12) && at_targets[k] <= through_a_corner * (1 + 1e-12);
  }
  return right ? EXIT_SUCCESS : EXIT_FAILURE;
}
