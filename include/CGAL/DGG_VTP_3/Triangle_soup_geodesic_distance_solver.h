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

#include <CGAL/DGG_VTP_3/Propagation_statistics.h>
#include <CGAL/DGG_VTP_3/Shortest_path_tree.h>
#include <CGAL/DGG_VTP_3/parameters.h>
#include <CGAL/DGG_VTP_3/internal/Element_numbering.h>
#include <CGAL/DGG_VTP_3/internal/Solver_core.h>
#include <CGAL/DGG_VTP_3/internal/Vertex_copies.h>
#include <CGAL/DGG_VTP_3/internal/unfold_input.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <memory>
#include <utility>
#include <vector>

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
 * makes a soup so, splitting vertices where needed; given the copies it makes as `copy_of`, the
 * sheets it splits apart stay one surface, an edge of three triangles included). Vertices where
 * several fans of triangles meet are kept (see `number_of_non_manifold_vertices()`), and points no
 * triangle uses are unreachable. Where sheets meet along an edge, a query also throws
 * `std::invalid_argument` once its propagation has made more than 10,000 + 1,000 x (number of
 * triangles) windows: around a sharp corner there, windows crossing between the sheets can
 * multiply faster than they are pruned (meshes make 10 to 50 per triangle).
 *
 * \tparam GeomTraits a model of `DGGVTPTraits_3`; its `FT` is the number type of the results.
 */
template <class GeomTraits>
class Triangle_soup_geodesic_distance_solver
{
public:
  using Traits = GeomTraits;
  using FT = typename Traits::FT;
  /// the index of a point
  using vertex_descriptor = std::size_t;
  /// the index of a triangle
  using face_descriptor = std::size_t;
  /// the vertex and face index maps: a soup's elements are their indices
  using Vertex_index_map = Identity_property_map<std::size_t>;
  using Face_index_map = Identity_property_map<std::size_t>;
  /// a point of the surface: a triangle and barycentric coordinates, as for `Geodesic_distance_solver`
  using Face_location = std::pair<face_descriptor, std::array<FT, 3>>;

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
   *   \cgalParamNBegin{copy_of}
   *     \cgalParamDescription{the copies of each point (see `parameters::copy_of()`): a point split
   *                           where sheets meet is still one point, reached from every sheet}
   *     \cgalParamType{a random access range of integer indices into `points`, one per point}
   *     \cgalParamDefault{no copies: every point is its own}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{geom_traits}
   *     \cgalParamDescription{an instance of a geometric traits class}
   *     \cgalParamType{a model of `DGGVTPTraits_3`}
   *     \cgalParamDefault{`GeomTraits()`}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{DGG_VTP_3::parameters::concurrency_tag}
   *     \cgalParamDescription{as for `Geodesic_distance_solver`; the points are read in parallel
   *                           too, and so are the triangles if `TriangleRange` is random access}
   *     \cgalParamType{`CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`, a value}
   *     \cgalParamDefault{`CGAL::Sequential_tag()`}
   *   \cgalParamNEnd
   * \cgalNamedParamsEnd
   *
   * \throws std::invalid_argument for what the constructor of `Geodesic_distance_solver` refuses,
   *         for a triangle that does not have 3 indices or refers to a point that does not exist,
   *         for two triangles that go along an edge in the same direction (inconsistent
   *         orientations, or an edge of more than two triangles), and for `copy_of` not of one
   *         index per point, giving a copy at another place than its point, or making two
   *         triangles sheets of one (on the same three points, through copies).
   */
  template <class PointRange, class TriangleRange, class NamedParameters = parameters::Default_named_parameters>
  Triangle_soup_geodesic_distance_solver(const PointRange& points, const TriangleRange& triangles,
                                         const NamedParameters& np = parameters::default_values())
    : m_core(prepare(points, triangles, np))
  {}

  /// as `Geodesic_distance_solver::compute_distances()`
  template <class ConcurrencyTag = Sequential_tag, class Source, class VertexDistanceMap,
            class NamedParameters = parameters::Default_named_parameters>
  Propagation_statistics compute_distances(const Source& source, VertexDistanceMap distances,
                                           const NamedParameters& np = parameters::default_values()) const
  {
    return m_core->template distances_to_nearest_source<ConcurrencyTag>(std::vector<Source>(1, source), distances, np);
  }

  /// as `Geodesic_distance_solver::compute_distances_to_nearest_source()`
  template <class ConcurrencyTag = Sequential_tag, class SourceRange, class VertexDistanceMap,
            class NamedParameters = parameters::Default_named_parameters>
  Propagation_statistics compute_distances_to_nearest_source(const SourceRange& sources, VertexDistanceMap distances,
                                                             const NamedParameters& np = parameters::default_values()) const
  {
    return m_core->template distances_to_nearest_source<ConcurrencyTag>(sources, distances, np);
  }

  /// as `Geodesic_distance_solver::compute_distances_from_each_source()`
  template <class ConcurrencyTag = Sequential_tag, class VertexRange, class VertexDistanceMapRange,
            class NamedParameters = parameters::Default_named_parameters>
  std::vector<Propagation_statistics>
  compute_distances_from_each_source(const VertexRange& sources, const VertexDistanceMapRange& distance_maps,
                                     const NamedParameters& np = parameters::default_values()) const
  {
    return m_core->template distances_from_each_source<ConcurrencyTag>(sources, distance_maps, np);
  }

