// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// dggvtp --repair (the Python module's repair=True): CGAL's own repairs of real scans, run on the
// loaded soup before the solver's input checks, with the results still reported per vertex of the
// file.

#ifndef DGGVTP_REPAIR_H
#define DGGVTP_REPAIR_H

#include <dggvtp/load_mesh.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace dggvtp {

// What the repairs did to the file's vertices: a file vertex whose points are all gone from the
// faces takes the value of the file vertex that now stands at its place (stitched or collapsed
// onto it), or nan (label -1) where none does.
struct Repair_record
{
  static constexpr std::size_t removed = std::numeric_limits<std::size_t>::max();
  std::map<std::size_t, std::size_t> lost; // file vertex -> file vertex at its place, or removed
  std::string repair_name = "--repair";   // for messages

  // the file vertex that a source or target at `v` stands on; throws Input_error for a removed one
  std::size_t file_vertex(std::size_t v, const std::string& what) const
  {
    const auto l = lost.find(v);
    if(l == lost.end())
      return v;
    if(l->second == removed)
      throw Input_error(what + " " + std::to_string(v) + " was removed by " + repair_name +
                        " (it is in no face any more)");
    return l->second;
  }

  // per file vertex (either may be null: none): lost vertices take their stand-in's values, or nan
  // and -1
  void apply(double* distances, long long* labels) const
  {
    for(const auto& [v, to] : lost)
    {
      if(distances)
        distances[v] = to == removed ? std::numeric_limits<double>::quiet_NaN() : distances[to];
      if(labels)
        labels[v] = to == removed ? -1 : labels[to];
    }
  }

  // the file vertices merged into each file vertex (the lost vertices at its place), for results
  // that are not an array per file vertex (sparse rows)
  std::map<std::size_t, std::vector<std::size_t>> merged_into() const
  {
    std::map<std::size_t, std::vector<std::size_t>> out;
    for(const auto& [v, to] : lost)
      if(to != removed)
        out[to].push_back(v);
    return out;
  }
};

namespace internal {

// "3 faces and 1 vertex": counts as a warning says them
inline std::string faces_and_vertices(std::size_t faces, std::size_t vertices)
{
  return std::to_string(faces) + (faces == 1 ? " face" : " faces") + " and " + std::to_string(vertices) +
         (vertices == 1 ? " vertex" : " vertices");
}

} // namespace internal

// Thresholds of remove_almost_degenerate_faces: far beyond what a mesher makes on purpose, so
// that only faces near those the solver refuses (slivers, edges below rounding) are changed.
// A cap: an angle within 0.1 degree of a flat one; a needle: its longest edge 1e4 times its
// shortest, which is collapsed if shorter than 1e-4 times the bounding box's diagonal.
constexpr double repair_cap_degrees = 179.9;
constexpr double repair_needle_ratio = 1e4;
constexpr double repair_collapse_relative_length = 1e-4;

// The library's message for input it refuses (std::invalid_argument), with what `repair` can do
// about it: the faces CGAL's repairs may fix (degenerate faces, slivers, too short edges) get
// "; --repair removes such faces", or " (after --repair)" when it ran.
inline std::string with_repair_hint(const std::string& what, const Repair_option& repair)
{
  const bool repairable = what.find(" is degenerate") != std::string::npos ||
                          what.find(" is a sliver") != std::string::npos ||
                          what.find(" has an edge of length") != std::string::npos;
  if(!repairable)
    return what;
  return what + (repair.on ? " (after " + repair.name + ")" : "; " + repair.name + " removes such faces");
}

