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

#ifndef CGAL_DGG_VTP_3_INTERNAL_WINDOW_PRUNING_H
#define CGAL_DGG_VTP_3_INTERNAL_WINDOW_PRUNING_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/Key_ratio.h>
#include <CGAL/DGG_VTP_3/internal/Tuning.h>
#include <CGAL/DGG_VTP_3/internal/Window.h>
#include <CGAL/DGG_VTP_3/internal/number_type_math.h>
#include <CGAL/DGG_VTP_3/internal/planar_geometry.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

// The innermost loop of the exact mode calls trim_pair() for every overlapping pair of windows of
// a list; GCC leaves it out of line (it is large), which costs about 5% of the propagation.
#if defined(__GNUC__)
#  define CGAL_DGG_VTP_3_HOT_INLINE inline __attribute__((always_inline))
#else
#  define CGAL_DGG_VTP_3_HOT_INLINE inline
#endif

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// The pruning rules, as geometry on windows of one window list: all in the frame of the list's
// halfedge (a = (0, 0), b = (length, 0), the apex c above).

// moves the start (or the end) of the interval to `t` if `t` lies strictly inside it; a crossing
// that rounding puts outside (or a NaN) leaves the window whole, which is always safe
template <class FT>
inline void shrink_start_to(Window<FT>& w, FT t)
{
  if(w.b0 < t && t < w.b1)
    w.cut_start(t);
}
template <class FT>
inline void shrink_end_to(Window<FT>& w, FT t)
{
  if(w.b0 < t && t < w.b1)
    w.cut_end(t);
}

// ---------------------------------------------------------------------------------------------
// The ICH rule (Xin and Wang), applied as trimming: the part of the interval where reaching the
// edge through its end vertex a (or b) is strictly shorter carries no shortest path, here or
// beyond. Along the edge `sigma + |p - s| - |p - a|` only decreases, so that part is a prefix
// (a suffix for b) found in closed form. `da`, `db`: the distances of a and b (+inf: not
// reached). Returns false when nothing of the window is left.
template <class FT>
inline bool trim_by_end_vertices(Window<FT>& w, FT len, FT da, FT db)
{
  const FT inf = Number_type_math<FT>::infinity();
  const FT sx = w.source.x;
  const FT ss = sx * sx + w.source.y * w.source.y;
  if(da < inf)
  {
    // reaching p = (t, 0) through a costs da + t (a margin keeps rounding from trimming ties)
    const FT k = da + Tuning<FT>::rounding_margin(da + len) - w.sigma;
    if(w.distance_to_base_point(w.b1) > k + w.sigma + w.b1)
      return false;
    if(w.distance_to_base_point(w.b0) > k + w.sigma + w.b0)
      shrink_start_to(w, (ss - k * k) / (number<FT>(2) * (k + sx)));
  }
  if(db < inf)
  {
    // through b it costs db + u at u = len - t, solved as above in u, from b: in t, the squares
    // of lengths of the edge's size would cancel where the window and b are much nearer each
    // other than that (a source 3e-10 from b on an edge of 0.06 trimmed 2e-10 instead of 2e-12,
    // +15% at the apex beyond, at epsilon 1e-2: benchmark copies_near_source.py)
    const FT k = db + Tuning<FT>::rounding_margin(db + len) - w.sigma;
    const FT su = len - sx;
    if(w.distance_to_base_point(w.b0) > k + w.sigma + (len - w.b0))
      return false;
    if(w.distance_to_base_point(w.b1) > k + w.sigma + (len - w.b1))
      shrink_end_to(w, len - (su * su + w.source.y * w.source.y - k * k) / (number<FT>(2) * (k + su)));
  }
  return w.b0 < w.b1;
}

// ---------------------------------------------------------------------------------------------
// "One angle, two sides"

// A window of a list seen from the apex c: where its ray to c crosses the edge, and its distance
// to c along that ray if the crossing lies in its interval (+inf: it does not light c)
template <class FT>
struct Toward_apex
{
  FT crossing;
  FT distance;
};

// B, the window of a list that reaches the apex c best by key: its key at c and where its ray to
// c crosses the edge; and the window that gives c its shortest distance (`value`), which is what
// c is relaxed with (windows null if no window lights c). In the exact mode they are the same.
template <class FT>
struct Best_toward_apex
{
  const Window<FT>* window;
  FT distance;
  FT crossing;
  const Window<FT>* value_window;
  FT value;
};

