// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// The module of test_DGG_VTP_3; the test cases are in the topic files next to this one.

#define BOOST_TEST_MODULE DGG_VTP_3
#include <boost/test/unit_test.hpp>
