// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

#ifndef DGGVTP_LOAD_MESH_H
#define DGGVTP_LOAD_MESH_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace dggvtp {

// Bad input: the message goes to the user as `error: <message>`, exit status 2.
struct Input_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// A mesh file as a polygon soup in the file's vertex order, made into a valid polygon mesh
// without renumbering the file's vertices: repairs only append points.
struct Loaded_soup
{
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  std::vector<Point> points;                     // the file's points, then the duplicates made by repairs
  std::vector<std::vector<std::size_t>> polygons;
  std::size_t file_vertices = 0;                 // points declared by the file
  std::vector<std::size_t> file_vertex_of;       // per point: the file vertex it stands for
  std::vector<std::string> repairs;              // what loading changed, for a warning
};

namespace internal {

// orient_polygon_soup copies its visitor, so the copy reports into the soup it points to
struct Repair_visitor : CGAL::Polygon_mesh_processing::Default_orientation_visitor
{
  std::size_t* duplicated;
  std::size_t* reversed;
  std::vector<std::size_t>* file_vertex_of;
  void duplicated_vertex(std::size_t original, std::size_t copy)
  {
    ++*duplicated;
    if(file_vertex_of->size() <= copy)
      file_vertex_of->resize(copy + 1);
    (*file_vertex_of)[copy] = (*file_vertex_of)[original];
  }
  void polygon_orientation_reversed(std::size_t) { ++*reversed; }
};

} // namespace internal

inline Loaded_soup load_soup(const std::string& path)
{
  Loaded_soup soup;
  if(!std::ifstream(path).good())
    throw Input_error("cannot open '" + path + "'");
  if(!CGAL::IO::read_polygon_soup(path, soup.points, soup.polygons, CGAL::parameters::verbose(false)))
    throw Input_error("cannot read '" + path + "' as a mesh (unsupported format, or an invalid or truncated file)");
  if(soup.points.empty())
    throw Input_error("'" + path + "' has no vertices");
  soup.file_vertices = soup.points.size();
  for(std::size_t i = 0; i < soup.points.size(); ++i)
    for(int c = 0; c < 3; ++c)
      if(!std::isfinite(soup.points[i][c]))
        throw Input_error("vertex " + std::to_string(i) + " has a coordinate that is not finite");
  for(std::size_t f = 0; f < soup.polygons.size(); ++f)
  {
    const auto& polygon = soup.polygons[f];
    if(polygon.size() < 3)
      throw Input_error("face " + std::to_string(f) + " has fewer than 3 vertices");
    for(std::size_t k = 0; k < polygon.size(); ++k)
    {
      if(polygon[k] >= soup.file_vertices)
        throw Input_error("face " + std::to_string(f) + " refers to vertex " + std::to_string(polygon[k]) +
                          ", but the file has " + std::to_string(soup.file_vertices) + " vertices");
      for(std::size_t j = 0; j < k; ++j)
        if(polygon[j] == polygon[k])
          throw Input_error("face " + std::to_string(f) + " uses vertex " + std::to_string(polygon[k]) + " twice");
    }
  }

  soup.file_vertex_of.resize(soup.points.size());
  for(std::size_t i = 0; i < soup.points.size(); ++i)
    soup.file_vertex_of[i] = i;
  std::size_t duplicated = 0, reversed = 0;
  internal::Repair_visitor visitor;
  visitor.duplicated = &duplicated;
  visitor.reversed = &reversed;
  visitor.file_vertex_of = &soup.file_vertex_of;
  CGAL::Polygon_mesh_processing::orient_polygon_soup(soup.points, soup.polygons, CGAL::parameters::visitor(visitor));
  soup.file_vertex_of.resize(soup.points.size());
  if(duplicated > 0)
    soup.repairs.push_back("split " + std::to_string(duplicated) + " non-manifold vertices");
  if(reversed > 0)
    soup.repairs.push_back("reoriented " + std::to_string(reversed) + " faces");
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(soup.polygons))
    throw Input_error("the faces of '" + path + "' do not form a valid surface, even after orienting them");
  return soup;
}

// The soup as a triangle mesh with the point type of `Kernel`; mesh vertex i is soup point i.
template <class Kernel>
CGAL::Surface_mesh<typename Kernel::Point_3> make_triangle_mesh(Loaded_soup& soup)
{
  using Point = typename Kernel::Point_3;
  std::vector<Point> points;
  points.reserve(soup.points.size());
  for(const auto& p : soup.points)
    points.emplace_back(typename Kernel::FT(p.x()), typename Kernel::FT(p.y()), typename Kernel::FT(p.z()));
  CGAL::Surface_mesh<Point> mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, soup.polygons, mesh);
  if(!CGAL::is_triangle_mesh(mesh))
  {
    soup.repairs.push_back("triangulated the faces with more than 3 vertices");
    if(!CGAL::Polygon_mesh_processing::triangulate_faces(mesh))
      throw Input_error("a face with more than 3 vertices could not be triangulated");
  }
  return mesh;
}

} // namespace dggvtp

#endif // DGGVTP_LOAD_MESH_H
