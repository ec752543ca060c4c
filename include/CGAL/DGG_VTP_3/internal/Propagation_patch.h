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

#ifndef CGAL_DGG_VTP_3_INTERNAL_PROPAGATION_PATCH_H
#define CGAL_DGG_VTP_3_INTERNAL_PROPAGATION_PATCH_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/Propagation_statistics.h>
#include <CGAL/DGG_VTP_3/internal/Window.h>
#include <CGAL/DGG_VTP_3/internal/Window_lists.h>
#include <CGAL/DGG_VTP_3/internal/Window_pruning.h>

#include <boost/heap/d_ary_heap.hpp>

#include <algorithm>
#include <cstdint>
#include <deque>
#include <functional>
#include <utility>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// What a Window_propagation keeps per patch of faces (see Patch_partition): its halfedges' window
// lists, its vertices' queue, the scratch of propagating a list.
template <class FT>
struct Propagation_patch
{
  using Index = std::uint32_t;
  using Queue_entry = std::pair<FT, Index>; // a vertex at a distance
  using Queue = boost::heap::d_ary_heap<Queue_entry, boost::heap::arity<4>,
                                        boost::heap::compare<std::greater<Queue_entry>>>;

  Propagation_patch(Index id, Index first_face, Index end_face)
    : id(id), first_halfedge(3 * first_face), lists(3 * std::size_t(end_face - first_face))
  {}

  // empty, for the next propagation; `scheduled` (per halfedge of the mesh: its list is in a FIFO)
  // back to 0 for those of this patch's FIFO
  void clear(std::vector<char>& scheduled)
  {
    for(Index h : fifo)
      scheduled[h] = 0;
    fifo.clear();
    queue.clear();
    lists.clear();
    stats = Propagation_statistics();
  }

  // the halfedges of the non-empty window lists not in the FIFO (`scheduled`: per halfedge of the
  // mesh), in increasing order, whatever the order the lists were used in
  std::vector<Index> unscheduled_lists(const std::vector<char>& scheduled) const
  {
    std::vector<Index> out;
    lists.for_each_used([&](Index i) {
      if(!lists.empty(i) && !scheduled[first_halfedge + i])
        out.push_back(first_halfedge + i);
    });
    std::sort(out.begin(), out.end());
    return out;
  }

  // the most windows alive at once in its lists since the last call
  std::size_t take_peak()
  {
    const std::size_t peak = lists.peak();
    lists.reset_peak();
    return peak;
  }

  // its counts added to those of the whole propagation
  void add_statistics(Propagation_statistics& s) const
  {
    s.windows_created += lists.created();
    s.pseudo_sources += stats.pseudo_sources;
    s.vertices_popped += stats.vertices_popped;
  }

  Index id, first_halfedge;
  Window_lists<FT> lists;          // per halfedge of the patch: windows entering its face
  Queue queue;                     // vertex-oriented priority queue Q (lazy deletion)
  std::deque<Index> fifo;          // FIFO F of window lists to propagate
  std::vector<Window<FT>> buffer;  // the window list being propagated
  std::vector<FT> starts;          // its windows' starts, sorted, before pairwise trimming
  std::vector<Toward_apex<FT>> toward_apex; // per window of that list
  Propagation_statistics stats;
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_PROPAGATION_PATCH_H