// Every window of `windows` seen from the apex c (into `toward_apex`), and the best of them (key
// ratio `keys`). A window lights c also when its crossing misses its interval by no more than
// rounding: when c lies exactly on the line from a pseudo-source through a vertex (a regular
// grid), the windows on either side of that vertex meet along the ray to c, their ends and the
// crossing each rounded on their own, and the crossing may fall in a gap of a few ulps between
// them. Then no window would reach c straight, and the path through that vertex would be lost
// (c's distance too long by up to 0.14%). A ray that misses by rounding stands for a real path,
// along the window's end ray, longer only by a term of the second order in that miss.
template <class FT>
inline Best_toward_apex<FT> best_toward_apex(const std::vector<Window<FT>>& windows, const Vec2<FT>& c,
                                             const Key_ratio<FT>& keys, std::vector<Toward_apex<FT>>& toward_apex)
{
  using Math = Number_type_math<FT>;
  Best_toward_apex<FT> best{nullptr, Math::infinity(), number<FT>(0), nullptr, Math::infinity()};
  toward_apex.resize(windows.size());
  const FT rho_minus_one = keys.rho() - number<FT>(1);
  for(std::size_t i = 0; i < windows.size(); ++i)
  {
    const Window<FT>& w = windows[i];
    Toward_apex<FT>& t = toward_apex[i];
    const FT x = t.crossing = x_axis_crossing(w.source, c);
    t.distance = Math::infinity();
    // the crossing and the ends are computed from the coordinates of the source and of c
    const FT margin = Tuning<FT>::rounding_margin(Math::abs(w.source.x) + Math::abs(w.source.y) + Math::abs(c.x) + c.y);
    if(w.b0 - margin <= x && x <= w.b1 + margin)
    {
      const FT d = t.distance = w.distance_to(c);
      if(d < best.distance)
      {
        best.window = &w;
        best.distance = d;
        best.crossing = x;
      }
      const FT value = d + rho_minus_one * w.sigma;
      if(value < best.value)
      {
        best.value_window = &w;
        best.value = value;
      }
    }
  }
  return best;
}

// The part of a window's interval whose rays may still go left of the apex c (those up to
// `left_end`) and right of it (from `right_start` on), given the best window B to c.
template <class FT>
struct Sides
{
  FT left_end;
  FT right_start;
};

// A shortest path does not cross B's path to c where B is there first. If w's own way to c
// (straight when it lights c, else through its nearer end) is no shorter than B's, then B is
// first at every point of its path that a ray of w reaches (else that ray, then B's path, would
// reach c sooner), so w keeps only the rays that stay on their side of B's path: above the edge,
// those that pass c on B's side of B's crossing; below it, those that did not cut B's segment
// from its pseudo-source. Below the edge, the two windows' unfoldings are known to be the same
// surface only inside w's lit triangle, so that test applies only when w's interval contains
// B's crossing. "Shorter" and "first" are by key (see Window): the argument holds for keys as
// for distances, since a key, too, grows along a straight path by the length travelled.
template <class FT>
inline Sides<FT> sides_of_best_path(const Window<FT>& w, const Toward_apex<FT>& t, const Vec2<FT>& c,
                                    const Best_toward_apex<FT>& best)
{
  using Point = Vec2<FT>;
  const FT inf = Number_type_math<FT>::infinity();
  FT to_c = t.distance;
  if(!(to_c < inf))
  {
    const FT end = t.crossing < w.b0 ? w.b0 : w.b1;
    to_c = w.distance_to_base_point(end) + length(c - Point{end, number<FT>(0)});
  }
  Sides<FT> keep{w.b1, w.b0};
  if(to_c >= best.distance)
  {
    keep.left_end = (std::min)(best.crossing, w.b1);
    keep.right_start = (std::max)(best.crossing, w.b0);
    if(w.b0 < best.crossing && best.crossing < w.b1)
    {
      // a ray of w that meets the edge on the other side of B's line than w's source crossed
      // that line below the edge; on B's segment [s_B, (B's crossing, 0)] (not beyond s_B) up
      // to the ray through s_B, which meets the edge at beyond_sB (all of them if s_B is not
      // nearer the edge than w's source). Sources that coincide to rounding are one
      // pseudo-source unfolded two ways (around either side of a vertex on its line to c, as on
      // a regular grid), tying at c: no ray of w crossed B's path, and the sign of `side`, noise
      // then, would cut all of one side of w, with the paths beyond c that only it carries.
      using Math = Number_type_math<FT>;
      const Point& sB = best.window->source;
      const Point along_B{best.crossing - sB.x, -sB.y};
      const FT side = cross(along_B, w.source - sB);
      const FT noise = Tuning<FT>::rounding_margin(
        (Math::abs(along_B.x) + Math::abs(along_B.y)) *
        (Math::abs(sB.x) + Math::abs(sB.y) + Math::abs(w.source.x) + Math::abs(w.source.y)));
      const bool sB_nearer = sB.y > w.source.y;
      const FT beyond_sB = sB_nearer ? x_axis_crossing(w.source, sB) : number<FT>(0);
      if(side < -noise)
        keep.left_end = sB_nearer ? (std::min)(best.crossing, beyond_sB) : -inf;
      else if(side > noise)
        keep.right_start = sB_nearer ? (std::max)(best.crossing, beyond_sB) : inf;
    }
  }
  return keep;
}

