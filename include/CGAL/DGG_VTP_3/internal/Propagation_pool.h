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

#ifndef CGAL_DGG_VTP_3_INTERNAL_PROPAGATION_POOL_H
#define CGAL_DGG_VTP_3_INTERNAL_PROPAGATION_POOL_H

#include <CGAL/license/DGG_VTP_3.h>

#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// The propagations of a solver's queries, kept between queries: a query takes one that is free
// (or makes one) and gives it back when it is done, so that the per-vertex, per-face and
// per-halfedge arrays are allocated once per thread that queries, not once per query, and a query
// resets them in the time of what the previous one touched (see Window_propagation). The const
// queries stay safe to run from many threads at once: a propagation is in one query at a time.
// A propagation whose run threw is not given back (see Window_propagation::reusable()). The pool
// holds at most as many as queries ran at once; clear() frees them. It is not copied: its
// propagations refer to the mesh of the solver that owns it.
template <class Propagation>
class Propagation_pool
{
public:
  // A propagation taken from the pool for one query; back into it at the end of the lease
  class Lease
  {
  public:
    Lease(Propagation_pool& pool, std::unique_ptr<Propagation> p) : m_pool(&pool), m_propagation(std::move(p)) {}
    Lease(Lease&&) = default;
    Lease& operator=(Lease&&) = delete;
    ~Lease()
    {
      if(m_propagation && m_propagation->reusable())
        m_pool->give_back(m_propagation);
    }
    Propagation& operator*() const { return *m_propagation; }
    Propagation* operator->() const { return m_propagation.get(); }

  private:
    Propagation_pool* m_pool;
    std::unique_ptr<Propagation> m_propagation;
  };

  Propagation_pool() = default;
  Propagation_pool(const Propagation_pool&) = delete;
  Propagation_pool& operator=(const Propagation_pool&) = delete;

  // a free propagation, or a new one from `make()`
  template <class Make>
  Lease take(const Make& make)
  {
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      if(!m_free.empty())
      {
        std::unique_ptr<Propagation> p = std::move(m_free.back());
        m_free.pop_back();
        return Lease(*this, std::move(p));
      }
    }
    return Lease(*this, make());
  }

  // the free propagations destroyed; those of queries running now come back at their end
  void clear()
  {
    std::vector<std::unique_ptr<Propagation>> freed;
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      freed.swap(m_free);
    }
  }

private:
  // From a destructor: nothing may throw. A propagation that finds no room (the list cannot
  // grow) is destroyed instead, which only costs the next query its allocation.
  void give_back(std::unique_ptr<Propagation>& p) noexcept
  {
    try
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      m_free.push_back(std::move(p));
    }
    catch(...)
    {
    }
  }

  std::mutex m_mutex;
  std::vector<std::unique_ptr<Propagation>> m_free;
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_PROPAGATION_POOL_H
