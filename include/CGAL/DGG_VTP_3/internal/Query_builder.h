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

#ifndef CGAL_DGG_VTP_3_INTERNAL_QUERY_BUILDER_H
#define CGAL_DGG_VTP_3_INTERNAL_QUERY_BUILDER_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/Propagation_query.h>

#include <CGAL/number_utils.h>

#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <algorithm>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// Sources and targets as the user gives them (vertices, or surface points as
// CGAL::Polygon_mesh_processing::Face_location: a face and the barycentric coordinates of
// source(halfedge(f)), target(halfedge(f)), target(next(halfedge(f))), the order of the corners of
// Unfolded_mesh) checked and turned into the solver's numbering.
template <class Numbering, class UnfoldedMesh, class FT>
class Query_builder
{
  using vertex_descriptor = typename Numbering::vertex_descriptor;
  using face_descriptor = typename Numbering::face_descriptor;
  using Index = std::uint32_t;

public:
  // a vertex, or a surface point of the solver's numbering
  struct Location
  {
    bool is_vertex;
    Index vertex;
    Surface_point<FT> point;
  };

  // `numbering`: of the vertices and faces of `mesh` (see Unfolded_numbering)
  Query_builder(const Numbering& numbering, const UnfoldedMesh& mesh) : m_numbering(numbering), m_mesh(mesh) {}

  Index vertex_index(vertex_descriptor v, const char* what) const
  {
    const std::size_t i = m_numbering.vertex_index(v);
    if(i == m_numbering.number_of_vertices())
      throw std::invalid_argument(std::string("the ") + what + " is not a vertex of the mesh");
    return Index(i);
  }

  template <class Element>
  Location locate(const Element& e, const char* what) const
  {
    if constexpr(std::is_convertible<Element, vertex_descriptor>::value)
      return Location{true, vertex_index(e, what), Surface_point<FT>{}};
    else
      return surface_point(e.first, e.second, what);
  }

  // the sources of `range` in the query, numbered in the range's order
  template <class Range>
  void add_sources(const Range& range, Propagation_query<FT>& query) const
  {
    std::vector<Index> point_numbers;
    Index k = 0;
    for(const auto& e : range)
    {
      const Location l = locate(e, "source");
      if(l.is_vertex)
      {
        query.vertex_sources.push_back(l.vertex);
        query.source_numbers.push_back(k);
      }
      else
      {
        query.point_sources.push_back(l.point);
        point_numbers.push_back(k);
      }
      ++k;
    }
    query.source_numbers.insert(query.source_numbers.end(), point_numbers.begin(), point_numbers.end());
  }

  // the targets of `range` in the query; returns, per target in the range's order, its place:
  // a vertex (is_vertex) or the number of a point target
  template <class Range>
  std::vector<std::pair<bool, Index>> add_targets(const Range& range, Propagation_query<FT>& query) const
  {
    std::vector<std::pair<bool, Index>> places;
    for(const auto& e : range)
    {
      const Location l = locate(e, "target");
      if(l.is_vertex)
      {
        query.vertex_targets.push_back(l.vertex);
        places.emplace_back(true, l.vertex);
      }
      else
      {
        places.emplace_back(false, Index(query.point_targets.size()));
        query.point_targets.push_back(l.point);
      }
    }
    return places;
  }

private:
  // Barycentric coordinates may be off by rounding (PMP::locate() gives such), not more: each at
  // least -tolerance, their sum within tolerance of 1, the tolerance being 1e-12, or 64 units in
  // the last place of a coarser floating-point type. Slightly negative ones become 0 and the
  // others are rescaled; a point with two zero coordinates is the vertex of the third.
  template <class Coordinates>
  Location surface_point(face_descriptor f, const Coordinates& coordinates, const char* what) const
  {
    const std::size_t i = m_numbering.face_index(f);
    if(i == m_numbering.number_of_faces())
      throw std::invalid_argument(std::string("the face of the ") + what + " is not a face of the mesh");
    using Coordinate = std::decay_t<decltype(coordinates[0])>;
    double tolerance = 1e-12;
    if constexpr(std::is_floating_point<Coordinate>::value)
      tolerance = (std::max)(tolerance, 64. * double(std::numeric_limits<Coordinate>::epsilon()));
    double b[3], sum = 0.;
    for(int k = 0; k < 3; ++k)
    {
      b[k] = CGAL::to_double(coordinates[k]);
      if(!std::isfinite(b[k]) || b[k] < -tolerance)
        throw std::invalid_argument(std::string("the barycentric coordinates of the ") + what +
                                    " must be finite and not negative");
      sum += b[k];
    }
    if(!(std::abs(sum - 1.) <= tolerance))
      throw std::invalid_argument(std::string("the barycentric coordinates of the ") + what + " must add up to 1");
    Location l{false, 0, Surface_point<FT>{Index(i), {number<FT>(0), number<FT>(0), number<FT>(0)}}};
    int zeros = 0, last_nonzero = 0;
    bool rescale = false;
    for(int k = 0; k < 3; ++k)
    {
      if(b[k] <= 0.)
      {
        ++zeros;
        rescale = rescale || b[k] < 0.;
        continue;
      }
      last_nonzero = k;
      l.point.barycentric[k] = number<FT>(coordinates[k]);
    }
    if(zeros == 2)
      return Location{true, m_mesh.source(3 * l.point.face + Index(last_nonzero)), Surface_point<FT>{}};
    if(rescale)
    {
      FT total(0);
      for(int k = 0; k < 3; ++k)
        total += l.point.barycentric[k];
      for(int k = 0; k < 3; ++k)
        l.point.barycentric[k] /= total;
    }
    return l;
  }

  const Numbering& m_numbering;
  const UnfoldedMesh& m_mesh;
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_QUERY_BUILDER_H
