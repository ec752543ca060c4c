// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

#ifndef DGGVTP_LOAD_MESH_H
#define DGGVTP_LOAD_MESH_H

#include <dggvtp/fast_read.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/io.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace dggvtp {

// Bad input: the message goes to the user as `error: <message>`, exit status 2.
struct Input_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// A mesh file as a polygon soup in the file's vertex order, made into a valid polygon mesh
// without renumbering the file's vertices: repairs only append points.
struct Loaded_soup
{
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  std::vector<Point> points;                     // the file's points, then the duplicates made by repairs
  // the faces when all are triangles, each with its corners in the order of the face of a
  // Surface_mesh made from the file (its halfedge(f) starts at the third vertex), so that the
  // propagation, and the distances to the last bit, do not depend on the path through loading;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::vector<std::size_t>> polygons; // or else the polygons
  std::size_t file_vertices = 0;                 // points declared by the file
  std::vector<std::size_t> file_vertex_of;       // per point: the file vertex it stands for
  std::vector<std::string> repairs;              // what loading changed, for a warning
};

namespace internal {

// orient_polygon_soup copies its visitor, so the copy reports into the soup it points to
struct Repair_visitor : CGAL::Polygon_mesh_processing::Default_orientation_visitor
{
  std::size_t* duplicated;
  std::size_t* reversed;
  std::vector<std::size_t>* file_vertex_of;
  void duplicated_vertex(std::size_t original, std::size_t copy)
  {
    ++*duplicated;
    if(file_vertex_of->size() <= copy)
      file_vertex_of->resize(copy + 1);
    (*file_vertex_of)[copy] = (*file_vertex_of)[original];
  }
  void polygon_orientation_reversed(std::size_t) { ++*reversed; }
};

} // namespace internal

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

// The scalar types of PLY, each under its two names
enum class Ply_type { unknown, int8, uint8, int16, uint16, int32, uint32, float32, float64 };

inline Ply_type ply_type(const std::string& name)
{
  if(name == "char" || name == "int8") return Ply_type::int8;
  if(name == "uchar" || name == "uint8") return Ply_type::uint8;
  if(name == "short" || name == "int16") return Ply_type::int16;
  if(name == "ushort" || name == "uint16") return Ply_type::uint16;
  if(name == "int" || name == "int32") return Ply_type::int32;
  if(name == "uint" || name == "uint32") return Ply_type::uint32;
  if(name == "float" || name == "float32") return Ply_type::float32;
  if(name == "double" || name == "float64") return Ply_type::float64;
  return Ply_type::unknown;
}

// bytes of a value in the binary formats; 0 for an unknown type
inline int ply_type_size(Ply_type type)
{
  switch(type)
  {
    case Ply_type::int8: case Ply_type::uint8: return 1;
    case Ply_type::int16: case Ply_type::uint16: return 2;
    case Ply_type::int32: case Ply_type::uint32: case Ply_type::float32: return 4;
    case Ply_type::float64: return 8;
    default: return 0;
  }
}

inline bool is_ply_signed_integer(Ply_type type)
{
  return type == Ply_type::int8 || type == Ply_type::int16 || type == Ply_type::int32;
}

inline bool is_ply_integer(Ply_type type)
{
  return ply_type_size(type) > 0 && type != Ply_type::float32 && type != Ply_type::float64;
}

// Reads one ASCII value of a PLY type the way CGAL's reader extracts it (chars as numbers, then
// narrowed; floats through CGAL's iformat), so that the walk below and CGAL's reader stop at the
// same place: where a number does not read, CGAL goes on with an uninitialised list size.
template <class T, class Read_as = T>
bool read_ply_ascii_as(std::istream& in, double& value)
{
  Read_as v;
  if(!(in >> v))
    return false;
  value = double(static_cast<T>(v));
  return true;
}

template <class T>
bool read_ply_ascii_float(std::istream& in, double& value)
{
  T v;
  if(!(in >> CGAL::IO::iformat(v)))
    return false;
  value = double(v);
  return true;
}

