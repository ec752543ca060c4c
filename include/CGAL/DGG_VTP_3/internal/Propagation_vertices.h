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

#include <CGAL/DGG_VTP_3/internal/Direct_distances.h>
#include <CGAL/DGG_VTP_3/internal/Index_set.h>
#include <CGAL/DGG_VTP_3/internal/Patch_partition.h>
#include <CGAL/DGG_VTP_3/internal/Key_ratio.h>
#include <CGAL/DGG_VTP_3/internal/Propagation_query.h>
#include <CGAL/DGG_VTP_3/internal/Pseudo_source_emission.h>
#include <CGAL/DGG_VTP_3/internal/Pseudo_source_states.h>
#include <CGAL/DGG_VTP_3/internal/Tuning.h>
#include <CGAL/DGG_VTP_3/internal/Unfolded_mesh.h>
#include <CGAL/DGG_VTP_3/internal/Vertex_directions.h>
#include <CGAL/DGG_VTP_3/internal/number_type_math.h>
#include <CGAL/DGG_VTP_3/internal/planar_geometry.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// What one propagation knows of the vertices: the shortest distance found so far, the directions
// the paths of that length arrive from, which vertices are sources or pseudo-sources, and what the
// query asks to record of the paths (their pseudo-sources, where they arrive from). Kept from one
// propagation to the next on the same mesh: reset() puts back what the last one changed, the
// vertices it reached (every change is to a vertex once it has a distance).
// `direct_only`: the propagation is the certified geodesic graph's build rule (see
// Direct_distances); ordinary queries never instantiate it.
template <class FT, bool direct_only = false>
class Propagation_vertices
{
  using Mesh = Unfolded_mesh<FT>;
  using Index = typename Mesh::Index;
  using Point = Vec2<FT>;
  using T = Tuning<FT>;
  using Emitters = typename Pseudo_source_states<FT>::Mode;

public:
  // per vertex: the corner and the direction (in that corner's frame) its path arrives from
  struct Arrival
  {
    Index corner;
    Point direction;
  };
  static Index no_origin() { return Index(-1); }

  // `partition`: the patches that change the vertices, each its own vertices (see Round_scheduler)
  Propagation_vertices(const Mesh& mesh, const Patch_partition<FT>& partition)
    : m_mesh(mesh)
    , m_partition(partition)
    , m_keys(number<FT>(0), mesh.number_of_vertices())
    , m_reached_by_patch(mesh.number_of_vertices(), partition.size())
    , distance(mesh.number_of_vertices(), Number_type_math<FT>::infinity())
    , least_key(mesh.number_of_vertices(), Number_type_math<FT>::infinity())
    , is_source(mesh.number_of_vertices(), 0)
    , pseudo_sources(mesh, partition)
  {}

  // Every vertex unreached, for a propagation of key ratio `keys` for `query`, which may ask to
  // record the pseudo-sources of the paths and where they arrive from; the records of a
  // propagation that did not ask for them are empty.
  void reset(const Key_ratio<FT>& keys, const Propagation_query<FT>& query)
  {
    const bool origins = query.record_origins, arrivals = query.record_arrivals;
    for(Index v : m_reached)
    {
      distance[v] = least_key[v] = Number_type_math<FT>::infinity();
      if(!incoming.empty())
        incoming[v] = Incoming_directions<FT>();
      is_source[v] = 0;
      if(!m_origin.empty())
        m_origin[v] = no_origin();
      if(!m_arrival.empty())
        m_arrival[v] = no_arrival();
    }
    if constexpr(direct_only)
      direct.reset(m_reached, query.vertex_sources.at(0), distance.size());
    m_reached.clear();
    m_reached_by_patch.clear();
    m_keys = keys;
    pseudo_sources.reset(direct_only ? Emitters::direct_only : keys.is_exact() ? Emitters::exact : Emitters::dgg);
    if(keys.is_exact() && incoming.empty()) // the exact mode's shadows only
      incoming.assign(distance.size(), Incoming_directions<FT>());
    if(origins && m_origin.empty())
      m_origin.assign(distance.size(), no_origin());
    if(arrivals && m_arrival.empty())
      m_arrival.assign(distance.size(), no_arrival());
    m_record_origins = origins;
    m_record_arrivals = arrivals;
  }

