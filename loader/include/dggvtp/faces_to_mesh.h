// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// The faces of a polygon soup added to a Surface_mesh one by one.

#ifndef DGGVTP_FACES_TO_MESH_H
#define DGGVTP_FACES_TO_MESH_H

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <cstddef>
#include <vector>

namespace dggvtp {
namespace internal {

// Adds `polygons` (indices into `points`) to the empty `mesh` face by face, and returns the number
// of faces that did not fit. Not by polygon_soup_to_polygon_mesh(): its precondition is a soup it
// can take whole, without a vertex where separate fans meet (which a Surface_mesh holds), and it
// left a face that did not fit out only in builds without assertions. Euler::add_face() refuses
// such a face by returning the null face.
template <class Point, class PointRange, class PolygonRange>
std::size_t faces_to_mesh(const PointRange& points, const PolygonRange& polygons, CGAL::Surface_mesh<Point>& mesh)
{
  using Vertex = typename CGAL::Surface_mesh<Point>::Vertex_index;
  mesh.reserve(points.size(), 2 * polygons.size(), polygons.size());
  for(const auto& p : points) // an empty mesh numbers them 0, 1, ... as the polygons do
    mesh.add_vertex(Point(p));
  std::size_t left_out = 0;
  std::vector<Vertex> corners;
  for(const auto& polygon : polygons)
  {
    corners.clear();
    for(std::size_t v : polygon)
      corners.push_back(Vertex(typename Vertex::size_type(v)));
    if(CGAL::Euler::add_face(corners, mesh) == CGAL::Surface_mesh<Point>::null_face())
      ++left_out;
  }
  return left_out;
}

} // namespace internal
} // namespace dggvtp

#endif // DGGVTP_FACES_TO_MESH_H
