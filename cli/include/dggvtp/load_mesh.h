// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

#ifndef DGGVTP_LOAD_MESH_H
#define DGGVTP_LOAD_MESH_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
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
  std::vector<std::vector<std::size_t>> polygons;
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
// OFF, the face sizes are checked when the vertices are plain points.
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

  skip_comments();
  const std::string keyword = read_word();
  in.get(); // CGAL's reader takes the character that ends the keyword, whatever it is
  if(keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0)
    return; // not a header CGAL reads as OFF: it says so
  const bool dimensional = keyword.find('n') != std::string::npos;
  const bool colours = keyword.find('C') != std::string::npos;
  const int homogeneous = keyword.find('4') != std::string::npos ? 1 : 0;
  const bool normals = keyword.find('N') != std::string::npos;
  const bool textures = keyword.compare(0, 2, "ST") == 0;
  skip_comments();
  if(std::isalpha(in.peek()))
  {
    if(read_word() != "BINARY")
      return;
    if(in.get() != '\n')
      in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
    const auto int32 = [&in] {
      unsigned char b[4] = {0, 0, 0, 0};
      in.read(reinterpret_cast<char*>(b), 4);
      return static_cast<std::int32_t>((std::uint32_t(b[0]) << 24) | (std::uint32_t(b[1]) << 16) |
                                       (std::uint32_t(b[2]) << 8) | std::uint32_t(b[3]));
    };
    if(dimensional)
      int32();
    const long long vertices = int32(), faces = int32();
    int32(); // edges
    if(!in)
      return;
    if(vertices < 0 || faces < 0 || 12 * vertices + 4 * faces > bytes)
      throw too_large(vertices, faces);
    // faces as CGAL reads them: a size, then that many indices (walked for plain vertices only:
    // 3 or 4 floats; with normals, colours or textures the vertex size is CGAL's business)
    if(keyword != "OFF" && keyword != "4OFF")
      return;
    if(!in.seekg(static_cast<std::streamoff>(vertices * (keyword == "OFF" ? 12 : 16)), std::ios::cur))
      return;
    for(long long f = 0; f < faces; ++f)
    {
      const long long size = int32();
      if(!in)
        return;
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
    in >> vertices; // the dimension
  in >> vertices >> faces >> edges;
  if(!in)
    return;
  // a vertex line takes at least 5 bytes ("0 0 0"), a face line at least 1
  if(vertices < 0 || faces < 0 || vertices > bytes || faces > bytes || 5 * vertices + faces > bytes)
    throw too_large(vertices, faces);

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
    while(numbers >> entry)
      entries.push_back(entry);
    return true;
  };
  // With a C in the keyword, CGAL takes what follows the coordinates (normals, texture) or the
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
      return;
    if(colours)
      check_colour((3 + homogeneous) * (normals ? 2 : 1) + (textures ? 2 + homogeneous : 0),
                   "vertex " + std::to_string(v));
  }
  colour_entries_seen = -1;
  for(long long f = 0; f < faces; ++f)
  {
    if(!read_entries())
      return;
    if(entries.empty())
      return;
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
    std::string type;   // "list" for a list
    int size = 0;       // bytes of the value (of each entry, for a list)
    int count_size = 0; // bytes of a list's size; 0 for a scalar
    bool count_signed = false;
  };
  struct Element
  {
    std::string name;
    long long count = 0;
    std::vector<Property> properties;
  };
  const auto type_size = [](const std::string& type, bool& is_signed) {
    is_signed = type == "char" || type == "short" || type == "int" || type == "int8" || type == "int16" ||
                type == "int32";
    if(type == "char" || type == "uchar" || type == "int8" || type == "uint8")
      return 1;
    if(type == "short" || type == "ushort" || type == "int16" || type == "uint16")
      return 2;
    if(type == "int" || type == "uint" || type == "float" || type == "int32" || type == "uint32" || type == "float32")
      return 4;
    if(type == "double" || type == "float64")
      return 8;
    return 0;
  };

  std::string line, format;
  std::vector<Element> elements;
  if(!std::getline(in, line) || line.compare(0, 3, "ply") != 0)
    return;
  for(;;)
  {
    if(!std::getline(in, line))
      return;
    if(!line.empty() && line.back() == '\r')
      line.pop_back();
    std::istringstream words(line);
    std::string word;
    words >> word;
    if(word == "end_header")
      break;
    if(word == "format")
      words >> format;
    else if(word == "element")
    {
      Element e;
      if(!(words >> e.name >> e.count))
        return;
      if(e.count < 0 || e.count > bytes)
        throw Input_error("'" + path + "' declares " + std::to_string(e.count) + " elements '" + e.name +
                          "', more than its " + std::to_string(bytes) + " bytes can hold");
      elements.push_back(e);
    }
    else if(word == "property")
    {
      if(elements.empty()) // CGAL's reader would add it to the last of no elements
        throw Input_error("'" + path + "': the PLY header has a property before any element");
      std::string type, count_type, item_type;
      words >> type;
      Property p;
      p.type = type;
      bool is_signed = false;
      if(type == "list")
      {
        words >> count_type >> item_type >> p.name;
        p.count_size = type_size(count_type, p.count_signed);
        p.size = type_size(item_type, is_signed);
        if(p.count_size == 0 || count_type.compare(0, 5, "float") == 0 || count_type == "double")
          throw Input_error("'" + path + "': the PLY list '" + p.name + "' has a size type that is not an integer type");
      }
      else
      {
        p.size = type_size(type, is_signed);
        words >> p.name;
      }
      if(p.size == 0) // CGAL's reader may go on with a null reader for it (fuzzer)
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
            if(p.type != "float" && p.type != "float32" && p.type != "double" && p.type != "float64")
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
  std::string token;
  for(const Element& e : elements)
  {
    bool has_list = false;
    long long record_size = 0;
    for(const Property& p : e.properties)
    {
      has_list = has_list || p.count_size > 0;
      record_size += p.size;
    }
    if(!has_list)
    {
      if(ascii)
      {
        for(long long r = 0; r < e.count * static_cast<long long>(e.properties.size()); ++r)
          if(!(in >> token))
            return;
      }
      else if(!in.seekg(static_cast<std::streamoff>(e.count * record_size), std::ios::cur))
        return;
      continue;
    }
    for(long long r = 0; r < e.count; ++r)
      for(const Property& p : e.properties)
      {
        if(p.count_size == 0)
        {
          if(ascii ? !(in >> token) : !in.seekg(p.size, std::ios::cur))
            return;
          continue;
        }
        long long size = 0;
        if(ascii)
        {
          double value;
          if(!(in >> value))
            return;
          if(!(value >= 0.) || value > double(bytes))
            throw list_too_large(e, r, value);
          size = static_cast<long long>(value);
          for(long long k = 0; k < size; ++k)
            if(!(in >> token))
              return;
        }
        else
        {
          unsigned char b[8] = {0, 0, 0, 0, 0, 0, 0, 0};
          if(!in.read(reinterpret_cast<char*>(b), p.count_size))
            return;
          std::uint64_t u = 0;
          for(int k = 0; k < p.count_size; ++k)
            u |= std::uint64_t(b[big_endian ? p.count_size - 1 - k : k]) << (8 * k);
          if(p.count_signed && (u >> (8 * p.count_size - 1)) != 0)
            throw list_too_large(e, r, double(static_cast<long long>(u) - (1LL << (8 * p.count_size))));
          if(u > std::uint64_t(bytes))
            throw list_too_large(e, r, double(u));
          size = static_cast<long long>(u);
          if(!in.seekg(static_cast<std::streamoff>(size * p.size), std::ios::cur))
            return;
        }
      }
  }
}

inline Loaded_soup load_soup(const std::string& path)
{
  Loaded_soup soup;
  {
    errno = 0;
    std::ifstream probe(path);
    if(!probe.good())
      throw Input_error("cannot read '" + path + "': " + (errno != 0 ? std::strerror(errno) : "cannot open it"));
  }
  {
    std::string extension = path.substr(path.rfind('.') == std::string::npos ? path.size() : path.rfind('.') + 1);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if(extension == "off")
      check_off_declarations(path);
    else if(extension == "ply")
      check_ply_declarations(path);
  }
  if(!CGAL::IO::read_polygon_soup(path, soup.points, soup.polygons, CGAL::parameters::verbose(false)))
    throw Input_error("cannot read '" + path + "' as a mesh (unsupported format, or an invalid or truncated file)");
  if(soup.points.empty())
    throw Input_error("'" + path + "' has no vertices");
  soup.file_vertices = soup.points.size();
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
      if(polygon[k] >= soup.file_vertices)
        throw Input_error("face " + std::to_string(f) + " refers to vertex " + std::to_string(polygon[k]) +
                          ", but the file has " + std::to_string(soup.file_vertices) + " vertices");
      for(std::size_t j = 0; j < k; ++j)
        if(polygon[j] == polygon[k])
          throw Input_error("face " + std::to_string(f) + " uses vertex " + std::to_string(polygon[k]) + " twice");
    }
  }

  soup.file_vertex_of.resize(soup.points.size());
  for(std::size_t i = 0; i < soup.points.size(); ++i)
    soup.file_vertex_of[i] = i;
  return soup;
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

// The soup as a triangle mesh with the point type of `Kernel`; mesh vertex i is soup point i.
// Consumes the soup's points and polygons.
template <class Kernel>
CGAL::Surface_mesh<typename Kernel::Point_3> make_triangle_mesh(Loaded_soup& soup)
{
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
  // the mesh holds everything now: give the soup's memory back before the propagation
  std::vector<typename Loaded_soup::Point>().swap(soup.points);
  std::vector<std::vector<std::size_t>>().swap(soup.polygons);
  if(!CGAL::is_triangle_mesh(mesh))
  {
    soup.repairs.push_back("triangulated the faces with more than 3 vertices");
    if(!CGAL::Polygon_mesh_processing::triangulate_faces(mesh))
      throw Input_error("a face with more than 3 vertices could not be triangulated");
  }
  return mesh;
}

} // namespace dggvtp

#endif // DGGVTP_LOAD_MESH_H
