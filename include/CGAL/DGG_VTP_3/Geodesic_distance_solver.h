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

#ifndef CGAL_DGG_VTP_3_GEODESIC_DISTANCE_SOLVER_H
#define CGAL_DGG_VTP_3_GEODESIC_DISTANCE_SOLVER_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/Propagation_cancelled.h>
#include <CGAL/DGG_VTP_3/Propagation_statistics.h>
#include <CGAL/DGG_VTP_3/Shortest_path_tree.h>
#include <CGAL/DGG_VTP_3/parameters.h>
#include <CGAL/DGG_VTP_3/internal/Element_numbering.h>
#include <CGAL/DGG_VTP_3/internal/Solver_core.h>
#include <CGAL/DGG_VTP_3/internal/unfold_input.h>

#include <CGAL/Default.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// the default index maps, looked up only when no map type is given
template <class TriangleMesh>
struct Vertex_index_map_of
{
  using type = typename GetInitializedVertexIndexMap<TriangleMesh>::const_type;
};

template <class TriangleMesh>
struct Face_index_map_of
{
  using type = typename GetInitializedFaceIndexMap<TriangleMesh>::const_type;
};

} // namespace internal

/*!
 * \ingroup PkgDGGVTP3Ref
 *
 * Geodesic distances from a source vertex to every vertex of a triangle mesh, by window
 * propagation: exact (the VTP algorithm) or, with a positive accuracy, by DGG-VTP.
 *
 * The constructor does all the per-mesh work once (edge lengths, every triangle unfolded onto each
 * of its edges, the corners around each vertex); the mesh is not read again afterwards and may be
 * destroyed.
 * Queries are `const` and keep their scratch to themselves, so one solver may serve several
 * threads at once when `FT` is `float`, `double` or `long double`. Not with the other number
 * types: `CORE::Expr` shares its representations between copies without locking them, and a
 * query copies the solver's lengths into its windows; `CGAL::Gmpfr` computes at the default
 * precision of the thread that runs the query (MPFR keeps one per thread), not at the one the
 * solver was prepared with. With those, a solver serves one thread at a time, and the
 * `Parallel_tag` of its queries runs on one thread.
 *
 * \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`, with triangle faces.
 * \tparam GeomTraits a model of `DGGVTPTraits_3`; by default the kernel of the mesh's points.
 *         Its `FT` is the number type of the results: `float`, `double`, `long double` or
 *         `CGAL::Gmpfr` (computing at its default precision), or an exact type with
 *         square roots (`CORE::Expr`: no rounding margins; an unreached vertex gets
 *         `std::numeric_limits<double>::max()`, the type having no infinity). An exact type
 *         without square roots (the `FT` of `CGAL::Exact_predicates_exact_constructions_kernel`)
 *         is refused at compile time: use `CGAL::Exact_predicates_exact_constructions_kernel_with_sqrt`
 *         or an inexact kernel. The propagation runs in `FT`, but
 *         at least in `double`: in float, windows that tie within rounding would be trimmed in
 *         the wrong order, and the cones lost that way would leave vertices unreachable (float is
 *         kept for input and output).
 * \tparam VertexIndexMap the type of the vertex index map given to the constructor, by default the
 *         one `CGAL::get_initialized_vertex_index_map()` returns for the mesh.
 * \tparam FaceIndexMap the type of the face index map given to the constructor, by default the
 *         one `CGAL::get_initialized_face_index_map()` returns for the mesh.
 *
 * Sources and targets are vertices or points anywhere on the surface, as
 * `CGAL::Polygon_mesh_processing::Face_location` (a face and barycentric coordinates): a point
 * on an edge or at a vertex (zero coordinates) is that edge point or that vertex.
 * `CGAL::Polygon_mesh_processing::locate()` (or `locate_with_AABB_tree()` for many points)
 * gives the location of a 3D point.
 */
template <class TriangleMesh,
          class GeomTraits = Default,
          class VertexIndexMap = Default,
          class FaceIndexMap = Default>
