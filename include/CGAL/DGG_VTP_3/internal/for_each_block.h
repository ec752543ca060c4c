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

#ifndef CGAL_DGG_VTP_3_INTERNAL_FOR_EACH_BLOCK_H
#define CGAL_DGG_VTP_3_INTERNAL_FOR_EACH_BLOCK_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <cstddef>
#include <exception>
#include <type_traits>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// The loops of the preparation: `body(begin, end)` over blocks of consecutive indices that cover
// [0, n), with `Parallel_tag` shared among TBB's threads (blocks of at least `grain` indices),
// else in one block. A body only writes what belongs to its own indices, so that the result is
// the same bit for bit whatever the blocks; a block may keep scratch for its indices (CGAL::for_each
// calls per element, and would allocate it per element).
//
// An exception in parallel is not passed on as it is: which block fails first depends on the
// threads, and the message names the element (a degenerate face, a sharp cone). The loop is run
// again on the calling thread, from index 0, so that the error of the first element in index order
// is the one thrown; an error that this run does not meet (memory) is rethrown as it came.
template <class ConcurrencyTag, class Body>
void for_each_block(std::size_t n, const Body& body, std::size_t grain = 4096)
{
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr(std::is_convertible<ConcurrencyTag, Parallel_tag>::value)
  {
    std::exception_ptr error;
    try
    {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                        [&body](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); });
    }
    catch(...)
    {
      error = std::current_exception();
    }
    if(!error)
      return;
    body(std::size_t(0), n);
    std::rethrow_exception(error);
  }
  else
#endif
  {
    (void)grain;
    body(std::size_t(0), n);
  }
}

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_FOR_EACH_BLOCK_H
