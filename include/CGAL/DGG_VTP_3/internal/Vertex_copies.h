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

#ifndef CGAL_DGG_VTP_3_INTERNAL_VERTEX_COPIES_H
#define CGAL_DGG_VTP_3_INTERNAL_VERTEX_COPIES_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/Tuning.h>
#include <CGAL/DGG_VTP_3/internal/Unfolded_mesh.h>
#include <CGAL/DGG_VTP_3/internal/Window.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <iterator>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// Copies of one point. A soup with an edge of more than two triangles, or sheets meeting at a
// vertex, is made a surface by splitting (CGAL::Polygon_mesh_processing::orient_polygon_soup()
// appends copies of the points where sheets meet). The copies are still one point of the input:
// a path reaching one goes on from all of them at no cost, and one reaching an edge between
// copies crosses into every sheet that has that edge. So a copy is a singular vertex (paths may
// turn there at any angle, into another sheet), its distance is relayed to the other copies as
// a step of length zero, and a window crossing an edge of copies enters the faces of all of
// its sheets.

// Per point, a number shared by its copies alone (the least point of its copies): point i is a
// copy of point copy_of[i], and of that one's copies. Throws std::invalid_argument for a range
// of another size than the points', an index beyond them, or a copy at another place than its
// point (`coordinates(i)`: the coordinates of point i, comparable with ==).
template <class CopyRange, class Coordinates>
std::vector<std::uint32_t> copy_groups(const CopyRange& copy_of, std::size_t nv, const Coordinates& coordinates)
{
  if(std::size_t(std::distance(std::begin(copy_of), std::end(copy_of))) != nv)
    throw std::invalid_argument("copy_of must give one point per point (" + std::to_string(nv) + ")");
  std::vector<std::uint32_t> group(nv);
  std::iota(group.begin(), group.end(), std::uint32_t(0));
  const auto root = [&group](std::uint32_t v) {
    while(group[v] != v)
      v = group[v] = group[group[v]];
    return v;
  };
  std::size_t i = 0;
  for(const auto& c : copy_of)
  {
    const std::size_t j = std::size_t(c);
    if(j >= nv)
      throw std::invalid_argument("copy_of gives point " + std::to_string(i) + " as a copy of point " +
                                  std::to_string(c) + ", but there are " + std::to_string(nv) + " points");
    if(j != i && !(coordinates(i) == coordinates(j)))
      throw std::invalid_argument("copy_of gives point " + std::to_string(i) + " as a copy of point " +
                                  std::to_string(j) + ", which is at another place");
    const std::uint32_t a = root(std::uint32_t(i)), b = root(std::uint32_t(j));
    group[(std::max)(a, b)] = (std::min)(a, b);
    ++i;
  }
  for(std::uint32_t v = 0; v < nv; ++v)
    group[v] = root(v);
  return group;
}

// Throws std::invalid_argument for two faces on the same three points, one of them at least
// through copies (`next`: per vertex, the next copy, itself if none). Windows would cross
// between those sheets of one triangle at every edge, through every sequence of sheets, as
// copies of one another tied with their vertices' distances, so that none prunes the others:
// their number grows exponentially with the crossings that the triangle's sharpest corner allows
// (3 sheets: 98,318 windows at 13 degrees, more than 20 s at 11; a fuzz input at 0.24 degrees
// ran for ever). Such a face is a defect of the input; leaving it out changes no distance.
template <class FT>
void refuse_faces_on_one_triangle(const std::vector<std::uint32_t>& group,
                                  const std::vector<typename Unfolded_mesh<FT>::Index>& next,
                                  const Unfolded_mesh<FT>& mesh)
{
  using Index = typename Unfolded_mesh<FT>::Index;
  std::vector<std::array<std::uint32_t, 3>> corners;
  for(Index f = 0; f < mesh.number_of_faces(); ++f)
  {
    std::array<std::uint32_t, 3> c{};
    bool copy = false;
    for(Index k = 0; k < 3; ++k)
    {
      const Index v = mesh.source(3 * f + k);
      c[k] = group[v];
      copy = copy || next[v] != v;
    }
    if(copy)
    {
      std::sort(c.begin(), c.end());
      corners.push_back(c);
    }
  }
  std::sort(corners.begin(), corners.end());
  const auto twice = std::adjacent_find(corners.begin(), corners.end());
  if(twice != corners.end())
    throw std::invalid_argument("two triangles are on the same points " + std::to_string((*twice)[0]) + ", " +
                                std::to_string((*twice)[1]) + " and " + std::to_string((*twice)[2]) +
                                " (copy_of making them copies): leave all but one of them out");
}

