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

#ifndef CGAL_DGG_VTP_3_INTERNAL_PROPAGATION_QUERY_H
#define CGAL_DGG_VTP_3_INTERNAL_PROPAGATION_QUERY_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/Surface_point.h>
#include <CGAL/DGG_VTP_3/internal/number_type_math.h>

#include <cstdint>
#include <functional>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// A field that a propagation adds its sources to (Propagation_query::prior), per vertex: the
// length of a path to an earlier source (+infinity: none), a lower bound of the exact distance to
// those, and the number of that source plus the number of vertices (see Propagation_vertices::origins())
template <class FT>
struct Prior_field
{
  std::vector<FT> distance, lower_bound;
  std::vector<std::uint32_t> origin;
};

// What one propagation is asked: where it starts, how far it needs to go, what it records.
template <class FT>
struct Propagation_query
{
  using Index = std::uint32_t;
  // the sources, numbered in this order: first the vertices, then the surface points (a surface
  // point at a vertex is given as that vertex)
  std::vector<Index> vertex_sources;
  std::vector<Surface_point<FT>> point_sources;
  std::vector<Index> source_numbers;          // per vertex source, then per point source: its number in the user's range
  FT max_distance = Number_type_math<FT>::infinity(); // stop there; farther vertices are unreached
  // stop once these are final (none: the whole field)
  std::vector<Index> vertex_targets;
  std::vector<Surface_point<FT>> point_targets;
  // search toward the targets (see Distance_to_go): the pair queries do; the other target queries
  // grow a disk, whose values are the whole field's bits (the manual, "Targets")
  bool toward_targets = false;
  bool record_origins = false;                // the pseudo-source of each vertex (nearest sources, paths)
  bool record_arrivals = false;               // the direction each vertex's path arrives from (paths)
  // Add the sources to a field rather than start from nothing (see Propagation_vertices::keep_field):
  // to `prior`, or if none to the field of the propagation's last run
  bool add_to_field = false;
  const Prior_field<FT>* prior = nullptr;
  // the user's `callback`: given the fraction of vertices popped, false cancels (empty: none)
  std::function<bool(double)> progress;
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_PROPAGATION_QUERY_H
