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

#include <array>
#include <cstdint>

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

// A point on an edge belongs to both faces of the edge: `q` (on the edge opposite corner k, i.e.
// of halfedge 3 f + k + 1, so its coordinate k is 0) as the face on the other side sees it. Its
// face is Index(-1) on a border edge.
template <class FT>
Surface_point<FT> same_point_across_edge(const Unfolded_mesh<FT>& mesh, const Surface_point<FT>& q, int k)
{
  using Mesh = Unfolded_mesh<FT>;
  using Index = typename Mesh::Index;
  Surface_point<FT> other{Index(-1), {number<FT>(0), number<FT>(0), number<FT>(0)}};
  const Index o = mesh.opposite(3 * q.face + (k + 1) % 3);
  if(o == Mesh::no_halfedge)
    return other;
  other.face = Mesh::face(o);
  other.barycentric[o % 3] = q.barycentric[(k + 2) % 3]; // o starts where 3 f + k + 1 ends
  other.barycentric[(o + 1) % 3] = q.barycentric[(k + 1) % 3];
  return other;
}

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_SURFACE_POINT_H