inline bool read_ply_ascii_value(std::istream& in, Ply_type type, double& value)
{
  switch(type)
  {
    case Ply_type::int8: return read_ply_ascii_as<signed char, short>(in, value);
    case Ply_type::uint8: return read_ply_ascii_as<unsigned char, unsigned short>(in, value);
    case Ply_type::int16: return read_ply_ascii_as<short>(in, value);
    case Ply_type::uint16: return read_ply_ascii_as<unsigned short>(in, value);
    case Ply_type::int32: return read_ply_ascii_as<std::int32_t>(in, value);
    case Ply_type::uint32: return read_ply_ascii_as<std::uint32_t>(in, value);
    case Ply_type::float32: return read_ply_ascii_float<float>(in, value);
    default: return read_ply_ascii_float<double>(in, value);
  }
}

// CGAL's PLY reader allocates each list (a face's vertex indices) at the size it declares before
// reading it, and iterates over each element as many times as the header says, even an element
// without properties: a file of a few bytes could claim gigabytes, a negative size, or keep the
// reader busy for ever; a property declared before any element makes it write through `back()`
// of an empty vector, and a vertex coordinate that is not float or double makes it call through a
// null pointer (segmentation faults, both). Refused here first: properties must follow an
// element, coordinates must be float or double, an element's count and a list's size must fit in
// the file's bytes (lists are walked in the text and binary formats alike), and every type must be
// one of PLY's.
inline void check_ply_declarations(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  in.seekg(0, std::ios::end);
  const std::streamoff end = in.tellg();
  if(!in || end < 0)
    return;
  const long long bytes = static_cast<long long>(end);
  in.seekg(0);

  struct Property
  {
    std::string name;
    std::string type;   // as written; "list" for a list
    Ply_type item = Ply_type::unknown;  // the value's type (each entry's, for a list)
    Ply_type count = Ply_type::unknown; // a list's size type
    bool list = false;
    int size() const { return ply_type_size(item); }
    int count_size() const { return ply_type_size(count); }
  };
  struct Element
  {
    std::string name;
    long long count = 0;
    std::vector<Property> properties;
  };

  // the header as CGAL reads it: "ply" as the first word of line 1, the format as the second word
  // of line 2 (whatever the first), then a keyword a line; without an end_header line CGAL goes
  // on reading the elements from the end of the file, where a list size is an uninitialised
  // value it allocates (fuzzer: std::length_error)
  std::string line, word, format;
  std::vector<Element> elements;
  if(!std::getline(in, line) || !(std::istringstream(line) >> word) || word != "ply")
    return;
  if(!std::getline(in, line) || !(std::istringstream(line) >> word >> format >> word))
    return;
  for(;;)
  {
    if(!std::getline(in, line))
      throw Input_error("'" + path + "': the PLY header does not end (no end_header line)");
    std::istringstream words(line);
    if(!(words >> word))
      return; // CGAL's reader stops at an empty header line
    if(word == "end_header")
      break;
    if(word == "element")
    {
      // read as CGAL reads it, into a std::size_t: a count beyond long long (fuzzer: an element
      // without properties, iterated for ever) or written negative (wrapped around) is refused
      Element e;
      std::size_t count;
      if(!(words >> e.name >> count))
        return;
      if(count > static_cast<unsigned long long>(bytes))
        throw Input_error("'" + path + "' declares " + std::to_string(count) + " elements '" + e.name +
                          "', more than its " + std::to_string(bytes) + " bytes can hold");
      e.count = static_cast<long long>(count);
      elements.push_back(e);
    }
    else if(word == "property")
    {
      if(elements.empty()) // CGAL's reader would add it to the last of no elements
        throw Input_error("'" + path + "': the PLY header has a property before any element");
      Property p;
      words >> p.type;
      p.list = p.type == "list";
      std::string count_type, item_type = p.type;
      if(p.list)
        words >> count_type >> item_type;
      words >> p.name;
      p.item = ply_type(item_type);
      if(p.list)
      {
        p.count = ply_type(count_type);
        if(!is_ply_integer(p.count))
          throw Input_error("'" + path + "': the PLY list '" + p.name + "' has a size type that is not an integer type");
      }
      if(p.item == Ply_type::unknown) // CGAL's reader may go on with a null reader for it (fuzzer)
        throw Input_error("'" + path + "': the PLY property '" + p.name + "' has an unknown type");
      elements.back().properties.push_back(p);
    }
  }

  // CGAL reads a point's x, y and z (the first property of each name) as float or double, and
  // dereferences a null pointer when they are something else
  for(const Element& e : elements)
    if(e.name == "vertex" || e.name == "vertices")
      for(const char* coordinate : {"x", "y", "z"})
        for(const Property& p : e.properties)
          if(p.name == coordinate)
          {
            if(p.list || (p.item != Ply_type::float32 && p.item != Ply_type::float64))
              throw Input_error("'" + path + "': the vertex coordinate " + coordinate + " is of type " + p.type +
                                "; only float and double coordinates are read");
            break;
          }

  const bool ascii = format == "ascii";
  const bool big_endian = format == "binary_big_endian";
  if(!ascii && !big_endian && format != "binary_little_endian")
    return;
  const auto list_too_large = [&](const Element& e, long long record, double size) {
    std::ostringstream what;
    what << "'" << path << "': element " << record << " of '" << e.name << "' declares a list of " << size
         << " entries, " << (size < 0. ? std::string("a negative size")
                                       : "more than the file's " + std::to_string(bytes) + " bytes can hold");
    return Input_error(what.str());
  };
  // Where the data ends early (or a number does not read), CGAL's reader may take an uninitialised
  // list size (it reads into an uninitialised variable once the stream has failed) and allocate
  // it: refused, although it only matters before a list.
  const auto truncated = [&](const Element& e) {
    return Input_error("'" + path + "' is truncated or damaged: the elements '" + e.name + "' do not read");
  };
  for(const Element& e : elements)
  {
    bool has_list = false;
    long long record_size = 0;
    for(const Property& p : e.properties)
    {
      has_list = has_list || p.list;
      record_size += p.size();
    }
    if(!has_list)
    {
      if(ascii)
      {
        double value;
        for(long long r = 0; r < e.count; ++r)
          for(const Property& p : e.properties)
            if(!read_ply_ascii_value(in, p.item, value))
              throw truncated(e);
      }
      else if(!in.seekg(static_cast<std::streamoff>(e.count * record_size), std::ios::cur))
        throw truncated(e);
      continue;
    }
    for(long long r = 0; r < e.count; ++r)
      for(const Property& p : e.properties)
      {
        double value;
        if(!p.list)
        {
          if(ascii ? !read_ply_ascii_value(in, p.item, value) : !in.seekg(p.size(), std::ios::cur))
            throw truncated(e);
          continue;
        }
        long long size = 0;
        if(ascii)
        {
          if(!read_ply_ascii_value(in, p.count, value))
            throw truncated(e);
          if(!(value >= 0.) || value > double(bytes))
            throw list_too_large(e, r, value);
          size = static_cast<long long>(value);
          for(long long k = 0; k < size; ++k)
            if(!read_ply_ascii_value(in, p.item, value))
              throw truncated(e);
        }
        else
        {
          unsigned char b[8] = {0, 0, 0, 0, 0, 0, 0, 0};
          const int count_size = p.count_size();
          if(!in.read(reinterpret_cast<char*>(b), count_size))
            throw truncated(e);
          std::uint64_t u = 0;
          for(int k = 0; k < count_size; ++k)
            u |= std::uint64_t(b[big_endian ? count_size - 1 - k : k]) << (8 * k);
          if(is_ply_signed_integer(p.count) && (u >> (8 * count_size - 1)) != 0)
            throw list_too_large(e, r, double(static_cast<long long>(u) - (1LL << (8 * count_size))));
          if(u > std::uint64_t(bytes))
            throw list_too_large(e, r, double(u));
          size = static_cast<long long>(u);
          if(!in.seekg(static_cast<std::streamoff>(size * p.size()), std::ios::cur))
            throw truncated(e);
        }
      }
  }
}

