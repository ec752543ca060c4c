// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

#ifndef DGGVTP_FAST_READ_H
#define DGGVTP_FAST_READ_H

#include <dggvtp/fast_obj.h>
#include <dggvtp/fast_off.h>
#include <dggvtp/fast_ply.h>
#include <dggvtp/fast_soup.h>
#include <dggvtp/fast_stl.h>
#include <dggvtp/mapped_file.h>

#include <optional>
#include <string>

namespace dggvtp {
namespace internal {

// The file read by the fast reader of its format (`extension`, lower case), or nothing when that
// reader does not take it (a rarer variant, or input CGAL's path refuses or repairs).
inline std::optional<Fast_soup> read_fast(const std::string& path, const std::string& extension)
{
  const Mapped_file file(path);
  if(!file.valid())
    return std::nullopt;
  Fast_soup soup;
  bool read = false;
  if(extension == "ply")
    read = read_fast_ply(file.begin(), file.end(), soup);
  else if(extension == "obj")
    read = read_fast_obj(file.begin(), file.end(), soup);
  else if(extension == "off")
    read = read_fast_off(file.begin(), file.end(), soup);
  else if(extension == "stl")
    read = read_fast_stl(file.begin(), file.end(), soup);
  if(!read)
    return std::nullopt;
  return soup;
}

} // namespace internal
} // namespace dggvtp

#endif // DGGVTP_FAST_READ_H
