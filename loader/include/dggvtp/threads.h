// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// The --threads option of dggvtp and dggvtp-batch and the Python module's threads=: one number
// (0 = all cores, 1 = sequential) turned into a concurrency tag and a TBB task arena of that many
// threads, for the preparation and the propagations alike.

#ifndef DGGVTP_THREADS_H
#define DGGVTP_THREADS_H

#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#endif

#include <cstddef>
#include <type_traits>

namespace dggvtp {

// Runs `f(tag)` with the concurrency tag of `threads` (1: Sequential_tag) in a TBB task arena of
// `threads` threads (0: TBB's default arena, all cores). An arena alone does not get its threads:
// TBB's process-wide limit on workers is the number of cores, so that an arena of 8 on 2 cores
// would run on 2. The limit is raised to `threads` for the call, and 8 threads really interleave
// on 2 cores. The limit being process-wide, concurrent calls share the smallest one (a process
// pool's workers each calling with threads=1 run sequentially and set none).
template <class F>
void with_threads(long threads, F f)
{
  if(threads == 1)
  {
    f(CGAL::Sequential_tag());
    return;
  }
#ifdef CGAL_LINKED_WITH_TBB
  if(threads > 1)
  {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
    tbb::task_arena arena(static_cast<int>(threads));
    arena.execute([&] { f(CGAL::Parallel_if_available_tag()); });
    return;
  }
#endif
  f(CGAL::Parallel_if_available_tag());
}

// The number of threads that work under `tag` within with_threads(), for --stats: those of the
// arena, as far as TBB's limit allows
template <class ConcurrencyTag>
std::size_t threads_of(ConcurrencyTag)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value)
  {
    const std::size_t arena = std::size_t(tbb::this_task_arena::max_concurrency());
    const std::size_t limit = tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
    return arena < limit ? arena : limit;
  }
#endif
  return 1;
}

} // namespace dggvtp

#endif // DGGVTP_THREADS_H