  // for `query`: from nothing (reset()), or from a prior field (keep_field(), after load_field())
  void start(const Key_ratio<FT>& keys, const Propagation_query<FT>& query)
  {
    CGAL_precondition(!query.add_to_field || query.record_origins);
    CGAL_precondition(!direct_only || (!query.add_to_field && !keys.is_exact() && query.vertex_sources.size() == 1 &&
                                       query.point_sources.empty()));
    if(!query.add_to_field || query.prior != nullptr)
      reset(keys, query);
    if(query.prior != nullptr)
      load_field(*query.prior);
    if(query.add_to_field)
      keep_field(keys);
  }

  // the vertices that have had a distance since reset(), patch by patch, once finish() has
  // listed them at the end of the propagation
  const std::vector<Index>& reached() const { return m_reached; }

  // At the end of a propagation: lists the vertices reached, and puts those beyond `max_distance`
  // at +infinity (their least key too: nothing is said of them); returns how many are within it.
  // `pending`: no key the propagation left undone is below it (see early_termination.h), so that
  // a least key above it is not final, and it is the lower bound there (+infinity: it ran to
  // the end); at the vertices `targets`, `pending_at_targets`, which may be larger (a search toward
  // the targets leaves work pending elsewhere, below what it can give them).
  std::size_t finish(FT max_distance, FT pending, const std::vector<Index>& targets, FT pending_at_targets)
  {
    m_reached.clear();
    for(std::size_t k = 0; k < m_reached_by_patch.shards(); ++k)
      m_reached.insert(m_reached.end(), m_reached_by_patch.members(k).begin(), m_reached_by_patch.members(k).end());
    // in the exact mode keys are distances, which may keep a value 64 ulps above the least
    const auto least = [this](Index v) { return m_keys.is_exact() ? distance[v] : least_key[v]; };
    std::vector<std::pair<Index, FT>> at_targets;
    for(Index t : targets)
      at_targets.emplace_back(t, (std::min)(least(t), pending_at_targets));
    std::size_t within = 0;
    for(Index v : m_reached)
    {
      if(distance[v] > max_distance)
        distance[v] = least_key[v] = Number_type_math<FT>::infinity();
      else
        least_key[v] = (std::min)(least(v), pending);
      within += distance[v] < Number_type_math<FT>::infinity();
    }
    for(const auto& [t, key] : at_targets)
      if(distance[t] < Number_type_math<FT>::infinity())
        least_key[t] = key;
    return within;
  }
  const std::vector<Index>& origins() const { return m_record_origins ? m_origin : m_none; }
  const std::vector<Arrival>& arrivals() const { return m_record_arrivals ? m_arrival : m_no_arrivals; }

  // Sources added to a field (Propagation_query::add_to_field): the vertices the last run reached,
  // or that load_field() gave a distance, keep it, their least key and their origin, as a prior
  // field that the new sources improve where they are nearer. A prior vertex enters the rules with
  // its distance as its key, undiscounted even where it would emit (key()), and it never emits for a
  // path that does not make it shorter (it arrives from every direction, see relax()). So a window
  // of the new sources is cut there only at points whose key exceeds d(u) + |ux| >= exact(x) to the
  // earlier sources, for a prior vertex u: points strictly nearer to those, which no shortest path
  // from a new source to a vertex it wins passes (the manual, "Adding sources to a field").
  // Windows do not stop at their distance bound then (`keys` made with stops not allowed): a stop
  // makes its relay vertices emit at their distance over rho, and a prior relay's windows, below
  // every prior key by that discount, would cross the whole prior field
  // (benchmark/DGG_VTP_3/README.md, Table 13).
  void keep_field(const Key_ratio<FT>& keys)
  {
    if(m_in_field.empty())
      m_in_field.assign(distance.size(), 0);
    for(Index v : m_reached)
    {
      is_source[v] = prior;
      m_in_field[v] = 1;
      if(!incoming.empty())
        incoming[v] = Incoming_directions<FT>{-Number_type_math<FT>::infinity(), Number_type_math<FT>::infinity()};
    }
    m_reached.clear();
    m_reached_by_patch.clear();
    m_keys = keys;
    pseudo_sources.reset(keys.is_exact() ? Emitters::exact : Emitters::dgg);
  }