// ---------------------------------------------------------------------------------------------
// Pairwise trimming (as in MMP and VTP): where two windows of one list overlap, the part of one
// that is everywhere farther than the other (by key) carries no shortest path and is cut off.

// The points of (lo, hi) where the two windows give equal distances: sigma_u + r_u = sigma_w + r_w.
// Squaring twice gives a quadratic; its spurious roots only add harmless piece boundaries.
template <class FT>
inline int equal_distance_points(const Window<FT>& u, const Window<FT>& w, FT lo, FT hi, FT* out)
{
  const FT xu = u.source.x, yu = u.source.y, xw = w.source.x, yw = w.source.y;
  const FT delta = w.sigma - u.sigma;
  // r_u^2 - r_w^2 = A t + B, so A t + B - delta^2 = 2 delta r_w
  const FT A = number<FT>(2) * (xw - xu);
  const FT C = (xu * xu + yu * yu - xw * xw - yw * yw) - delta * delta;
  const FT d2 = number<FT>(4) * delta * delta;
  const FT a = A * A - d2;
  const FT b = number<FT>(2) * A * C + d2 * number<FT>(2) * xw;
  const FT c = C * C - d2 * (xw * xw + yw * yw);
  int n = 0;
  auto keep = [&](FT t) { if(lo < t && t < hi) out[n++] = t; };
  using Math = Number_type_math<FT>;
  const FT scale = (std::max)(Math::abs(a), (std::max)(Math::abs(b), Math::abs(c)));
  if(!(scale > FT(0)))
    return 0;
  if(Math::abs(a) <= Tuning<FT>::rounding_margin(scale))
  {
    if(b != FT(0))
      keep(-c / b);
    return n;
  }
  const FT disc = b * b - number<FT>(4) * a * c;
  if(disc < FT(0))
    return 0;
  const FT q = -(b + (b < FT(0) ? -Math::sqrt(disc) : Math::sqrt(disc))) / number<FT>(2);
  keep(q / a);
  if(q != FT(0))
    keep(c / q);
  return n;
}

// `x` is farther on the pieces [cuts[k], cuts[k+1]] with farther[k] == -1: cut off the run of
// such pieces at either end of the overlap, where that end is also an end of `x`
template <class FT>
inline void cut_where_farther(Window<FT>& x, const FT* cuts, const int* farther, int pieces)
{
  int first = 0;
  while(first < pieces && farther[first] == -1)
    ++first;
  int last = pieces;
  while(last > first && farther[last - 1] == -1)
    --last;
  const bool starts_x = cuts[0] == x.b0;
  const bool ends_x = cuts[pieces] == x.b1;
  if(first == pieces) // farther on the whole overlap
  {
    if(starts_x && ends_x)
      x.cut_end(x.b0);
    else if(starts_x)
      x.cut_start(cuts[pieces]);
    else if(ends_x)
      x.cut_end(cuts[0]);
    return;
  }
  if(starts_x && first > 0)
    x.cut_start(cuts[first]);
  if(ends_x && last < pieces)
    x.cut_end(cuts[last]);
}

