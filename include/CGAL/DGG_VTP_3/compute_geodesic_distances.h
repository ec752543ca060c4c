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

#ifndef CGAL_DGG_VTP_3_COMPUTE_GEODESIC_DISTANCES_H
#define CGAL_DGG_VTP_3_COMPUTE_GEODESIC_DISTANCES_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/Geodesic_distance_solver.h>

#include <type_traits>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {

/*!
 * \ingroup PkgDGGVTP3Ref
 *
 * computes the geodesic distance from a source vertex, or from the nearest of several, to every
 * vertex of `tm`: the one-shot form of `Geodesic_distance_solver`, with the same named parameters
 * and the same defaults (it is written in terms of the class). The arguments come in the order of
 * `CGAL::Heat_method_3::estimate_geodesic_distances()`.
 *
 * \tparam ConcurrencyTag `CGAL::Sequential_tag` (the default), `CGAL::Parallel_tag` or
 *         `CGAL::Parallel_if_available_tag`, as for `Geodesic_distance_solver::compute_distances()`
 * \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph` with triangle faces
 * \tparam VertexDistanceMap a writable vertex property map with the traits' `FT` as value type
 * \tparam Sources a `vertex_descriptor`, or a range of them
 *
 * \param tm the triangle mesh
 * \param distances receives the distances; unreachable vertices get `+infinity`
 * \param sources the source vertex, or the source vertices
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
 * \returns what the propagation did
 * \throws std::invalid_argument for the input the constructor of `Geodesic_distance_solver` or
 *         its queries refuse
 */
template <class ConcurrencyTag = Sequential_tag, class TriangleMesh, class VertexDistanceMap, class Sources,
          class NamedParameters = parameters::Default_named_parameters>
Propagation_statistics
compute_geodesic_distances(const TriangleMesh& tm,
                           VertexDistanceMap distances,
                           const Sources& sources,
                           const NamedParameters& np = parameters::default_values())
{
  using Traits = typename GetGeomTraits<TriangleMesh, NamedParameters>::type;
  using Vertex_index_map = typename GetInitializedVertexIndexMap<TriangleMesh, NamedParameters>::const_type;
  using Face_index_map = typename GetInitializedFaceIndexMap<TriangleMesh, NamedParameters>::const_type;
  using Solver = Geodesic_distance_solver<TriangleMesh, Traits, Vertex_index_map, Face_index_map>;
  const Solver solver(tm, np);
  if constexpr(std::is_convertible<Sources, typename Solver::vertex_descriptor>::value ||
               std::is_convertible<Sources, typename Solver::Face_location>::value)
    return solver.template compute_distances<ConcurrencyTag>(sources, distances, np);
  else
    return solver.template compute_distances_to_nearest_source<ConcurrencyTag>(sources, distances, np);
}

} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_COMPUTE_GEODESIC_DISTANCES_H
