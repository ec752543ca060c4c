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

#ifndef CGAL_DGG_VTP_3_INTERNAL_PROPAGATION_VERTICES_H
#define CGAL_DGG_VTP_3_INTERNAL_PROPAGATION_VERTICES_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/Key_ratio.h>
#include <CGAL/DGG_VTP_3/internal/Pseudo_source_emission.h>
#include <CGAL/DGG_VTP_3/internal/Pseudo_source_states.h>
#include <CGAL/DGG_VTP_3/internal/Tuning.h>
#include <CGAL/DGG_VTP_3/internal/Unfolded_mesh.h>
#include <CGAL/DGG_VTP_3/internal/Vertex_directions.h>
#include <CGAL/DGG_VTP_3/internal/number_type_math.h>
#include <CGAL/DGG_VTP_3/internal/planar_geometry.h>

#include <algorithm>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// What one propagation knows of the vertices: the shortest distance found so far, the directions
// the paths of that length arrive from, which vertices are sources or pseudo-sources, and what the
// query asks to record of the paths (their pseudo-sources, where they arrive from).
template <class FT>
class Propagation_vertices
{
  using Mesh = Unfolded_mesh<FT>;
  using Index = typename Mesh::Index;
  using Point = Vec2<FT>;
  using T = Tuning<FT>;

public:
  // per vertex: the corner and the direction (in that corner's frame) its path arrives from
  struct Arrival
  {
    Index corner;
    Point direction;
  };
  static Index no_origin() { return Index(-1); }

  // `keys`: the key ratio of the propagation
  Propagation_vertices(const Mesh& mesh, const Key_ratio<FT>& keys)
    : m_mesh(mesh)
    , m_keys(keys)
    , distance(mesh.number_of_vertices(), Number_type_math<FT>::infinity())
    , incoming(mesh.number_of_vertices())
    , is_source(mesh.number_of_vertices(), 0)
    , pseudo_sources(mesh, !keys.is_exact())
  {}

  void record(bool origins, bool arrivals)
  {
    if(origins)
      origin.assign(distance.size(), no_origin());
    if(arrivals)
      arrival.assign(distance.size(), Arrival{Mesh::no_halfedge, Point{number<FT>(0), number<FT>(0)}});
  }

  // vertex `s` is the source numbered `k` in the query's order
  void set_source(Index s, Index k)
  {
    is_source[s] = 1;
    distance[s] = number<FT>(0);
    if(!origin.empty())
      origin[s] = (std::min)(origin[s], Index(distance.size()) + k);
  }

  // Lines 23-24: a path of length `d` reaches `v`, arriving from `direction` (pointing back along
  // the path, in the frame of `corner`, one of v's corners: position `back` at `v`), from the
  // pseudo-source `origin`. Paths that tie with the best one widen the recorded range of arrival
  // directions: the shadow of a saddle is the union of their shadows. Returns whether `v` must be
  // queued (again) at its distance. With `corner` no_halfedge, `v` is reached from `from`, a copy
  // of it (the same point, see Vertex_copies.h), at the copy's distance `d`: copies are singular,
  // so no direction is recorded, and only a shorter distance counts (a tie would go back and
  // forth between the copies).
  bool relax(Index v, FT d, Index corner, const Point& direction, Index from)
  {
    const FT dv = distance[v];
    Incoming_directions<FT>& in = incoming[v];
    const bool shorter = d < dv - T::rounding_margin(dv) || dv == Number_type_math<FT>::infinity();
    if(corner == Mesh::no_halfedge && !shorter)
      return false;
    const FT back = corner == Mesh::no_halfedge ? number<FT>(0) : direction_position(m_mesh, corner, direction);
    if(shorter)
    {
      distance[v] = d;
      pseudo_sources.distance_dropped(v);
      in.low = in.high = back;
      if(!origin.empty())
        origin[v] = from;
      if(!arrival.empty())
        arrival[v] = Arrival{corner, direction};
      return true;
    }
    if(d <= dv + T::rounding_margin(dv) && !(in.low <= back && back <= in.high))
    {
      in.low = (std::min)(in.low, back);
      in.high = (std::max)(in.high, back);
      if(d < dv)
      {
        distance[v] = d;
        if(!origin.empty())
          origin[v] = from;
        if(!arrival.empty())
          arrival[v] = Arrival{corner, direction};
      }
      return true; // emit the wider shadow if already popped
    }
    return false;
  }

  // The key of vertex `v` at distance `d`, as the ICH rule compares it: that of its windows (d /
  // rho) if it emits all around, else its distance, which no path through it beats by key (a path
  // bending there is beaten by one passing beside it, as in the exact algorithm, and along a
  // straight path a key grows no faster than the distance). `own`: whether `v` is of the patch
  // that asks; another patch's vertex may become a pseudo-source during the round, so only what
  // the mesh makes one counts there.
  FT key(Index v, FT d, bool own) const
  {
    const bool emits = is_source[v] || (own ? pseudo_sources.emits(v) : m_mesh.is_exact_pseudo_source(v));
    return emits ? m_keys.key(d) : d;
  }

private:
  const Mesh& m_mesh;
  const Key_ratio<FT> m_keys;

public:
  std::vector<FT> distance;                       // best distance found so far (+inf: not reached)
  std::vector<Incoming_directions<FT>> incoming;  // arrival directions of its best paths
  std::vector<char> is_source;                    // one of the sources (they emit all around)
  Pseudo_source_states<FT> pseudo_sources;        // DGG-VTP's vertices that emit all around
  std::vector<Index> origin;   // the pseudo-source of its path: a vertex, or the number of vertices +
                               // the number of a source in the query's order (if the query asks)
  std::vector<Arrival> arrival; // where its path arrives from (if the query asks)
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_PROPAGATION_VERTICES_H
