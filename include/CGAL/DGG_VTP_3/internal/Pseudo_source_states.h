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
template <class FT>
class Pseudo_source_states
{
  using Mesh = Unfolded_mesh<FT>;
  using Index = typename Mesh::Index;

public:
  // in the exact mode (`dgg` false) no vertex is one: the exact algorithm has its own rules
  Pseudo_source_states(const Mesh& mesh, bool dgg)
    : m_state(mesh.number_of_vertices(), not_emitting)
  {
    if(dgg)
      for(Index v = 0; v < Index(m_state.size()); ++v)
        if(mesh.is_exact_pseudo_source(v))
          m_state[v] = to_emit;
  }

  // `v` emits all around, or will
  bool emits(Index v) const { return m_state[v] != not_emitting; }

  // `v` is popped: whether it emits now (and then it has)
  bool emit_at_pop(Index v)
  {
    if(m_state[v] != to_emit)
      return false;
    m_state[v] = emitted;
    return true;
  }

  // a shorter path reached `v`: it emits again when popped
  void distance_dropped(Index v)
  {
    if(m_state[v] == emitted)
      m_state[v] = to_emit;
  }

  // `v` becomes a pseudo-source: returns true if it was not one, and then it must be popped
  // (again) to emit
  bool make_emitter(Index v)
  {
    if(m_state[v] != not_emitting)
      return false;
    m_state[v] = to_emit;
    return true;
  }

private:
  enum State : char { not_emitting, to_emit, emitted };
  std::vector<State> m_state; // per vertex
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_PSEUDO_SOURCE_STATES_H
