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

#ifndef CGAL_DGG_VTP_3_INTERNAL_WINDOW_LISTS_H
#define CGAL_DGG_VTP_3_INTERNAL_WINDOW_LISTS_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/Window.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// One window list per halfedge (VTP groups windows by the edge side they sit on), all lists
// threaded through one pool of windows with a free list: no allocation per window, and memory
// proportional to the live wavefront, not to the number of windows ever created. The pool grows
// by blocks that never move: a vector would double its capacity and copy itself, holding up to
// three times the live windows at that moment. The lists a propagation used are remembered by
// blocks of consecutive halfedges (a byte per block, not a number per list: a whole field uses
// every list), so that the next propagation on the same mesh starts from clean lists at a cost in
// proportion to what this one touched, not to the mesh (see clear()).
template <class FT>
class Window_lists
{
public:
  using Index = std::uint32_t;
  static constexpr Index nil = Index(-1);

  explicit Window_lists(std::size_t number_of_halfedges)
    : m_head(number_of_halfedges, nil), m_block_used((number_of_halfedges >> block_of_lists_bits) + 1, 0)
  {}

  bool empty(Index h) const { return m_head[h] == nil; }
  // the number of lists
  std::size_t size() const { return m_head.size(); }

  void push(Index h, const Window<FT>& w)
  {
    Index i;
    if(m_free != nil)
    {
      i = m_free;
      m_free = next(i);
    }
    else
    {
      i = m_size++;
      if((i & block_mask) == 0)
      {
        m_window_blocks.emplace_back(new Window<FT>[block_mask + 1]);
        m_next_blocks.emplace_back(new Index[block_mask + 1]);
      }
    }
    window(i) = w;
    if(!m_block_used[h >> block_of_lists_bits])
    {
      m_block_used[h >> block_of_lists_bits] = 1;
      m_used_blocks.push_back(h >> block_of_lists_bits);
    }
    next(i) = m_head[h];
    m_head[h] = i;
    ++m_created;
    if(++m_live > m_peak)
      m_peak = m_live;
  }

  // asks the memory for the first window of list `h`, about to be taken: lists wait for their face
  // to enter the propagation region, long enough for their windows to leave the caches
  void prefetch(Index h) const
  {
    const Index i = m_head[h];
    if(i != nil)
    {
      __builtin_prefetch(&window(i));
      __builtin_prefetch(&m_next_blocks[i >> block_bits][i & block_mask]);
    }
  }

  // moves the windows of list `h` into `out` (cleared first) and empties the list
  void take(Index h, std::vector<Window<FT>>& out)
  {
    out.clear();
    Index i = m_head[h];
    m_head[h] = nil;
    while(i != nil)
    {
      out.push_back(window(i));
      const Index n = next(i);
      next(i) = m_free;
      m_free = i;
      --m_live;
      i = n;
    }
  }

  // whether `predicate(h, w)` holds for every window w in the lists (h: its list)
  template <class Predicate>
  bool all_windows(const Predicate& predicate) const
  {
    bool all = true;
    for_each_used([&](Index h) {
      for(Index i = m_head[h]; all && i != nil; i = next(i))
        all = predicate(h, window(i));
    });
    return all;
  }

  // `f(h)` for each list that may have held a window since clear(), empty or not (those of the
  // blocks used), by blocks in the order they were first used
  template <class F>
  void for_each_used(const F& f) const
  {
    for(Index b : m_used_blocks)
      for(Index h = b << block_of_lists_bits; h < (std::min)(std::size_t(b + 1) << block_of_lists_bits, m_head.size()); ++h)
        f(h);
  }

  // every list empty and every count 0, as when constructed, in the time of the lists used since
  // the last clear() (an early-terminated propagation leaves windows behind)
  void clear()
  {
    for_each_used([this](Index h) { m_head[h] = nil; });
    for(Index b : m_used_blocks)
      m_block_used[b] = 0;
    m_used_blocks.clear();
    m_free = nil;
    m_size = 0;
    m_live = m_peak = m_created = 0;
    m_window_blocks.clear();
    m_next_blocks.clear();
  }

  std::size_t created() const { return m_created; }
  std::size_t peak() const { return m_peak; }
  // the peak from now on
  void reset_peak() { m_peak = m_live; }

  // gives the pool back once the wavefront has passed (a patch's lists stay empty afterwards)
  void release_if_empty()
  {
    if(m_live != 0 || m_size == 0)
      return;
    m_window_blocks.clear();
    m_next_blocks.clear();
    m_size = 0;
    m_free = nil;
  }

private:
  // 1024 slots per block: a propagation has a pool per patch (up to 256), each holding a partly
  // used block while the wavefront crosses it
  static constexpr int block_bits = 10;
  static constexpr int block_of_lists_bits = 6; // 64 lists
  static constexpr Index block_mask = (Index(1) << block_bits) - 1;
  Window<FT>& window(Index i) { return m_window_blocks[i >> block_bits][i & block_mask]; }
  const Window<FT>& window(Index i) const { return m_window_blocks[i >> block_bits][i & block_mask]; }
  Index& next(Index i) { return m_next_blocks[i >> block_bits][i & block_mask]; }
  Index next(Index i) const { return m_next_blocks[i >> block_bits][i & block_mask]; }

  std::vector<Index> m_head;      // per halfedge: first window of its list, or nil
  std::vector<char> m_block_used; // per block of 64 halfedges: a list of it held a window since clear()
  std::vector<Index> m_used_blocks; // those blocks, in the order they were first used
  std::vector<std::unique_ptr<Window<FT>[]>> m_window_blocks; // the pool: windows, live or free
  std::vector<std::unique_ptr<Index[]>> m_next_blocks; // per slot: next window of its list, or next free slot
  Index m_size = 0;               // slots ever used
  Index m_free = nil;             // first free slot of the pool
  std::size_t m_live = 0;         // windows currently stored in lists
  std::size_t m_peak = 0;         // maximum of m_live
  std::size_t m_created = 0;      // windows ever stored
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_WINDOW_LISTS_H