template <class Polygon>
std::array<std::uint32_t, 3> as_surface_mesh_face(const Polygon& p)
{
  return {std::uint32_t(p[2]), std::uint32_t(p[0]), std::uint32_t(p[1])};
}

namespace internal {

// a file that does not open gets the same error whichever reader would have read it
inline void check_readable(const std::string& path)
{
  errno = 0;
  std::ifstream probe(path);
  if(!probe.good())
    throw Input_error("cannot read '" + path + "': " + (errno != 0 ? std::strerror(errno) : "cannot open it"));
}

// the format as CGAL's read_polygon_soup chooses it
inline std::string lower_case_extension(const std::string& path)
{
  std::string extension = path.substr(path.rfind('.') == std::string::npos ? path.size() : path.rfind('.') + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return extension;
}

// Every point is the file's own so far: the file's vertices, numbered as in the file (repairs
// append copies later).
inline void number_file_vertices(Loaded_soup& soup)
{
  soup.file_vertices = soup.points.size();
  soup.file_vertex_of.resize(soup.points.size());
  std::iota(soup.file_vertex_of.begin(), soup.file_vertex_of.end(), std::size_t(0));
}

// A fast reader's soup as load_soup_with_cgal() makes it of the same file, or nothing where one
// of its checks fails (a face repeating a vertex, too many points for 32-bit indices): that path
// then refuses the file, or takes it, as before. The fast readers already refuse what else it
// checks (no vertices, a coordinate not finite, a face of fewer than 3 vertices, an index beyond
// the vertices).
inline std::optional<Loaded_soup> soup_of(Fast_soup& fast)
{
  if(fast.points.size() >= std::numeric_limits<std::uint32_t>::max())
    return std::nullopt;
  Loaded_soup soup;
  if(fast.all_triangles())
  {
    soup.triangles.reserve(fast.faces);
    for(std::size_t c = 0; c < fast.corners.size(); c += 3)
    {
      const std::uint32_t* t = &fast.corners[c];
      if(t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
        return std::nullopt;
      soup.triangles.push_back(as_surface_mesh_face(t));
    }
  }
  else
  {
    soup.polygons.reserve(fast.faces);
    std::size_t first = 0;
    for(const std::size_t last : fast.face_ends)
    {
      for(std::size_t k = first; k < last; ++k)
        for(std::size_t j = first; j < k; ++j)
          if(fast.corners[j] == fast.corners[k])
            return std::nullopt;
      soup.polygons.emplace_back(fast.corners.begin() + first, fast.corners.begin() + last);
      first = last;
    }
  }
  std::vector<std::uint32_t>().swap(fast.corners);
  soup.points.swap(fast.points);
  number_file_vertices(soup);
  return soup;
}

} // namespace internal

// The file through CGAL's reader, behind the checks above that keep it from hazardous input: the
// path of every file the fast readers do not take. Throws Input_error for input it refuses.
inline Loaded_soup load_soup_with_cgal(const std::string& path)
{
  Loaded_soup soup;
  internal::check_readable(path);
  {
    const std::string extension = internal::lower_case_extension(path);
    if(extension == "off")
      check_off_declarations(path);
    else if(extension == "ply")
      check_ply_declarations(path);
  }
  if(!CGAL::IO::read_polygon_soup(path, soup.points, soup.polygons, CGAL::parameters::verbose(false)))
    throw Input_error("cannot read '" + path + "' as a mesh (unsupported format, or an invalid or truncated file)");
  if(soup.points.empty())
    throw Input_error("'" + path + "' has no vertices");
  for(std::size_t i = 0; i < soup.points.size(); ++i)
    for(int c = 0; c < 3; ++c)
      if(!std::isfinite(soup.points[i][c]))
        throw Input_error("vertex " + std::to_string(i) + " has a coordinate that is not finite");
  for(std::size_t f = 0; f < soup.polygons.size(); ++f)
  {
    const auto& polygon = soup.polygons[f];
    if(polygon.size() < 3)
      throw Input_error("face " + std::to_string(f) + " has fewer than 3 vertices");
    for(std::size_t k = 0; k < polygon.size(); ++k)
    {
      if(polygon[k] >= soup.points.size())
        throw Input_error("face " + std::to_string(f) + " refers to vertex " + std::to_string(polygon[k]) +
                          ", but the file has " + std::to_string(soup.points.size()) + " vertices");
      for(std::size_t j = 0; j < k; ++j)
        if(polygon[j] == polygon[k])
          throw Input_error("face " + std::to_string(f) + " uses vertex " + std::to_string(polygon[k]) + " twice");
    }
  }

  internal::number_file_vertices(soup);
  if(soup.points.size() < std::numeric_limits<std::uint32_t>::max() &&
     std::all_of(soup.polygons.begin(), soup.polygons.end(), [](const auto& p) { return p.size() == 3; }))
  {
    soup.triangles.reserve(soup.polygons.size());
    for(const auto& p : soup.polygons)
      soup.triangles.push_back(as_surface_mesh_face(p));
    std::vector<std::vector<std::size_t>>().swap(soup.polygons);
  }
  return soup;
}

// The mesh file `path` as a soup. The common layouts of each format (internal::read_fast) are
// read in one pass of the file; any other file, and any file that input policy refuses, goes
// through load_soup_with_cgal(), which gives the same soup for what both read. Throws Input_error
// for input it refuses.
inline Loaded_soup load_soup(const std::string& path)
{
  internal::check_readable(path);
  if(std::optional<internal::Fast_soup> fast = internal::read_fast(path, internal::lower_case_extension(path)))
    if(std::optional<Loaded_soup> soup = internal::soup_of(*fast))
      return std::move(*soup);
  return load_soup_with_cgal(path);
}

// what the repairs work on, when the triangles do not go to the solver as they are
inline void triangles_to_polygons(Loaded_soup& soup)
{
  soup.polygons.reserve(soup.triangles.size());
  for(const auto& t : soup.triangles)
    soup.polygons.push_back({t[1], t[2], t[0]});
  std::vector<std::array<std::uint32_t, 3>>().swap(soup.triangles);
}

// A solver of the soup's triangles (a Triangle_soup_geodesic_distance_solver). Throws
// std::invalid_argument as the solver does.
template <class Solver>
Solver make_soup_solver(const Loaded_soup& soup)
{
  using Point = typename Solver::Traits::Point_3;
  using FT = typename Solver::Traits::FT;
  if constexpr(std::is_same<Point, Loaded_soup::Point>::value)
    return Solver(soup.points, soup.triangles);
  else
  {
    // Converted into an array first, not by a point map: GCC 12.2's vectorizer (-O2) drops the
    // rounding to float of a point made and read in the same loop, so float input would be read
    // in double.
    std::vector<Point> points;
    points.reserve(soup.points.size());
    for(const auto& p : soup.points)
      points.emplace_back(FT(p.x()), FT(p.y()), FT(p.z()));
    return Solver(points, soup.triangles);
  }
}

// the solver holds everything now: give the soup's memory back before the propagation
inline void release_soup(Loaded_soup& soup)
{
  std::vector<Loaded_soup::Point>().swap(soup.points);
  std::vector<std::array<std::uint32_t, 3>>().swap(soup.triangles);
  std::vector<std::vector<std::size_t>>().swap(soup.polygons);
}

// Orients the polygons consistently, splitting non-manifold vertices (appended copies).
inline void orient_soup(Loaded_soup& soup)
{
  std::size_t duplicated = 0, reversed = 0;
  internal::Repair_visitor visitor;
  visitor.duplicated = &duplicated;
  visitor.reversed = &reversed;
  visitor.file_vertex_of = &soup.file_vertex_of;
  CGAL::Polygon_mesh_processing::orient_polygon_soup(soup.points, soup.polygons, CGAL::parameters::visitor(visitor));
  soup.file_vertex_of.resize(soup.points.size());
  if(duplicated > 0)
    soup.repairs.push_back("split " + std::to_string(duplicated) + " non-manifold vertices");
  if(reversed > 0)
    soup.repairs.push_back("reoriented " + std::to_string(reversed) + " faces");
}

namespace internal {

// Splits polygon `f` of the soup (more than 3 vertices) into triangles, appended to `triangles`
// (same orientation); throws Input_error when it cannot. This replaces CGAL's triangulate_faces,
// whose constrained Delaunay triangulation of the polygon, in its plane seen along an inexact
// normal, crashes on polygons that touch or cross themselves there (fuzzer: a pentagon with two
// vertices at the same place: where two sides crossed, computing their intersection failed and the
// triangulation took an uninitialised point as the new vertex; with the repeated place merged, the
// vertex count matched the polygon's and CGAL used the new vertex's halfedge, which is null; in
// double and float alike). Here:
// - a quad is split along the diagonal CGAL chooses (the one whose two triangles' normals agree
//   best), computed in double;
// - a larger polygon is projected onto the coordinate plane most parallel to it (exact: it drops
//   one coordinate) and cut by ear clipping with exact predicates: an ear is a strictly convex
//   corner whose triangle holds no other corner, not even on its border. A simple polygon always
//   has one; a polygon that crosses or touches itself there may run out of ears: refused.
inline void triangulate_polygon(const Loaded_soup& soup, std::size_t f, std::vector<std::vector<std::size_t>>& triangles)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const std::vector<std::size_t>& polygon = soup.polygons[f];
  const std::size_t n = polygon.size();
  const auto& p = soup.points;
  const auto refuse = [&](const std::string& why) {
    return Input_error("face " + std::to_string(f) + " (" + std::to_string(n) + " vertices) cannot be triangulated: " + why);
  };
  // Newell's normal: twice the vector area of the polygon
  double normal[3] = {0., 0., 0.};
  for(std::size_t i = 0; i < n; ++i)
  {
    const K::Point_3& a = p[polygon[i]];
    const K::Point_3& b = p[polygon[(i + 1) % n]];
    normal[0] += (a.y() - b.y()) * (a.z() + b.z());
    normal[1] += (a.z() - b.z()) * (a.x() + b.x());
    normal[2] += (a.x() - b.x()) * (a.y() + b.y());
  }
  if(!std::isfinite(normal[0]) || !std::isfinite(normal[1]) || !std::isfinite(normal[2]))
    throw refuse("its coordinates are too large");
  int axis = 0;
  for(int c = 1; c < 3; ++c)
    if(std::abs(normal[c]) > std::abs(normal[axis]))
      axis = c;
  if(normal[axis] == 0.)
    throw refuse("it has no area");

  if(n == 4)
  {
    const K::Point_3 &p0 = p[polygon[0]], &p1 = p[polygon[1]], &p2 = p[polygon[2]], &p3 = p[polygon[3]];
    const double p1p3 = CGAL::cross_product(p2 - p1, p3 - p2) * CGAL::cross_product(p0 - p3, p1 - p0);
    const double p0p2 = CGAL::cross_product(p1 - p0, p1 - p2) * CGAL::cross_product(p3 - p2, p3 - p0);
    if(p0p2 > p1p3)
    {
      triangles.push_back({polygon[0], polygon[1], polygon[2]});
      triangles.push_back({polygon[2], polygon[3], polygon[0]});
    }
    else
    {
      triangles.push_back({polygon[1], polygon[2], polygon[3]});
      triangles.push_back({polygon[3], polygon[0], polygon[1]});
    }
    return;
  }

  // (y, z), (z, x) or (x, y): the polygon turns counterclockwise there if normal[axis] > 0
  std::vector<K::Point_2> q;
  q.reserve(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    const K::Point_3& a = p[polygon[i]];
    q.emplace_back(a[(axis + 1) % 3], a[(axis + 2) % 3]);
  }
  const CGAL::Orientation convex = normal[axis] > 0. ? CGAL::LEFT_TURN : CGAL::RIGHT_TURN;
  const CGAL::Orientation outside = normal[axis] > 0. ? CGAL::RIGHT_TURN : CGAL::LEFT_TURN;
  std::vector<std::size_t> prev(n), next(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    prev[i] = (i + n - 1) % n;
    next[i] = (i + 1) % n;
  }
  const auto is_ear = [&](std::size_t i) {
    const std::size_t a = prev[i], c = next[i];
    if(CGAL::orientation(q[a], q[i], q[c]) != convex)
      return false;
    for(std::size_t j = next[c]; j != a; j = next[j])
      if(CGAL::orientation(q[a], q[i], q[j]) != outside && CGAL::orientation(q[i], q[c], q[j]) != outside &&
         CGAL::orientation(q[c], q[a], q[j]) != outside)
        return false;
    return true;
  };
  std::size_t remaining = n, i = 0, tried = 0;
  while(remaining > 3)
  {
    if(is_ear(i))
    {
      triangles.push_back({polygon[prev[i]], polygon[i], polygon[next[i]]});
      next[prev[i]] = next[i];
      prev[next[i]] = prev[i];
      i = prev[i];
      --remaining;
      tried = 0;
    }
    else
    {
      i = next[i];
      if(++tried > remaining)
        throw refuse("it crosses or touches itself, or has two vertices at the same place");
    }
  }
  if(CGAL::orientation(q[prev[i]], q[i], q[next[i]]) != convex)
    throw refuse("it crosses or touches itself, or has two vertices at the same place");
  triangles.push_back({polygon[prev[i]], polygon[i], polygon[next[i]]});
}

// Replaces the polygons with more than 3 vertices by triangles.
inline void triangulate_soup(Loaded_soup& soup)
{
  bool any = false;
  for(const auto& polygon : soup.polygons)
    any = any || polygon.size() > 3;
  if(!any)
    return;
  std::vector<std::vector<std::size_t>> triangles;
  for(std::size_t f = 0; f < soup.polygons.size(); ++f)
  {
    if(soup.polygons[f].size() == 3)
      triangles.push_back(soup.polygons[f]);
    else
      triangulate_polygon(soup, f, triangles);
  }
  soup.polygons.swap(triangles);
  soup.repairs.push_back("triangulated the faces with more than 3 vertices");
}

template <class Kernel>
CGAL::Surface_mesh<typename Kernel::Point_3> soup_to_mesh(const Loaded_soup& soup)
{
  using Point = typename Kernel::Point_3;
  std::vector<Point> points;
  points.reserve(soup.points.size());
  for(const auto& p : soup.points)
    points.emplace_back(typename Kernel::FT(p.x()), typename Kernel::FT(p.y()), typename Kernel::FT(p.z()));
  CGAL::Surface_mesh<Point> mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, soup.polygons, mesh);
  return mesh;
}

} // namespace internal

