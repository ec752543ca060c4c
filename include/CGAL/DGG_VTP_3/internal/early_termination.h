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

#ifndef CGAL_DGG_VTP_3_INTERNAL_EARLY_TERMINATION_H
#define CGAL_DGG_VTP_3_INTERNAL_EARLY_TERMINATION_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/Key_ratio.h>
#include <CGAL/DGG_VTP_3/internal/Point_targets.h>
#include <CGAL/DGG_VTP_3/internal/Propagation_query.h>
#include <CGAL/DGG_VTP_3/internal/Tuning.h>
#include <CGAL/DGG_VTP_3/internal/Window_lists.h>
#include <CGAL/DGG_VTP_3/internal/Distance_bound.h>
#include <CGAL/DGG_VTP_3/internal/number_type_math.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// Early termination (targets, max_distance), from the propagation's own invariant.
//
// Everything the propagation will still do starts from its pending work: a vertex in a queue
// (key k: it emits windows and relaxes its neighbours at k or more) or a window in a list (every
// value it or its descendants give, at the apex of a face or along the children's intervals, is
// rho sigma + |p - source| for a point p beyond its interval, so at least its lower bound
// rho sigma + distance_to_interval; a relaxation at the apex and a child window are no exception).
// Nothing else makes distances: a value can only come from a chain of such steps, and each step
// is at least its parent's lower bound, but one: a window that stops at its distance bound makes
// its relay vertices emit (Window_propagation::stop_at_bound), and a relay popped before is put
// back in the queue at its own distance, below the window's lower bound, and may give vertices
// near it values below P. That emission stands in for the window's beam beyond the stop only,
// where the window's own values are beyond its lower bound: a shortest path to a vertex at D < P
// does not pass there, so the contract (K(v) <= exact, the manual) never needs it for such a
// vertex; it can only make a distance shorter, within the contract either way. Measured: no
// vertex got another value so (every vertex of pinion and spot as a target and three radii, at
// epsilon 1, 0.5 and 0.2, where windows stop; python/tests/test_early_termination.py).
// So, between two rounds (when no message is in flight), with
//   P = the smallest key of the queues and lower bound of the windows in the lists,
// no distance smaller than P will ever be set again. A vertex (or point target) whose distance
// D <= L satisfies D < P - rounding is final: later values are all >= P. The largest distance of
// interest L is the maximum distance, or the largest distance of the targets found so far
// (+inf while one is unreached), whichever is smaller.
//
// The rounds are those of the full propagation up to L; beyond, they pop no vertex farther than
// pop_limit() (rho L) unless it is the nearest one left. What a vertex popped beyond rho L does
// only sets values beyond L (see pop_limit()), so the values of interest are the full field's; in
// the exact mode they are its bits in every comparison made, while with a positive accuracy the
// rounds' other order (a patch's messages arrive at other rounds' ends) may let another path of
// the contract win at a few vertices. A margin of mean edge lengths, which this replaces, had
// nothing to do with how far a window waiting on a long edge may still reach. The lists are only
// scanned once every queued vertex is beyond L, near the end of an early-terminated propagation.

// L: the largest distance the query needs to be final (+inf: every vertex). A point target's
// distance is bounded by the windows seen crossing its face and by its corners' distances.
template <class FT>
FT early_termination_limit(const Propagation_query<FT>& query, const Point_targets<FT>& point_targets,
                           const Unfolded_mesh<FT>& mesh, const std::vector<FT>& distance)
{
  FT limit = query.max_distance;
  if(!query.vertex_targets.empty() || !point_targets.empty())
  {
    FT targets = point_targets.empty() ? number<FT>(0) : point_targets.largest_bound(mesh, distance);
    for(std::uint32_t v : query.vertex_targets)
      targets = (std::max)(targets, distance[v]);
    limit = (std::min)(limit, targets);
  }
  return limit;
}

// How far the rounds pop while the distances of interest are those up to `limit` (see
// early_termination_limit; +infinity: every vertex): rho limit, beyond rounding. A vertex popped
// at a distance d beyond that only sends out values of at least d, and the windows that the ICH
// rule left to it (at key d / rho > limit) would give no less either: nothing of it reaches a
// distance of interest. Popping only up to there, rather than a round's band of edges beyond the
// limit, spares a local query most of its work (a row of a local distance matrix: 6 times fewer
// windows). Once the nearest vertex is beyond, a round pops it (and its ties) alone, so that
// windows waiting outside the region R for one of their face's vertices are still propagated:
// on bunny_1M, a radius of 10 edges, 5,734 windows so, 16,090 with a whole band there.
template <class FT>
FT pop_limit(FT limit, const Key_ratio<FT>& keys)
{
  if(!(limit < Number_type_math<FT>::infinity()))
    return limit;
  const FT far = keys.rho() * limit;
  return far + Tuning<FT>::rounding_margin(far);
}

// Once nothing is pending below `limit` (see nothing_pending_below()), no key left undone is below
// this at a target: a value v gives the key v / rho or more (see Propagation_vertices::finish)
template <class FT>
FT least_key_left(FT limit, const Key_ratio<FT>& keys)
{
  return keys.key(limit) - Tuning<FT>::rounding_margin(limit);
}

// Whether nothing pending can give a target a value below `limit` (beyond rounding), given the
// nearest queued vertex of all patches (its distance plus its bound to the targets, see
// Distance_to_go: the queue's order) and the window lists of the patches numbered `woken` (the
// others hold none), each window's values being at least its key ratio `keys` times sigma plus its
// straight distance to its interval, and the rest of the way at least `to_go(patch, list, window)`.
template <class FT, class Patches, class ToGo>
bool nothing_pending_below(FT limit, FT nearest_queued, const Key_ratio<FT>& keys, const Patches& patches,
                           const std::vector<std::uint32_t>& woken, const ToGo& to_go)
{
  if(!(limit < Number_type_math<FT>::infinity()))
    return false;
  const FT above = limit + Tuning<FT>::rounding_margin(limit);
  if(!(nearest_queued > above))
    return false;
  for(std::uint32_t k : woken)
    if(!patches[k].lists.all_windows([&](std::uint32_t h, const Window<FT>& w) {
         return keys.distance(w.sigma) + distance_to_interval(w.source, w.b0, w.b1) + to_go(patches[k], h, w) > above;
       }))
      return false;
  return true;
}

// The least key that the work left pending may still give any vertex (a queued vertex's
// distance over rho, a window's key at its interval), less rounding: where a query ends with work
// left, a least key above it is not final, and this is the lower bound there (see
// Propagation_vertices::finish). The queues hold `(order, vertex)` entries, superseded ones too.
template <class FT, class Patches, class Distances>
FT least_pending_key(const Key_ratio<FT>& keys, const Patches& patches, const std::vector<std::uint32_t>& woken,
                     const Distances& distance)
{
  FT least = Number_type_math<FT>::infinity();
  for(std::uint32_t k : woken)
  {
    for(const auto& entry : patches[k].queue)
      least = (std::min)(least, keys.key(distance[entry.second]));
    patches[k].lists.all_windows([&](std::uint32_t, const Window<FT>& w) {
      least = (std::min)(least, w.sigma + distance_to_interval(w.source, w.b0, w.b1));
      return true;
    });
  }
  return least < Number_type_math<FT>::infinity() ? least - Tuning<FT>::rounding_margin(least) : least;
}

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_EARLY_TERMINATION_H
