// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// What --version prints: the package's version and the version of CGAL it was built with.

#ifndef DGGVTP_VERSION_H
#define DGGVTP_VERSION_H

#include <CGAL/DGG_VTP_3/version.h>
#include <CGAL/version.h>

#include <string>

namespace dggvtp {

inline std::string version_text(const std::string& program)
{
  return program + " " DGG_VTP_3_VERSION_STR " (DGG-VTP for CGAL), CGAL " CGAL_VERSION_STR "\n";
}

} // namespace dggvtp

#endif // DGGVTP_VERSION_H
