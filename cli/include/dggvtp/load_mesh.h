// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

#ifndef DGGVTP_LOAD_MESH_H
#define DGGVTP_LOAD_MESH_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <set>
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
  {
    errno = 0;
    std::ifstream probe(path);
    if(!probe.good())
      throw Input_error("cannot read '" + path + "': " + (errno != 0 ? std::strerror(errno) : "cannot open it"));
  }
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
  return soup;
}

// Orients the polygons consistently, splitting non-manifold vertices (appended copies).
inline void orient_soup(Loaded_soup& soup)
{
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
}

namespace internal {

template <class Kernel>
CGAL::Surface_mesh<typename Kernel::Point_3> soup_to_mesh(const Loaded_soup& soup)
{
  using Point = typename Kernel::Point_3;
  std::vector<Point> points;
  points.reserve(soup.points.size());
  for(const auto& p : soup.points)
    points.emplace_back(typename Kernel::FT(p.x()), typename Kernel::FT(p.y()), typename Kernel::FT(p.z()));
  CGAL::Surface_mesh<Point> mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, soup.polygons, mesh);
  return mesh;
}

} // namespace internal

// The soup as a triangle mesh with the point type of `Kernel`; mesh vertex i is soup point i.
// Consumes the soup's points and polygons.
template <class Kernel>
CGAL::Surface_mesh<typename Kernel::Point_3> make_triangle_mesh(Loaded_soup& soup)
{
  // A face that does not fit (inconsistent orientation, more than two faces on an edge) is left
  // out by the conversion; only then is the soup oriented, which on a clean million-face file
  // would cost ten times the rest of loading.
  auto mesh = internal::soup_to_mesh<Kernel>(soup);
  if(num_faces(mesh) != soup.polygons.size())
  {
    orient_soup(soup);
    mesh = internal::soup_to_mesh<Kernel>(soup);
    if(num_faces(mesh) != soup.polygons.size())
      throw Input_error("the faces do not form a surface, even after orienting them");
  }
  // a vertex where separate fans of faces meet is kept as it is (geodesics may go from one fan to
  // the other through it); say so, since such input is often a defect
  std::vector<typename boost::graph_traits<decltype(mesh)>::halfedge_descriptor> pinched;
  CGAL::Polygon_mesh_processing::non_manifold_vertices(mesh, std::back_inserter(pinched));
  std::set<std::size_t> pinched_vertices;
  for(auto h : pinched)
    pinched_vertices.insert(std::size_t(target(h, mesh)));
  if(!pinched_vertices.empty())
    soup.repairs.push_back("kept " + std::to_string(pinched_vertices.size()) +
                           " non-manifold vertices, where separate fans of faces meet");
  // the mesh holds everything now: give the soup's memory back before the propagation
  std::vector<typename Loaded_soup::Point>().swap(soup.points);
  std::vector<std::vector<std::size_t>>().swap(soup.polygons);
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
