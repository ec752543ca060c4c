// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

#ifndef DGGVTP_TEXT_NUMBERS_H
#define DGGVTP_TEXT_NUMBERS_H

#include <fast_float/fast_float.h>

#include <cmath>
#include <cstdint>
#include <system_error>

namespace dggvtp {
namespace internal {

// Numbers of the text formats, for the fast readers. Each function reads one number at `p` (no
// leading space) and returns the character after it, or nullptr where it does not read the number
// exactly as CGAL's readers do; the fast reader then gives the file up to CGAL's (guarded) path,
// which reads, or refuses, it as before.
//
// CGAL reads coordinates with `std::istream >> double` (or float): libstdc++ gathers a sign, digits,
// a point and an exponent, and converts them with strtod (strtof), correctly rounded; a value that
// overflows fails. fast_float's from_chars is correctly rounded too, so the same text gives the same
// bits. Only the plain forms are taken, -?(D+(.D*)?|.D+)([eE][-+]?D+)?: no '+' sign, no "inf" or
// "nan" (the stream does not read those either), no hexadecimal; and only finite results.

inline bool is_digit(char c) { return c >= '0' && c <= '9'; }

// isspace in the "C" locale, what the streams skip between numbers
inline bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

// the end of the decimal number at `p`, or nullptr if there is none in the plain form above
inline const char* scan_decimal(const char* p, const char* end)
{
  if(p != end && *p == '-')
    ++p;
  const char* const digits = p;
  while(p != end && is_digit(*p))
    ++p;
  bool any = p != digits;
  if(p != end && *p == '.')
  {
    const char* const fraction = ++p;
    while(p != end && is_digit(*p))
      ++p;
    any = any || p != fraction;
  }
  if(!any)
    return nullptr;
  if(p != end && (*p == 'e' || *p == 'E'))
  {
    ++p;
    if(p != end && (*p == '-' || *p == '+'))
      ++p;
    const char* const exponent = p;
    while(p != end && is_digit(*p))
      ++p;
    if(p == exponent)
      return nullptr;
  }
  return p;
}

// a float or double coordinate, as `>> T` reads it
template <class T>
const char* read_real(const char* p, const char* end, T& value)
{
  const char* const last = scan_decimal(p, end);
  if(last == nullptr)
    return nullptr;
  const fast_float::from_chars_result result = fast_float::from_chars(p, last, value);
  if(result.ec != std::errc() || result.ptr != last || !std::isfinite(value))
    return nullptr;
  return last;
}

// three coordinates separated by blanks, after blanks; the end of the third, or null
inline const char* read_point(const char* p, const char* end, double (&c)[3])
{
  for(double& x : c)
  {
    while(p != end && is_space(*p))
      ++p;
    p = read_real(p, end, x);
    if(p == nullptr || (p != end && !is_space(*p)))
      return nullptr;
  }
  return p;
}

// an unsigned decimal integer of digits only, at most `max`
inline const char* read_index(const char* p, const char* end, std::uint64_t max, std::uint64_t& value)
{
  const char* const first = p;
  value = 0;
  while(p != end && is_digit(*p))
  {
    value = 10 * value + std::uint64_t(*p - '0');
    if(value > max) // max < 2^32: no overflow before this test
      return nullptr;
    ++p;
  }
  return p == first ? nullptr : p;
}

} // namespace internal
} // namespace dggvtp

#endif // DGGVTP_TEXT_NUMBERS_H