// the groups of copy_groups(), per vertex of the prepared mesh (see Unfolding_order); a group's
// number remains the user's number of its least point
inline std::vector<std::uint32_t> in_unfolded_order(const std::vector<std::uint32_t>& group, const Unfolding_order& order)
{
  std::vector<std::uint32_t> out(group.size());
  for(std::size_t i = 0; i < out.size(); ++i)
    out[i] = group[order.vertices[i]];
  return out;
}

// Links the copies of each point that faces use (`group`: per vertex, as copy_groups() gives it)
// and the halfedges along the same edge in different sheets, in cycles (see
// Unfolded_mesh::next_copy()); a copy becomes singular. Nothing is stored where no point has a
// copy.
template <class FT>
void link_copies(const std::vector<std::uint32_t>& group, Unfolded_mesh<FT>& mesh)
{
  using Index = typename Unfolded_mesh<FT>::Index;
  const Index nv = Index(mesh.number_of_vertices());
  // the copies that faces use, in cycles: each points to the one before it
  std::vector<Index> last(nv, Unfolded_mesh<FT>::no_halfedge), next(nv);
  bool copies = false;
  for(Index v = 0; v < nv; ++v)
  {
    next[v] = v;
    if(mesh.corners_begin(v) == mesh.corners_end(v))
      continue;
    Index& l = last[group[v]];
    if(l != Unfolded_mesh<FT>::no_halfedge)
    {
      next[v] = next[l];
      next[l] = v;
      copies = true;
    }
    l = v;
  }
  if(!copies)
    return;
  refuse_faces_on_one_triangle(group, next, mesh);
  for(Index v = 0; v < nv; ++v)
    if(next[v] != v)
      mesh.m_singular[v] = mesh.m_exact_pseudo_source[v] = 1;
  mesh.m_next_copy.swap(next);

  // the halfedges between copies, by the groups of their ends (the lesser first)
  std::vector<std::pair<std::uint64_t, Index>> keyed;
  for(Index h = 0; h < mesh.number_of_halfedges(); ++h)
    if(mesh.next_copy(mesh.source(h)) != mesh.source(h) && mesh.next_copy(mesh.target(h)) != mesh.target(h))
    {
      const std::uint64_t a = group[mesh.source(h)], b = group[mesh.target(h)];
      keyed.emplace_back((std::min)(a, b) << 32 | (std::max)(a, b), h);
    }
  std::sort(keyed.begin(), keyed.end());
  std::vector<Index> twin;
  for(std::size_t first = 0, end = 0; first < keyed.size(); first = end)
  {
    end = first + 1;
    while(end < keyed.size() && keyed[end].first == keyed[first].first)
      ++end;
    // one sheet's edge (a halfedge, or two opposite ones) has nowhere else to go
    if(end - first == 1 || (end - first == 2 && mesh.opposite(keyed[first].second) == keyed[first + 1].second))
      continue;
    if(twin.empty())
    {
      twin.resize(mesh.number_of_halfedges());
      std::iota(twin.begin(), twin.end(), Index(0));
    }
    for(std::size_t k = first; k < end; ++k)
      twin[keyed[k].second] = keyed[k + 1 < end ? k + 1 : first].second;
  }
  mesh.m_next_twin.swap(twin);
}

// whether vertices `a` and `b` are the same point (one, or copies)
template <class FT>
bool same_point(const Unfolded_mesh<FT>& mesh, typename Unfolded_mesh<FT>::Index a, typename Unfolded_mesh<FT>::Index b)
{
  for(auto u = mesh.next_copy(a); u != a; u = mesh.next_copy(u))
    if(u == b)
      return true;
  return a == b;
}

// The clearance of the point of copy `v`: the least distance from it to the far edge of a face
// at one of its copies (the least height there), below which no other vertex is seen from it.
template <class FT>
FT copy_clearance(const Unfolded_mesh<FT>& mesh, typename Unfolded_mesh<FT>::Index v)
{
  FT least = mesh.length(*mesh.corners_begin(v));
  auto u = v;
  do
  {
    for(auto c = mesh.corners_begin(u); c != mesh.corners_end(u); ++c)
      least = (std::min)(least, mesh.apex(Unfolded_mesh<FT>::next(*c)).y);
    u = mesh.next_copy(u);
  } while(u != v);
  return least;
}

