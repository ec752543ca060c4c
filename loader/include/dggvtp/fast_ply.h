// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

#ifndef DGGVTP_FAST_PLY_H
#define DGGVTP_FAST_PLY_H

#include <dggvtp/fast_soup.h>
#include <dggvtp/text_numbers.h>

#include <array>
#include <cstdint>
#include <cmath>
#include <cstring>
#include <limits>
#include <string_view>
#include <utility>

namespace dggvtp {
namespace internal {

// The common PLY layout in one pass: in ASCII, binary little- or big-endian,
//   element vertex V  with  property float|double x, y, z  (each either type, in this order)
//   element face F    with  property list uchar int|uint vertex_indices (or vertex_index)
// and comment and obj_info lines; V, F >= 1. Anything else (other elements or properties, other
// types, a value that does not read, a face of fewer than 3 vertices, an index out of range, a
// file that ends early) returns false, and the file goes to CGAL's guarded reader. What this
// accepts, CGAL's read_PLY reads into the same points (floats widened to double) and faces.
class Fast_ply_reader
{
  using Tokens = std::array<std::string_view, 6>;

  // the words of a header line (at most 6; a 7th makes the line unknown)
  static std::size_t split(std::string_view line, Tokens& tokens)
  {
    std::size_t n = 0, i = 0;
    while(i < line.size())
    {
      while(i < line.size() && is_space(line[i]))
        ++i;
      const std::size_t first = i;
      while(i < line.size() && !is_space(line[i]))
        ++i;
      if(i == first)
        break;
      if(n == tokens.size())
        return n + 1;
      tokens[n++] = line.substr(first, i - first);
    }
    return n;
  }

  static int real_size(std::string_view type)
  {
    if(type == "float" || type == "float32") return 4;
    if(type == "double" || type == "float64") return 8;
    return 0;
  }

  static bool count(std::string_view text, std::uint64_t max, std::uint64_t& value)
  {
    const char* const last = text.data() + text.size();
    return read_index(text.data(), last, max, value) == last && value >= 1;
  }

