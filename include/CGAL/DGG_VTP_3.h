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

#ifndef CGAL_DGG_VTP_3_H
#define CGAL_DGG_VTP_3_H

#include <CGAL/license/DGG_VTP_3.h>

/// \file DGG_VTP_3.h
/// Convenience header: geodesic distances on triangle meshes by window propagation, exact (VTP)
/// or accuracy-controlled (DGG-VTP).

#include <CGAL/DGG_VTP_3/Geodesic_distance_solver.h>
#include <CGAL/DGG_VTP_3/Propagation_cancelled.h>
#include <CGAL/DGG_VTP_3/Propagation_statistics.h>
#include <CGAL/DGG_VTP_3/Triangle_soup_geodesic_distance_solver.h>
#include <CGAL/DGG_VTP_3/compute_geodesic_distances.h>
#include <CGAL/DGG_VTP_3/isolines.h>
#include <CGAL/DGG_VTP_3/version.h>

#endif // CGAL_DGG_VTP_3_H