  // a prior field for keep_field(), after reset()
  void load_field(const Prior_field<FT>& field)
  {
    for(Index v = 0; v < Index(field.distance.size()); ++v)
      if(field.distance[v] < Number_type_math<FT>::infinity())
      {
        distance[v] = field.distance[v];
        least_key[v] = field.lower_bound[v];
        if(m_record_origins)
          m_origin[v] = field.origin[v];
        m_reached.push_back(v);
      }
  }

  // vertex `s` is the source numbered `k` in the query's order
  void set_source(Index s, Index k)
  {
    m_reached_by_patch.insert(s, m_partition.owner(s));
    if(m_record_origins) // the first of the sources there, not a prior field's
      m_origin[s] = is_source[s] == 1 ? (std::min)(m_origin[s], Index(distance.size()) + k) : Index(distance.size()) + k;
    is_source[s] = 1;
    distance[s] = least_key[s] = number<FT>(0);
  }

  // Lines 23-24: a path of length `d` and key `key` reaches `v`, arriving from `direction`
  // (pointing back along the path, in the frame of `corner`, one of v's corners: position `back`
  // at `v`), from the pseudo-source `origin`. Paths that tie with the best one widen the recorded range of arrival
  // directions: the shadow of a saddle is the union of their shadows. Returns whether `v` must be
  // queued (again) at its distance. With `corner` no_halfedge, `v` is reached from `from`, a copy
  // of it (the same point, see Vertex_copies.h), at the copy's distance `d`: copies are singular,
  // so no direction is recorded, and only a shorter distance counts (a tie would go back and
  // forth between the copies).
  // In a direct-only run, a vertex given its first w (see Direct_distances) is queued too, to emit.
  bool relax(Index v, FT d, FT key, Index corner, const Point& direction, Index from)
  {
    if constexpr(direct_only)
    {
      const bool first_w = direct.reach(v, d, from);
      if(first_w)
        pseudo_sources.make_emitter(v);
      return relax_distance(v, d, key, corner, direction, from) || first_w;
    }
    else
      return relax_distance(v, d, key, corner, direction, from);
  }

  // The key of vertex `v` at distance `d`, as the ICH rule compares it: that of its windows (d /
  // rho) if it emits all around, else its distance, which no path through it beats by key (a path
  // bending there is beaten by one passing beside it, as in the exact algorithm, and along a
  // straight path a key grows no faster than the distance). `own`: whether `v` is of the patch
  // that asks; another patch's vertex may become a pseudo-source during the round, so only what
  // the mesh makes one counts there, and it may leave the prior field, so it counts as in it if
  // it was at the start of the run (d is the largest key, the one that cuts the least).
  // In a direct-only run: the least key that reached it, or w / rho, its windows' (see
  // Direct_distances), both of the form w(x, c) / rho + a path from c, c an out-edge.
  FT key(Index v, FT d, bool own) const
  {
    if constexpr(direct_only)
      return (std::min)(least_key[v], m_keys.key(direct[v]));
    if(own ? is_source[v] == prior : !m_in_field.empty() && m_in_field[v])
      return d;
    const bool emits = is_source[v] || (own ? pseudo_sources.emits(v) : m_mesh.is_exact_pseudo_source(v));
    return emits ? m_keys.key(d) : d;
  }