  template <class T>
  static T load(const char* p, bool big_endian)
  {
    unsigned char b[sizeof(T)];
    std::memcpy(b, p, sizeof(T));
    if(big_endian)
      for(std::size_t i = 0; i < sizeof(T) / 2; ++i)
        std::swap(b[i], b[sizeof(T) - 1 - i]);
    T value;
    std::memcpy(&value, b, sizeof(T));
    return value;
  }

public:
  static bool read(const char* begin, const char* end, Fast_soup& soup)
  {
    const char* p = begin;
    std::string_view line;
    Tokens t;
    if(!next_line(p, end, line) || split(line, t) != 1 || t[0] != "ply")
      return false;
    if(!next_line(p, end, line) || split(line, t) != 3 || t[0] != "format" || t[2] != "1.0")
      return false;
    const bool ascii = t[1] == "ascii", big_endian = t[1] == "binary_big_endian";
    if(!ascii && !big_endian && t[1] != "binary_little_endian")
      return false;

    // header: the vertex element, its 3 coordinates, the face element, its list, end_header
    int stage = 0;
    std::uint64_t vertices = 0, faces = 0;
    std::array<int, 3> coordinate_size{};
    for(;;)
    {
      if(!next_line(p, end, line))
        return false;
      const std::size_t n = split(line, t);
      if(n >= 1 && (t[0] == "comment" || t[0] == "obj_info"))
        continue;
      if(n == 1 && t[0] == "end_header" && stage == 6)
        break;
      if(n == 3 && t[0] == "element" && stage == 0 && t[1] == "vertex" &&
         count(t[2], std::numeric_limits<std::uint32_t>::max() - 1, vertices))
        stage = 1;
      else if(n == 3 && t[0] == "property" && stage >= 1 && stage <= 3 &&
              t[2] == std::string_view("xyz" + (stage - 1), 1) && real_size(t[1]) != 0)
      {
        coordinate_size[std::size_t(stage - 1)] = real_size(t[1]);
        ++stage;
      }
      else if(n == 3 && t[0] == "element" && stage == 4 && t[1] == "face" &&
              count(t[2], std::numeric_limits<std::uint32_t>::max(), faces))
        stage = 5;
      // int or uint: both read as 32 bits, and an index at or beyond `vertices` (a negative int too)
      // is refused either way
      else if(n == 5 && t[0] == "property" && stage == 5 && t[1] == "list" && (t[2] == "uchar" || t[2] == "uint8") &&
              (t[3] == "int" || t[3] == "int32" || t[3] == "uint" || t[3] == "uint32") &&
              (t[4] == "vertex_indices" || t[4] == "vertex_index"))
        stage = 6;
      else
        return false;
    }

    // the counts must fit in the bytes left (at least "0 0 0" a vertex and "3 0 1 2" a face in
    // ASCII, 12 and 13 bytes in binary) before anything is allocated for them
    if((ascii ? 5 * vertices + 7 * faces : 12 * vertices + 13 * faces) > std::uint64_t(end - p))
      return false;
    soup.points.reserve(std::size_t(vertices));
    soup.corners.reserve(3 * std::size_t(faces));
    return ascii ? read_ascii(p, end, vertices, faces, coordinate_size, soup)
                 : read_binary(p, end, big_endian, vertices, faces, coordinate_size, soup);
  }

private:
  static bool read_binary(const char* p, const char* end, bool big_endian, std::uint64_t vertices,
                          std::uint64_t faces, const std::array<int, 3>& size, Fast_soup& soup)
  {
    const std::size_t record = std::size_t(size[0] + size[1] + size[2]);
    if(std::uint64_t(end - p) / record < vertices)
      return false;
    for(std::uint64_t v = 0; v < vertices; ++v)
    {
      double c[3];
      for(int k = 0; k < 3; ++k)
      {
        c[k] = size[k] == 4 ? double(load<float>(p, big_endian)) : load<double>(p, big_endian);
        if(!std::isfinite(c[k]))
          return false;
        p += size[k];
      }
      soup.points.emplace_back(c[0], c[1], c[2]);
    }
    std::array<std::uint32_t, 255> face;
    for(std::uint64_t f = 0; f < faces; ++f)
    {
      if(p == end)
        return false;
      const std::size_t n = static_cast<unsigned char>(*p++);
      if(n < 3 || std::size_t(end - p) < 4 * n)
        return false;
      for(std::size_t k = 0; k < n; ++k, p += 4)
      {
        face[k] = load<std::uint32_t>(p, big_endian);
        if(face[k] >= vertices) // a negative int is beyond too
          return false;
      }
      soup.add_face(face.data(), n);
    }
    return true;
  }

  // the values are separated by white space of any kind, as `>>` reads them
  static bool read_ascii(const char* p, const char* end, std::uint64_t vertices, std::uint64_t faces,
                         const std::array<int, 3>& size, Fast_soup& soup)
  {
    const auto value_end = [end](const char* q) { return q != nullptr && (q == end || is_space(*q)); };
    const auto skip = [&p, end] {
      while(p != end && is_space(*p))
        ++p;
    };
    for(std::uint64_t v = 0; v < vertices; ++v)
    {
      double c[3];
      for(int k = 0; k < 3; ++k)
      {
        skip();
        const char* q;
        if(size[k] == 4)
        {
          float x;
          q = read_real(p, end, x);
          c[k] = x;
        }
        else
          q = read_real(p, end, c[k]);
        if(!value_end(q))
          return false;
        p = q;
      }
      soup.points.emplace_back(c[0], c[1], c[2]);
    }
    std::array<std::uint32_t, 255> face;
    for(std::uint64_t f = 0; f < faces; ++f)
    {
      skip();
      std::uint64_t n, index;
      const char* q = read_index(p, end, 255, n);
      if(!value_end(q) || n < 3)
        return false;
      p = q;
      for(std::size_t k = 0; k < n; ++k)
      {
        skip();
        q = read_index(p, end, vertices - 1, index);
        if(!value_end(q))
          return false;
        p = q;
        face[k] = std::uint32_t(index);
      }
      soup.add_face(face.data(), std::size_t(n));
    }
    return true;
  }
};

inline bool read_fast_ply(const char* begin, const char* end, Fast_soup& soup)
{
  return Fast_ply_reader::read(begin, end, soup);
}

} // namespace internal
} // namespace dggvtp

#endif // DGGVTP_FAST_PLY_H
