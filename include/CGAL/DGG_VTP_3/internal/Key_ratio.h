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

#ifndef CGAL_DGG_VTP_3_INTERNAL_KEY_RATIO_H
#define CGAL_DGG_VTP_3_INTERNAL_KEY_RATIO_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/internal/Tuning.h>
#include <CGAL/DGG_VTP_3/internal/number_type_math.h>

#include <cstddef>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// The key ratio rho of a propagation (Tuning::key_ratio): a pseudo-source at distance d sends its
// windows out with the key d / rho, and a window of key sigma gives the distance rho sigma (see
// Window and the manual's argument), and the constants of the distance bound derived from rho,
// computed once, and whether windows stop at their distance bound (where Tuning::stops_pay says
// they gain, unless the propagation forbids them). rho = 1 is the exact algorithm: keys are
// distances, bit for bit.
template <class FT>
class Key_ratio
{
public:
  // Whether windows stop: where they gain; never, where stops would break the propagation's
  // argument (see Propagation_vertices::keep_field); always, where the windows must end without
  // relays that emit (see Direct_distances).
  enum class Stops { where_they_pay, never, always };

  Key_ratio(FT accuracy, std::size_t number_of_vertices, Stops stops = Stops::where_they_pay)
    : m_rho(Tuning<FT>::key_ratio(accuracy))
    , m_lambda(number<FT>(1) / m_rho)
    , m_one_minus_lambda((m_rho - number<FT>(1)) / m_rho) // without cancellation for a small epsilon
    , m_k(m_one_minus_lambda * (number<FT>(1) + m_lambda) / number<FT>(2))
    , m_stops(m_rho > FT(1) && (stops == Stops::always ||
                                (stops == Stops::where_they_pay && Tuning<FT>::stops_pay(accuracy, number_of_vertices))))
  {}

  bool is_exact() const { return !(m_rho > FT(1)); }
  // windows stop at their distance bound, and take CH-relay vertices for it
  bool stops() const { return m_stops; }
  FT rho() const { return m_rho; }
  // the key of distance `d`
  FT key(FT d) const { return is_exact() ? d : d * m_lambda; }
  // the distance of key `sigma`
  FT distance(FT sigma) const { return is_exact() ? sigma : m_rho * sigma; }

  // 1 / rho, 1 - 1 / rho, and k = (1 - 1 / rho^2) / 2 (see distance_bound)
  FT lambda() const { return m_lambda; }
  FT one_minus_lambda() const { return m_one_minus_lambda; }
  FT k() const { return m_k; }

private:
  FT m_rho, m_lambda, m_one_minus_lambda, m_k;
  bool m_stops;
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_KEY_RATIO_H
