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

#include <CGAL/DGG_VTP_3/internal/Default_init_allocator.h>
#include <CGAL/DGG_VTP_3/internal/for_each_block.h>

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
// order, the corners grouped by vertex, the opposite of each halfedge. `ConcurrencyTag` says how
// the loops run (for_each_block()); the results do not depend on it.

// One stable pass of a counting sort of the items 0 to n-1 by `digit(i)`, in [0, digits), shared
// among threads in fixed blocks of 2^16 items: each block counts its digits, then its items of
// digit d go after those of the smaller digits and of the blocks before it, where one pass over
// all the items would put them; `place(i, position)` moves item i. Returns where the items of
// each digit begin (digits + 1 offsets). With `skip_one_digit`, a pass whose items all have one
// digit (which would move nothing) places nothing and returns no offsets.
template <class ConcurrencyTag, class Digit, class Place>
std::vector<std::size_t> counting_sort_pass(std::size_t n, std::size_t digits, const Digit& digit, const Place& place,
                                            bool skip_one_digit)
{
  constexpr std::size_t block = std::size_t(1) << 16;
  const std::size_t blocks = (n + block - 1) / block;
  std::vector<std::size_t> first(blocks * digits);
  for_each_block<ConcurrencyTag>(blocks, [&](std::size_t b0, std::size_t b1) {
    for(std::size_t b = b0; b < b1; ++b)
    {
      std::size_t* count = first.data() + b * digits;
      std::fill(count, count + digits, std::size_t(0));
      for(std::size_t i = b * block; i < (std::min)(n, (b + 1) * block); ++i)
        ++count[digit(i)];
    }
  }, 1);
  std::vector<std::size_t> digit_begin(digits + 1, 0);
  for(std::size_t d = 0, at = 0; d < digits; ++d)
  {
    digit_begin[d] = at;
    for(std::size_t b = 0; b < blocks; ++b)
      at += std::exchange(first[b * digits + d], at);
    digit_begin[d + 1] = at;
    if(skip_one_digit && at - digit_begin[d] == n)
      return std::vector<std::size_t>();
  }
  for_each_block<ConcurrencyTag>(blocks, [&](std::size_t b0, std::size_t b1) {
    for(std::size_t b = b0; b < b1; ++b)
      for(std::size_t i = b * block; i < (std::min)(n, (b + 1) * block); ++i)
        place(i, first[b * digits + digit(i)]++);
  }, 1);
  return digit_begin;
}

// a face and its place on the space-filling curve (no initializers: arrays of them are written whole)
struct Face_key
{
  std::uint64_t key;
  std::uint32_t face;
};

// Sorts (key, face) pairs by key, faces of equal keys in increasing order, as std::sort would:
// a least significant digit first radix sort of the 63-bit keys, a few times faster.
template <class ConcurrencyTag>
void sort_by_key(Uninitialized_vector<Face_key>& keys)
{
  constexpr int digit_bits = 11;
  constexpr std::size_t digits = std::size_t(1) << digit_bits;
  Uninitialized_vector<Face_key> sorted(keys.size());
  for(int shift = 0; shift < 64; shift += digit_bits)
    if(!counting_sort_pass<ConcurrencyTag>(
          keys.size(), digits, [&](std::size_t i) { return std::size_t((keys[i].key >> shift) & (digits - 1)); },
          [&](std::size_t i, std::size_t position) { sorted[position] = keys[i]; }, true)
          .empty())
      keys.swap(sorted);
}

// Faces along a Z-order (Morton) curve of their centroids: faces near each other in the order are
// near each other on the surface, so that the propagation's working set is a few compact blocks of
// memory whatever the order of the user's faces, and a range of faces is a compact patch.
// `extent` receives the largest side of the bounding box of the vertices the faces use.
template <class ConcurrencyTag, class FT>
std::vector<std::uint32_t> faces_in_space_order(const std::vector<FT>& xyz,
                                                const Uninitialized_vector<std::uint32_t>& corner_vertex, double& extent)
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
  Uninitialized_vector<Face_key> keys(nf);
  for_each_block<ConcurrencyTag>(nf, [&](std::size_t f0, std::size_t f1) {
    for(std::size_t f = f0; f < f1; ++f)
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
      keys[f] = Face_key{key, std::uint32_t(f)};
    }
  });
  sort_by_key<ConcurrencyTag>(keys);
  std::vector<std::uint32_t> order(nf);
  for_each_block<ConcurrencyTag>(nf, [&](std::size_t f0, std::size_t f1) {
    for(std::size_t f = f0; f < f1; ++f)
      order[f] = keys[f].face;
  });
  return order;
}

