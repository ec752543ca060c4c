// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

#ifndef DGGVTP_LOAD_MESH_H
#define DGGVTP_LOAD_MESH_H

#include <dggvtp/check_off.h>
#include <dggvtp/check_ply.h>
#include <dggvtp/faces_to_mesh.h>
#include <dggvtp/fast_read.h>
#include <dggvtp/input_error.h>
#include <dggvtp/loaded_soup.h>
#include <dggvtp/triangulate.h>

#include <CGAL/DGG_VTP_3/parameters.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/io.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace dggvtp {

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

// a file that does not open gets the same error whichever reader would have read it
inline void check_readable(const std::string& path)
{
  errno = 0;
  std::ifstream probe(path);
  if(!probe.good())
    throw Input_error("cannot read '" + path + "': " + (errno != 0 ? std::strerror(errno) : "cannot open it"));
}

// the format as CGAL's read_polygon_soup chooses it
inline std::string lower_case_extension(const std::string& path)
{
  std::string extension = path.substr(path.rfind('.') == std::string::npos ? path.size() : path.rfind('.') + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return extension;
}

// Leaves out the faces marked in `marked` (one per face); returns how many.
template <class Face>
std::size_t leave_out(std::vector<Face>& faces, const std::vector<char>& marked)
{
  std::size_t kept = 0;
  for(std::size_t f = 0; f < faces.size(); ++f)
    if(!marked[f])
    {
      if(kept != f)
        faces[kept] = std::move(faces[f]);
      ++kept;
    }
  const std::size_t dropped = faces.size() - kept;
  faces.resize(kept);
  return dropped;
}

// Leaves out the faces marked in `marked` (one per face), with a line "--repair: dropped N faces
// with a repeated corner" in `repairs` if any.
template <class Face>
void drop_faces(std::vector<Face>& faces, const std::vector<char>& marked, const Repair_option& repair,
                std::vector<std::string>& repairs)
{
  if(const std::size_t dropped = leave_out(faces, marked))
    repairs.push_back(repair.name + ": dropped " + std::to_string(dropped) + " faces with a repeated corner");
}

// Leaves out every triangle on the same three vertices as one before it, with a line in
// `repairs`: split into sheets, they would be sheets of one triangle, which the solver refuses
// (see Vertex_copies.h: windows between them multiply without end), and a path through one of
// them is as long through the one kept, so that no distance changes.
inline void drop_repeated_triangles(std::vector<std::vector<std::size_t>>& triangles, std::vector<std::string>& repairs)
{
  std::vector<std::pair<std::array<std::size_t, 3>, std::size_t>> corners(triangles.size());
  for(std::size_t f = 0; f < triangles.size(); ++f)
  {
    std::array<std::size_t, 3> c{triangles[f][0], triangles[f][1], triangles[f][2]};
    std::sort(c.begin(), c.end());
    corners[f] = {c, f};
  }
  std::sort(corners.begin(), corners.end());
  std::vector<char> repeated(triangles.size(), 0);
  for(std::size_t k = 1; k < corners.size(); ++k)
    if(corners[k].first == corners[k - 1].first)
      repeated[corners[k].second] = 1;
  if(const std::size_t dropped = leave_out(triangles, repeated))
    repairs.push_back("dropped " + std::to_string(dropped) + " faces on the same three vertices as another face");
}

// Every point is the file's own so far: the file's vertices, numbered as in the file (repairs
// append copies later).
inline void number_file_vertices(Loaded_soup& soup)
{
  soup.file_vertices = soup.points.size();
  soup.file_vertex_of.resize(soup.points.size());
  std::iota(soup.file_vertex_of.begin(), soup.file_vertex_of.end(), std::size_t(0));
}

// A fast reader's soup as load_soup_with_cgal() makes it of the same file, or nothing where one
// of its checks fails (a face repeating a vertex, too many points for 32-bit indices): that path
// then refuses the file, or takes it, as before. The fast readers already refuse what else it
// checks (no vertices, a coordinate not finite, a face of fewer than 3 vertices, an index beyond
// the vertices).
inline std::optional<Loaded_soup> soup_of(Fast_soup& fast)
{
  if(fast.points.size() >= std::numeric_limits<std::uint32_t>::max())
    return std::nullopt;
  Loaded_soup soup;
  if(fast.all_triangles())
  {
    soup.triangles.reserve(fast.faces);
    for(std::size_t c = 0; c < fast.corners.size(); c += 3)
    {
      const std::uint32_t* t = &fast.corners[c];
      if(t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
        return std::nullopt;
      soup.triangles.push_back(as_surface_mesh_face(t));
    }
  }
  else
  {
    soup.polygons.reserve(fast.faces);
    std::size_t first = 0;
    for(const std::size_t last : fast.face_ends)
    {
      for(std::size_t k = first; k < last; ++k)
        for(std::size_t j = first; j < k; ++j)
          if(fast.corners[j] == fast.corners[k])
            return std::nullopt;
      soup.polygons.emplace_back(fast.corners.begin() + first, fast.corners.begin() + last);
      first = last;
    }
  }
  std::vector<std::uint32_t>().swap(fast.corners);
  soup.points.swap(fast.points);
  number_file_vertices(soup);
  return soup;
}

} // namespace internal

// The file through CGAL's reader, behind the checks above that keep it from hazardous input: the
// path of every file the fast readers do not take. Throws Input_error for input it refuses. A face
// that repeats a vertex is refused, or, with `repair` on, left out with a line in soup.repairs:
// such a face has no area, and CGAL's repairs cannot take it.
inline Loaded_soup load_soup_with_cgal(const std::string& path, const Repair_option& repair = Repair_option())
{
  Loaded_soup soup;
  internal::check_readable(path);
  {
    const std::string extension = internal::lower_case_extension(path);
    if(extension == "off")
      check_off_declarations(path);
    else if(extension == "ply")
      check_ply_declarations(path);
  }
  if(!CGAL::IO::read_polygon_soup(path, soup.points, soup.polygons, CGAL::parameters::verbose(false)))
    throw Input_error("cannot read '" + path + "' as a mesh (unsupported format, or an invalid or truncated file)");
  if(soup.points.empty())
    throw Input_error("'" + path + "' has no vertices");
  for(std::size_t i = 0; i < soup.points.size(); ++i)
    for(int c = 0; c < 3; ++c)
      if(!std::isfinite(soup.points[i][c]))
        throw Input_error("vertex " + std::to_string(i) + " has a coordinate that is not finite");
  std::vector<char> repeats(soup.polygons.size(), 0);
  for(std::size_t f = 0; f < soup.polygons.size(); ++f)
  {
    const auto& polygon = soup.polygons[f];
    if(polygon.size() < 3)
      throw Input_error("face " + std::to_string(f) + " has fewer than 3 vertices");
    for(std::size_t k = 0; k < polygon.size(); ++k)
    {
      if(polygon[k] >= soup.points.size())
        throw Input_error("face " + std::to_string(f) + " refers to vertex " + std::to_string(polygon[k]) +
                          ", but the file has " + std::to_string(soup.points.size()) + " vertices");
      for(std::size_t j = 0; j < k; ++j)
        if(polygon[j] == polygon[k] && !repair.on)
          throw Input_error("face " + std::to_string(f) + " uses vertex " + std::to_string(polygon[k]) + " twice; " +
                            repair.name + " drops such faces");
        else if(polygon[j] == polygon[k])
          repeats[f] = 1;
    }
  }
  internal::drop_faces(soup.polygons, repeats, repair, soup.repairs);

  internal::number_file_vertices(soup);
  if(soup.points.size() < std::numeric_limits<std::uint32_t>::max() &&
     std::all_of(soup.polygons.begin(), soup.polygons.end(), [](const auto& p) { return p.size() == 3; }))
  {
    soup.triangles.reserve(soup.polygons.size());
    for(const auto& p : soup.polygons)
      soup.triangles.push_back(as_surface_mesh_face(p));
    std::vector<std::vector<std::size_t>>().swap(soup.polygons);
  }
  return soup;
}

// The mesh file `path` as a soup. The common layouts of each format (internal::read_fast) are
// read in one pass of the file; any other file, and any file that input policy refuses, goes
// through load_soup_with_cgal(), which gives the same soup for what both read. Throws Input_error
// for input it refuses.
// `repair`: as for load_soup_with_cgal() (a face that repeats a vertex takes that path).
inline Loaded_soup load_soup(const std::string& path, const Repair_option& repair = Repair_option())
{
  internal::check_readable(path);
  if(std::optional<internal::Fast_soup> fast = internal::read_fast(path, internal::lower_case_extension(path)))
    if(std::optional<Loaded_soup> soup = internal::soup_of(*fast))
      return std::move(*soup);
  return load_soup_with_cgal(path, repair);
}

// what the repairs work on, when the triangles do not go to the solver as they are
inline void triangles_to_polygons(Loaded_soup& soup)
{
  soup.polygons.reserve(soup.triangles.size());
  for(const auto& t : soup.triangles)
    soup.polygons.push_back({t[1], t[2], t[0]});
  std::vector<std::array<std::uint32_t, 3>>().swap(soup.triangles);
}

namespace internal {

// Per point of the soup, the point it is a copy of (the first point of its file vertex), itself if
// none: the copies that repairs made where sheets meet are one point of the file, reached from
// every sheet (the solver's copy_of). A copy that a repair moved elsewhere is a point of its own.
inline std::vector<std::size_t> copies_of_points(const Loaded_soup& soup)
{
  std::vector<std::size_t> first(soup.file_vertices, std::size_t(-1)), copy_of(soup.file_vertex_of.size());
  for(std::size_t i = 0; i < copy_of.size(); ++i)
  {
    std::size_t& f = first[soup.file_vertex_of[i]];
    if(f == std::size_t(-1))
      f = i;
    copy_of[i] = soup.points[f] == soup.points[i] ? f : i;
  }
  return copy_of;
}

} // namespace internal

// A solver of the soup's triangles (a Triangle_soup_geodesic_distance_solver), prepared as
// `ConcurrencyTag` says, the copies of a file vertex made by repairs given as one point (copy_of).
// Throws std::invalid_argument as the solver does.
template <class Solver, class ConcurrencyTag>
Solver make_soup_solver(const Loaded_soup& soup)
{
  using Point = typename Solver::Traits::Point_3;
  using FT = typename Solver::Traits::FT;
  const auto np = CGAL::DGG_VTP_3::parameters::concurrency_tag(ConcurrencyTag());
  const auto make = [&soup, &np](const auto& points) {
    if(soup.file_vertex_of.size() == soup.file_vertices)
      return Solver(points, soup.triangles, np);
    using Copies = std::vector<std::size_t>;
    return Solver(points, soup.triangles,
                  CGAL::Named_function_parameters<Copies, CGAL::DGG_VTP_3::internal_np::copy_of_t, std::decay_t<decltype(np)>>(
                    internal::copies_of_points(soup), np));
  };
  if constexpr(std::is_same<Point, Loaded_soup::Point>::value)
    return make(soup.points);
  else
  {
    // Converted into an array first, not by a point map: GCC 12.2's vectorizer (-O2) drops the
    // rounding to float of a point made and read in the same loop, so float input would be read
    // in double.
    std::vector<Point> points;
    points.reserve(soup.points.size());
    for(const auto& p : soup.points)
      points.emplace_back(FT(p.x()), FT(p.y()), FT(p.z()));
    return make(points);
  }
}

// the solver holds everything now: give the soup's memory back before the propagation
inline void release_soup(Loaded_soup& soup)
{
  std::vector<Loaded_soup::Point>().swap(soup.points);
  std::vector<std::array<std::uint32_t, 3>>().swap(soup.triangles);
  std::vector<std::vector<std::size_t>>().swap(soup.polygons);
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
  faces_to_mesh(points, soup.polygons, mesh);
  return mesh;
}

} // namespace internal