// `u` starts no later than `w`. Their overlap is cut where D_u - D_w = 0 (a hyperbola meets the
// edge at most twice); on each piece in between the difference has one sign, which the
// piece's middle tells: its ends are roots or near-ties, so only a clear contradiction there
// leaves the piece alone. A piece where the two tie within rounding is left to both: two
// different pseudo-sources tie along a piece only near the ray through both, beyond which their
// rays part, and that ray may be a shortest path through vertices in a row (on a grid wrapped
// around a bore, giving the piece to either window lost it: 0.5% too long).
template <class FT>
CGAL_DGG_VTP_3_HOT_INLINE void trim_pair(Window<FT>& u, Window<FT>& w)
{
  const FT lo = (std::max)(u.b0, w.b0);
  const FT hi = (std::min)(u.b1, w.b1);
  if(!(lo < hi))
    return;
  // the straight lengths from each source image, kept for the slopes below (as differences of
  // distances and sigma they would lose machine epsilon x sigma of themselves)
  const FT lu_lo = length(Vec2<FT>{lo - u.source.x, -u.source.y});
  const FT lu_hi = length(Vec2<FT>{hi - u.source.x, -u.source.y});
  const FT du_lo = u.sigma + lu_lo;
  const FT du_hi = u.sigma + lu_hi;
  const FT m = Tuning<FT>::rounding_margin((std::max)(du_lo, du_hi));
  // One pseudo-source unfolded two ways (through other sheets at copies, or around either side of
  // a vertex), within rounding: the same rays into the same face, so w adds nothing on the
  // overlap. Kept, such windows multiply at every edge between sheets and prune none of one
  // another (a fuzz input, a needle folded onto sheets of itself: 380,844 windows from a vertex).
  using Math = Number_type_math<FT>;
  if(Math::abs(u.sigma - w.sigma) + Math::abs(u.source.x - w.source.x) + Math::abs(u.source.y - w.source.y) <= m)
  {
    const FT overlap[2] = {lo, hi};
    const int w_farther = -1;
    cut_where_farther(w, overlap, &w_farther, 1);
    return;
  }
  const auto difference = [&](FT x) { return u.distance_to_base_point(x) - w.distance_to_base_point(x); };
  const FT lw_lo = length(Vec2<FT>{lo - w.source.x, -w.source.y});
  const FT lw_hi = length(Vec2<FT>{hi - w.source.x, -w.source.y});
  const FT f_lo = du_lo - (w.sigma + lw_lo);
  const FT f_hi = du_hi - (w.sigma + lw_hi);

  // per piece, the sign of D_u - D_w: +1 u is farther, -1 w is farther or they tie, 0 unknown
  FT cuts[4] = {lo, hi, hi, hi};
  int sign[3];
  int pieces = 1;
  // The slope of D_u - D_w is cos_u - cos_w, the cosines of the rays with the edge, each
  // increasing along it: slopes in [a, b] bound the difference on the overlap from both sides
  // by lines through its ends, and when those bounds keep one sign, no root search is needed.
  const FT slack = Tuning<FT>::slope_slack();
  const FT a = (lo - u.source.x) / lu_lo - (hi - w.source.x) / lw_hi - slack;
  const FT b = (hi - u.source.x) / lu_hi - (lo - w.source.x) / lw_lo + slack;
  const FT len = hi - lo;
  const FT lowest = (a >= FT(0)) ? f_lo : (b <= FT(0)) ? f_hi
                  : f_lo + a * (f_hi - f_lo - b * len) / (a - b);
  const FT highest = (a >= FT(0)) ? f_hi : (b <= FT(0)) ? f_lo
                   : f_lo + b * (f_hi - f_lo - a * len) / (b - a);
  if(lowest > m)
    sign[0] = 1;
  else if(highest < -m)
    sign[0] = -1;
  else
  {
    int n = 1;
    n += equal_distance_points(u, w, lo, hi, cuts + n);
    cuts[n++] = hi;
    if(n == 4 && cuts[2] < cuts[1])
      std::swap(cuts[1], cuts[2]);
    FT at_cut[4];
    at_cut[0] = f_lo;
    at_cut[n - 1] = f_hi;
    for(int k = 1; k + 1 < n; ++k)
      at_cut[k] = difference(cuts[k]);
    pieces = n - 1;
    for(int k = 0; k < pieces; ++k)
    {
      const FT at_middle = difference((cuts[k] + cuts[k + 1]) / number<FT>(2));
      const FT fmin = (std::min)(at_cut[k], at_cut[k + 1]);
      const FT fmax = (std::max)(at_cut[k], at_cut[k + 1]);
      if(at_middle > m)
        sign[k] = fmin > -m ? 1 : 0;
      else if(at_middle < -m)
        sign[k] = fmax < m ? -1 : 0;
      else
        sign[k] = 0;
    }
  }
  int opposite_sign[3];
  for(int k = 0; k < pieces; ++k)
    opposite_sign[k] = -sign[k];
  cut_where_farther(w, cuts, sign, pieces);
  cut_where_farther(u, cuts, opposite_sign, pieces);
}

// trims every overlapping pair of `windows` (sorted by start on the way; `starts` is scratch)
// and removes the windows left empty
template <class FT>
inline void trim_overlapping_windows(std::vector<Window<FT>>& windows, std::vector<FT>& starts)
{
  if(windows.size() < 2)
    return;
  std::sort(windows.begin(), windows.end(), [](const Window<FT>& a, const Window<FT>& b) { return a.b0 < b.b0; });
  starts.resize(windows.size());
  for(std::size_t i = 0; i < windows.size(); ++i)
    starts[i] = windows[i].b0;
  for(std::size_t i = 0; i < windows.size(); ++i)
    for(std::size_t j = i + 1; j < windows.size() && starts[j] < windows[i].b1; ++j)
      if(windows[i].b0 < windows[i].b1)
        trim_pair(windows[i], windows[j]);
  std::size_t kept = 0;
  for(const Window<FT>& w : windows)
    if(w.b0 < w.b1)
      windows[kept++] = w;
  windows.resize(kept);
}

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_WINDOW_PRUNING_H