// renumbers the faces: new face i is the user's face order[i] (the corners' vertices and the
// opposite halfedges if known, the only per-face data so far)
template <class ConcurrencyTag>
void reorder_faces(const std::vector<std::uint32_t>& order, Uninitialized_vector<std::uint32_t>& corner_vertex,
                   Uninitialized_vector<std::uint32_t>& opposite)
{
  constexpr std::uint32_t none = std::uint32_t(-1);
  const std::size_t nf = order.size();
  Uninitialized_vector<std::uint32_t> new_face(nf);
  for_each_block<ConcurrencyTag>(nf, [&](std::size_t f0, std::size_t f1) {
    for(std::size_t f = f0; f < f1; ++f)
      new_face[order[f]] = std::uint32_t(f);
  });
  Uninitialized_vector<std::uint32_t> reordered_vertex(3 * nf), reordered_opposite(opposite.empty() ? 0 : 3 * nf);
  for_each_block<ConcurrencyTag>(nf, [&](std::size_t f0, std::size_t f1) {
    for(std::size_t f = f0; f < f1; ++f)
      for(int k = 0; k < 3; ++k)
      {
        reordered_vertex[3 * f + k] = corner_vertex[3 * order[f] + k];
        if(!opposite.empty())
        {
          const std::uint32_t h = opposite[3 * order[f] + k];
          reordered_opposite[3 * f + k] = h == none ? h : 3 * new_face[h / 3] + h % 3;
        }
      }
  });
  corner_vertex.swap(reordered_vertex);
  if(!opposite.empty())
    opposite.swap(reordered_opposite);
}

// Renumbers the vertices in the order the faces first use them (after reorder_faces(), the faces'
// space order), those of no face last in their order: the propagation reads and writes per-vertex
// arrays as it reads the faces, and a vertex's neighbours are then near it in memory (bunny_1M,
// whose subdivision numbers vertices level by level: 24% less time at epsilon 1e-1). Relabels the
// corners' vertices and reorders the coordinates (3 per vertex); returns the order: new vertex i
// is vertex order[i] of before.
template <class ConcurrencyTag, class FT>
std::vector<std::uint32_t> reorder_vertices(Uninitialized_vector<std::uint32_t>& corner_vertex, std::vector<FT>& xyz)
{
  constexpr std::uint32_t none = std::uint32_t(-1);
  const std::size_t nv = xyz.size() / 3;
  std::vector<std::uint32_t> new_vertex(nv, none), order;
  order.reserve(nv);
  for(std::uint32_t v : corner_vertex) // first uses: in the faces' order, on one thread
    if(new_vertex[v] == none)
    {
      new_vertex[v] = std::uint32_t(order.size());
      order.push_back(v);
    }
  for(std::uint32_t v = 0; v < nv; ++v)
    if(new_vertex[v] == none)
    {
      new_vertex[v] = std::uint32_t(order.size());
      order.push_back(v);
    }
  for_each_block<ConcurrencyTag>(corner_vertex.size(), [&](std::size_t h0, std::size_t h1) {
    for(std::size_t h = h0; h < h1; ++h)
      corner_vertex[h] = new_vertex[corner_vertex[h]];
  });
  std::vector<FT> reordered(xyz.size());
  for_each_block<ConcurrencyTag>(nv, [&](std::size_t v0, std::size_t v1) {
    for(std::size_t v = v0; v < v1; ++v)
      for(int c = 0; c < 3; ++c)
        reordered[3 * v + c] = xyz[3 * order[v] + c];
  });
  xyz.swap(reordered);
  return order;
}

