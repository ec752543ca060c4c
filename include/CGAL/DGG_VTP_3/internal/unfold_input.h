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

#ifndef CGAL_DGG_VTP_3_INTERNAL_UNFOLD_INPUT_H
#define CGAL_DGG_VTP_3_INTERNAL_UNFOLD_INPUT_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/Default_init_allocator.h>
#include <CGAL/DGG_VTP_3/internal/Unfolded_mesh.h>
#include <CGAL/DGG_VTP_3/internal/for_each_block.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cstdint>
#include <iterator>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// The user's input, a triangle mesh or a triangle soup, as the arrays `unfold_triangles()` works
// from: coordinates per vertex, vertex per corner and, for a mesh, opposite halfedge per halfedge.

// Reads point `p` (through the traits) into xyz[3i..3i+2]; throws for a coordinate that is not finite.
template <class FT, class GeomTraits, class Point>
void store_point(const GeomTraits& gt, const Point& p, std::size_t i, std::vector<FT>& xyz)
{
  xyz[3 * i] = number<FT>(gt.compute_x_3_object()(p));
  xyz[3 * i + 1] = number<FT>(gt.compute_y_3_object()(p));
  xyz[3 * i + 2] = number<FT>(gt.compute_z_3_object()(p));
  for(int c = 0; c < 3; ++c)
    if(!CGAL::is_finite(xyz[3 * i + c]))
      throw std::invalid_argument("vertex " + std::to_string(i) + " has a coordinate that is not finite");
}

// Fills the mesh from a user's triangle mesh (a free function: the graph's next(), source()...
// would be hidden inside the class by the members of the same names). Returns the orders of the
// faces and vertices (see Unfolding_order; user numbers by the index maps). The graph is walked on
// this thread (its ranges need not be random access); `ConcurrencyTag` is unfold_triangles()'s.
template <class ConcurrencyTag, class FT, class TriangleMesh, class VertexPointMap, class VertexIndexMap, class FaceIndexMap,
          class GeomTraits>
Unfolding_order unfold_triangle_mesh(const TriangleMesh& tm, VertexPointMap vpm, VertexIndexMap vim,
                                     FaceIndexMap fim, const GeomTraits& gt, Unfolded_mesh<FT>& out)
{
  using Index = typename Unfolded_mesh<FT>::Index;
  constexpr Index no_halfedge = Unfolded_mesh<FT>::no_halfedge;
  using Graph_traits = boost::graph_traits<TriangleMesh>;
  using halfedge_descriptor = typename Graph_traits::halfedge_descriptor;

  const std::size_t nv = static_cast<std::size_t>(num_vertices(tm));
  const std::size_t nf = static_cast<std::size_t>(num_faces(tm));
  if(!CGAL::is_triangle_mesh(tm))
    throw std::invalid_argument("the mesh has faces that are not triangles");
  check_index_range<FT>(nv, nf);

  std::vector<FT> xyz(3 * nv);
  std::vector<char> vertex_seen(nv, 0);
  for(auto v : vertices(tm))
  {
    const std::size_t i = static_cast<std::size_t>(get(vim, v));
    if(i >= nv || vertex_seen[i])
      throw std::invalid_argument("the vertex index map is not a bijection onto [0, num_vertices)");
    vertex_seen[i] = 1;
    store_point(gt, get(vpm, v), i, xyz);
  }

  Uninitialized_vector<Index> corner_vertex(3 * nf), opposite_halfedge(3 * nf);
  std::vector<char> face_seen(nf, 0);
  for(auto f : faces(tm))
  {
    const std::size_t fi = static_cast<std::size_t>(get(fim, f));
    if(fi >= nf || face_seen[fi])
      throw std::invalid_argument("the face index map is not a bijection onto [0, num_faces)");
    face_seen[fi] = 1;
    halfedge_descriptor h = halfedge(f, tm);
    for(int k = 0; k < 3; ++k, h = next(h, tm))
    {
      const Index hi = Index(3 * fi + k);
      corner_vertex[hi] = Index(get(vim, source(h, tm)));
      const halfedge_descriptor o = opposite(h, tm);
      if(is_border(o, tm))
        opposite_halfedge[hi] = no_halfedge;
      else
      {
        const auto fo = face(o, tm);
        halfedge_descriptor g = halfedge(fo, tm);
        int ko = 0;
        while(g != o) { g = next(g, tm); ++ko; }
        opposite_halfedge[hi] = Index(3 * get(fim, fo) + ko);
      }
    }
  }
  return unfold_triangles<ConcurrencyTag>(std::move(xyz), std::move(corner_vertex), std::move(opposite_halfedge), out);
}


template <class Integer>
bool is_negative_index(Integer v)
{
  if constexpr(std::is_signed<Integer>::value)
    return v < 0;
  else
    return false;
}

// Fills the mesh from a triangle soup: `points` (a random access range, read through the point
// map `pm`) and `triangles` (a range of ranges of 3 indices into `points`). The faces must form
// a surface as they are (each edge shared by at most two triangles, which go along it in opposite
// directions); vertices where several fans of triangles meet are kept. Returns the orders of the
// faces and points (see Unfolding_order). The points (a random access range) are read as
// `ConcurrencyTag` says, and so are the triangles if they are a random access range too.
template <class ConcurrencyTag, class FT, class PointRange, class TriangleRange, class PointMap, class GeomTraits>
Unfolding_order unfold_triangle_soup(const PointRange& points, const TriangleRange& triangles, PointMap pm,
                                     const GeomTraits& gt, Unfolded_mesh<FT>& out)
{
  using Index = typename Unfolded_mesh<FT>::Index;
  const std::size_t nv = static_cast<std::size_t>(std::distance(std::begin(points), std::end(points)));
  const std::size_t nf = static_cast<std::size_t>(std::distance(std::begin(triangles), std::end(triangles)));
  check_index_range<FT>(nv, nf);

  std::vector<FT> xyz(3 * nv);
  for_each_block<ConcurrencyTag>(nv, [&](std::size_t i0, std::size_t i1) {
    for(std::size_t i = i0; i < i1; ++i)
      store_point(gt, get(pm, *(std::begin(points) + i)), i, xyz);
  });

  Uninitialized_vector<Index> corner_vertex(3 * nf);
  const auto read_triangle = [&](std::size_t f, const auto& triangle) {
    std::size_t k = 0;
    for(const auto& v : triangle)
    {
      if(k == 3)
        break;
      if(is_negative_index(v) || std::size_t(v) >= nv)
        throw std::invalid_argument("triangle " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                                    ", but there are " + std::to_string(nv) + " points");
      corner_vertex[3 * f + k++] = Index(v);
    }
    if(k != 3 || std::size_t(std::distance(std::begin(triangle), std::end(triangle))) != 3)
      throw std::invalid_argument("face " + std::to_string(f) + " is not a triangle");
  };
  using Triangle_iterator = decltype(std::begin(triangles));
  if constexpr(std::is_convertible<typename std::iterator_traits<Triangle_iterator>::iterator_category,
                                   std::random_access_iterator_tag>::value)
    for_each_block<ConcurrencyTag>(nf, [&](std::size_t f0, std::size_t f1) {
      for(std::size_t f = f0; f < f1; ++f)
        read_triangle(f, *(std::begin(triangles) + f));
    });
  else
  {
    std::size_t f = 0;
    for(const auto& triangle : triangles)
      read_triangle(f++, triangle);
  }

  return unfold_triangles<ConcurrencyTag>(std::move(xyz), std::move(corner_vertex), Uninitialized_vector<Index>(), out);
}

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_UNFOLD_INPUT_H
