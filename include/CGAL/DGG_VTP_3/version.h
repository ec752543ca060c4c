// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// All rights reserved.
//
// This file is part of DGG_VTP_3, a package written for CGAL (www.cgal.org).
//
// $URL$
// $Id$
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : DGG-VTP for CGAL team

#ifndef CGAL_DGG_VTP_3_VERSION_H
#define CGAL_DGG_VTP_3_VERSION_H

#include <CGAL/license/DGG_VTP_3.h>

/// \file version.h
/// The version of the package, as CGAL gives its own in `<CGAL/version.h>`. This is its one
/// place: the project's CMake reads the three numbers for `project()` and the CMake package's
/// version file, the Python package's setup for its metadata; the programs' `--version` and
/// `dggvtp.__version__` print `DGG_VTP_3_VERSION_STR`.

#define DGG_VTP_3_VERSION_MAJOR 0
#define DGG_VTP_3_VERSION_MINOR 1
#define DGG_VTP_3_VERSION_PATCH 0

/// "MAJOR.MINOR.PATCH"
#define DGG_VTP_3_VERSION_STR                                                                                       \
  CGAL_STRINGIZE(DGG_VTP_3_VERSION_MAJOR) "." CGAL_STRINGIZE(DGG_VTP_3_VERSION_MINOR) "." CGAL_STRINGIZE(            \
    DGG_VTP_3_VERSION_PATCH)
/// MAJOR * 10000 + MINOR * 100 + PATCH, for comparisons in `#if`
#define DGG_VTP_3_VERSION_NR (DGG_VTP_3_VERSION_MAJOR * 10000 + DGG_VTP_3_VERSION_MINOR * 100 + DGG_VTP_3_VERSION_PATCH)

#endif // CGAL_DGG_VTP_3_VERSION_H
