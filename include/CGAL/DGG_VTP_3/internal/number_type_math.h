// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

#ifndef CGAL_DGG_VTP_3_INTERNAL_NUMBER_TYPE_MATH_H
#define CGAL_DGG_VTP_3_INTERNAL_NUMBER_TYPE_MATH_H

#include <CGAL/config.h>

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
// (NaN for Gmpfr).
template <class FT>
struct Number_type_math
{
  static_assert(std::is_floating_point<FT>::value,
                "DGG_VTP_3 computes in float, double, long double or CGAL::Gmpfr only");

  static FT infinity() { return std::numeric_limits<FT>::infinity(); }
  // the gap between 1 and the next number, 2^(1 - p) for p bits (rounding to nearest errs by half
  // of it, relative); std::numeric_limits calls it epsilon
  static FT machine_epsilon() { return std::numeric_limits<FT>::epsilon(); }
  static FT sqrt(FT x) { return std::sqrt(x); }
  static FT abs(FT x) { return std::abs(x); }
  static FT atan2(FT y, FT x) { return std::atan2(y, x); }
  static FT fmod(FT x, FT y) { return std::fmod(x, y); }
  static FT cos(FT x) { return std::cos(x); }
  static FT sin(FT x) { return std::sin(x); }
};

#ifdef CGAL_USE_MPFR
// CGAL::Gmpfr through MPFR's own functions. As CGAL's Gmpfr arithmetic does, a result gets the
// larger of its operands' precision and the default precision, and is rounded by the default
// rounding mode.
template <>
struct Number_type_math<Gmpfr>
{
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
  static Gmpfr cos(const Gmpfr& x) { return unary(mpfr_cos, x); }
  static Gmpfr sin(const Gmpfr& x) { return unary(mpfr_sin, x); }
  static Gmpfr atan2(const Gmpfr& y, const Gmpfr& x) { return binary(mpfr_atan2, y, x); }
  static Gmpfr fmod(const Gmpfr& x, const Gmpfr& y) { return binary(mpfr_fmod, x, y); }

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

  template <class Function>
  static Gmpfr binary(Function f, const Gmpfr& x, const Gmpfr& y)
  {
    Gmpfr r(0, (std::max)(precision(x), precision(y)));
    f(r.fr(), x.fr(), y.fr(), mpfr_get_default_rounding_mode());
    return r;
  }
};
#endif // CGAL_USE_MPFR

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_NUMBER_TYPE_MATH_H
