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

#ifndef CGAL_DGG_VTP_3_INTERNAL_DEFAULT_INIT_ALLOCATOR_H
#define CGAL_DGG_VTP_3_INTERNAL_DEFAULT_INIT_ALLOCATOR_H

#include <CGAL/license/DGG_VTP_3.h>

#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// std::allocator, but resize(n) default-initializes the new elements instead of value-initializing
// them: numbers and trivial structs are left as they are. For the preparation's large arrays that a
// loop then writes whole, block by block on several threads: zeroing them first was a pass over
// the memory on one thread (the first touch of every page, about 300 MB on a 1M-vertex mesh).
template <class T>
class Default_init_allocator : public std::allocator<T>
{
public:
  template <class U>
  struct rebind
  {
    using other = Default_init_allocator<U>;
  };

  Default_init_allocator() = default;
  template <class U>
  Default_init_allocator(const Default_init_allocator<U>&) noexcept {}

  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible<U>::value)
  {
    ::new(static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args)
  {
    ::new(static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

// a vector whose resize() leaves numbers uninitialized, for arrays written whole right after
template <class T>
using Uninitialized_vector = std::vector<T, Default_init_allocator<T>>;

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_DEFAULT_INIT_ALLOCATOR_H
