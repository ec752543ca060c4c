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

#ifndef CGAL_DGG_VTP_3_PARAMETERS_H
#define CGAL_DGG_VTP_3_PARAMETERS_H

#include <CGAL/license/DGG_VTP_3.h>

/// \file parameters.h
/// The named parameters of this package that CGAL's list does not have. CGAL 5.5's list of named
/// parameters is closed, so these are free functions that start a chain: CGAL's own parameters
/// may follow them (`CGAL::DGG_VTP_3::parameters::max_distance(0.5).accuracy(1e-4)`), and one of
/// them is added to an existing chain with its second argument
/// (`parameters::targets(points, parameters::max_distance(0.5))`).

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace DGG_VTP_3 {

// CGAL's own named parameters are seen through these namespaces too
namespace internal_np {

using namespace CGAL::internal_np;

struct max_distance_t {};
struct targets_t {};
struct target_distances_t {};
struct nearest_source_map_t {};
struct lower_bound_map_t {};
struct copy_of_t {};
struct concurrency_tag_t {};
struct prior_distance_map_t {};
struct prior_nearest_source_map_t {};
struct prior_lower_bound_map_t {};
struct first_sample_t {};
struct distance_map_t {};

} // namespace internal_np

/// The largest `accuracy` the package supports. Every accuracy in [0, maximal_accuracy] keeps the
/// contract (every distance at most (1 + accuracy) times the exact one, none below it); a larger
/// one is refused with `std::invalid_argument`: a relative error above 100% no longer approximates
/// a distance.
constexpr double maximal_accuracy = 1.;

namespace parameters {

using namespace CGAL::parameters;

#define CGAL_DGG_VTP_3_NAMED_PARAMETER(name)                                                          \
  template <class T>                                                                                 \
  CGAL::Named_function_parameters<T, internal_np::name##_t> name(const T& value)                     \
  {                                                                                                  \
    return CGAL::Named_function_parameters<T, internal_np::name##_t>(value);                         \
  }                                                                                                  \
  template <class T, class U, class Tag, class Base>                                                 \
  CGAL::Named_function_parameters<T, internal_np::name##_t, CGAL::Named_function_parameters<U, Tag, Base>> \
  name(const T& value, const CGAL::Named_function_parameters<U, Tag, Base>& np)                      \
  {                                                                                                  \
    return CGAL::Named_function_parameters<T, internal_np::name##_t,                                 \
                                           CGAL::Named_function_parameters<U, Tag, Base>>(value, np); \
  }

/// Stops the propagation at this distance: farther vertices get `+infinity`.
CGAL_DGG_VTP_3_NAMED_PARAMETER(max_distance)
/// Vertices or surface points (`CGAL::Polygon_mesh_processing::Face_location`): the propagation
/// stops as soon as their distances are final.
CGAL_DGG_VTP_3_NAMED_PARAMETER(targets)
/// An output iterator that receives the distance of each of the `targets`, in their order.
CGAL_DGG_VTP_3_NAMED_PARAMETER(target_distances)
/// A writable vertex property map that receives, per vertex, the number of its nearest source in
/// the range of sources (`std::size_t(-1)` where unreachable).
CGAL_DGG_VTP_3_NAMED_PARAMETER(nearest_source_map)
/// A writable vertex property map that receives, per vertex, a certified lower bound of its exact
/// distance: the least key that reached it (see the manual, "Certified error"), so that the exact
/// distance lies in [lower bound, distance], an interval of width at most epsilon x distance;
/// equal to the distance in the exact mode, and `+infinity` where the distance is.
CGAL_DGG_VTP_3_NAMED_PARAMETER(lower_bound_map)
/// For `Triangle_soup_geodesic_distance_solver`: a random access range of point indices, one per
/// point, point `i` being a copy of point `copy_of[i]` (itself if it is none) and of that one's
/// copies. Copies are one point of the surface, split where sheets meet (as
/// `CGAL::Polygon_mesh_processing::orient_polygon_soup()` splits an edge of more than two
/// triangles and a vertex where fans meet): paths go from one copy to the others at no cost, and
/// across an edge between copies into every sheet that has it.
CGAL_DGG_VTP_3_NAMED_PARAMETER(copy_of)
/// The preparation of a solver's constructor on several threads: `CGAL::Parallel_tag` (TBB),
/// `CGAL::Parallel_if_available_tag` or `CGAL::Sequential_tag`, as a value
/// (`concurrency_tag(CGAL::Parallel_tag())`). CGAL names it so from 6.0 on.
CGAL_DGG_VTP_3_NAMED_PARAMETER(concurrency_tag)
/// A readable vertex property map: the field of earlier sources (per vertex its distance to
/// them, `+infinity` where unreached, as a query of the same solver at the same accuracy or less
/// gave it) that the sources of the query are added to. The result is the field of all the
/// sources, within the contract, and the propagation goes only where the new sources are nearer
/// (see the manual, "Adding sources to a field"). Not with `targets` and `max_distance`.
CGAL_DGG_VTP_3_NAMED_PARAMETER(prior_distance_map)
/// A readable vertex property map: with `prior_distance_map`, the number of each vertex's nearest
/// earlier source (`std::size_t(-1)` where unreached); the new sources are numbered from one
/// beyond the largest. Needed for `nearest_source_map` with a prior field.
CGAL_DGG_VTP_3_NAMED_PARAMETER(prior_nearest_source_map)
/// A readable vertex property map: with `prior_distance_map`, the certified lower bounds of the
/// prior field (as `lower_bound_map` gave them), kept where no new source is nearer; by default
/// the prior distance divided by 1 + accuracy, which the contract makes a lower bound.
CGAL_DGG_VTP_3_NAMED_PARAMETER(prior_lower_bound_map)
/// For `farthest_point_sampling()`: the first sample, a `vertex_descriptor` (by default the vertex
/// of index 0). The programs call it `--first-sample`, the Python module `first_sample`.
CGAL_DGG_VTP_3_NAMED_PARAMETER(first_sample)
/// For `farthest_point_sampling()`: a writable vertex property map that receives, per vertex, its
/// distance to the nearest sample (the field of the samples, within the contract).
CGAL_DGG_VTP_3_NAMED_PARAMETER(distance_map)

#undef CGAL_DGG_VTP_3_NAMED_PARAMETER

} // namespace parameters
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_PARAMETERS_H
