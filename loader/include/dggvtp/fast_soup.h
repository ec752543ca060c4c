// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

#ifndef DGGVTP_FAST_SOUP_H
#define DGGVTP_FAST_SOUP_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace dggvtp {
namespace internal {

// What a fast reader makes of a file: the points and faces as CGAL's reader would give them (same
// doubles, same orders), with every face's indices already checked to be in range. The corners of
// all faces follow each other; `face_ends` is only made once a face is not a triangle, so that a
// triangle mesh costs no more than its corners.
struct Fast_soup
{
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  std::vector<Point> points;
  std::vector<std::uint32_t> corners;   // the faces' vertex indices, face after face
  std::vector<std::size_t> face_ends;   // where each face's corners end; empty while all are triangles
  std::size_t faces = 0;

  void add_face(const std::uint32_t* vertices, std::size_t size)
  {
    if(size != 3 && all_triangles())
      for(std::size_t f = 1; f <= faces; ++f)
        face_ends.push_back(3 * f);
    corners.insert(corners.end(), vertices, vertices + size);
    if(size != 3 || !all_triangles())
      face_ends.push_back(corners.size());
    ++faces;
  }
  bool all_triangles() const { return face_ends.empty(); }
};

// the bytes of a text line (without its '\n' and a '\r' before it), and the start of the next line
inline bool next_line(const char*& p, const char* end, std::string_view& line)
{
  if(p == end)
    return false;
  const char* const first = p;
  while(p != end && *p != '\n')
    ++p;
  const char* last = p;
  if(p != end)
    ++p;
  if(last != first && last[-1] == '\r')
    --last;
  line = std::string_view(first, std::size_t(last - first));
  return true;
}

} // namespace internal
} // namespace dggvtp

#endif // DGGVTP_FAST_SOUP_H
