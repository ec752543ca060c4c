// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// The isolines of dggvtp's distances (--isolines, --isolines-at) as an OBJ file of polylines.

#ifndef DGGVTP_ISOLINE_FILE_H
#define DGGVTP_ISOLINE_FILE_H

#include <dggvtp/load_mesh.h>

#include <CGAL/DGG_VTP_3/isolines.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace dggvtp {

// `count` values evenly spaced strictly between 0 and the largest finite distance (the isolines
// at those two ends are a point and nothing)
inline std::vector<double> evenly_spaced_values(const std::vector<double>& distances, std::size_t count)
{
  double farthest = 0.;
  for(double d : distances)
    if(std::isfinite(d))
      farthest = (std::max)(farthest, d);
  std::vector<double> values;
  for(std::size_t k = 1; k <= count; ++k)
    values.push_back(farthest * double(k) / double(count + 1));
  return values;
}

// Writes the isolines of `distances` (per file vertex of the mesh `mesh_name`) at `values` as OBJ:
// per value a comment, then per piece its points as v lines and one l line through them; a closed
// piece repeats its first vertex at the end of its l line. The field is interpolated on the
// triangles of `soup`, the soup the solver was made of (polygons triangulated, orientations fixed,
// the repairs of --repair made), which making the mesh consumes; a vertex split there takes the
// distance of its file vertex.
inline void write_isolines_obj(std::FILE* file, const std::string& mesh_name, Loaded_soup soup,
                               const std::vector<double>& distances, const std::vector<double>& values)
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  auto mesh = make_triangle_mesh<Kernel>(soup);
  using Mesh = decltype(mesh);
  if(num_vertices(mesh) != soup.file_vertex_of.size())
    throw std::logic_error("the mesh of the isolines does not have a vertex per point of the soup");
  auto d = mesh.template add_property_map<typename Mesh::Vertex_index, double>("v:distance", 0.).first;
  for(auto v : vertices(mesh))
    d[v] = distances[soup.file_vertex_of[std::size_t(v)]];
  std::vector<CGAL::DGG_VTP_3::Isoline_piece<Mesh, Kernel::Point_3>> pieces;
  CGAL::DGG_VTP_3::compute_isolines(mesh, d, values, std::back_inserter(pieces));

  const auto number = [](double x) {
    char text[32];
    return std::string(text, std::to_chars(text, text + sizeof text, x, std::chars_format::general, 17).ptr);
  };
  std::fprintf(file, "# dggvtp: isolines of the geodesic distance on %s, one l line per connected piece\n",
               mesh_name.c_str());
  std::size_t written = 0, piece = 0;
  for(std::size_t k = 0; k < values.size(); ++k)
  {
    std::fprintf(file, "# isoline %zu at distance %s\n", k, number(values[k]).c_str());
    for(; piece < pieces.size() && pieces[piece].value_index == k; ++piece)
    {
      std::string lines;
      for(const auto& p : pieces[piece].points)
        lines += "v " + number(p.x()) + " " + number(p.y()) + " " + number(p.z()) + "\n";
      lines += "l";
      const std::size_t n = pieces[piece].points.size();
      for(std::size_t i = 1; i <= n; ++i)
        lines += " " + std::to_string(written + i);
      if(pieces[piece].closed)
        lines += " " + std::to_string(written + 1);
      lines += "\n";
      std::fwrite(lines.data(), 1, lines.size(), file);
      written += n;
    }
  }
}

} // namespace dggvtp

#endif // DGGVTP_ISOLINE_FILE_H
