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

#ifndef CGAL_DGG_VTP_3_INTERNAL_FARTHEST_POINT_SAMPLING_H
#define CGAL_DGG_VTP_3_INTERNAL_FARTHEST_POINT_SAMPLING_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/Propagation_cancelled.h>
#include <CGAL/DGG_VTP_3/internal/Propagation_query.h>
#include <CGAL/DGG_VTP_3/internal/number_type_math.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// The vertex farthest from the sources of a field that only shrinks, the lowest user's number first
// among ties (the propagation numbers vertices in its own order: see Unfolding_order): a max-heap of
// (distance, user's number) entries, one pushed per change, the stale ones (above the vertex's
// distance now) dropped as they come up, so that a sample costs the log of what its cell changed.
// Unreached vertices (+infinity: another connected component) come first, in the user's order. A
// vertex taken as a sample is never given again, even where others are at distance 0 (copies,
// coincident vertices).
template <class FT>
class Farthest_vertices
{
  using Index = std::uint32_t;
  using Entry = std::pair<FT, Index>;

public:
  // of the vertices that `user_number` numbers (per vertex, the user's number; `vertex_of`, its
  // inverse), `first` taken
  Farthest_vertices(const std::vector<Index>& user_number, const std::vector<Index>& vertex_of, Index first)
    : m_user_number(user_number), m_vertex_of(vertex_of), m_taken(user_number.size(), 0)
  {
    m_taken[first] = 1;
  }

  // `changed`: the vertices whose distance changed since the last call
  void update(const std::vector<Index>& changed, const std::vector<FT>& distance)
  {
    // stale entries pile up as the cells shrink: rebuilt once they outnumber the vertices twice
    if(m_heap.size() + changed.size() > 2 * distance.size() + 1024)
    {
      m_heap.clear();
      for(Index v = 0; v < Index(distance.size()); ++v)
        if(distance[v] < Number_type_math<FT>::infinity())
          m_heap.emplace_back(distance[v], m_user_number[v]);
      std::make_heap(m_heap.begin(), m_heap.end(), before);
      return;
    }
    for(Index v : changed)
      if(distance[v] < Number_type_math<FT>::infinity())
      {
        m_heap.emplace_back(distance[v], m_user_number[v]);
        std::push_heap(m_heap.begin(), m_heap.end(), before);
      }
  }

  // the farthest vertex not taken yet, which is taken (the number of vertices if there is none)
  Index take_farthest(const std::vector<FT>& distance)
  {
    while(m_unreached < distance.size() && (distance[m_vertex_of[m_unreached]] < Number_type_math<FT>::infinity() ||
                                             m_taken[m_vertex_of[m_unreached]]))
      ++m_unreached;
    Index v = m_unreached < distance.size() ? m_vertex_of[m_unreached] : Index(0);
    if(m_unreached == distance.size())
    {
      while(!m_heap.empty() && (m_heap.front().first != distance[m_vertex_of[m_heap.front().second]] ||
                                m_taken[m_vertex_of[m_heap.front().second]]))
      {
        std::pop_heap(m_heap.begin(), m_heap.end(), before);
        m_heap.pop_back();
      }
      if(m_heap.empty())
        return Index(distance.size());
      v = m_vertex_of[m_heap.front().second];
    }
    m_taken[v] = 1;
    return v;
  }


private:
  // whether `a` comes after `b`: nearer, or as far with a higher user's number
  static bool before(const Entry& a, const Entry& b)
  {
    return a.first < b.first || (a.first == b.first && a.second > b.second);
  }

  const std::vector<Index>& m_user_number;
  const std::vector<Index>& m_vertex_of;
  std::vector<Entry> m_heap;
  std::vector<char> m_taken;   // per vertex: taken as a sample
  std::size_t m_unreached = 0; // no vertex of a user's number below it is unreached and not taken
};

// Farthest-point sampling of `k` vertices from `first`, by one propagation that adds each sample
// to the field of those before (Propagation_query::add_to_field): a sample costs its Voronoi cell
// and the border around it, not a whole field. Each sample is the farthest vertex of the field of
// the ones before: with accuracy epsilon, its exact distance to them is at least the largest one
// divided by (1 + epsilon), as the field is within that factor; in the exact mode it is the
// greedy sequence itself. `progress(fraction)` is called between the rounds of each propagation
// and after each sample, with the fraction of the k samples taken (a sample's propagation counting
// as its share of vertices popped); returning false cancels. On return, `propagation` holds the
// field of the samples, its origins numbered in the order of the samples.
template <class ConcurrencyTag, class Propagation, class FT>
std::vector<std::uint32_t> farthest_point_sampling(Propagation& propagation, std::uint32_t first, std::size_t k,
                                                   FT accuracy, const std::function<bool(double)>& progress,
                                                   const std::vector<std::uint32_t>& user_number,
                                                   const std::vector<std::uint32_t>& vertex_of)
{
  Propagation_query<FT> query;
  query.record_origins = true;
  std::vector<std::uint32_t> samples(1, first);
  if(progress) // within the whole field of the first sample, the longest
    query.progress = [&](double f) { return progress((double(samples.size() - 1) + f) / double(k)); };
  Farthest_vertices<FT> farthest(user_number, vertex_of, first);
  for(;;)
  {
    query.vertex_sources.assign(1, samples.back());
    query.source_numbers.assign(1, std::uint32_t(samples.size() - 1));
    propagation.template run<ConcurrencyTag>(query, accuracy);
    query.add_to_field = true;
    if(progress && !progress(double(samples.size()) / double(k)))
      throw Propagation_cancelled();
    if(samples.size() == k)
      return samples;
    farthest.update(propagation.reached(), propagation.distances());
    samples.push_back(farthest.take_farthest(propagation.distances()));
  }
}

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_FARTHEST_POINT_SAMPLING_H
