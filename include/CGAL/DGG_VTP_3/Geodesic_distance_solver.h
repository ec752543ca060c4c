// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

#ifndef CGAL_DGG_VTP_3_GEODESIC_DISTANCE_SOLVER_H
#define CGAL_DGG_VTP_3_GEODESIC_DISTANCE_SOLVER_H

#include <CGAL/DGG_VTP_3/Propagation_statistics.h>
#include <CGAL/DGG_VTP_3/internal/Effective_concurrency_tag.h>
#include <CGAL/DGG_VTP_3/internal/Patch_partition.h>
#include <CGAL/DGG_VTP_3/internal/Unfolded_mesh.h>
#include <CGAL/DGG_VTP_3/internal/Window_propagation.h>

#include <CGAL/Default.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/for_each.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/range/irange.hpp>

#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {

/*!
 * \ingroup PkgDGGVTP3Ref
 *
 * Geodesic distances from a source vertex to every vertex of a triangle mesh, by window
 * propagation: exact (the VTP algorithm) or, with a positive accuracy, by DGG-VTP.
 *
 * The constructor does all the per-mesh work once (edge lengths, every triangle unfolded onto each
 * of its edges, vertex angle sums); the mesh is not read again afterwards and may be destroyed.
 * Queries are `const` and keep their scratch to themselves, so one solver may serve several
 * threads at once.
 *
 * \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`, with triangle faces.
 * \tparam GeomTraits a model of `DGGVTPTraits_3`; by default the kernel of the mesh's points.
 *         Its `FT` is the number type of the results (`double`, `float`, or an exact type with
 *         square roots). The propagation runs in `FT`, but at least in `double`: in float,
 *         windows that tie within rounding get trimmed in the wrong order, and the cones lost
 *         that way left vertices unreachable (float is kept for input and output).
 * \tparam VertexIndexMap the type of the vertex index map given to the constructor, by default the
 *         one `CGAL::get_initialized_vertex_index_map()` returns for the mesh.
 */
template <class TriangleMesh,
          class GeomTraits = Default,
          class VertexIndexMap = Default>
class Geodesic_distance_solver
{
public:
  using Traits = typename Default::Get<GeomTraits, typename GetGeomTraits<TriangleMesh>::type>::type;
  using FT = typename Traits::FT;
  using Vertex_index_map = typename Default::Get<VertexIndexMap,
                             typename GetInitializedVertexIndexMap<TriangleMesh>::const_type>::type;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;

private:
  using Computation_FT = typename std::conditional<std::is_same<FT, float>::value, double, FT>::type;
  using Mesh = internal::Unfolded_mesh<Computation_FT>;

public:

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
   * \cgalNamedParamsEnd
   *
   * \throws std::invalid_argument if a face is not a triangle, a coordinate is not finite, or a
   *         face is degenerate (zero length edge or zero area), a face is a sliver (an edge more
   *         than 1e10 times longer than the height on it) or a vertex is the tip of a cone
   *         sharper than 1e-4 radians (a closed fan whose angles add up to less): windows would
   *         wrap around those too many times (see the input policy in the user manual), or
   *         if the mesh has more faces or vertices than 32-bit indices can number (about 1.4e9).
   */
  template <class NamedParameters = parameters::Default_named_parameters>
  explicit Geodesic_distance_solver(const TriangleMesh& tm,
                                    const NamedParameters& np = parameters::default_values())
    : m_vim(get_initialized_vertex_index_map(tm, np))
  {
    internal::unfold_triangle_mesh(
      tm,
      parameters::choose_parameter(parameters::get_parameter(np, internal_np::vertex_point),
                                   get_const_property_map(CGAL::vertex_point, tm)),
      m_vim, get_initialized_face_index_map(tm, np),
      parameters::choose_parameter<Traits>(parameters::get_parameter(np, internal_np::geom_traits)),
      m_mesh);
    m_partition = internal::Patch_partition<Computation_FT>(m_mesh);
    m_vertices.resize(m_mesh.number_of_vertices());
    for(vertex_descriptor v : vertices(tm))
      m_vertices[static_cast<std::size_t>(get(m_vim, v))] = v;
  }

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
   * \param source_vertex a vertex of the mesh given to the constructor
   * \param distances a writable vertex property map with value type `FT`
   * \param np an optional sequence of named parameters among the ones listed below
   *
   * \cgalNamedParamsBegin
   *   \cgalParamNBegin{accuracy}
   *     \cgalParamDescription{the accuracy epsilon of DGG-VTP: every distance is within a relative
   *                           error epsilon of the exact one; 0 is the exact algorithm (VTP)}
   *     \cgalParamType{`double`, finite and >= 0}
   *     \cgalParamDefault{`0`}
   *   \cgalParamNEnd
   * \cgalNamedParamsEnd
   *
   * \returns what the propagation did
   * \throws std::invalid_argument if `source_vertex` is not a vertex of the mesh or the accuracy
   *         is negative or not finite.
   */
  template <class ConcurrencyTag = Sequential_tag, class VertexDistanceMap,
            class NamedParameters = parameters::Default_named_parameters>
  Propagation_statistics compute_distances(vertex_descriptor source_vertex,
                                           VertexDistanceMap distances,
                                           const NamedParameters& np = parameters::default_values()) const
  {
    return compute_distances_to_nearest_source<ConcurrencyTag>(std::vector<vertex_descriptor>(1, source_vertex),
                                                               distances, np);
  }

