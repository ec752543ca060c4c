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

#ifndef CGAL_DGG_VTP_3_INTERNAL_NUMBER_TYPE_MATH_H
#define CGAL_DGG_VTP_3_INTERNAL_NUMBER_TYPE_MATH_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/config.h>
#include <CGAL/number_type_basic.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#ifdef CGAL_USE_MPFR
#include <CGAL/Gmpfr.h>
#include <mpfr.h>
#endif

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// Everything the propagation asks of its number type beyond + - * /, comparisons and construction
// from int and double, in one place: supporting a number type means specialising this struct.
// std::numeric_limits is not used elsewhere: for a class type that does not specialise it (as
// CGAL::Gmpfr does not), infinity() and epsilon() silently return a default-constructed value
// (NaN for Gmpfr). No angles: the propagation decides with sign tests (see Vertex_directions.h),
// so a square root is all it needs beyond a field.
template <class FT, bool exact = Algebraic_structure_traits<FT>::Is_exact::value>
struct Number_type_math
{
  static_assert(std::is_floating_point<FT>::value,
                "DGG_VTP_3 computes in float, double, long double, CGAL::Gmpfr or an exact type with square "
                "roots (CORE::Expr, the number type of CGAL's exact kernel with sqrt) only");

  static constexpr bool is_exact = false;
  static FT infinity() { return std::numeric_limits<FT>::infinity(); }
  // the gap between 1 and the next number, 2^(1 - p) for p bits (rounding to nearest errs by half
  // of it, relative); std::numeric_limits calls it epsilon
  static FT machine_epsilon() { return std::numeric_limits<FT>::epsilon(); }
  static FT sqrt(FT x) { return std::sqrt(x); }
  static FT abs(FT x) { return std::abs(x); }
  template <class T>
  static FT convert(const T& x) { return FT(x); }
};

// An exact number type with square roots (CGAL's Algebraic_structure_traits: Is_exact, Sqrt): no
// rounding, so every rounding margin is zero (machine_epsilon() is 0) and the propagation is the
// algorithm in exact arithmetic. Such a type has no infinity: an unreached vertex gets the largest
// double instead, which no distance on a mesh of finite double coordinates reaches.
template <class FT>
struct Number_type_math<FT, true>
{
  static constexpr bool has_sqrt =
    !std::is_same<typename Algebraic_structure_traits<FT>::Sqrt, Null_functor>::value;
  static_assert(has_sqrt,
                "DGG_VTP_3 needs square roots, and this exact number type has none (the FT of "
                "CGAL::Exact_predicates_exact_constructions_kernel): use "
                "CGAL::Exact_predicates_exact_constructions_kernel_with_sqrt for exact distances, or "
                "CGAL::Exact_predicates_inexact_constructions_kernel (double)");

  static constexpr bool is_exact = true;
  static FT infinity() { return FT((std::numeric_limits<double>::max)()); }
  static FT machine_epsilon() { return FT(0); }
  static FT sqrt(const FT& x)
  {
    if constexpr(has_sqrt)
      return CGAL::sqrt(x);
    else
      return x; // never run: the static_assert above stays the only error
  }
  static FT abs(const FT& x) { return CGAL::abs(x); }
  template <class T>
  static FT convert(const T& x) { return FT(x); }
};

#ifdef CGAL_USE_MPFR
// CGAL::Gmpfr through MPFR's own functions. As CGAL's Gmpfr arithmetic does, a result gets the
// larger of its operands' precision and the default precision, and is rounded by the default
// rounding mode. The numbers the propagation starts from (coordinates, constants, the user's
// parameters) are made by convert(), at the default precision, so that the whole computation is
// at the precision the user set.
template <>
struct Number_type_math<Gmpfr>
{
  static constexpr bool is_exact = false;

  static Gmpfr infinity()
  {
    Gmpfr r(0, Gmpfr::get_default_precision());
    mpfr_set_inf(r.fr(), 1);
    return r;
  }

  // 2^(1 - p), p the default precision: CGAL's Gmpfr never computes below the default precision,
  // so this bounds every rounding error even where operands carry more bits
  static Gmpfr machine_epsilon()
  {
    const Gmpfr::Precision_type p = Gmpfr::get_default_precision();
    Gmpfr r(1, p);
    mpfr_mul_2si(r.fr(), r.fr(), 1 - long(p), MPFR_RNDN);
    return r;
  }

  static Gmpfr sqrt(const Gmpfr& x) { return unary(mpfr_sqrt, x); }
  static Gmpfr abs(const Gmpfr& x) { return unary(mpfr_abs, x); }
  // at the default precision: Gmpfr's own constructors from int and double take 256 and 512
  // bits, and every result computed from such a number would carry them
  template <class T>
  static Gmpfr convert(const T& x) { return Gmpfr(x, Gmpfr::get_default_precision()); }

private:
  static Gmpfr::Precision_type precision(const Gmpfr& x)
  {
    return (std::max)(x.get_precision(), Gmpfr::get_default_precision());
  }

  template <class Function>
  static Gmpfr unary(Function f, const Gmpfr& x)
  {
    Gmpfr r(0, precision(x));
    f(r.fr(), x.fr(), mpfr_get_default_rounding_mode());
    return r;
  }
};
#endif // CGAL_USE_MPFR

// `x` (a number of any type FT can be made from) as an FT at the working precision: how the
// propagation makes every number that enters its arithmetic (constants included; comparing with
// FT(0) makes no number). For all types but CGAL::Gmpfr that is FT(x).
template <class FT, class T>
FT number(const T& x)
{
  return Number_type_math<FT>::convert(x);
}

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_NUMBER_TYPE_MATH_H