  /// as `Geodesic_distance_solver::compute_distances_from_each_source_set()`, `distances[i]`
  /// being the distance of point `i`
  template <class ConcurrencyTag = Sequential_tag, class SourceSetRange, class RowFunction,
            class NamedParameters = parameters::Default_named_parameters>
  void compute_distances_from_each_source_set(const SourceSetRange& source_sets, const RowFunction& row,
                                              const NamedParameters& np = parameters::default_values()) const
  {
    m_core->template distances_from_each_source_set<ConcurrencyTag>(source_sets, row, np);
  }

  /// as `Geodesic_distance_solver::compute_pair_distances()`, the sources and targets being
  /// point indices or `Face_location`s
  template <class ConcurrencyTag = Sequential_tag, class PairRange, class PairFunction,
            class NamedParameters = parameters::Default_named_parameters>
  void compute_pair_distances(const PairRange& pairs, const PairFunction& pair,
                              const NamedParameters& np = parameters::default_values()) const
  {
    internal::pair_distances<ConcurrencyTag>(*m_core, pairs, pair, np, [this](auto& propagation, const auto& query, const auto& places) {
      return Shortest_path_tree<Triangle_soup_geodesic_distance_solver>(m_core, propagation, query, places);
    });
  }

  /// as `Geodesic_distance_solver::compute_shortest_path_tree()`
  template <class ConcurrencyTag = Sequential_tag, class SourceRange,
            class NamedParameters = parameters::Default_named_parameters>
  Shortest_path_tree<Triangle_soup_geodesic_distance_solver>
  compute_shortest_path_tree(const SourceRange& sources, const NamedParameters& np = parameters::default_values()) const
  {
    return m_core->template shortest_path_tree<ConcurrencyTag>(
      sources, np, [this](auto& propagation, const auto& query, const auto& targets) {
        return Shortest_path_tree<Triangle_soup_geodesic_distance_solver>(m_core, propagation, query, targets);
      });
  }

  /// Copies share the prepared mesh, which no query changes: a copy costs a pointer. Moving a
  /// solver copies it too, so that the solver moved from answers as before; an assigned solver
  /// answers as the one assigned. Not while another thread queries the solver assigned to.
  Triangle_soup_geodesic_distance_solver(const Triangle_soup_geodesic_distance_solver&) = default;
  Triangle_soup_geodesic_distance_solver& operator=(const Triangle_soup_geodesic_distance_solver&) = default;

  /// as `Geodesic_distance_solver::farthest_point_sampling()`
  template <class ConcurrencyTag = Sequential_tag, class OutputIterator,
            class NamedParameters = parameters::Default_named_parameters>
  OutputIterator farthest_point_sampling(std::size_t k, OutputIterator samples,
                                         const NamedParameters& np = parameters::default_values()) const
  {
    for(std::size_t v : m_core->template farthest_point_sampling<ConcurrencyTag>(k, np))
      *samples++ = v;
    return samples;
  }

  /// Gives back the memory that queries keep for the next ones: the scratch of a propagation (a
  /// few arrays over the vertices, faces and halfedges), one for each thread that queried at
  /// once, which the next query makes again. The solver stays usable, from any thread, and its
  /// results do not change. Shared by the copies of the solver.
  void release_query_memory() const { m_core->release_query_memory(); }

  /// the number of points
  std::size_t number_of_vertices() const { return m_core->number_of_vertices(); }

  /// as `Geodesic_distance_solver::number_of_non_manifold_vertices()`
  std::size_t number_of_non_manifold_vertices() const { return m_core->number_of_non_manifold_vertices(); }

private:
  friend class Shortest_path_tree<Triangle_soup_geodesic_distance_solver>;
  using Core = internal::Solver_core<internal::Index_numbering, FT>;

  template <class PointRange, class TriangleRange, class NamedParameters>
  static std::shared_ptr<const Core> prepare(const PointRange& points, const TriangleRange& triangles, const NamedParameters& np)
  {
    using Point = typename std::iterator_traits<decltype(std::begin(points))>::value_type;
    using Tag = typename Core::template Preparation_tag<NamedParameters>;
    typename Core::Mesh mesh;
    const auto pm =
      parameters::choose_parameter<Identity_property_map<Point>>(parameters::get_parameter(np, internal_np::point_map));
    const auto gt = parameters::choose_parameter<GeomTraits>(parameters::get_parameter(np, internal_np::geom_traits));
    internal::Unfolding_order order = internal::unfold_triangle_soup<Tag>(points, triangles, pm, gt, mesh);
    if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::copy_of_t>::value)
    {
      const auto at = [&](std::size_t i) {
        const auto& p = get(pm, *(std::begin(points) + i));
        return std::array<typename GeomTraits::FT, 3>{
          gt.compute_x_3_object()(p), gt.compute_y_3_object()(p), gt.compute_z_3_object()(p)};
      };
      internal::link_copies(
        internal::in_unfolded_order(
          internal::copy_groups(parameters::get_parameter(np, internal_np::copy_of_t()), mesh.number_of_vertices(), at),
          order),
        mesh);
    }
    return std::make_shared<const Core>(Tag(), internal::Index_numbering(mesh.number_of_vertices(), mesh.number_of_faces()),
                                        std::move(mesh), std::move(order));
  }

  // the prepared soup and the queries; shared by the copies of the solver and by the shortest
  // path trees it computed, never changed
  std::shared_ptr<const Core> m_core;
};

} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_TRIANGLE_SOUP_GEODESIC_DISTANCE_SOLVER_H