// The soup's faces repaired into a triangle mesh with the point type of `Kernel` (mesh vertex i
// is soup point i); consumes the faces.
template <class Kernel>
CGAL::Surface_mesh<typename Kernel::Point_3> make_triangle_mesh(Loaded_soup& soup)
{
  if(soup.polygons.empty())
    triangles_to_polygons(soup);
  internal::triangulate_soup(soup);
  // A face that does not fit (inconsistent orientation, more than two faces on an edge) is left
  // out by the conversion; only then is the soup oriented, which on a clean million-face file
  // would cost ten times the rest of loading.
  auto mesh = internal::soup_to_mesh<Kernel>(soup);
  if(num_faces(mesh) != soup.polygons.size())
  {
    orient_soup(soup);
    mesh = internal::soup_to_mesh<Kernel>(soup);
    if(num_faces(mesh) != soup.polygons.size())
      throw Input_error("the faces do not form a surface, even after orienting them");
  }
  // a vertex where separate fans of faces meet is kept as it is (geodesics may go from one fan to
  // the other through it); say so, since such input is often a defect
  std::vector<typename boost::graph_traits<decltype(mesh)>::halfedge_descriptor> pinched;
  CGAL::Polygon_mesh_processing::non_manifold_vertices(mesh, std::back_inserter(pinched));
  std::set<std::size_t> pinched_vertices;
  for(auto h : pinched)
    pinched_vertices.insert(std::size_t(target(h, mesh)));
  if(!pinched_vertices.empty())
    soup.repairs.push_back("kept " + std::to_string(pinched_vertices.size()) +
                           " non-manifold vertices, where separate fans of faces meet");
  std::vector<std::vector<std::size_t>>().swap(soup.polygons);
  return mesh;
}

