// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// All rights reserved.
//
// This file is part of DGG_VTP_3, a package written for CGAL (www.cgal.org).
//
// $URL$
// $Id$
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : DGG-VTP for CGAL team

#ifndef CGAL_DGG_VTP_3_INTERNAL_SURFACE_POINT_H
#define CGAL_DGG_VTP_3_INTERNAL_SURFACE_POINT_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/Unfolded_mesh.h>
#include <CGAL/DGG_VTP_3/internal/Vertex_copies.h>

#include <array>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// A point of the surface in the solver's numbering: a face and the barycentric coordinates of its
// three corners (corner k of face f is the source of halfedge 3 f + k, as in Unfolded_mesh).
template <class FT>
struct Surface_point
{
  std::uint32_t face;
  std::array<FT, 3> barycentric;
};

// A point on an edge belongs to every face of the edge: appends to `out` the point `q` (on the
// edge opposite corner k, i.e. of halfedge e = 3 f + k + 1, so its coordinate k is 0) as the face
// on the other side sees it, if any, and the faces of the same edge in other sheets (see
// Vertex_copies.h).
template <class FT>
void same_point_across_edge(const Unfolded_mesh<FT>& mesh, const Surface_point<FT>& q, int k,
                            std::vector<Surface_point<FT>>& out)
{
  using Mesh = Unfolded_mesh<FT>;
  using Index = typename Mesh::Index;
  const Index e = 3 * q.face + Index((k + 1) % 3);
  const auto add = [&](Index g) {
    Surface_point<FT> other{Mesh::face(g), {number<FT>(0), number<FT>(0), number<FT>(0)}};
    // g starts where e ends (its opposite, or a twin the same way), or where e starts
    const bool reversed = same_point(mesh, mesh.source(g), mesh.target(e));
    other.barycentric[g % 3] = q.barycentric[reversed ? (k + 2) % 3 : (k + 1) % 3];
    other.barycentric[(g + 1) % 3] = q.barycentric[reversed ? (k + 1) % 3 : (k + 2) % 3];
    out.push_back(other);
  };
  const Index o = mesh.opposite(e);
  if(o != Mesh::no_halfedge)
    add(o);
  for(Index g = mesh.next_twin(e); g != e; g = mesh.next_twin(g))
    if(g != o)
      add(g);
}

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_SURFACE_POINT_H
