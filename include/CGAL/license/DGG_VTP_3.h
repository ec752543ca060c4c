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

// The licence check of the package, in CGAL's scheme (CGAL/license.h): every header of the
// package includes this one. The package is under the GPLv3+; CGAL_LICENSE_WARNING makes a build
// say so, CGAL_LICENSE_ERROR makes it fail, and CGAL_DGG_VTP_3_COMMERCIAL_LICENSE, the date a
// commercial licence of the package covers, is checked against the release of CGAL in use.

#ifndef CGAL_LICENSE_DGG_VTP_3_H
#define CGAL_LICENSE_DGG_VTP_3_H

#include <CGAL/config.h>
#include <CGAL/license.h>

#ifdef CGAL_DGG_VTP_3_COMMERCIAL_LICENSE

#  if CGAL_DGG_VTP_3_COMMERCIAL_LICENSE < CGAL_RELEASE_DATE
#    if defined(CGAL_LICENSE_WARNING)
       CGAL_pragma_warning("Your commercial license for CGAL does not cover this release of the "
                           "Geodesic Distances by Window Propagation package.")
#    endif
#    ifdef CGAL_LICENSE_ERROR
#      error "Your commercial license for CGAL does not cover this release \
of the Geodesic Distances by Window Propagation package. \
You get this error, as you defined CGAL_LICENSE_ERROR."
#    endif
#  endif

#else // no CGAL_DGG_VTP_3_COMMERCIAL_LICENSE

#  if defined(CGAL_LICENSE_WARNING)
     CGAL_pragma_warning("\nThe macro CGAL_DGG_VTP_3_COMMERCIAL_LICENSE is not defined."
                         "\nYou use the Geodesic Distances by Window Propagation package "
                         "under the terms of the GPLv3+.")
#  endif
#  ifdef CGAL_LICENSE_ERROR
#    error "The macro CGAL_DGG_VTP_3_COMMERCIAL_LICENSE is not defined.\
 You use the Geodesic Distances by Window Propagation package under the terms of \
the GPLv3+. You get this error, as you defined CGAL_LICENSE_ERROR."
#  endif

#endif // no CGAL_DGG_VTP_3_COMMERCIAL_LICENSE

#endif // CGAL_LICENSE_DGG_VTP_3_H