  // the distance `v` sends its windows out with, when it emits
  FT emission_distance(Index v) const
  {
    if constexpr(direct_only)
      return direct[v];
    else
      return distance[v];
  }

private:
  static Arrival no_arrival() { return Arrival{Mesh::no_halfedge, Point{number<FT>(0), number<FT>(0)}}; }

  bool relax_distance(Index v, FT d, FT key, Index corner, const Point& direction, Index from)
  {
    least_key[v] = (std::min)(least_key[v], key);
    const FT dv = distance[v];
    const bool shorter = d < dv - T::rounding_margin(dv) || dv == Number_type_math<FT>::infinity();
    // DGG-VTP's pseudo-sources emit all around: the directions of arrival matter to the exact
    // mode's shadows only, and a tie keeps the value it has (see the manual's ties)
    const bool directions = m_keys.is_exact() && corner != Mesh::no_halfedge;
    if(!shorter && !directions)
      return false;
    const FT back = directions ? direction_position(m_mesh, corner, direction) : number<FT>(0);
    if(shorter)
    {
      m_reached_by_patch.insert(v, m_partition.owner(v));
      if(is_source[v] == prior)
        is_source[v] = 0;
      distance[v] = d;
      pseudo_sources.distance_dropped(v);
      if(directions)
        incoming[v].low = incoming[v].high = back;
      if(m_record_origins)
        m_origin[v] = from;
      if(m_record_arrivals)
        m_arrival[v] = Arrival{corner, direction};
      return true;
    }
    Incoming_directions<FT>& in = incoming[v];
    if(d <= dv + T::rounding_margin(dv) && !(in.low <= back && back <= in.high))
    {
      in.low = (std::min)(in.low, back);
      in.high = (std::max)(in.high, back);
      if(d < dv)
      {
        distance[v] = d;
        if(m_record_origins)
          m_origin[v] = from;
        if(m_record_arrivals)
          m_arrival[v] = Arrival{corner, direction};
      }
      return true; // emit the wider shadow if already popped
    }
    return false;
  }

  const Mesh& m_mesh;
  const Patch_partition<FT>& m_partition;
  Key_ratio<FT> m_keys;
  Index_set m_reached_by_patch; // the vertices given a distance, listed by the patch that owns them
  std::vector<Index> m_reached; // see reached()
  bool m_record_origins = false, m_record_arrivals = false;
  std::vector<Index> m_origin;   // per vertex: see origins() (empty until a propagation records them)
  std::vector<Arrival> m_arrival; // per vertex: see arrivals() (likewise)
  // per vertex, in a run that adds sources to a field: whether it was in the field at the start
  // (the runs do not reset, see Window_propagation::m_reusable)
  std::vector<char> m_in_field;
  const std::vector<Index> m_none;
  const std::vector<Arrival> m_no_arrivals;

public:
  std::vector<FT> distance;                       // best distance found so far (+inf: not reached)
  // The least key that reached it, whatever its distance: a lower bound of the exact distance (the
  // manual's K(v)), equal to `distance` where the path of the least key is the true
  // source's straight one.
  std::vector<FT> least_key;
  // arrival directions of its best paths, per vertex in the exact mode (empty until one runs)
  std::vector<Incoming_directions<FT>> incoming;
  // 1: one of the sources (they emit all around); `prior`: its distance is the prior field's
  std::vector<char> is_source;
  static constexpr char prior = 2;
  Pseudo_source_states<FT> pseudo_sources;        // DGG-VTP's vertices that emit all around
  struct No_direct_distances {};
  // in a direct-only run, the source's out-edges
  std::conditional_t<direct_only, Direct_distances<FT>, No_direct_distances> direct;
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_PROPAGATION_VERTICES_H
