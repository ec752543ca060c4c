// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// A case that compares Parallel_tag with Sequential_tag cannot run in a build without TBB: there,
// Parallel_if_available_tag is Sequential_tag and Parallel_tag does not compile, so the comparison
// would compare the sequential path with itself and pass. Such a case refuses instead: it fails
// with a message that says so. CTest counts that message as a skip (SKIP_REGULAR_EXPRESSION, see
// CMakeLists.txt), listed in its summary; under DGG_VTP_3_REQUIRE_ALL_TESTS a build without TBB is
// refused at configuration.

#ifndef DGG_VTP_3_TEST_WITHOUT_TBB_H
#define DGG_VTP_3_TEST_WITHOUT_TBB_H

#include <boost/test/unit_test.hpp>

#ifndef CGAL_LINKED_WITH_TBB
#define DGG_VTP_3_REFUSE_WITHOUT_TBB(what)                                                              \
  BOOST_FAIL("built without TBB, not run: " << what                                                     \
             << " needs Parallel_tag (configure with TBB; Debian: libtbb-dev)")
#endif

#endif // DGG_VTP_3_TEST_WITHOUT_TBB_H
