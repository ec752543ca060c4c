// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// The checks an OFF file passes before CGAL's reader reads it (see check_off_declarations()).

#ifndef DGGVTP_CHECK_OFF_H
#define DGGVTP_CHECK_OFF_H

#include <dggvtp/input_error.h>

#include <CGAL/IO/io.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace dggvtp {

// CGAL's OFF reader allocates what the header declares (vertices, faces) and what each face line
// declares (its number of vertices) before reading them, and converts indices from double to
// size_t unchecked: a file of a few bytes could claim gigabytes, or a negative index. Such files
// are refused here, before CGAL reads them: declared counts must fit in the file's bytes, and a
// face line must list as many vertex indices as it declares, each in [0, vertices). In binary
// OFF, the face sizes are walked too.
//
// Of the header's variants ([ST][C][N][4][n]OFF, as CGAL 5.5 parses the keyword), those CGAL
// cannot read safely or correctly are refused outright:
// - ST (texture coordinates): in text, File_scanner_OFF::scan_texture indexes the line's numbers
//   with members that only a C in the keyword initialises (without it: an uninitialised index, a
//   read anywhere in memory; found by the fuzzer), and with C it does not check the bounds;
// - C in binary OFF: CGAL does not read the colours there, it reads them as the next vertices;
// - n with a dimension other than 3: CGAL reads 3 coordinates a vertex whatever it says;
// - SKEL (a skeleton, lines and points, not a surface), which none of these checks cover.
// Plain, C (text), N and 4 variants are kept: CGAL bounds-checks normals and homogeneous
// coordinates, and colours are checked below.
inline void check_off_declarations(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  in.seekg(0, std::ios::end);
  const std::streamoff end = in.tellg();
  if(!in || end < 0)
    return; // CGAL's reader reports it
  const long long bytes = static_cast<long long>(end);
  in.seekg(0);
  const auto skip_comments = [&in] {
    for(;;)
    {
      in >> std::ws;
      if(in.peek() != '#')
        return;
      in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
    }
  };
  const auto read_word = [&in] {
    std::string word;
    while(std::isalnum(in.peek()))
      word += char(in.get());
    return word;
  };
  const auto too_large = [&](long long vertices, long long faces) {
    return Input_error("'" + path + "' declares " + std::to_string(vertices) + " vertices and " +
                       std::to_string(faces) + " faces, more than its " + std::to_string(bytes) +
                       " bytes can hold");
  };
  // CGAL's header reader estimates the number of halfedges in int arithmetic, as 2 * edges, or
  // as 2.1 * (vertices + faces + 10) converted to int: it overflows (fuzzer: signed overflow)
  // beyond these counts
  const auto check_countable = [&](long long vertices, long long faces, long long edges) {
    if(edges > std::numeric_limits<int>::max() / 2 || edges < std::numeric_limits<int>::min() / 2 ||
       vertices + faces > 1000000000)
      throw Input_error("'" + path + "' declares " + std::to_string(vertices) + " vertices, " +
                        std::to_string(faces) + " faces and " + std::to_string(edges) +
                        " edges, more than CGAL's OFF reader can count");
  };
  // A missing record (the file ends early) or a face line without numbers: CGAL reads on, in text
  // to the colour of the record before, out of the bounds of this one's numbers (fuzzer: heap
  // overflow in File_scanner_OFF::scan_color on a truncated CNOFF), in binary an uninitialised face
  // size, which it allocates; refused here for every variant.
  const auto truncated = [&](const std::string& record, long long index, long long count) {
    return Input_error("'" + path + "' is truncated or damaged: " + record + " " + std::to_string(index) + " of " +
                       std::to_string(count) + " is missing");
  };

  skip_comments();
  const std::string keyword = read_word();
  in.get(); // CGAL's reader takes the character that ends the keyword, whatever it is
  // the keyword's prefixes, in CGAL's order
  std::size_t j = 0;
  const auto prefix = [&](const char* letters) {
    const std::size_t n = std::strlen(letters);
    if(keyword.compare(j, n, letters) != 0)
      return false;
    j += n;
    return true;
  };
  const bool textures = prefix("ST");
  const bool colours = prefix("C");
  const bool normals = prefix("N");
  const int homogeneous = prefix("4") ? 1 : 0;
  const bool dimensional = prefix("n");
  const std::string format = keyword.substr(j);
  if(format == "SKEL")
    throw Input_error("'" + path + "' is a skeleton (" + keyword + " header), not a surface mesh");
  if(format != "OFF")
    return; // not a header CGAL reads as OFF: it says so
  if(textures)
    throw Input_error("'" + path + "' has texture coordinates (" + keyword +
                      " header), which CGAL's OFF reader cannot read safely: remove them and the ST");
  skip_comments();
  const bool binary = std::isalpha(in.peek()) != 0;
  if(binary && read_word() != "BINARY")
    return;
  if(binary && colours)
    throw Input_error("'" + path + "' is a binary OFF file with colours (" + keyword +
                      " BINARY), which CGAL's OFF reader reads as coordinates");
  const auto check_dimension = [&](long long dimension) {
    if(dimensional && dimension != 3)
      throw Input_error("'" + path + "' declares " + std::to_string(dimension) +
                        " dimensions (" + keyword + " header); only 3 are read");
  };
  if(binary)
  {
    if(in.get() != '\n')
      in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
    const auto int32 = [&in] {
      unsigned char b[4] = {0, 0, 0, 0};
      in.read(reinterpret_cast<char*>(b), 4);
      return static_cast<std::int32_t>((std::uint32_t(b[0]) << 24) | (std::uint32_t(b[1]) << 16) |
                                       (std::uint32_t(b[2]) << 8) | std::uint32_t(b[3]));
    };
    if(dimensional)
    {
      const long long dimension = int32();
      if(!in)
        return;
      check_dimension(dimension);
    }
    const long long vertices = int32(), faces = int32(), edges = int32();
    if(!in)
      return;
    if(vertices < 0 || faces < 0 || 12 * vertices + 4 * faces > bytes)
      throw too_large(vertices, faces);
    check_countable(vertices, faces, edges);
    // faces as CGAL reads them: a size, then that many indices, after the vertices: 3 or 4 floats,
    // twice that with normals (no colours: refused above)
    const long long vertex_bytes = 4 * (3 + homogeneous) * (normals ? 2 : 1);
    if(!in.seekg(static_cast<std::streamoff>(vertices * vertex_bytes), std::ios::cur))
      return;
    for(long long f = 0; f < faces; ++f)
    {
      const long long size = int32();
      if(!in)
        throw truncated("face", f, faces);
      if(size < 0 || 4 * size > bytes)
        throw Input_error("face " + std::to_string(f) + " of '" + path + "' declares " + std::to_string(size) +
                          " vertices, more than its " + std::to_string(bytes) + " bytes can hold");
      if(!in.seekg(static_cast<std::streamoff>(4 * size), std::ios::cur))
        return;
    }
    return;
  }

  long long vertices = -1, faces = -1, edges = 0;
  if(dimensional)
  {
    long long dimension = 0;
    if(!(in >> dimension))
      return;
    check_dimension(dimension);
  }
  in >> vertices >> faces >> edges;
  if(!in)
    return;
  // a vertex line takes at least 5 bytes ("0 0 0"), a face line at least 1
  if(vertices < 0 || faces < 0 || vertices > bytes || faces > bytes || 5 * vertices + faces > bytes)
    throw too_large(vertices, faces);
  check_countable(vertices, faces, edges);

  // the body as CGAL reads it: one line a record, after blank and comment lines
  std::string line;
  std::vector<double> entries;
  const auto read_entries = [&]() {
    skip_comments();
    if(!std::getline(in, line))
      return false;
    std::istringstream numbers(line.substr(0, line.find('#')));
    entries.clear();
    double entry;
    while(numbers >> CGAL::IO::iformat(entry)) // as CGAL parses them
      entries.push_back(entry);
    return true;
  };
  // With a C in the keyword, CGAL takes what follows the coordinates (and normals) or the
  // indices as a colour: 1 entry, an index into a table of 149 colours, or 3 (or 4) components,
  // converted to unsigned char. Other counts make it read past the line's numbers, other values
  // past the table or outside unsigned char: refused, with every record alike since CGAL decides
  // from the first one that has colours.
  long long colour_entries_seen = -1;
  const auto check_colour = [&](long long first, const std::string& what) {
    if(!colours)
      return;
    const long long n = static_cast<long long>(entries.size()) - first;
    bool valid = (n == 0 || n == 1 || n == 3 || n == 4) && (colour_entries_seen < 0 || n == colour_entries_seen);
    if(valid && n == 1)
      valid = entries[first] >= 0. && entries[first] < 149.;
    if(valid && n >= 3)
    {
      bool integers = true;
      for(long long k = first; k < first + 3; ++k)
        integers = integers && entries[k] == std::floor(entries[k]);
      for(long long k = first; k < first + 3; ++k)
        valid = valid && entries[k] >= 0. && entries[k] <= (integers ? 255. : 1.);
    }
    if(!valid)
      throw Input_error(what + " of '" + path + "' has a colour CGAL cannot read (its reader would go astray)");
    colour_entries_seen = n;
  };
  for(long long v = 0; v < vertices; ++v)
  {
    if(!read_entries())
      throw truncated("vertex", v, vertices);
    if(colours)
      check_colour((3 + homogeneous) * (normals ? 2 : 1), "vertex " + std::to_string(v));
  }
  colour_entries_seen = -1;
  for(long long f = 0; f < faces; ++f)
  {
    if(!read_entries() || entries.empty())
      throw truncated("face", f, faces);
    const double size = entries[0];
    if(!(size >= 0.) || size != std::floor(size) || size > double(entries.size() - 1))
    {
      std::ostringstream what;
      what << "face " << f << " of '" << path << "' does not list the " << size << " vertex indices it declares";
      throw Input_error(what.str());
    }
    for(std::size_t k = 1; k <= std::size_t(size); ++k)
      if(!(entries[k] >= 0.) || !(entries[k] < double(vertices)) || entries[k] != std::floor(entries[k]))
      {
        std::ostringstream index;
        index << entries[k];
        throw Input_error("face " + std::to_string(f) + " refers to vertex " + index.str() + ", but the file has " +
                          std::to_string(vertices) + " vertices");
      }
    check_colour(static_cast<long long>(size) + 1, "face " + std::to_string(f));
  }
}

} // namespace dggvtp

#endif // DGGVTP_CHECK_OFF_H
