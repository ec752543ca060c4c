// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

#ifndef DGGVTP_FAST_OFF_H
#define DGGVTP_FAST_OFF_H

#include <dggvtp/fast_soup.h>
#include <dggvtp/text_numbers.h>

#include <cstdint>
#include <string_view>
#include <vector>

namespace dggvtp {
namespace internal {

// Plain text OFF in one pass: an `OFF` line, a `V F E` line, then one line a record as CGAL 5.5's
// File_scanner_OFF reads them (after any white space): exactly 3 coordinates a vertex, `n i1 ... in`
// a face. Comments, other header variants (C, N, 4, n, ST, BINARY, SKEL), extra numbers on a line
// (colours), a value that does not read plainly, an index beyond the vertices, a face of fewer
// than 3 vertices or a missing record return false, for the guarded path through CGAL's reader.
// What this accepts passes check_off_declarations, and CGAL reads it into the same soup.
inline bool read_fast_off(const char* begin, const char* end, Fast_soup& soup)
{
  const char* p = begin;
  std::string_view line;
  if(!next_line(p, end, line) || line != "OFF")
    return false;
  if(!next_line(p, end, line))
    return false;
  // V, F, E: within what check_off_declarations lets CGAL's header reader count
  std::uint64_t counts[3];
  {
    const char* q = line.data();
    const char* const eol = q + line.size();
    for(std::uint64_t& n : counts)
    {
      while(q != eol && is_space(*q))
        ++q;
      q = read_index(q, eol, 1000000000, n);
      if(q == nullptr || (q != eol && !is_space(*q)))
        return false;
    }
    while(q != eol && is_space(*q))
      ++q;
    if(q != eol || counts[0] == 0 || counts[1] == 0 || counts[0] + counts[1] > 1000000000)
      return false;
  }
  const std::uint64_t vertices = counts[0], faces = counts[1];
  // the next record's line, after white space (CGAL's skip_comment, but without comments)
  const auto record = [&]() {
    while(p != end && is_space(*p))
      ++p;
    return p != end && *p != '#' && next_line(p, end, line);
  };
  const auto rest_is_blank = [](const char* q, const char* eol) {
    while(q != eol && is_space(*q))
      ++q;
    return q == eol;
  };
  // the counts must fit in the bytes left ("0 0 0" a vertex, "3 0 1 2" a face at least) before
  // anything is allocated for them
  if(5 * vertices + 7 * faces > std::uint64_t(end - p))
    return false;
  soup.points.reserve(std::size_t(vertices));
  for(std::uint64_t v = 0; v < vertices; ++v)
  {
    if(!record())
      return false;
    const char* q = line.data();
    const char* const eol = q + line.size();
    double c[3];
    q = read_point(q, eol, c);
    if(q == nullptr)
      return false;
    if(!rest_is_blank(q, eol))
      return false;
    soup.points.emplace_back(c[0], c[1], c[2]);
  }
  soup.corners.reserve(3 * std::size_t(faces));
  std::vector<std::uint32_t> face;
  for(std::uint64_t f = 0; f < faces; ++f)
  {
    if(!record())
      return false;
    const char* q = line.data();
    const char* const eol = q + line.size();
    std::uint64_t n, index;
    q = read_index(q, eol, 1000000, n);
    if(q == nullptr || n < 3)
      return false;
    face.clear();
    for(std::uint64_t k = 0; k < n; ++k)
    {
      if(q == eol || !is_space(*q))
        return false;
      while(q != eol && is_space(*q))
        ++q;
      q = read_index(q, eol, vertices - 1, index);
      if(q == nullptr)
        return false;
      face.push_back(std::uint32_t(index));
    }
    if(!rest_is_blank(q, eol))
      return false;
    soup.add_face(face.data(), face.size());
  }
  return true;
}

} // namespace internal
} // namespace dggvtp

#endif // DGGVTP_FAST_OFF_H
