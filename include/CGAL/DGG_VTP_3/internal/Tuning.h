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

#ifndef CGAL_DGG_VTP_3_INTERNAL_TUNING_H
#define CGAL_DGG_VTP_3_INTERNAL_TUNING_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/number_type_math.h>

#include <cmath>
#include <cstddef>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// Every constant the propagation was tuned or calibrated with, in one place, with what it was
// measured on. The figures behind them are in benchmark/DGG_VTP_3/README.md.
template <class FT>
struct Tuning
{
  // ---- accuracy control (DGG-VTP) -----------------------------------------------------------

  // The key ratio rho: every decision of DGG-VTP compares keys, a window's pseudo-source distance
  // divided by rho plus the straight length beyond it, and this makes every distance at most rho
  // times the exact one (the manual's argument). rho = 1 + eps, less a margin for the rounding of
  // the keys (64 machine epsilons, far below any accepted eps in double); 1 (the exact mode) when
  // nothing is left of eps.
  static FT key_ratio(FT accuracy)
  {
    const FT margin = number<FT>(2) * rounding_margin(number<FT>(1));
    return accuracy > margin ? number<FT>(1) + accuracy - margin : number<FT>(1);
  }

  // Windows stop at their distance bound (and their relays emit) only where that pays: the
  // bound lies at about (a relay's distance) / epsilon, so a stop saves something once windows
  // travel that far, and how far they travel grows like the number of edges across the mesh,
  // about sqrt(vertices). Without stops the rules on keys alone keep the contract as well (a stop
  // is a pruning the argument allows, not one it needs) and prune much by themselves. Measured on
  // meshes of 650 to 1M vertices, stops win where epsilon sqrt(vertices) is above about 10 and
  // lose below it, both ways by up to 2.4 times (benchmark/DGG_VTP_3/README.md, "Where stops pay").
  static bool stops_pay(FT accuracy, std::size_t vertices)
  {
    return CGAL::to_double(accuracy) * std::sqrt(double(vertices)) >= 10.;
  }

  // A vertex that becomes the CH-relay vertex of a window that will stop within this many lengths
  // of the window's edge becomes a pseudo-source at once (see Window_propagation::anticipate_stop):
  // on bunny_1M, windows at 1e-1 / 1e-2 / 1e-4: 11.0M / 17.8M / 29.3M when relays emit only once
  // their window has stopped, 7.7M / 13.5M / 29.2M with 3, 7.2M / 12.7M / 30.8M when every vertex
  // emits.
  static FT stop_anticipation() { return number<FT>(3); }

  // ---- rounding ------------------------------------------------------------------------------

  // Ties within this (relative to `scale`) are ties: distances are not compared more finely
  // than rounding allows.
  static FT rounding_margin(FT scale) { return number<FT>(64) * Number_type_math<FT>::machine_epsilon() * scale; }

  // A window crossing into another sheet (Vertex_copies.h) that lights no more of its edge than
  // this at one of its ends passes through that end, a copy: it is left to the copy's own
  // windows, whose paths differ from its by the square of this, relatively. Relative to the least
  // of the edge, the window's straight length to the copy and the copy's clearance (see
  // for_each_face_across()): relative to the edge alone, a source 3e-8 from a copy on an edge of
  // length 1 got +4.8% in the exact mode.
  static FT sheet_crossing_sliver() { return Number_type_math<FT>::sqrt(Number_type_math<FT>::machine_epsilon()); }

  // ... and its key there is compared with the copy's within this (relative to the key plus the
  // edge's length) rather than within rounding_margin(): it was unfolded into every face that it
  // crossed around the copy, each adding the rounding of a few machine epsilons to its source,
  // and up to pi / min_cone_angle() faces fit around a point (about 6e4 machine epsilons). A fuzz
  // input (two needles 100 long meeting at a copy) had its windows 2e-12 below the copy's key of
  // 100, 1.4 rounding margins: they circled it from sheet to sheet for ever.
  static FT sheet_crossing_tie(FT scale) { return number<FT>(1024) * rounding_margin(scale); }

