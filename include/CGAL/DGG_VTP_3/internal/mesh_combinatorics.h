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

#ifndef CGAL_DGG_VTP_3_INTERNAL_MESH_COMBINATORICS_H
#define CGAL_DGG_VTP_3_INTERNAL_MESH_COMBINATORICS_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// The combinatorics Unfolded_mesh is prepared from, before any geometry: the faces in space
// order, the corners grouped by vertex, the opposite of each halfedge.

// Sorts (key, face) pairs by key, faces of equal keys in increasing order, as std::sort would:
// a least significant digit first radix sort of the 63-bit keys, a few times faster.
inline void sort_by_key(std::vector<std::pair<std::uint64_t, std::uint32_t>>& keys)
{
  constexpr int digit_bits = 11;
  constexpr std::uint64_t digit_mask = (std::uint64_t(1) << digit_bits) - 1;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> sorted(keys.size());
  for(int shift = 0; shift < 64; shift += digit_bits)
  {
    std::vector<std::size_t> first(digit_mask + 2, 0);
    for(const auto& k : keys)
      ++first[((k.first >> shift) & digit_mask) + 1];
    if(std::count(first.begin(), first.end(), keys.size()) == 1)
      continue; // one digit for all: nothing moves
    for(std::size_t d = 0; d <= digit_mask; ++d)
      first[d + 1] += first[d];
    for(const auto& k : keys)
      sorted[first[(k.first >> shift) & digit_mask]++] = k;
    keys.swap(sorted);
  }
}

// Faces along a Z-order (Morton) curve of their centroids: faces near each other in the order are
// near each other on the surface, so that the propagation's working set is a few compact blocks of
// memory whatever the order of the user's faces, and a range of faces is a compact patch.
// `extent` receives the largest side of the bounding box of the vertices the faces use.
template <class FT>
std::vector<std::uint32_t> faces_in_space_order(const std::vector<FT>& xyz,
                                                const std::vector<std::uint32_t>& corner_vertex, double& extent)
{
  const std::size_t nf = corner_vertex.size() / 3;
  const std::size_t nv = xyz.size() / 3;
  // the bounding box of the vertices the faces use
  std::vector<char> used(nv, 0);
  for(std::uint32_t v : corner_vertex)
    used[v] = 1;
  double low[3], high[3];
  extent = 0.;
  std::fill(low, low + 3, std::numeric_limits<double>::infinity());
  std::fill(high, high + 3, -std::numeric_limits<double>::infinity());
  for(std::size_t v = 0; v < nv; ++v)
    if(used[v])
      for(int c = 0; c < 3; ++c)
      {
        low[c] = (std::min)(low[c], CGAL::to_double(xyz[3 * v + c]));
        high[c] = (std::max)(high[c], CGAL::to_double(xyz[3 * v + c]));
      }
  for(int c = 0; c < 3; ++c)
    extent = (std::max)(extent, high[c] - low[c]);
  // 21 bits a coordinate, interleaved
  const auto spread = [](std::uint64_t x) {
    x &= 0x1fffff;
    x = (x | x << 32) & 0x1f00000000ffffULL;
    x = (x | x << 16) & 0x1f0000ff0000ffULL;
    x = (x | x << 8) & 0x100f00f00f00f00fULL;
    x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
    x = (x | x << 2) & 0x1249249249249249ULL;
    return x;
  };
  const double scale = extent > 0. && std::isfinite(extent) ? double((1 << 21) - 1) / extent : 0.;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keys(nf);
  for(std::size_t f = 0; f < nf; ++f)
  {
    double centroid[3] = {0., 0., 0.};
    for(int k = 0; k < 3; ++k)
      for(int c = 0; c < 3; ++c)
        centroid[c] += CGAL::to_double(xyz[3 * corner_vertex[3 * f + k] + c]) / 3.;
    std::uint64_t key = 0;
    for(int c = 0; c < 3; ++c)
    {
      // written so that a NaN (a box too large for a double: inf times a zero scale) gives cell 0
      const double t = (centroid[c] - low[c]) * scale;
      const double cell = t > 0. ? (std::min)(t, double((1 << 21) - 1)) : 0.;
      key |= spread(std::uint64_t(cell)) << c;
    }
    keys[f] = {key, std::uint32_t(f)};
  }
  sort_by_key(keys);
  std::vector<std::uint32_t> order(nf);
  for(std::size_t f = 0; f < nf; ++f)
    order[f] = keys[f].second;
  return order;
}

