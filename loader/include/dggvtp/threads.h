// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// The --threads option of dggvtp and dggvtp-batch and the Python module's threads=: one number
// (0 = all cores, 1 = sequential) turned into a concurrency tag and a TBB thread limit, for the
// preparation and the propagations alike.

#ifndef DGGVTP_THREADS_H
#define DGGVTP_THREADS_H

#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <cstddef>
#include <optional>
#include <type_traits>

namespace dggvtp {

// Runs `f(tag)` with the concurrency tag of `threads` (1: Sequential_tag) under TBB's thread limit
// of `threads`. TBB's limit is process-wide: concurrent calls share the smallest one.
template <class F>
void with_threads(long threads, F f)
{
  if(threads == 1)
  {
    f(CGAL::Sequential_tag());
    return;
  }
#ifdef CGAL_LINKED_WITH_TBB
  std::optional<tbb::global_control> limit;
  if(threads > 0)
    limit.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
#endif
  f(CGAL::Parallel_if_available_tag());
}

// The number of threads that work under `tag` within with_threads(), for --stats: TBB runs at most
// as many as the limit and the cores allow
template <class ConcurrencyTag>
std::size_t threads_of(ConcurrencyTag)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value)
    return (std::min)(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism),
                      std::size_t(tbb::this_task_arena::max_concurrency()));
#endif
  return 1;
}

} // namespace dggvtp

#endif // DGGVTP_THREADS_H
