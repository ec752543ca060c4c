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

#ifndef CGAL_DGG_VTP_3_INTERNAL_INDEX_SET_H
#define CGAL_DGG_VTP_3_INTERNAL_INDEX_SET_H

#include <CGAL/license/DGG_VTP_3.h>

#include <cstdint>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// A set of the indices 0 to n - 1 (vertices, faces, halfedges) that a propagation marks:
// membership in constant time, and clear() in the time of the members, not of n, so that the next
// propagation on the mesh starts at the cost of what the last one touched. The members are listed
// per shard (a propagation's patch): the patches of a round insert their own indices from several
// threads at once, each into its own shard's list.
class Index_set
{
public:
  using Index = std::uint32_t;

  explicit Index_set(std::size_t n = 0, std::size_t shards = 1) : m_member(n, 0), m_members(shards) {}

  bool contains(Index i) const { return m_member[i] != 0; }
  // returns whether `i` was not a member; `shard`: the only thread that inserts into it now
  bool insert(Index i, std::size_t shard = 0)
  {
    if(m_member[i])
      return false;
    m_member[i] = 1;
    m_members[shard].push_back(i);
    return true;
  }
  // the members of shard `shard`, in the order they were inserted
  const std::vector<Index>& members(std::size_t shard = 0) const { return m_members[shard]; }
  std::size_t shards() const { return m_members.size(); }
  void clear()
  {
    for(std::vector<Index>& members : m_members)
    {
      for(Index i : members)
        m_member[i] = 0;
      members.clear();
    }
  }

private:
  std::vector<char> m_member;                // per index
  std::vector<std::vector<Index>> m_members; // per shard
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_INDEX_SET_H
