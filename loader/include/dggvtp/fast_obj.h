// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

#ifndef DGGVTP_FAST_OBJ_H
#define DGGVTP_FAST_OBJ_H

#include <dggvtp/fast_soup.h>
#include <dggvtp/text_numbers.h>

#include <cstdint>
#include <limits>
#include <string_view>
#include <vector>

namespace dggvtp {
namespace internal {

// OBJ in one pass, line by line as CGAL 5.5's read_OBJ reads it: `v x y z` (exactly 3
// coordinates), `f` with positive indices, `vt`, `vn`, `o`, `g`, `s`, `usemtl`, `mtllib` and
// comment lines ignored, blank lines skipped. A face's indices are read as CGAL reads them: an int,
// then the line is skipped up to and including the next space, at most 256 characters (so
// `1/2/3` gives 1; as in CGAL, `1\t2 3` gives 1 and 3). Anything else (other keywords, relative or
// zero indices, a coordinate or index that does not read plainly, an index beyond the vertices, a
// face of fewer than 3 vertices) returns false, for CGAL's reader to read or refuse.
inline bool read_fast_obj(const char* begin, const char* end, Fast_soup& soup)
{
  std::vector<std::uint32_t> face;
  const char* p = begin;
  while(p != end)
  {
    const char* const first = p;
    while(p != end && *p != '\n')
      ++p;
    const char* const eol = p; // CGAL's getline keeps a '\r', a white space to `>>`
    if(p != end)
      ++p;
    const char* q = first;
    while(q != eol && is_space(*q))
      ++q;
    const char* const word = q;
    while(q != eol && !is_space(*q))
      ++q;
    const std::string_view keyword(word, std::size_t(q - word));
    if(keyword.empty() || keyword.front() == '#' || keyword == "vt" || keyword == "vn" || keyword == "o" ||
       keyword == "g" || keyword == "s" || keyword == "usemtl" || keyword == "mtllib")
      continue;
    if(keyword == "v")
    {
      double c[3];
      q = read_point(q, eol, c);
      if(q == nullptr)
        return false;
      while(q != eol && is_space(*q))
        ++q;
      if(q != eol)
        return false;
      soup.points.emplace_back(c[0], c[1], c[2]);
    }
    else if(keyword == "f")
    {
      face.clear();
      for(;;)
      {
        while(q != eol && is_space(*q))
          ++q;
        if(q == eol)
          break;
        std::uint64_t index;
        q = read_index(q, eol, std::uint64_t(std::numeric_limits<int>::max()), index);
        if(q == nullptr || index == 0)
          return false;
        face.push_back(std::uint32_t(index - 1));
        for(int skipped = 0; q != eol && skipped < 256; ++skipped) // iss.ignore(256, ' ')
          if(*q++ == ' ')
            break;
      }
      if(face.size() < 3)
        return false;
      soup.add_face(face.data(), face.size());
    }
    else
      return false;
  }
  if(soup.points.empty() || soup.faces == 0)
    return false;
  for(const std::uint32_t v : soup.corners)
    if(v >= soup.points.size())
      return false;
  return true;
}

} // namespace internal
} // namespace dggvtp

#endif // DGGVTP_FAST_OBJ_H
