// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// What the loader makes of a mesh file or of arrays: a soup in the file's vertex order.

#ifndef DGGVTP_LOADED_SOUP_H
#define DGGVTP_LOADED_SOUP_H

#include <dggvtp/input_error.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace dggvtp {

// A mesh file as a polygon soup in the file's vertex order, made into a valid polygon mesh
// without renumbering the file's vertices: repairs only append points.
struct Loaded_soup
{
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  std::vector<Point> points;                     // the file's points, then the duplicates made by repairs
  // the faces when all are triangles, each with its corners in the order of the face of a
  // Surface_mesh made from the file (its halfedge(f) starts at the third vertex), so that the
  // propagation, and the distances to the last bit, do not depend on the path through loading;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::vector<std::size_t>> polygons; // or else the polygons
  std::size_t file_vertices = 0;                 // points declared by the file
  std::vector<std::size_t> file_vertex_of;       // per point: the file vertex it stands for
  std::vector<std::string> repairs;              // what loading changed, for a warning
};

// The repairs a caller asks for (dggvtp's --repair, the Python module's repair=True), and the name
// that messages give them: what the loader refuses says that they exist, what they change says
// that they did it.
struct Repair_option
{
  std::string name = "--repair";
  bool on = false;
};

template <class Polygon>
std::array<std::uint32_t, 3> as_surface_mesh_face(const Polygon& p)
{
  return {std::uint32_t(p[2]), std::uint32_t(p[0]), std::uint32_t(p[1])};
}

} // namespace dggvtp

#endif // DGGVTP_LOADED_SOUP_H
