// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// Polygons of a soup cut into triangles, where CGAL's triangulate_faces would crash.

#ifndef DGGVTP_TRIANGULATE_H
#define DGGVTP_TRIANGULATE_H

#include <dggvtp/loaded_soup.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace dggvtp {
namespace internal {

// Splits polygon `f` of the soup (more than 3 vertices) into triangles, appended to `triangles`
// (same orientation); throws Input_error when it cannot. This replaces CGAL's triangulate_faces,
// whose constrained Delaunay triangulation of the polygon, in its plane seen along an inexact
// normal, crashes on polygons that touch or cross themselves there (fuzzer: a pentagon with two
// vertices at the same place: where two sides crossed, computing their intersection failed and the
// triangulation took an uninitialised point as the new vertex; with the repeated place merged, the
// vertex count matched the polygon's and CGAL used the new vertex's halfedge, which is null; in
// double and float alike). Here:
// - a quad is split along the diagonal CGAL chooses (the one whose two triangles' normals agree
//   best), computed in double;
// - a larger polygon is projected onto the coordinate plane most parallel to it (exact: it drops
//   one coordinate) and cut by ear clipping with exact predicates: an ear is a strictly convex
//   corner whose triangle holds no other corner, not even on its border. A simple polygon always
//   has one; a polygon that crosses or touches itself there may run out of ears: refused.
inline void triangulate_polygon(const Loaded_soup& soup, std::size_t f, std::vector<std::vector<std::size_t>>& triangles)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const std::vector<std::size_t>& polygon = soup.polygons[f];
  const std::size_t n = polygon.size();
  const auto& p = soup.points;
  const auto refuse = [&](const std::string& why) {
    return Input_error("face " + std::to_string(f) + " (" + std::to_string(n) + " vertices) cannot be triangulated: " + why);
  };
  // Newell's normal: twice the vector area of the polygon
  double normal[3] = {0., 0., 0.};
  for(std::size_t i = 0; i < n; ++i)
  {
    const K::Point_3& a = p[polygon[i]];
    const K::Point_3& b = p[polygon[(i + 1) % n]];
    normal[0] += (a.y() - b.y()) * (a.z() + b.z());
    normal[1] += (a.z() - b.z()) * (a.x() + b.x());
    normal[2] += (a.x() - b.x()) * (a.y() + b.y());
  }
  if(!std::isfinite(normal[0]) || !std::isfinite(normal[1]) || !std::isfinite(normal[2]))
    throw refuse("its coordinates are too large");
  int axis = 0;
  for(int c = 1; c < 3; ++c)
    if(std::abs(normal[c]) > std::abs(normal[axis]))
      axis = c;
  if(normal[axis] == 0.)
    throw refuse("it has no area");

  if(n == 4)
  {
    const K::Point_3 &p0 = p[polygon[0]], &p1 = p[polygon[1]], &p2 = p[polygon[2]], &p3 = p[polygon[3]];
    const double p1p3 = CGAL::cross_product(p2 - p1, p3 - p2) * CGAL::cross_product(p0 - p3, p1 - p0);
    const double p0p2 = CGAL::cross_product(p1 - p0, p1 - p2) * CGAL::cross_product(p3 - p2, p3 - p0);
    if(p0p2 > p1p3)
    {
      triangles.push_back({polygon[0], polygon[1], polygon[2]});
      triangles.push_back({polygon[2], polygon[3], polygon[0]});
    }
    else
    {
      triangles.push_back({polygon[1], polygon[2], polygon[3]});
      triangles.push_back({polygon[3], polygon[0], polygon[1]});
    }
    return;
  }

  // (y, z), (z, x) or (x, y): the polygon turns counterclockwise there if normal[axis] > 0
  std::vector<K::Point_2> q;
  q.reserve(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    const K::Point_3& a = p[polygon[i]];
    q.emplace_back(a[(axis + 1) % 3], a[(axis + 2) % 3]);
  }
  const CGAL::Orientation convex = normal[axis] > 0. ? CGAL::LEFT_TURN : CGAL::RIGHT_TURN;
  const CGAL::Orientation outside = normal[axis] > 0. ? CGAL::RIGHT_TURN : CGAL::LEFT_TURN;
  std::vector<std::size_t> prev(n), next(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    prev[i] = (i + n - 1) % n;
    next[i] = (i + 1) % n;
  }
  const auto is_ear = [&](std::size_t i) {
    const std::size_t a = prev[i], c = next[i];
    if(CGAL::orientation(q[a], q[i], q[c]) != convex)
      return false;
    for(std::size_t j = next[c]; j != a; j = next[j])
      if(CGAL::orientation(q[a], q[i], q[j]) != outside && CGAL::orientation(q[i], q[c], q[j]) != outside &&
         CGAL::orientation(q[c], q[a], q[j]) != outside)
        return false;
    return true;
  };
  std::size_t remaining = n, i = 0, tried = 0;
  while(remaining > 3)
  {
    if(is_ear(i))
    {
      triangles.push_back({polygon[prev[i]], polygon[i], polygon[next[i]]});
      next[prev[i]] = next[i];
      prev[next[i]] = prev[i];
      i = prev[i];
      --remaining;
      tried = 0;
    }
    else
    {
      i = next[i];
      if(++tried > remaining)
        throw refuse("it crosses or touches itself, or has two vertices at the same place");
    }
  }
  if(CGAL::orientation(q[prev[i]], q[i], q[next[i]]) != convex)
    throw refuse("it crosses or touches itself, or has two vertices at the same place");
  triangles.push_back({polygon[prev[i]], polygon[i], polygon[next[i]]});
}

// Replaces the polygons with more than 3 vertices by triangles.
inline void triangulate_soup(Loaded_soup& soup)
{
  bool any = false;
  for(const auto& polygon : soup.polygons)
    any = any || polygon.size() > 3;
  if(!any)
    return;
  std::vector<std::vector<std::size_t>> triangles;
  for(std::size_t f = 0; f < soup.polygons.size(); ++f)
  {
    if(soup.polygons[f].size() == 3)
      triangles.push_back(soup.polygons[f]);
    else
      triangulate_polygon(soup, f, triangles);
  }
  soup.polygons.swap(triangles);
  soup.repairs.push_back("triangulated the faces with more than 3 vertices");
}

} // namespace internal
} // namespace dggvtp

#endif // DGGVTP_TRIANGULATE_H
