# Checks CGAL's forms on every header of include/ (cmake -P, SOURCE_DIR = the repository): the
# file header (copyright, SPDX licence, authors), an include guard CGAL_..._H, and the package's
# licence check <CGAL/license/DGG_VTP_3.h> included right after the guard.
file(GLOB_RECURSE _headers RELATIVE ${SOURCE_DIR} ${SOURCE_DIR}/include/*.h)
set(_bad 0)
foreach(_header IN LISTS _headers)
  file(READ ${SOURCE_DIR}/${_header} _text)
  set(_missing "")
  foreach(_line "^// Copyright \\(c\\) [0-9]+ " "\n// SPDX-License-Identifier: GPL-3.0-or-later\n"
                "\n// Author\\(s\\)     : [^\n]+\n" "\n#ifndef (CGAL_[A-Z0-9_]+_H)\n#define CGAL_[A-Z0-9_]+_H\n")
    if(NOT _text MATCHES "${_line}")
      string(APPEND _missing " '${_line}'")
    endif()
  endforeach()
  if(NOT _header STREQUAL "include/CGAL/license/DGG_VTP_3.h"
     AND NOT _text MATCHES "\n#define CGAL_[A-Z0-9_]+_H\n\n#include <CGAL/license/DGG_VTP_3.h>\n")
    string(APPEND _missing " '#include <CGAL/license/DGG_VTP_3.h>' after the guard")
  endif()
  if(_missing)
    message(SEND_ERROR "${_header}: no${_missing}")
    math(EXPR _bad "${_bad} + 1")
  endif()
endforeach()
list(LENGTH _headers _count)
if(_bad)
  message(FATAL_ERROR "${_bad} of ${_count} headers without CGAL's file header, guard or licence check")
endif()
message(STATUS "${_count} headers in CGAL's form")