// Calls `add(g, w)` for each halfedge g whose face a window leaving the face of `x` across its
// edge enters: opposite(x), if any, then the twins of `x` (the same edge in other sheets). `w`
// is in the frame of opposite(x), the edge the other way; a twin along the same way as `x` gets
// it mirrored (its sides swapped, with their relays).
// A window through one end of the edge, a copy, enters no other sheet where the copy has a key
// no larger than the window's there, to the rounding of a window unfolded around it
// (Tuning::sheet_crossing_tie(); `covered(v, key)`: whether v's key is at most `key`): a copy
// emits all around, into every sheet. "Through" means within a sliver of the copy, sqrt(machine
// epsilon) (Tuning::sheet_crossing_sliver()) times the least of the edge's length, the straight
// length a from the window's source image to the copy and the copy's clearance c (above): a
// path from the copy to a point at b >= c from it (every vertex but the copy) is longer than the
// window's ray through the sliver by at most about sliver^2 (1/a + 1/b) / 2, which is below
// machine epsilon times the ray's length a + b, at any distance from a source (case
// copies_near_source: a source 3e-8 from a copy on an edge of length 1, where a sliver
// relative to the edge alone cost 4.8% in the exact mode). Carried on, such windows circle the
// copy from sheet to sheet, tied with its key so that no rule prunes them, and multiply at
// every crossing (fuzz inputs: 11 triangles on 5 points with edges of 3 to 6 sheets, 215,967
// windows from one vertex, then 357; two needles meeting at a copy, whose windows' keys drifted
// below the copy's by 1.4 rounding margins, for ever, then 2,234).
template <class FT, class Add, class Covered>
void for_each_face_across(const Unfolded_mesh<FT>& mesh, typename Unfolded_mesh<FT>::Index x, const Window<FT>& w,
                          Add&& add, Covered&& covered)
{
  const auto o = mesh.opposite(x);
  if(o != Unfolded_mesh<FT>::no_halfedge)
    add(o, w);
  if(mesh.next_twin(x) == x)
    return;
  const FT len = mesh.length(x), widest = Tuning<FT>::sheet_crossing_sliver() * len;
  // in the frame of opposite(x): the target of x at 0, its source at len
  const auto through = [&](typename Unfolded_mesh<FT>::Index v, FT at) {
    const FT a = length(Vec2<FT>{at - w.source.x, -w.source.y});
    const FT sliver = Tuning<FT>::sheet_crossing_sliver() * (std::min)((std::min)(len, a), copy_clearance(mesh, v));
    const FT key = w.sigma + a;
    return w.b1 - w.b0 <= sliver && (at == 0 ? w.b0 <= sliver : w.b1 >= len - sliver) &&
           covered(v, key + Tuning<FT>::sheet_crossing_tie(key + len));
  };
  if(w.b1 - w.b0 <= widest && ((w.b0 <= widest && through(mesh.target(x), number<FT>(0))) ||
                               (w.b1 >= len - widest && through(mesh.source(x), len))))
    return;
  for(auto g = mesh.next_twin(x); g != x; g = mesh.next_twin(g))
  {
    if(g == o)
      continue;
    if(same_point(mesh, mesh.source(g), mesh.target(x)))
    {
      add(g, w);
      continue;
    }
    const FT along = mesh.length(g);
    Window<FT> m = w;
    m.b0 = along - w.b1;
    m.b1 = along - w.b0;
    m.source.x = along - w.source.x;
    std::swap(m.relay_left, m.relay_right);
    std::swap(m.relay_left_vertex, m.relay_right_vertex);
    add(g, m);
  }
}

// as above, for a window that lights its whole edge (from a pseudo-source)
template <class FT, class Add>
void for_each_face_across(const Unfolded_mesh<FT>& mesh, typename Unfolded_mesh<FT>::Index x, const Window<FT>& w,
                          Add&& add)
{
  for_each_face_across(mesh, x, w, add, [](typename Unfolded_mesh<FT>::Index, FT) { return false; });
}

// The most windows a propagation on `mesh` may make: Tuning::max_windows_between_sheets() where
// an edge is between sheets, none (0) otherwise.
template <class FT>
std::size_t window_limit(const Unfolded_mesh<FT>& mesh)
{
  return mesh.has_twins() ? Tuning<FT>::max_windows_between_sheets(mesh.number_of_faces()) : 0;
}

// throws std::invalid_argument once `created` windows are beyond `limit` (see window_limit())
inline void refuse_windows_beyond(std::size_t limit, std::size_t created)
{
  if(limit != 0 && created > limit)
    throw std::invalid_argument(
      "the propagation made more than " + std::to_string(limit) + " windows on a mesh with edges of more than two "
      "triangles: windows crossing between their sheets around a sharp corner multiply without end; leave "
      "out the extra triangles at those edges, or the sharp corner");
}

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_VERTEX_COPIES_H