  // On a mesh with edges between sheets, windows crossing between the sheets around a sharp
  // corner can still multiply faster than the rules prune them (a fuzz input: needles 20,000 long
  // at a point of 7 sheets, windows a few 1e-4 from it, tied with its key, for ever); a
  // propagation that makes more windows than this there is refused (std::invalid_argument) rather
  // than left to run. Meshes make 10 to 50 windows per face (bunny_1M: 15 at 1e-4; the fuzz
  // inputs that no longer hang, up to 1,149: a folded needle, 9,191 windows on 8 faces).
  static std::size_t max_windows_between_sheets(std::size_t faces) { return 10000 + 1000 * faces; }

  // Radians by which a saddle's shadow cone is widened for rounding (emitting more is safe).
  static FT shadow_widening() { return number<FT>(8) * Number_type_math<FT>::sqrt(rounding_margin(number<FT>(1))); }

  // Slopes of distance differences (the pairwise trimming's bounds) come from the rays' cosines,
  // each a coordinate over a straight length computed directly (taken as a distance minus sigma,
  // they lost machine epsilon x sigma / length, beyond this slack once sigma / length > 1e8, as
  // on caps); the slack is far above their rounding and only widens the bounds (safe).
  static FT slope_slack() { return Number_type_math<FT>::sqrt(Number_type_math<FT>::machine_epsilon()); }

  // A vertex whose angle sum is below 2 pi by less than this (relative) is treated as a saddle
  // (see Unfolded_mesh: leaning towards saddles is the safe side); none in exact arithmetic.
  static FT flat_tolerance() { return Number_type_math<FT>::is_exact ? number<FT>(0) : number<FT>(1e-6); }

  // ---- input geometry the propagation can finish on (user manual: input policy) ----------------

  // Windows wrap around a sliver tube a number of times that grows like the slivers'
  // length / height, and around a cone about pi / (cone angle) times.
  static FT max_sliver_ratio() { return number<FT>(1e10); }
  static FT min_cone_angle() { return number<FT>(1e-4); }

  // Windows circle a closed loop of edges (a cone, a pocket of two faces) about
  // rounding_margin(d) / (the loop's length) times before they are pruned, ties being kept: an
  // edge must be at least this times the mesh's size (its bounding box's largest side), so that
  // at distances d of that size the loops cost at most about 2e4 turns. Fuzzer: a pocket of two
  // triangles of edges 6e-39 hung from a unit triangle ran for ever, in double and float. Needles
  // far shorter than the rounding of the distances are fine (tests: 1e-9 in float).
  static FT min_relative_edge() { return number<FT>(1e-3) * Number_type_math<FT>::machine_epsilon(); }

  // ---- patches and rounds (Parallel_tag, and memory locality for any tag) --------------------

  // Patches have at least this many faces, and a mesh at most this many patches; their number
  // depends on the mesh only, never on the number of threads. The fuzzer makes patches of a few
  // faces (CGAL_DGG_VTP_3_MIN_PATCH_FACES), so that its small meshes run rounds across patches.
#ifdef CGAL_DGG_VTP_3_MIN_PATCH_FACES
  static std::size_t min_patch_faces() { return CGAL_DGG_VTP_3_MIN_PATCH_FACES; }
#else
  static std::size_t min_patch_faces() { return 2048; }
#endif
  static std::size_t max_patches() { return 256; }

  // A round pops vertices up to this many mean edge lengths beyond the nearest: on bunny_1M
  // (1e-6, 730 rounds) 1 to 8 edges change the time by less than the noise; wider bands pop
  // vertices before the windows from other patches can shorten them (windows: +0.1% at 1, +2% at 8).
  static FT band_in_edges() { return number<FT>(4); }
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_TUNING_H