class Geodesic_distance_solver
{
public:
  using Traits = typename Default::Lazy_get<GeomTraits, GetGeomTraits<TriangleMesh>>::type;
  using FT = typename Traits::FT;
  using Vertex_index_map = typename Default::Lazy_get<VertexIndexMap, internal::Vertex_index_map_of<TriangleMesh>>::type;
  using Face_index_map = typename Default::Lazy_get<FaceIndexMap, internal::Face_index_map_of<TriangleMesh>>::type;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  /// a point of the surface, the type of `CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, FT>`
  using Face_location = std::pair<face_descriptor, std::array<FT, 3>>;

  /*!
   * prepares the mesh for distance queries.
   *
   * \param tm a triangle mesh; it is not modified
   * \param np an optional sequence of named parameters among the ones listed below
   *
   * \cgalNamedParamsBegin
   *   \cgalParamNBegin{vertex_point_map}
   *     \cgalParamDescription{a property map associating points to the vertices of `tm`}
   *     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and the
   *                    traits' `Point_3` as value type}
   *     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{geom_traits}
   *     \cgalParamDescription{an instance of a geometric traits class}
   *     \cgalParamType{a model of `DGGVTPTraits_3`}
   *     \cgalParamDefault{the kernel of the point type of the vertex point map}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{vertex_index_map}
   *     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index
   *                           between `0` and `num_vertices(tm) - 1`}
   *     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and
   *                    `std::size_t` as value type}
   *     \cgalParamDefault{an automatically indexed internal map}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{face_index_map}
   *     \cgalParamDescription{a property map associating to each face of `tm` a unique index
   *                           between `0` and `num_faces(tm) - 1`}
   *     \cgalParamType{a model of `ReadablePropertyMap` with `face_descriptor` as key and
   *                    `std::size_t` as value type}
   *     \cgalParamDefault{an automatically indexed internal map}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{DGG_VTP_3::parameters::concurrency_tag}
   *     \cgalParamDescription{how the preparation runs: with `CGAL::Parallel_tag` its loops over
   *                           faces and vertices are shared among TBB's threads (needs
   *                           `CGAL_LINKED_WITH_TBB`); walking `tm` stays on the calling thread.
   *                           The prepared solver, and so every distance, is the same bit for bit
   *                           for any tag and number of threads, and so is the error thrown for
   *                           input refused. One thread with an `FT` other than `float` and `double`}
   *     \cgalParamType{`CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`, a value}
   *     \cgalParamDefault{`CGAL::Sequential_tag()`}
   *   \cgalParamNEnd
   * \cgalNamedParamsEnd
   *
   * \throws std::invalid_argument if a face is not a triangle, a coordinate is not finite, the
   *         mesh is too large (its bounding box overflows a `double`, or a face's squared edge
   *         lengths or area overflow `FT`), a face is degenerate (zero length edge or zero area),
   *         a face is a sliver (an edge more than 1e10 times longer than the height on it), an
   *         edge is shorter than 1e-3 machine epsilons of `FT` times the size of the mesh, or a
   *         vertex is the tip of a cone sharper than 1e-4 radians (a closed fan whose angles add
   *         up to less): windows would wrap around those too many times (see the input policy in
   *         the user manual), or if the mesh has more faces or vertices than 32-bit indices can number (about 1.4e9).
   */
  template <class NamedParameters = parameters::Default_named_parameters>
  explicit Geodesic_distance_solver(const TriangleMesh& tm,
                                    const NamedParameters& np = parameters::default_values())
    : m_core(prepare(tm, np))
  {}

