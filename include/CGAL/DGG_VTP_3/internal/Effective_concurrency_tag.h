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

#ifndef CGAL_DGG_VTP_3_INTERNAL_EFFECTIVE_CONCURRENCY_TAG_H
#define CGAL_DGG_VTP_3_INTERNAL_EFFECTIVE_CONCURRENCY_TAG_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/tags.h>

#include <type_traits>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// The tag a computation in `FT` runs with: `ConcurrencyTag` (Parallel_tag is refused without
// TBB, as CGAL::for_each does, but before any work), but Sequential_tag for number types other
// than float and double: exact number types share their representations between copies without
// locking them, and the mesh's lengths are copied into every window.
template <class ConcurrencyTag, class FT>
struct Effective_concurrency_tag
{
#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!std::is_convertible<ConcurrencyTag, Parallel_tag>::value,
                "Parallel_tag is enabled but TBB is unavailable.");
#endif
  using type = typename std::conditional<std::is_floating_point<FT>::value, ConcurrencyTag, Sequential_tag>::type;
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_EFFECTIVE_CONCURRENCY_TAG_H