// The soup's polygons repaired as make_triangle_mesh() does, replaced with the triangles of the
// mesh, the corners of each in the mesh's order.
template <class Kernel>
void repair_into_triangles(Loaded_soup& soup)
{
  const auto mesh = make_triangle_mesh<Kernel>(soup);
  soup.triangles.clear();
  soup.triangles.reserve(num_faces(mesh));
  for(auto f : faces(mesh))
  {
    const auto h = halfedge(f, mesh);
    soup.triangles.push_back({std::uint32_t(source(h, mesh)), std::uint32_t(target(h, mesh)),
                              std::uint32_t(target(next(h, mesh), mesh))});
  }
}

// Builds the solver (a Triangle_soup_geodesic_distance_solver) of the soup into `solver`. A valid
// triangle soup goes to the solver as it is. Any other soup (polygons, inconsistent orientations,
// edges of more than two faces, vertices where several fans meet, or input the solver refuses)
// takes the path of repairs through a Surface_mesh, which accepts, repairs or refuses it, and goes
// to the solver as the mesh's triangles. Returns the seconds spent on repairs (part of loading,
// not of preparing). Throws Input_error or std::invalid_argument for input it refuses.
template <class Solver>
double make_solver(Loaded_soup& soup, std::optional<Solver>& solver)
{
  if(soup.polygons.empty())
  {
    try
    {
      solver.emplace(make_soup_solver<Solver>(soup));
      if(solver->number_of_non_manifold_vertices() == 0)
        return 0.;
      solver.reset();
    }
    catch(const std::invalid_argument&)
    {
    }
  }
  const auto t0 = std::chrono::steady_clock::now();
  repair_into_triangles<typename Solver::Traits>(soup);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  solver.emplace(make_soup_solver<Solver>(soup));
  return seconds;
}

// The solver's vertices that stand for the file vertex `file_vertex`: the vertex itself and the
// copies loading made of it (a source is a source on every sheet).
inline std::vector<std::size_t> solver_vertices_of(const Loaded_soup& soup, std::size_t file_vertex)
{
  std::vector<std::size_t> out;
  for(std::size_t i = 0; i < soup.file_vertex_of.size(); ++i)
    if(soup.file_vertex_of[i] == file_vertex)
      out.push_back(i);
  return out;
}

// Per file vertex, the smallest of the distances `d` (per mesh vertex) of the vertices that stand
// for it; +infinity for a file vertex no face uses.
template <class FT>
std::vector<double> file_vertex_distances(const Loaded_soup& soup, const std::vector<FT>& d)
{
  std::vector<double> out(soup.file_vertices, std::numeric_limits<double>::infinity());
  for(std::size_t i = 0; i < d.size(); ++i)
  {
    double& o = out[soup.file_vertex_of[i]];
    o = (std::min)(o, double(d[i]));
  }
  return out;
}

} // namespace dggvtp

#endif // DGGVTP_LOAD_MESH_H