  /*!
   * computes the geodesic distance from `source_vertex` to every vertex and writes it into
   * `distances`. Vertices that no path on the surface reaches (other connected components,
   * isolated vertices) get `+infinity`.
   *
   * \tparam ConcurrencyTag `CGAL::Sequential_tag` (the default), `CGAL::Parallel_tag` (the
   *         propagation runs in rounds over fixed patches of faces, and the patches of a round are
   *         shared among TBB's threads; needs `CGAL_LINKED_WITH_TBB`) or
   *         `CGAL::Parallel_if_available_tag`. The distances and statistics are the same bit for
   *         bit whatever the tag and the number of threads. With an `FT` other than `float` and
   *         `double` (exact number types are not thread-safe), one thread does the work.
   * \tparam Source `vertex_descriptor` or `CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, FT>`
   * \param source a vertex or a point of the mesh given to the constructor
   * \param distances a writable vertex property map with value type `FT`
   * \param np an optional sequence of named parameters among the ones listed below
   *
   * \cgalNamedParamsBegin
   *   \cgalParamNBegin{accuracy}
   *     \cgalParamDescription{the accuracy epsilon of DGG-VTP: every distance is at least the exact
   *                           one and at most (1 + epsilon) times it (see the manual); 0 is the
   *                           exact algorithm (VTP)}
   *     \cgalParamType{`double`, in [0, `CGAL::DGG_VTP_3::maximal_accuracy`] = [0, 1]}
   *     \cgalParamDefault{`0`}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{DGG_VTP_3::parameters::max_distance}
   *     \cgalParamDescription{the propagation stops there: vertices whose computed distance is
   *                           farther get `+infinity`, the others their distance, as without it
   *                           (with an accuracy, every vertex within max_distance / (1 + accuracy)
   *                           of the exact distance keeps its distance; see the user manual)}
   *     \cgalParamType{`double`, >= 0 (`+infinity` allowed)}
   *     \cgalParamDefault{`+infinity`}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{DGG_VTP_3::parameters::targets}
   *     \cgalParamDescription{the propagation stops as soon as the distances of these are final;
   *                           the other vertices then hold an upper bound of their distance (the
   *                           length of a path on the surface), or `+infinity` if not reached yet}
   *     \cgalParamType{a range of `vertex_descriptor` or of `Face_location`}
   *     \cgalParamDefault{none: every vertex}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{DGG_VTP_3::parameters::target_distances}
   *     \cgalParamDescription{receives the distance of each target, in the order of `targets`: at
   *                           a surface point, the exact distance (within the accuracy), not an
   *                           interpolation}
   *     \cgalParamType{an output iterator accepting `FT`}
   *     \cgalParamDefault{none}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{DGG_VTP_3::parameters::lower_bound_map}
   *     \cgalParamDescription{receives, per vertex, a certified lower bound of its exact distance
   *                           (the least key that reached it, see the manual's "Certified error"):
   *                           the exact distance is in [lower bound, distance], an interval of width
   *                           at most accuracy x distance; the distance itself in the exact mode,
   *                           `+infinity` where the distance is}
   *     \cgalParamType{a writable vertex property map with value type `FT`}
   *     \cgalParamDefault{none}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{DGG_VTP_3::parameters::nearest_source_map}
   *     \cgalParamDescription{receives, per vertex, the number of its nearest source in the order
   *                           of the sources (`std::size_t(-1)` where unreachable)}
   *     \cgalParamType{a writable vertex property map with value type `std::size_t`}
   *     \cgalParamDefault{none}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{DGG_VTP_3::parameters::prior_distance_map}
   *     \cgalParamDescription{adds the sources to the field of earlier ones: per vertex, its
   *                           distance to them (`+infinity` where unreached), as a query of this
   *                           solver at this accuracy or less gave it (within the contract). The
   *                           result is the field of all the sources, within the contract; the
   *                           propagation only goes where the new sources are nearer (see the
   *                           manual, "Adding sources to a field"). Not with `targets` and `max_distance`}
   *     \cgalParamType{a readable vertex property map with value type `FT`}
   *     \cgalParamDefault{none: from the sources alone}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{DGG_VTP_3::parameters::prior_nearest_source_map}
   *     \cgalParamDescription{with a prior field, the number of each vertex's nearest earlier
   *                           source; the new sources are numbered from one beyond the largest.
   *                           Needed for `nearest_source_map`}
   *     \cgalParamType{a readable vertex property map with value type `std::size_t`}
   *     \cgalParamDefault{none}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{DGG_VTP_3::parameters::prior_lower_bound_map}
   *     \cgalParamDescription{with a prior field, its certified lower bounds (as `lower_bound_map`
   *                           gave them), kept where no new source is nearer}
   *     \cgalParamType{a readable vertex property map with value type `FT`}
   *     \cgalParamDefault{the prior distance divided by 1 + accuracy}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{callback}
   *     \cgalParamDescription{progress and cancellation: called on the calling thread between
   *                           rounds of the propagation, after the first round and then at most
   *                           every 0.1 s (none for a propagation of one round), with the fraction
   *                           in [0, 1] of the vertices whose distance is final (popped from the
   *                           queue; unreachable vertices never are). Returning `false` cancels the
   *                           query: it throws `CGAL::DGG_VTP_3::Propagation_cancelled` and the
   *                           solver stays as it was, ready for the next query}
   *     \cgalParamType{a callable as `bool(double)`, e.g. `std::function<bool(double)>`}
   *     \cgalParamDefault{none}
   *   \cgalParamNEnd
   * \cgalNamedParamsEnd
   *
   * \returns what the propagation did
   * \throws std::invalid_argument if `source` is not a vertex or a point of the mesh (the face
   *         of another mesh, barycentric coordinates that are not finite, negative beyond rounding
   *         or do not add up to 1), the accuracy is not in [0, 1], or the maximum
   *         distance is negative or NaN; the same for the targets; for a prior distance negative
   *         or NaN, a prior lower bound outside [0, the prior distance], or no prior nearest source
   *         where the prior distance is finite.
   * \throws CGAL::DGG_VTP_3::Propagation_cancelled if `callback` returned `false`.
   */
  template <class ConcurrencyTag = Sequential_tag, class Source, class VertexDistanceMap,
            class NamedParameters = parameters::Default_named_parameters>
  Propagation_statistics compute_distances(const Source& source,
                                           VertexDistanceMap distances,
                                           const NamedParameters& np = parameters::default_values()) const
  {
    return compute_distances_to_nearest_source<ConcurrencyTag>(std::vector<Source>(1, source), distances, np);
  }