  /*!
   * the same with several sources: the distance of each vertex to the nearest of them.
   *
   * \tparam ConcurrencyTag as for `compute_distances()`
   * \tparam VertexRange a range of `vertex_descriptor`
   * \param np the named parameters of `compute_distances()`
   * \throws std::invalid_argument if `sources` is empty or has an element that is not a vertex of
   *         the mesh, or if the accuracy is negative or not finite.
   */
  template <class ConcurrencyTag = Sequential_tag, class VertexRange, class VertexDistanceMap,
            class NamedParameters = parameters::Default_named_parameters>
  Propagation_statistics compute_distances_to_nearest_source(const VertexRange& sources,
                                                             VertexDistanceMap distances,
                                                             const NamedParameters& np = parameters::default_values()) const
  {
    const Computation_FT accuracy = checked_accuracy(np);
    const std::vector<Index> indices = checked_indices(sources);
    if(indices.empty())
      throw std::invalid_argument("no source given");
    return propagate<ConcurrencyTag>(indices, accuracy, distances);
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
   * \param np the named parameters of `compute_distances()`
   * \returns what each propagation did, in the order of `sources`
   * \throws std::invalid_argument before any propagation if an element of `sources` is not a
   *         vertex of the mesh, if the two ranges differ in size, or if the accuracy is negative or
   *         not finite. No source: nothing is done.
   */
  template <class ConcurrencyTag = Sequential_tag, class VertexRange, class VertexDistanceMapRange,
            class NamedParameters = parameters::Default_named_parameters>
  std::vector<Propagation_statistics>
  compute_distances_from_each_source(const VertexRange& sources,
                                     const VertexDistanceMapRange& distance_maps,
                                     const NamedParameters& np = parameters::default_values()) const
  {
    const Computation_FT accuracy = checked_accuracy(np);
    const std::vector<Index> indices = checked_indices(sources);
    if(indices.size() != static_cast<std::size_t>(std::distance(std::begin(distance_maps), std::end(distance_maps))))
      throw std::invalid_argument("one distance map per source is needed");

    std::vector<Propagation_statistics> statistics(indices.size());
    CGAL::for_each<Effective_tag<ConcurrencyTag>>(boost::irange(std::size_t(0), indices.size()), [&](std::size_t k) {
      statistics[k] = propagate<Sequential_tag>(std::vector<Index>(1, indices[k]), accuracy,
                                                *(std::begin(distance_maps) + k));
      return true;
    });
    return statistics;
  }

  std::size_t number_of_vertices() const { return m_vertices.size(); }

private:
  using Index = typename Mesh::Index;

  template <class NamedParameters>
  static Computation_FT checked_accuracy(const NamedParameters& np)
  {
    const double accuracy = parameters::choose_parameter(parameters::get_parameter(np, internal_np::accuracy), 0.);
    if(!(accuracy >= 0.) || !std::isfinite(accuracy))
      throw std::invalid_argument("the accuracy must be a finite number >= 0");
    return Computation_FT(accuracy);
  }

  template <class VertexRange>
  std::vector<Index> checked_indices(const VertexRange& sources) const
  {
    std::vector<Index> indices;
    for(vertex_descriptor v : sources)
    {
      const std::size_t i = static_cast<std::size_t>(get(m_vim, v));
      if(i >= m_vertices.size() || m_vertices[i] != v)
        throw std::invalid_argument("the source is not a vertex of the mesh");
      indices.push_back(static_cast<Index>(i));
    }
    return indices;
  }

  template <class ConcurrencyTag>
  using Effective_tag = typename internal::Effective_concurrency_tag<ConcurrencyTag, Computation_FT>::type;

  template <class ConcurrencyTag, class VertexDistanceMap>
  Propagation_statistics propagate(const std::vector<Index>& sources, Computation_FT accuracy,
                                   VertexDistanceMap distances) const
  {
    internal::Window_propagation<Computation_FT> propagation(m_mesh, m_partition, accuracy);
    propagation.template run<Effective_tag<ConcurrencyTag>>(sources);
    const std::vector<Computation_FT>& d = propagation.distances();
    for(std::size_t i = 0; i < m_vertices.size(); ++i)
      put(distances, m_vertices[i], FT(d[i]));
    return propagation.statistics();
  }

  Vertex_index_map m_vim;                    // user's vertex -> internal index
  Mesh m_mesh;                               // intrinsic geometry and combinatorics
  internal::Patch_partition<Computation_FT> m_partition; // the faces cut into patches for the propagation's rounds
  std::vector<vertex_descriptor> m_vertices; // internal index -> user's vertex
};

} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_GEODESIC_DISTANCE_SOLVER_H
