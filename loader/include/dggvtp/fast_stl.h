// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

#ifndef DGGVTP_FAST_STL_H
#define DGGVTP_FAST_STL_H

#include <dggvtp/fast_soup.h>
#include <dggvtp/text_numbers.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace dggvtp {
namespace internal {

// Binary STL in one pass. CGAL 5.5's read_STL merges equal points (a std::map<Point_3, int>, so
// -0 and 0 are one point, the first one seen) and numbers them in the order they first appear;
// here a hash table does the same. A file that CGAL would first try as ASCII STL (its first word
// is `solid` followed by a space or a line break), ends before its triangles, declares none, or has
// a coordinate that is not finite (CGAL's map cannot order NaN) returns false, for CGAL's reader.
class Fast_stl_reader
{
  // the slots of the table hold a point's index + 1, 0 when empty
  std::vector<std::uint32_t> m_slots;
  std::size_t m_used = 0;

  static std::uint64_t hash(const float (&c)[3])
  {
    std::uint64_t h = 0;
    for(const float x : c)
    {
      const float key = x + 0.f; // -0 + 0 = +0: equal points, equal keys
      std::uint32_t bits;
      std::memcpy(&bits, &key, 4);
      h = (h ^ bits) * 0x9E3779B97F4A7C15ull;
    }
    return h ^ (h >> 29);
  }

  static bool equal(const Fast_soup::Point& p, const float (&c)[3])
  {
    return p.x() == double(c[0]) && p.y() == double(c[1]) && p.z() == double(c[2]);
  }

  void grow(const Fast_soup& soup)
  {
    std::vector<std::uint32_t> slots(2 * m_slots.size(), 0);
    const std::size_t mask = slots.size() - 1;
    for(std::uint32_t index = 0; index < soup.points.size(); ++index)
    {
      const Fast_soup::Point& p = soup.points[index];
      const float c[3] = {float(p.x()), float(p.y()), float(p.z())};
      std::size_t s = hash(c) & mask;
      while(slots[s] != 0)
        s = (s + 1) & mask;
      slots[s] = index + 1;
    }
    m_slots.swap(slots);
  }

  std::uint32_t index_of(const float (&c)[3], Fast_soup& soup)
  {
    if(2 * (m_used + 1) > m_slots.size())
      grow(soup);
    const std::size_t mask = m_slots.size() - 1;
    for(std::size_t s = hash(c) & mask;; s = (s + 1) & mask)
    {
      if(m_slots[s] == 0)
      {
        soup.points.emplace_back(double(c[0]), double(c[1]), double(c[2]));
        m_slots[s] = std::uint32_t(soup.points.size());
        ++m_used;
        return m_slots[s] - 1;
      }
      if(equal(soup.points[m_slots[s] - 1], c))
        return m_slots[s] - 1;
    }
  }

public:
  bool read(const char* begin, const char* end, Fast_soup& soup)
  {
    const char* word = begin;
    while(word != end && is_space(*word))
      ++word;
    if(end - word < 6 || (std::memcmp(word, "solid", 5) == 0 && (word[5] == ' ' || word[5] == '\n' || word[5] == '\r')))
      return false;
    if(end - begin < 84)
      return false;
    std::uint32_t triangles;
    std::memcpy(&triangles, begin + 80, 4); // little-endian, as CGAL reads it on this platform
    if(triangles == 0 || std::uint64_t(end - begin - 84) / 50 < triangles)
      return false;
    std::size_t capacity = 1024;
    while(capacity < triangles)
      capacity *= 2;
    m_slots.assign(capacity, 0);
    soup.points.reserve(triangles / 2 + 3);
    soup.corners.reserve(3 * std::size_t(triangles));
    const char* p = begin + 84;
    for(std::uint32_t t = 0; t < triangles; ++t, p += 50)
    {
      std::uint32_t face[3];
      for(int k = 0; k < 3; ++k)
      {
        float c[3];
        std::memcpy(c, p + 12 * (k + 1), 12);
        if(!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2]))
          return false;
        face[k] = index_of(c, soup);
      }
      soup.add_face(face, 3);
    }
    return true;
  }
};

inline bool read_fast_stl(const char* begin, const char* end, Fast_soup& soup)
{
  return Fast_stl_reader().read(begin, end, soup);
}

} // namespace internal
} // namespace dggvtp

#endif // DGGVTP_FAST_STL_H
