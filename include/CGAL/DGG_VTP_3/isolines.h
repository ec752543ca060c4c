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

#ifndef CGAL_DGG_VTP_3_ISOLINES_H
#define CGAL_DGG_VTP_3_ISOLINES_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {

/*!
 * \ingroup PkgDGGVTP3Ref
 *
 * One connected piece of an isoline, as `compute_isolines()` writes it.
 *
 * `points[i]` lies on the edge of `halfedges[i]`, which goes from a vertex below the value to a
 * vertex at or above it, at the fraction `t = (value - d(source)) / (d(target) - d(source))` of
 * the way, in `(0, 1]`.
 */
template <class TriangleMesh, class Point_3>
struct Isoline_piece
{
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  /// the position of the piece's value in the range of values given
  std::size_t value_index = 0;
  std::vector<Point_3> points;
  std::vector<halfedge_descriptor> halfedges;
  /// whether the last point joins the first: the first point is then not repeated at the end
  bool closed = false;
};

/*!
 * \ingroup PkgDGGVTP3Ref
 *
 * computes the isolines of a distance field given at the vertices of `tm`, linearly interpolated
 * over each triangle: for each value, the polylines through the mesh's edges at the points where
 * the interpolation equals the value, one `Isoline_piece` per connected piece. A closed curve is a
 * closed piece; an open piece ends on the border of the mesh, or on an edge to a vertex of infinite
 * distance (an unreachable vertex has no interpolation: no edge to it is crossed).
 *
 * A vertex whose distance equals the value counts as above it, so that the curve never runs along
 * an edge: it passes through the vertex instead, with one point at the vertex for each edge from
 * it to a vertex below (these points coincide). A crossing that no face continues (its only face
 * has a corner at infinite distance) makes no piece: a polyline needs two points.
 *
 * \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph` with triangle faces
 * \tparam VertexDistanceMap a readable vertex property map whose values convert to the traits'
 *         `FT`, finite or `+infinity`
 * \tparam ValueRange a range of values that convert to the traits' `FT`
 * \tparam OutputIterator an output iterator accepting `Isoline_piece<TriangleMesh, Point_3>`, with
 *         the traits' `Point_3`
 *
 * \param tm the triangle mesh
 * \param distances the distance of each vertex
 * \param values the values of the isolines; the pieces come value after value, in this order
 * \param out receives the pieces
 * \param np an optional sequence of named parameters among `vertex_point_map` and `geom_traits`,
 *        as for `compute_geodesic_distances()`
 *
 * \returns `out` past the last piece
 * \throws std::invalid_argument for a value that is not finite
 */
template <class TriangleMesh, class VertexDistanceMap, class ValueRange, class OutputIterator,
          class NamedParameters = parameters::Default_named_parameters>
OutputIterator compute_isolines(const TriangleMesh& tm,
                                VertexDistanceMap distances,
                                const ValueRange& values,
                                OutputIterator out,
                                const NamedParameters& np = parameters::default_values())
{
  using Traits = typename GetGeomTraits<TriangleMesh, NamedParameters>::type;
  using FT = typename Traits::FT;
  using Point_3 = typename Traits::Point_3;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  using edge_descriptor = typename boost::graph_traits<TriangleMesh>::edge_descriptor;
  using Piece = Isoline_piece<TriangleMesh, Point_3>;

  const auto vpm = parameters::choose_parameter(parameters::get_parameter(np, internal_np::vertex_point),
                                                get_const_property_map(CGAL::vertex_point, tm));
  const Traits traits = parameters::choose_parameter<Traits>(parameters::get_parameter(np, internal_np::geom_traits));
  const auto barycenter = traits.construct_barycenter_3_object();

  // per edge, the number of its crossing among the current value's (valid when its stamp is the
  // value's), so that both faces of an edge share one point, bit for bit
  constexpr std::size_t none = std::size_t(-1);
  auto node_of = get(CGAL::dynamic_edge_property_t<std::size_t>(), tm);
  auto stamp_of = get(CGAL::dynamic_edge_property_t<std::size_t>(), tm);
  for(edge_descriptor e : edges(tm))
    put(stamp_of, e, none);

  struct Crossing
  {
    halfedge_descriptor h; // from below to at or above
    Point_3 point;
    std::array<std::size_t, 2> next{{none, none}}; // the crossings joined to it through its faces
    bool visited = false;
  };

  std::size_t value_index = 0;
  for(const auto& given_value : values)
  {
    const FT value(given_value);
    if(!CGAL::is_finite(value))
      throw std::invalid_argument("an isoline value must be finite");
    const auto below = [&](halfedge_descriptor h) { return FT(get(distances, source(h, tm))) < value; };
    // an edge is crossed where one end is below and the other at or above, both finite
    const auto crosses = [&](halfedge_descriptor h) {
      const FT a(get(distances, source(h, tm))), b(get(distances, target(h, tm)));
      return CGAL::is_finite(a) && CGAL::is_finite(b) && ((a < value) != (b < value));
    };
    std::vector<Crossing> crossings;
    const auto crossing_of = [&](halfedge_descriptor h) {
      const edge_descriptor e = edge(h, tm);
      if(get(stamp_of, e) == value_index)
        return get(node_of, e);
      if(!below(h))
        h = opposite(h, tm);
      const FT a(get(distances, source(h, tm))), b(get(distances, target(h, tm)));
      const FT t = (value - a) / (b - a); // b > a: no division by zero
      Crossing c;
      c.h = h;
      // t * target + (1 - t) * source: the target itself when t = 1
      c.point = barycenter(get(vpm, target(h, tm)), t, get(vpm, source(h, tm)));
      crossings.push_back(c);
      put(stamp_of, e, value_index);
      put(node_of, e, crossings.size() - 1);
      return crossings.size() - 1;
    };
    const auto join = [&](std::size_t i, std::size_t j) {
      for(std::size_t k : {i, j})
      {
        std::array<std::size_t, 2>& next = crossings[k].next;
        (next[0] == none ? next[0] : next[1]) = (k == i ? j : i);
      }
    };
    for(auto f : faces(tm))
    {
      std::array<std::size_t, 2> found{{none, none}};
      std::size_t n = 0;
      const halfedge_descriptor h0 = halfedge(f, tm);
      halfedge_descriptor h = h0;
      do
      {
        if(crosses(h) && n < 2)
          found[n++] = crossing_of(h);
        h = next(h, tm);
      } while(h != h0);
      if(n == 2)
        join(found[0], found[1]);
    }

    // walks from `start` along unvisited crossings
    const auto walk = [&](std::size_t start) {
      Piece piece;
      piece.value_index = value_index;
      std::size_t current = start;
      while(current != none)
      {
        Crossing& c = crossings[current];
        c.visited = true;
        piece.points.push_back(c.point);
        piece.halfedges.push_back(c.h);
        std::size_t following = none;
        for(std::size_t k : c.next)
          if(k != none && !crossings[k].visited)
          {
            following = k;
            break;
          }
        current = following;
      }
      return piece;
    };
    // open pieces first, from their ends, so that what is left is closed curves
    for(std::size_t i = 0; i < crossings.size(); ++i)
      if(!crossings[i].visited && crossings[i].next[1] == none)
      {
        Piece piece = walk(i);
        if(piece.points.size() >= 2)
          *out++ = std::move(piece);
      }
    for(std::size_t i = 0; i < crossings.size(); ++i)
      if(!crossings[i].visited)
      {
        Piece piece = walk(i);
        piece.closed = true;
        *out++ = std::move(piece);
      }
    ++value_index;
  }
  return out;
}

} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_ISOLINES_H
