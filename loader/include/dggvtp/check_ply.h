// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// The checks a PLY file passes before CGAL's reader reads it (see check_ply_declarations()).

#ifndef DGGVTP_CHECK_PLY_H
#define DGGVTP_CHECK_PLY_H

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

} // namespace dggvtp

#endif // DGGVTP_CHECK_PLY_H