  /*!
   * the same with several sources: the distance of each vertex to the nearest of them.
   *
   * \tparam ConcurrencyTag as for `compute_distances()`
   * \tparam SourceRange a range of `vertex_descriptor` or of `Face_location`
   * \param np the named parameters of `compute_distances()`
   * \throws std::invalid_argument if `sources` is empty, for an element that `compute_distances()`
   *         refuses as source, or for its named parameters.
   */
  template <class ConcurrencyTag = Sequential_tag, class SourceRange, class VertexDistanceMap,
            class NamedParameters = parameters::Default_named_parameters>
  Propagation_statistics compute_distances_to_nearest_source(const SourceRange& sources,
                                                             VertexDistanceMap distances,
                                                             const NamedParameters& np = parameters::default_values()) const
  {
    return m_core->template distances_to_nearest_source<ConcurrencyTag>(sources, distances, np);
  }

  /*!
   * computes the geodesic distances from each source of `sources` to every vertex, one propagation
   * per source: those of `sources[k]` go into `distance_maps[k]`. Each is the propagation of
   * `compute_distances()`, so the distances are the same bit for bit whatever the concurrency tag
   * and the number of threads.
   *
   * \tparam ConcurrencyTag `CGAL::Sequential_tag` (the default), `CGAL::Parallel_tag` (the sources are shared
   *         among TBB's threads, each propagation runs on one thread; needs
   *         `CGAL_LINKED_WITH_TBB`; one thread with an `FT` other than `float` and `double`) or
   *         `CGAL::Parallel_if_available_tag`
   * \tparam VertexRange a range of `vertex_descriptor`
   * \tparam VertexDistanceMapRange a random access range of writable vertex property maps with value
   *         type `FT`, as many as sources; with `Parallel_tag` they are written at the same time,
   *         so two of them must not share their storage
   * \param np `accuracy` and `DGG_VTP_3::parameters::max_distance`, as for `compute_distances()`,
   *        applied to every propagation. The named parameters whose outputs are per query
   *        (`DGG_VTP_3::parameters::targets`, `DGG_VTP_3::parameters::target_distances`,
   *        `DGG_VTP_3::parameters::nearest_source_map`, `DGG_VTP_3::parameters::lower_bound_map`,
   *        `callback`) are refused at compile time:
   *        one output would have to serve every source (and the nearest of one source is that
   *        source).
   * \returns what each propagation did, in the order of `sources`
   * \throws std::invalid_argument before any propagation if an element of `sources` is not a
   *         vertex of the mesh, if the two ranges differ in size, if the accuracy is not in [0, 1],
   *         or if the maximum distance is negative or NaN. No source: nothing is done.
   */
  template <class ConcurrencyTag = Sequential_tag, class VertexRange, class VertexDistanceMapRange,
            class NamedParameters = parameters::Default_named_parameters>
  std::vector<Propagation_statistics>
  compute_distances_from_each_source(const VertexRange& sources,
                                     const VertexDistanceMapRange& distance_maps,
                                     const NamedParameters& np = parameters::default_values()) const
  {
    return m_core->template distances_from_each_source<ConcurrencyTag>(sources, distance_maps, np);
  }