// The corners (halfedges 3f+k) grouped by their vertex, in CSR form: those of vertex v are
// corners[begin[v]] to corners[begin[v+1]-1], in increasing order. A counting sort in two stable
// levels, so that no counter is shared between threads (atomic counters cost more than a second
// thread saves): the corners by ranges of 2^shift vertices (at most 2048 ranges), then each
// range's corners by vertex.
template <class ConcurrencyTag>
void group_corners_by_vertex(const Uninitialized_vector<std::uint32_t>& corner_vertex, std::size_t nv,
                             std::vector<std::uint32_t>& begin, Uninitialized_vector<std::uint32_t>& corners)
{
  struct Corner { std::uint32_t vertex, corner; };
  const std::size_t nh = corner_vertex.size();
  int shift = 0;
  while(((nv + (std::size_t(1) << shift) - 1) >> shift) > 2048)
    ++shift;
  const std::size_t ranges = (nv + (std::size_t(1) << shift) - 1) >> shift;
  Uninitialized_vector<Corner> by_range(nh);
  const std::vector<std::size_t> range_begin = counting_sort_pass<ConcurrencyTag>(
    nh, ranges, [&](std::size_t h) { return std::size_t(corner_vertex[h] >> shift); },
    [&](std::size_t h, std::size_t position) { by_range[position] = Corner{corner_vertex[h], std::uint32_t(h)}; },
    false);
  begin.resize(nv + 1);
  begin[nv] = std::uint32_t(nh);
  corners.resize(nh);
  for_each_block<ConcurrencyTag>(ranges, [&](std::size_t r0, std::size_t r1) {
    std::vector<std::uint32_t> fill;
    for(std::size_t r = r0; r < r1; ++r)
    {
      const std::size_t v0 = r << shift, v1 = (std::min)(nv, (r + 1) << shift);
      fill.assign(v1 - v0, 0);
      for(std::size_t i = range_begin[r]; i < range_begin[r + 1]; ++i)
        ++fill[by_range[i].vertex - v0];
      std::uint32_t at = std::uint32_t(range_begin[r]);
      for(std::size_t v = v0; v < v1; ++v)
      {
        begin[v] = at;
        at += std::exchange(fill[v - v0], at);
      }
      for(std::size_t i = range_begin[r]; i < range_begin[r + 1]; ++i)
        corners[fill[by_range[i].vertex - v0]++] = by_range[i].corner;
    }
  }, 1);
}

// The opposite of each halfedge a->b: the one halfedge b->a, or `no_halfedge` on the border.
// Both have a corner at a (a->b is the halfedge of its corner there, b->a the one before its
// corner there), so each vertex's corners (CSR `begin`, `corners`) are matched among themselves.
// Throws std::invalid_argument where two halfedges go from a to b: the faces do not form a
// surface as they are. Faces and vertices are named by the user's numbering, `face_order` and
// `vertex_order` (see reorder_faces(), reorder_vertices()).
template <class ConcurrencyTag>
Uninitialized_vector<std::uint32_t> matched_halfedges(const Uninitialized_vector<std::uint32_t>& corner_vertex,
                                                         const std::vector<std::uint32_t>& begin,
                                                         const Uninitialized_vector<std::uint32_t>& corners,
                                                         const std::vector<std::uint32_t>& face_order,
                                                         const std::vector<std::uint32_t>& vertex_order)
{
  const auto next = [](std::uint32_t h) { return h % 3 == 2 ? h - 2 : h + 1; };
  const auto prev = [](std::uint32_t h) { return h % 3 == 0 ? h + 2 : h - 1; };
  Uninitialized_vector<std::uint32_t> opposite(corner_vertex.size(), std::uint32_t(-1));
  for_each_block<ConcurrencyTag>(begin.size() - 1, [&](std::size_t a0, std::size_t a1) {
    std::vector<std::uint32_t> ahead, behind; // per corner at a: the vertex after it, the vertex before it
    for(std::size_t a = a0; a < a1; ++a)
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
            throw std::invalid_argument("triangles " + std::to_string(face_order[first[i] / 3]) + " and " +
                                        std::to_string(face_order[first[j] / 3]) + " both go from vertex " +
                                        std::to_string(vertex_order[a]) + " to vertex " +
                                        std::to_string(vertex_order[ahead[i]]) +
                                        ": their orientations disagree, or more than two triangles share the edge "
                                        "(CGAL::Polygon_mesh_processing::orient_polygon_soup() repairs both)");
        }
    }
  });
  return opposite;
}

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_MESH_COMBINATORICS_H
