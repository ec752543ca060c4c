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

#ifndef CGAL_DGG_VTP_3_INTERNAL_DIRECT_DISTANCES_H
#define CGAL_DGG_VTP_3_INTERNAL_DIRECT_DISTANCES_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/Window.h>
#include <CGAL/DGG_VTP_3/internal/number_type_math.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// The certified geodesic graph's build rule (see benchmark/DGG_VTP_3/README.md, Table 14, for the
// rule, its theorem and the experiment): a direct-only run, a propagation from one vertex x
// (Window_propagation with `direct_only`), keeps per vertex beside its distance the least length w
// of a straight path from x that reached it, a window of x's or an edge of x's corners
// (+infinity: none). The vertices with a w are the out-edges of x in the graph, and they alone
// send windows out besides x, with key w / rho: whatever cuts one of x's windows is then a vertex c
// with an edge x -> c of weight w and a path from c. Their distance, the least of every path, may
// be shorter (through another such vertex), and is not what they emit with. The run is done once
// none of x's windows is left. Such runs are sequential (see Geodesic_graph_build.h).
template <class FT>
class Direct_distances
{
public:
  using Index = std::uint32_t;

  // for a run from `root` on `n` vertices, after one that reached `reached` (every vertex given a w
  // was reached)
  void reset(const std::vector<Index>& reached, Index root, std::size_t n)
  {
    if(m_w.empty())
      m_w.assign(n, Number_type_math<FT>::infinity());
    else
      for(Index v : reached)
        m_w[v] = Number_type_math<FT>::infinity();
    m_root = root;
    m_live = 0;
    m_started = false;
    m_w[root] = number<FT>(0);
  }

  // A path of length `d` from pseudo-source `from` reaches `v`; returns whether it gives v its
  // first w (then v must emit).
  bool reach(Index v, FT d, Index from)
  {
    if(from != m_root || !(d < m_w[v]))
      return false;
    const bool first = m_w[v] == Number_type_math<FT>::infinity();
    m_w[v] = d;
    return first;
  }

  // a window is stored in a list, or taken from one to be propagated (some of its children are stored)
  void stored(const Window<FT>& w)
  {
    if(w.origin == m_root)
    {
      ++m_live;
      m_started = true;
    }
  }
  void taken(const std::vector<Window<FT>>& windows)
  {
    for(const Window<FT>& w : windows)
      if(w.origin == m_root)
        --m_live;
  }
  bool done() const { return m_started && m_live == 0; }

  // Whether a window may stop at its distance bound: one of x's if its relays are out-edges no
  // longer than its straight paths to them (the beam is left to them), any other always.
  bool may_stop(const Window<FT>& w) const
  {
    return w.origin != m_root ||
           ((!(w.relay_left > FT(0)) || m_w[w.relay_left_vertex] <= w.relay_left) &&
            (!(w.relay_right > FT(0)) || m_w[w.relay_right_vertex] <= w.relay_right));
  }

  // w of `v` (+infinity: none)
  FT operator[](Index v) const { return m_w[v]; }
  const std::vector<FT>& all() const { return m_w; }

private:
  Index m_root = 0;
  std::vector<FT> m_w;       // per vertex
  std::size_t m_live = 0;    // x's windows in the lists
  bool m_started = false;    // x has emitted
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_DIRECT_DISTANCES_H