  /*!
   * computes, for each set of vertices of `source_sets`, the geodesic distance from the nearest
   * vertex of the set to every vertex: one propagation per set, the set being one source (as
   * the copies of a vertex that was split to repair a mesh). Each field is handed to `row` as soon
   * as it is done, so that many of them need not be held at once. Each is the propagation of
   * `compute_distances_to_nearest_source()` from the set, so the distances are the same bit for
   * bit whatever the concurrency tag and the number of threads; `compute_distances_from_each_source()`
   * is this query with one vertex per set.
   *
   * \tparam ConcurrencyTag as for `compute_distances_from_each_source()`
   * \tparam SourceSetRange a range of ranges of `vertex_descriptor`
   * \tparam RowFunction a callable as `row(std::size_t k, const std::vector<FT>& distances,
   *         const Propagation_statistics& statistics)`: `k` is the number of the set in
   *         `source_sets`, `distances[i]` the distance of the vertex of index `i` (by the vertex
   *         index map; `+infinity` if unreachable), valid during the call only. With `Parallel_tag`
   *         it is called from several threads at once, the sets in no particular order. A callable
   *         of five parameters, `row(k, distances, statistics, reached, lower_bounds)`, also
   *         receives the indices of the vertices the propagation reached (`const std::vector<std::uint32_t>&`:
   *         every other is at `+infinity`) and, per vertex, the lower bounds of
   *         `DGG_VTP_3::parameters::lower_bound_map` (`const std::vector<FT>&`).
   * \param np as for `compute_distances_from_each_source()`
   * \throws std::invalid_argument before any propagation if an element of a set is not a vertex
   *         of the mesh, if a set is empty, if the accuracy is not in [0, 1], or if the
   *         maximum distance is negative or NaN. No set: nothing is done. An exception thrown by
   *         `row` ends the query and is rethrown (with `Parallel_tag`, once the propagations
   *         under way are done).
   */
  template <class ConcurrencyTag = Sequential_tag, class SourceSetRange, class RowFunction,
            class NamedParameters = parameters::Default_named_parameters>
  void compute_distances_from_each_source_set(const SourceSetRange& source_sets, const RowFunction& row,
                                              const NamedParameters& np = parameters::default_values()) const
  {
    m_core->template distances_from_each_source_set<ConcurrencyTag>(source_sets, row, np);
  }

