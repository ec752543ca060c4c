// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// What --version prints: the package's version (the CMake project's, given as DGGVTP_VERSION by
// the build) and the version of CGAL it was built with.

#ifndef DGGVTP_VERSION_H
#define DGGVTP_VERSION_H

#include <CGAL/version.h>

#include <string>

#ifndef DGGVTP_VERSION
#error "DGGVTP_VERSION must be defined by the build (cli/CMakeLists.txt)"
#endif

namespace dggvtp {

inline std::string version_text(const std::string& program)
{
  return program + " " DGGVTP_VERSION " (DGG-VTP for CGAL), CGAL " CGAL_VERSION_STR "\n";
}

} // namespace dggvtp

#endif // DGGVTP_VERSION_H
