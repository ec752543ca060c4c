// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

#ifndef CGAL_DGG_VTP_3_COMPUTE_GEODESIC_DISTANCES_H
#define CGAL_DGG_VTP_3_COMPUTE_GEODESIC_DISTANCES_H

#include <CGAL/DGG_VTP_3/Geodesic_distance_solver.h>

namespace CGAL {
namespace DGG_VTP_3 {

/*!
 * \ingroup PkgDGGVTP3Ref
 *
 * One-shot form of `Geodesic_distance_solver`: prepares the mesh and answers one query, with the
 * same named parameters and the same defaults (it is written in terms of the class).
 *
 * \tparam ConcurrencyTag `CGAL::Sequential_tag` (the default), `CGAL::Parallel_tag` or
 *         `CGAL::Parallel_if_available_tag`, as for `Geodesic_distance_solver::compute_distances()`
 * \param tm a triangle mesh, model of `FaceListGraph` and `HalfedgeListGraph`
 * \param source_vertex the source vertex
 * \param distances a writable vertex property map with the traits' `FT` as value type;
 *        unreachable vertices get `+infinity`
 * \param np optional named parameters: `vertex_point_map`, `geom_traits`, `vertex_index_map`,
 *        `face_index_map`, `accuracy`
 */
template <class ConcurrencyTag = Sequential_tag, class TriangleMesh, class VertexDistanceMap,
          class NamedParameters = parameters::Default_named_parameters>
Propagation_statistics
compute_geodesic_distances(const TriangleMesh& tm,
                           typename boost::graph_traits<TriangleMesh>::vertex_descriptor source_vertex,
                           VertexDistanceMap distances,
                           const NamedParameters& np = parameters::default_values())
{
  using Traits = typename GetGeomTraits<TriangleMesh, NamedParameters>::type;
  using Vertex_index_map = typename GetInitializedVertexIndexMap<TriangleMesh, NamedParameters>::const_type;
  const Geodesic_distance_solver<TriangleMesh, Traits, Vertex_index_map> solver(tm, np);
  return solver.template compute_distances<ConcurrencyTag>(source_vertex, distances, np);
}

} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_COMPUTE_GEODESIC_DISTANCES_H
