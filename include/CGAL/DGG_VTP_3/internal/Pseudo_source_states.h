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

#ifndef CGAL_DGG_VTP_3_INTERNAL_PSEUDO_SOURCE_STATES_H
#define CGAL_DGG_VTP_3_INTERNAL_PSEUDO_SOURCE_STATES_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/Index_set.h>
#include <CGAL/DGG_VTP_3/internal/Patch_partition.h>
#include <CGAL/DGG_VTP_3/internal/Unfolded_mesh.h>

#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// Which vertices of DGG-VTP are pseudo-sources emitting all around (paper, Algorithm 1, lines
// 11-13), and whether they have emitted at their current distance.
//
// The paper makes every vertex a pseudo-source. Here a vertex emits all around if a shortest path
// may bend there (a saddle, a border or non-manifold vertex, as in the exact algorithm, but all
// around rather than in its shadow: its distance is approximate and so is the direction it was
// reached from), or if it is the CH-relay vertex of a window that stops, or is about to, since
// the stop leaves the window's beam to it. A vertex that emits all around does so with its
// distance / rho as key (see Window), and again whenever its distance drops. The others, as in
// the exact algorithm, leave the paths through them to the windows that pass beside them. When
// epsilon is small few windows stop, and DGG-VTP then costs about what the exact algorithm does.
// In a direct-only run (Direct_distances) the vertices with a straight path from the
// source emit, and only they (see Direct_distances).
template <class FT>
class Pseudo_source_states
{
  using Mesh = Unfolded_mesh<FT>;
  using Index = typename Mesh::Index;

public:
  enum class Mode { exact, dgg, direct_only };

  // Every vertex starts in the state the mesh gives it (in DGG-VTP, its exact pseudo-sources emit;
  // in the exact mode no vertex is one: the exact algorithm has its own rules; nor in a direct-only
  // run). That state is read from the mesh, not written per vertex, so that a propagation starts
  // (reset()) in the time of the vertices the previous one changed, not of the mesh.
  // `partition`: the patches that change the vertices' states, each its own vertices
  Pseudo_source_states(const Mesh& mesh, const Patch_partition<FT>& partition)
    : m_mesh(mesh), m_partition(partition), m_state(mesh.number_of_vertices(), as_meshed)
    , m_changed(mesh.number_of_vertices(), partition.size())
  {}

  // back to the mesh's states, for a propagation of mode `mode`
  void reset(Mode mode)
  {
    for(std::size_t k = 0; k < m_changed.shards(); ++k)
      for(Index v : m_changed.members(k))
        m_state[v] = as_meshed;
    m_changed.clear();
    m_mode = mode;
  }

  // `v` emits all around, or will
  bool emits(Index v) const
  {
    const State s = state(v);
    return s == to_emit || s == emitted;
  }

  // `v` is popped at its distance: whether it emits now (and then it has); one that does not is
  // passed at that distance
  bool pop(Index v)
  {
    const State s = state(v);
    if(s == to_emit)
    {
      set(v, emitted);
      return true;
    }
    if(s == not_emitting)
      set(v, passed);
    return false;
  }

  // a shorter path reached `v`: it emits again when popped (not in a direct-only run: it emits
  // with the length of its straight path, not with its distance), and is popped again in any case
  void distance_dropped(Index v)
  {
    if(m_state[v] == emitted && m_mode != Mode::direct_only)
      m_state[v] = to_emit;
    else if(m_state[v] == passed)
      m_state[v] = not_emitting;
  }

  // `v`, which has a distance, becomes a pseudo-source: returns true if it must be queued again to
  // emit, having been popped at its distance already; one not yet popped emits when it is (a
  // vertex is queued when it gets a distance)
  bool make_emitter(Index v)
  {
    const State s = state(v);
    if(s != not_emitting && s != passed)
      return false;
    set(v, to_emit);
    return s == passed;
  }

private:
  enum State : char { as_meshed, not_emitting, passed, to_emit, emitted };

  State state(Index v) const
  {
    const State s = m_state[v];
    if(s != as_meshed)
      return s;
    return m_mode == Mode::dgg && m_mesh.is_exact_pseudo_source(v) ? to_emit : not_emitting;
  }

  void set(Index v, State s)
  {
    m_changed.insert(v, m_partition.owner(v));
    m_state[v] = s;
  }

  const Mesh& m_mesh;
  const Patch_partition<FT>& m_partition;
  Mode m_mode = Mode::exact;
  std::vector<State> m_state; // per vertex
  Index_set m_changed;        // the vertices whose state may not be as_meshed
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_PSEUDO_SOURCE_STATES_H
