// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team
//
// Shortest paths from a point of the surface to a few others, as polylines drawn into an OBJ
// file (`l` lines, which MeshLab and ParaView open next to the mesh): the points are located on
// the surface from 3D points with Polygon_mesh_processing::locate(), the query stops once the
// targets are final, and each path is traced back from its target.

#include <CGAL/DGG_VTP_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Surface_mesh.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Solver = CGAL::DGG_VTP_3::Geodesic_distance_solver<Mesh>;
using Tree = CGAL::DGG_VTP_3::Shortest_path_tree<Solver>;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : DGG_VTP_3_DATA_DIR "/spot.ply";
  const std::string output = (argc > 2) ? argv[2] : "paths.obj";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Invalid input: " << filename << " is not a triangle mesh." << std::endl;
    return EXIT_FAILURE;
  }

  // the source and the targets: the surface points nearest to some 3D points (here, vertices
  // moved off the surface a little)
  const std::vector<Mesh::Vertex_index> some(vertices(mesh).begin(), vertices(mesh).end());
  const auto near = [&](std::size_t k) {
    return PMP::locate(mesh.point(some[k * some.size() / 5]) + Kernel::Vector_3(1e-3, 1e-3, 1e-3), mesh);
  };
  const std::vector<Solver::Face_location> source = {near(0)};
  const std::vector<Solver::Face_location> targets = {near(1), near(2), near(3), near(4)};

  const Solver solver(mesh);
  namespace DP = CGAL::DGG_VTP_3::parameters;
  const Tree tree = solver.compute_shortest_path_tree(source, DP::targets(targets));

  std::ofstream obj(output);
  std::size_t written = 0;
  for(std::size_t k = 0; k < targets.size(); ++k)
  {
    std::vector<Tree::Path_point> path;
    tree.shortest_path_to_target(k, std::back_inserter(path));
    std::vector<Kernel::Point_3> points;
    Tree::points(mesh, path, std::back_inserter(points));
    double length = 0.;
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      obj << "v " << points[i] << "\n";
      if(i > 0)
        length += std::sqrt(CGAL::squared_distance(points[i - 1], points[i]));
    }
    obj << "l";
    for(std::size_t i = 0; i < points.size(); ++i)
      obj << " " << written + i + 1;
    obj << "\n";
    written += points.size();
    std::cout << "target " << k << ": distance " << tree.target_distance(k) << ", path of " << points.size()
              << " points, length " << length << std::endl;
    if(std::abs(length - tree.target_distance(k)) > 1e-9 * tree.target_distance(k))
      return EXIT_FAILURE;
  }
  std::cout << "paths written to " << output << std::endl;
  return EXIT_SUCCESS;
}