  /*!
   * computes, for each pair (source, target) of `pairs`, the geodesic distance between them, and
   * a certified lower bound of it: one propagation per pair, which searches toward its target
   * (ordered by distance plus the straight distance in space still to go) and stops as soon as
   * the target's distance is final, a fraction of a whole field. With an accuracy epsilon, the
   * distance is within [exact, (1 + epsilon) exact] and the lower bound within [exact / (1 +
   * epsilon), exact]; in the exact mode both are the exact distance. The distances are the same
   * bit for bit whatever the concurrency tag and the number of threads.
   *
   * \tparam ConcurrencyTag `Sequential_tag` (the default) or `Parallel_tag`: the pairs are
   *         shared among TBB's threads, each propagation on one thread
   * \tparam PairRange a range of pairs (`std::pair`: members `first`, the source, and `second`, the
   *         target), each a `vertex_descriptor` or a `Face_location`
   * \tparam PairFunction a callable as `pair(std::size_t k, FT distance, FT lower_bound)`: `k` is
   *         the number of the pair in `pairs`; `+infinity` for both if the target is unreachable
   *         (or beyond `DGG_VTP_3::parameters::max_distance`). A callable of four parameters,
   *         `pair(k, distance, lower_bound, path)`, also receives the shortest path, from the
   *         source to the target (`const std::vector<Path_point>&`; empty if unreachable),
   *         whose length is the distance. With `Parallel_tag` it is called from several threads
   *         at once, the pairs in no particular order.
   * \param np `accuracy`, `DGG_VTP_3::parameters::max_distance`
   * \throws std::invalid_argument before any propagation if an element of a pair is not a vertex
   *         or a surface point of the mesh (the message names the pair), or for the accuracy
   *         and maximum distance as `compute_distances()`. An exception thrown by `pair` ends the
   *         query and is rethrown.
   */
  template <class ConcurrencyTag = Sequential_tag, class PairRange, class PairFunction,
            class NamedParameters = parameters::Default_named_parameters>
  void compute_pair_distances(const PairRange& pairs, const PairFunction& pair,
                              const NamedParameters& np = parameters::default_values()) const
  {
    internal::pair_distances<ConcurrencyTag>(*m_core, pairs, pair, np, [this](auto& propagation, const auto& query, const auto& places) {
      return Shortest_path_tree<Geodesic_distance_solver>(m_core, propagation, query, places);
    });
  }

  /*!
   * computes the distances from `sources` as `compute_distances_to_nearest_source()` does, and
   * keeps what tracing the shortest paths back needs (per vertex about 40 bytes more than the
   * distance): the paths to every vertex and to the point `targets` (named parameter) can then be
   * traced. With DGG-VTP, a path goes through the pseudo-source vertices that produced the
   * distance, and its length is the distance reported.
   *
   * \tparam ConcurrencyTag, SourceRange as for `compute_distances_to_nearest_source()`
   * \param np `accuracy`, `DGG_VTP_3::parameters::max_distance`, `DGG_VTP_3::parameters::targets`
   *        (the paths to points that will be asked for, and early termination), `callback`
   */
  template <class ConcurrencyTag = Sequential_tag, class SourceRange,
            class NamedParameters = parameters::Default_named_parameters>
  Shortest_path_tree<Geodesic_distance_solver>
  compute_shortest_path_tree(const SourceRange& sources, const NamedParameters& np = parameters::default_values()) const
  {
    return m_core->template shortest_path_tree<ConcurrencyTag>(
      sources, np, [this](auto& propagation, const auto& query, const auto& targets) {
        return Shortest_path_tree<Geodesic_distance_solver>(m_core, propagation, query, targets);
      });
  }