// renumbers the faces: new face i is the user's face order[i] (the corners' vertices and the
// opposite halfedges if known, the only per-face data so far)
inline void reorder_faces(const std::vector<std::uint32_t>& order, std::vector<std::uint32_t>& corner_vertex,
                          std::vector<std::uint32_t>& opposite)
{
  constexpr std::uint32_t none = std::uint32_t(-1);
  const std::size_t nf = order.size();
  std::vector<std::uint32_t> new_face(nf);
  for(std::size_t f = 0; f < nf; ++f)
    new_face[order[f]] = std::uint32_t(f);
  std::vector<std::uint32_t> reordered_vertex(3 * nf), reordered_opposite(opposite.empty() ? 0 : 3 * nf);
  for(std::size_t f = 0; f < nf; ++f)
    for(int k = 0; k < 3; ++k)
    {
      reordered_vertex[3 * f + k] = corner_vertex[3 * order[f] + k];
      if(!opposite.empty())
      {
        const std::uint32_t h = opposite[3 * order[f] + k];
        reordered_opposite[3 * f + k] = h == none ? h : 3 * new_face[h / 3] + h % 3;
      }
    }
  corner_vertex.swap(reordered_vertex);
  if(!opposite.empty())
    opposite.swap(reordered_opposite);
}

// The corners (halfedges 3f+k) grouped by their vertex, in CSR form: those of vertex v are
// corners[begin[v]] to corners[begin[v+1]-1], in increasing order.
inline void group_corners_by_vertex(const std::vector<std::uint32_t>& corner_vertex, std::size_t nv,
                                    std::vector<std::uint32_t>& begin, std::vector<std::uint32_t>& corners)
{
  begin.assign(nv + 1, 0);
  for(std::uint32_t v : corner_vertex)
    ++begin[v + 1];
  for(std::size_t v = 0; v < nv; ++v)
    begin[v + 1] += begin[v];
  corners.resize(corner_vertex.size());
  std::vector<std::uint32_t> fill(begin.begin(), begin.end() - 1);
  for(std::uint32_t h = 0; h < corner_vertex.size(); ++h)
    corners[fill[corner_vertex[h]]++] = h;
}

// The opposite of each halfedge a->b: the one halfedge b->a, or `no_halfedge` on the border.
// Both have a corner at a (a->b is the halfedge of its corner there, b->a the one before its
// corner there), so each vertex's corners (CSR `begin`, `corners`) are matched among themselves.
// Throws std::invalid_argument where two halfedges go from a to b: the faces do not form a
// surface as they are. Faces are named by the user's numbering, `order`.
inline std::vector<std::uint32_t> matched_halfedges(const std::vector<std::uint32_t>& corner_vertex,
                                                   const std::vector<std::uint32_t>& begin,
                                                   const std::vector<std::uint32_t>& corners,
                                                   const std::vector<std::uint32_t>& order)
{
  const auto next = [](std::uint32_t h) { return h % 3 == 2 ? h - 2 : h + 1; };
  const auto prev = [](std::uint32_t h) { return h % 3 == 0 ? h + 2 : h - 1; };
  std::vector<std::uint32_t> opposite(corner_vertex.size(), std::uint32_t(-1));
  std::vector<std::uint32_t> ahead, behind; // per corner at a: the vertex after it, the vertex before it
  for(std::size_t a = 0; a + 1 < begin.size(); ++a)
  {
    const std::uint32_t* first = corners.data() + begin[a];
    const std::size_t n = begin[a + 1] - begin[a];
    ahead.resize(n);
    behind.resize(n);
    for(std::size_t i = 0; i < n; ++i)
    {
      ahead[i] = corner_vertex[next(first[i])];
      behind[i] = corner_vertex[prev(first[i])];
    }
    for(std::size_t i = 0; i < n; ++i)
      for(std::size_t j = 0; j < n; ++j)
      {
        if(behind[j] == ahead[i])
          opposite[first[i]] = prev(first[j]);
        if(j > i && ahead[j] == ahead[i])
          throw std::invalid_argument("triangles " + std::to_string(order[first[i] / 3]) + " and " +
                                      std::to_string(order[first[j] / 3]) + " both go from vertex " +
                                      std::to_string(a) + " to vertex " + std::to_string(ahead[i]) +
                                      ": their orientations disagree, or more than two triangles share the edge "
                                      "(CGAL::Polygon_mesh_processing::orient_polygon_soup() repairs both)");
      }
  }
  return opposite;
}

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_MESH_COMBINATORICS_H
