// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

#ifndef CGAL_DGG_VTP_3_INTERNAL_FOR_EACH_INDEX_H
#define CGAL_DGG_VTP_3_INTERNAL_FOR_EACH_INDEX_H

#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <cstddef>
#include <type_traits>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

template <class ConcurrencyTag>
constexpr bool is_parallel() { return std::is_convertible<ConcurrencyTag, Parallel_tag>::value; }

// The tag a computation in `FT` runs with: `ConcurrencyTag` (Parallel_tag is refused without
// TBB), but Sequential_tag for number types other than float and double: exact number types
// share their representations between copies without locking them, and the mesh's lengths are
// copied into every window.
template <class ConcurrencyTag, class FT>
struct Effective_concurrency_tag
{
#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!is_parallel<ConcurrencyTag>(), "Parallel_tag is enabled but TBB is unavailable.");
#endif
  using type = typename std::conditional<std::is_floating_point<FT>::value, ConcurrencyTag, Sequential_tag>::type;
};

// f(0), ..., f(n - 1): in this order with Sequential_tag, shared among TBB's threads in any order
// with Parallel_tag (each call must then touch only its own data). One index per task: callers
// give indices that are worth a task each.
template <class ConcurrencyTag, class Function>
void for_each_index(std::size_t n, const Function& f)
{
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr(is_parallel<ConcurrencyTag>())
  {
    if(n > 1)
    {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1),
                        [&f](const tbb::blocked_range<std::size_t>& range) {
                          for(std::size_t k = range.begin(); k != range.end(); ++k)
                            f(k);
                        });
      return;
    }
  }
#else
  static_assert(!is_parallel<ConcurrencyTag>(), "Parallel_tag is enabled but TBB is unavailable.");
#endif
  for(std::size_t k = 0; k < n; ++k)
    f(k);
}

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_FOR_EACH_INDEX_H
