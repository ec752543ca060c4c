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

#ifndef CGAL_DGG_VTP_3_TRIANGLE_SOUP_GEODESIC_DISTANCE_SOLVER_H
#define CGAL_DGG_VTP_3_TRIANGLE_SOUP_GEODESIC_DISTANCE_SOLVER_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/Geodesic_distance_solver.h>
#include <CGAL/DGG_VTP_3/internal/unfold_input.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <utility>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// A triangle soup has no graph type: its vertices and faces are their indices.
struct Triangle_soup_numbering
{};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

namespace boost {

template <>
struct graph_traits<CGAL::DGG_VTP_3::internal::Triangle_soup_numbering>
{
  using vertex_descriptor = std::size_t;
  using face_descriptor = std::size_t;
};

} // namespace boost

namespace CGAL {
namespace DGG_VTP_3 {

/*!
 * \ingroup PkgDGGVTP3Ref
 *
 * The solver of `Geodesic_distance_solver` for a triangle soup: an array of points and an array
 * of triangles (three indices into the points each), as a file or another language hands them
 * over, without building a CGAL mesh. Vertices are the indices of the points (`std::size_t`),
 * faces the indices of the triangles; every query, the named parameters, results and exceptions
 * are those of `Geodesic_distance_solver`, with distance and label maps keyed by these indices
 * (for example `CGAL::make_property_map(std::vector<FT>&)`).
 *
 * The triangles must form a surface as they are: each edge shared by at most two triangles, which
 * go along it in opposite directions (`CGAL::Polygon_mesh_processing::orient_polygon_soup()`
 * makes a soup so, splitting vertices where needed). Vertices where several fans of triangles
 * meet are kept (see `number_of_non_manifold_vertices()`), and points no triangle uses are
 * unreachable.
 *
 * \tparam GeomTraits a model of `DGGVTPTraits_3`; its `FT` is the number type of the results.
 */
template <class GeomTraits>
class Triangle_soup_geodesic_distance_solver
  : public Geodesic_distance_solver<internal::Triangle_soup_numbering, GeomTraits,
                                    Identity_property_map<std::size_t>, Identity_property_map<std::size_t>>
{
  using Base = Geodesic_distance_solver<internal::Triangle_soup_numbering, GeomTraits,
                                        Identity_property_map<std::size_t>, Identity_property_map<std::size_t>>;

public:
  /*!
   * prepares the soup for distance queries; the arrays are not read again afterwards.
   *
   * \tparam PointRange a random access range of points
   * \tparam TriangleRange a range of ranges of 3 integer indices into `points`
   * \param np an optional sequence of named parameters among the ones listed below
   *
   * \cgalNamedParamsBegin
   *   \cgalParamNBegin{point_map}
   *     \cgalParamDescription{a property map associating points to the elements of `points`}
   *     \cgalParamType{a model of `ReadablePropertyMap` with the value type of `PointRange` as key
   *                    and the traits' `Point_3` as value type}
   *     \cgalParamDefault{`CGAL::Identity_property_map`}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{geom_traits}
   *     \cgalParamDescription{an instance of a geometric traits class}
   *     \cgalParamType{a model of `DGGVTPTraits_3`}
   *     \cgalParamDefault{`GeomTraits()`}
   *   \cgalParamNEnd
   * \cgalNamedParamsEnd
   *
   * \throws std::invalid_argument for what the constructor of `Geodesic_distance_solver` refuses,
   *         for a triangle that does not have 3 indices or refers to a point that does not exist,
   *         and for two triangles that go along an edge in the same direction (inconsistent
   *         orientations, or an edge of more than two triangles).
   */
  template <class PointRange, class TriangleRange, class NamedParameters = parameters::Default_named_parameters>
  Triangle_soup_geodesic_distance_solver(const PointRange& points, const TriangleRange& triangles,
                                         const NamedParameters& np = parameters::default_values())
    : Triangle_soup_geodesic_distance_solver(unfold(points, triangles, np))
  {}

private:
  using Mesh = typename Base::Mesh;

  // the base is built from the unfolded soup and the order of its faces
  struct Unfolded
  {
    Mesh mesh;
    std::vector<std::uint32_t> order;
  };

  Triangle_soup_geodesic_distance_solver(Unfolded&& unfolded) : Base(std::move(unfolded.mesh), unfolded.order) {}

  template <class PointRange, class TriangleRange, class NamedParameters>
  static Unfolded unfold(const PointRange& points, const TriangleRange& triangles, const NamedParameters& np)
  {
    using Point = typename std::iterator_traits<decltype(std::begin(points))>::value_type;
    Unfolded unfolded;
    unfolded.order = internal::unfold_triangle_soup(
      points, triangles,
      parameters::choose_parameter<Identity_property_map<Point>>(parameters::get_parameter(np, internal_np::point_map)),
      parameters::choose_parameter<GeomTraits>(parameters::get_parameter(np, internal_np::geom_traits)),
      unfolded.mesh);
    return unfolded;
  }
};

} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_TRIANGLE_SOUP_GEODESIC_DISTANCE_SOLVER_H