// Repairs the soup with CGAL::Polygon_mesh_processing, in this order: stitch_borders (coincident
// border edges, as a scan cut in pieces has), remove_degenerate_faces (zero length edges, zero
// area), experimental::remove_almost_degenerate_faces (caps and needles, thresholds above) and
// remove_isolated_vertices (vertices no face uses, those of the file and those the repairs left).
// The soup becomes the repaired mesh's triangles over the same points (moved where a repair moved
// them); each kind of repair that changed something adds a line to soup.repairs, starting with the
// name of `repair`. Throws Input_error where the soup does not make a surface (as loading would).
inline Repair_record repair_soup(Loaded_soup& soup, const Repair_option& repair = Repair_option())
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  auto mesh = make_triangle_mesh<Kernel>(soup);
  const std::size_t points = soup.points.size(); // with the copies orienting made
  mesh.set_recycle_garbage(false); // mesh vertex i stays soup point i
  const auto count = [&mesh] {
    return std::make_pair(std::size_t(mesh.number_of_faces()), std::size_t(mesh.number_of_vertices()));
  };
  const auto report = [&](const std::string& what, std::pair<std::size_t, std::size_t> before) {
    const auto after = count();
    if(after != before)
      soup.repairs.push_back(repair.name + ": " + what + " removed " +
                             internal::faces_and_vertices(before.first - after.first, before.second - after.second));
  };

  const std::size_t stitched = PMP::stitch_borders(mesh);
  if(stitched > 0)
    soup.repairs.push_back(repair.name + ": stitch_borders stitched " + std::to_string(stitched) +
                           " pairs of coincident border edges");
  auto before = count();
  PMP::remove_degenerate_faces(mesh);
  if(num_vertices(mesh) == 0) // it clears a mesh whose faces are all degenerate
    throw Input_error("every face is degenerate (zero length edge or zero area): " + repair.name +
                      " leaves no surface");
  report("remove_degenerate_faces", before);
  CGAL::Bbox_3 box;
  for(auto v : vertices(mesh))
    box += mesh.point(v).bbox();
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  before = count();
  PMP::experimental::remove_almost_degenerate_faces(mesh, std::cos(repair_cap_degrees * CGAL_PI / 180.),
                                                    repair_needle_ratio, repair_collapse_relative_length * diagonal);
  report("remove_almost_degenerate_faces", before);
  const std::size_t isolated = PMP::remove_isolated_vertices(mesh);
  if(isolated > 0)
    soup.repairs.push_back(repair.name + ": remove_isolated_vertices removed " + std::to_string(isolated) +
                           (isolated == 1 ? " vertex" : " vertices"));
  // remove_degenerate_faces splits edges and faces in some configurations: a vertex the file does
  // not have would have no line in the results
  if(mesh.number_of_vertices() + mesh.number_of_removed_vertices() != points)
    throw Input_error(repair.name + " would add vertices to the mesh (CGAL's remove_degenerate_faces splits some faces), "
                      "which results per vertex of the file cannot hold");

  // the soup: the mesh's triangles, corners in the mesh's order, over the points it moved
  soup.triangles.clear();
  soup.triangles.reserve(mesh.number_of_faces());
  for(auto f : faces(mesh))
  {
    const auto h = halfedge(f, mesh);
    soup.triangles.push_back({std::uint32_t(source(h, mesh)), std::uint32_t(target(h, mesh)),
                              std::uint32_t(target(next(h, mesh), mesh))});
  }
  std::vector<char> kept(soup.file_vertices, 0); // file vertices with a point in the mesh
  std::map<Kernel::Point_3, std::size_t> place;  // of the mesh's points: the file vertex there
  for(auto v : vertices(mesh))
  {
    soup.points[std::size_t(v)] = mesh.point(v);
    kept[soup.file_vertex_of[std::size_t(v)]] = 1;
    place.emplace(mesh.point(v), soup.file_vertex_of[std::size_t(v)]);
  }
  Repair_record record;
  record.repair_name = repair.name;
  std::size_t merged = 0;
  for(std::size_t v = 0; v < soup.file_vertices; ++v)
    if(!kept[v])
    {
      const auto at = place.find(soup.points[v]);
      record.lost[v] = at == place.end() ? Repair_record::removed : at->second;
      merged += at == place.end() ? 0 : 1;
    }
  if(!record.lost.empty())
    soup.repairs.push_back(repair.name + ": " + std::to_string(record.lost.size() - merged) +
                           " vertices of the file removed (nan, label -1), " + std::to_string(merged) +
                           " merged with the vertex at their place (its distance and label)");
  return record;
}

} // namespace dggvtp

#endif // DGGVTP_REPAIR_H