  /*!
   * farthest-point sampling: `k` vertices, the first one given, each next one the farthest from
   * those before it (ties to the lowest index); in the exact mode the greedy sequence, with an
   * accuracy epsilon > 0 a sequence whose every sample's exact distance to those before it is at
   * least the largest one divided by 1 + epsilon. Each sample is added to the field of those before
   * (as `prior_distance_map` does), so that it costs its Voronoi cell, not a whole field. Vertices
   * that no sample reaches (other connected components) are at `+infinity`, the farthest: the next
   * sample is the first of them. A sample is never taken twice, even where the others are at
   * distance 0 (copies, coincident vertices).
   *
   * \tparam ConcurrencyTag as for `compute_distances()`
   * \tparam OutputIterator an output iterator accepting `vertex_descriptor`
   * \param k the number of samples, in [1, number_of_vertices()]
   * \param samples receives the samples, in order
   * \param np `accuracy`, `callback` (called between the rounds of each sample's propagation and
   *        after each sample, with the fraction of the samples taken), `DGG_VTP_3::parameters::lower_bound_map` and
   *        `DGG_VTP_3::parameters::nearest_source_map` (the number of the nearest sample, in the order
   *        of the samples), of the field of the samples, as for `compute_distances()`, and:
   * \cgalNamedParamsBegin
   *   \cgalParamNBegin{DGG_VTP_3::parameters::first_sample}
   *     \cgalParamDescription{the first sample}
   *     \cgalParamType{`vertex_descriptor`}
   *     \cgalParamDefault{the vertex of index 0}
   *   \cgalParamNEnd
   *   \cgalParamNBegin{DGG_VTP_3::parameters::distance_map}
   *     \cgalParamDescription{receives, per vertex, its distance to the nearest sample}
   *     \cgalParamType{a writable vertex property map with value type `FT`}
   *     \cgalParamDefault{none}
   *   \cgalParamNEnd
   * \cgalNamedParamsEnd
   * \returns the output iterator past the samples
   * \throws std::invalid_argument if `k` is 0 or above the number of vertices, the first sample is
   *         not a vertex of the mesh, or the accuracy is not in [0, 1].
   * \throws CGAL::DGG_VTP_3::Propagation_cancelled if `callback` returned `false`.
   */
  template <class ConcurrencyTag = Sequential_tag, class OutputIterator,
            class NamedParameters = parameters::Default_named_parameters>
  OutputIterator farthest_point_sampling(std::size_t k, OutputIterator samples,
                                         const NamedParameters& np = parameters::default_values()) const
  {
    for(const vertex_descriptor& v : m_core->template farthest_point_sampling<ConcurrencyTag>(k, np))
      *samples++ = v;
    return samples;
  }

  /// Copies share the prepared mesh, which no query changes: a copy costs a pointer. Moving a
  /// solver copies it too, so that the solver moved from answers as before; an assigned solver
  /// answers as the one assigned. Not while another thread queries the solver assigned to.
  Geodesic_distance_solver(const Geodesic_distance_solver&) = default;
  Geodesic_distance_solver& operator=(const Geodesic_distance_solver&) = default;

  /// Gives back the memory that queries keep for the next ones: the scratch of a propagation (a
  /// few arrays over the vertices, faces and halfedges), one for each thread that queried at
  /// once, which the next query makes again. The solver stays usable, from any thread, and its
  /// results do not change. Shared by the copies of the solver.
  void release_query_memory() const { m_core->release_query_memory(); }

  std::size_t number_of_vertices() const { return m_core->number_of_vertices(); }

  /// the number of vertices where several fans of faces meet; they are kept as they are, and
  /// shortest paths may go from one fan to another through them
  std::size_t number_of_non_manifold_vertices() const { return m_core->number_of_non_manifold_vertices(); }

private:
  friend class Shortest_path_tree<Geodesic_distance_solver>;
  using Numbering = internal::Mesh_numbering<TriangleMesh, Vertex_index_map, Face_index_map>;
  using Core = internal::Solver_core<Numbering, FT>;

  template <class NamedParameters>
  static std::shared_ptr<const Core> prepare(const TriangleMesh& tm, const NamedParameters& np)
  {
    using Tag = typename Core::template Preparation_tag<NamedParameters>;
    const Vertex_index_map vim = get_initialized_vertex_index_map(tm, np);
    const Face_index_map fim = get_initialized_face_index_map(tm, np);
    typename Core::Mesh mesh;
    internal::Unfolding_order order = internal::unfold_triangle_mesh<Tag>(
      tm,
      parameters::choose_parameter(parameters::get_parameter(np, internal_np::vertex_point),
                                   get_const_property_map(CGAL::vertex_point, tm)),
      vim, fim,
      parameters::choose_parameter<Traits>(parameters::get_parameter(np, internal_np::geom_traits)),
      mesh);
    return std::make_shared<const Core>(Tag(), Numbering(tm, vim, fim), std::move(mesh), std::move(order));
  }

  // the prepared mesh and the queries, on the numbers of the index maps; shared by the copies of
  // the solver and by the shortest path trees it computed, never changed
  std::shared_ptr<const Core> m_core;
};

} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_GEODESIC_DISTANCE_SOLVER_H