// The soup's faces repaired into a triangle mesh with the point type of `Kernel` (mesh vertex i
// is soup point i); consumes the faces.
template <class Kernel>
CGAL::Surface_mesh<typename Kernel::Point_3> make_triangle_mesh(Loaded_soup& soup)
{
  if(soup.polygons.empty())
    triangles_to_polygons(soup);
  internal::triangulate_soup(soup);
  // A face that does not fit (inconsistent orientation, more than two faces on an edge) is left
  // out by the conversion (soup_to_mesh); only then are repeated faces dropped and the soup oriented, which on
  // a clean million-face file would cost ten times the rest of loading.
  auto mesh = internal::soup_to_mesh<Kernel>(soup);
  if(num_faces(mesh) != soup.polygons.size())
  {
    internal::drop_repeated_triangles(soup.polygons, soup.repairs);
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
  std::vector<std::vector<std::size_t>>().swap(soup.polygons);
  return mesh;
}

// The soup's polygons repaired as make_triangle_mesh() does, replaced with the triangles of the
// mesh, the corners of each in the mesh's order.
template <class Kernel>
void repair_into_triangles(Loaded_soup& soup)
{
  const auto mesh = make_triangle_mesh<Kernel>(soup);
  soup.triangles.clear();
  soup.triangles.reserve(num_faces(mesh));
  for(auto f : faces(mesh))
  {
    const auto h = halfedge(f, mesh);
    soup.triangles.push_back({std::uint32_t(source(h, mesh)), std::uint32_t(target(h, mesh)),
                              std::uint32_t(target(next(h, mesh), mesh))});
  }
}

// Builds the solver (a Triangle_soup_geodesic_distance_solver) of the soup into `solver`. A valid
// triangle soup goes to the solver as it is. Any other soup (polygons, inconsistent orientations,
// edges of more than two faces, vertices where several fans meet, or input the solver refuses)
// takes the path of repairs through a Surface_mesh, which accepts, repairs or refuses it, and goes
// to the solver as the mesh's triangles. Returns the seconds spent on repairs (not on preparing).
// The solver is prepared as `ConcurrencyTag` says, the repairs on this thread. Throws Input_error
// or std::invalid_argument for input it refuses.
template <class ConcurrencyTag = CGAL::Sequential_tag, class Solver>
double make_solver(Loaded_soup& soup, std::optional<Solver>& solver)
{
  if(soup.polygons.empty())
  {
    try
    {
      solver.emplace(make_soup_solver<Solver, ConcurrencyTag>(soup));
      if(solver->number_of_non_manifold_vertices() == 0)
        return 0.;
      solver.reset();
    }
    catch(const std::invalid_argument&)
    {
    }
  }
  const auto t0 = std::chrono::steady_clock::now();
  repair_into_triangles<typename Solver::Traits>(soup);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  solver.emplace(make_soup_solver<Solver, ConcurrencyTag>(soup));
  return seconds;
}

// The solver's vertices that stand for the file vertex `file_vertex`: the vertex itself and the
// copies loading made of it (a source is a source on every sheet).
inline std::vector<std::size_t> solver_vertices_of(const Loaded_soup& soup, std::size_t file_vertex)
{
  std::vector<std::size_t> out;
  for(std::size_t i = 0; i < soup.file_vertex_of.size(); ++i)
    if(soup.file_vertex_of[i] == file_vertex)
      out.push_back(i);
  return out;
}

// The solver vertices of each file vertex of `file_vertices` (as solver_vertices_of() gives them),
// in one pass over the solver's vertices
inline std::vector<std::vector<std::size_t>> solver_vertex_sets(const Loaded_soup& soup,
                                                               const std::vector<std::size_t>& file_vertices)
{
  std::vector<std::size_t> set_of(soup.file_vertices, file_vertices.size()); // the last set of each
  for(std::size_t k = 0; k < file_vertices.size(); ++k)
    set_of[file_vertices[k]] = k;
  std::vector<std::vector<std::size_t>> sets(file_vertices.size());
  for(std::size_t i = 0; i < soup.file_vertex_of.size(); ++i)
    if(set_of[soup.file_vertex_of[i]] < file_vertices.size())
      sets[set_of[soup.file_vertex_of[i]]].push_back(i);
  for(std::size_t k = 0; k < file_vertices.size(); ++k) // a file vertex given twice
    if(set_of[file_vertices[k]] != k)
      sets[k] = sets[set_of[file_vertices[k]]];
  return sets;
}

// Per file vertex, the smallest of the distances `d` (per mesh vertex) of the vertices that stand
// for it; +infinity for a file vertex no face uses.
template <class FT>
std::vector<double> file_vertex_distances(const Loaded_soup& soup, const std::vector<FT>& d)
{
  std::vector<double> out(soup.file_vertices, std::numeric_limits<double>::infinity());
  for(std::size_t i = 0; i < d.size(); ++i)
  {
    double& o = out[soup.file_vertex_of[i]];
    o = (std::min)(o, double(d[i]));
  }
  return out;
}

// Per file vertex, the certified bound on the error of its distance `d`, given a lower bound of
// its exact distance (both as file_vertex_distances() gives them): d - lower, +infinity where d
// is (unreached), NaN where d is (a vertex a repair removed)
inline std::vector<double> certified_errors(const std::vector<double>& d, const std::vector<double>& lower)
{
  std::vector<double> out(d.size());
  for(std::size_t i = 0; i < d.size(); ++i)
    out[i] = std::isinf(d[i]) ? d[i] : d[i] - lower[i];
  return out;
}

} // namespace dggvtp

#endif // DGGVTP_LOAD_MESH_H
