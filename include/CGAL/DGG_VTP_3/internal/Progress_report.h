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

#ifndef CGAL_DGG_VTP_3_INTERNAL_PROGRESS_REPORT_H
#define CGAL_DGG_VTP_3_INTERNAL_PROGRESS_REPORT_H

#include <CGAL/license/DGG_VTP_3.h>

#include <CGAL/DGG_VTP_3/Propagation_cancelled.h>

#include <algorithm>
#include <chrono>
#include <cstddef>

namespace CGAL {
namespace DGG_VTP_3 {
namespace internal {

// The query's progress callback (named parameter `callback`) the first time it is asked, then at
// most every 0.1 s: a callback that draws a line must not slow the rounds down.
class Progress_report
{
public:
  // for a new propagation: the next call reports
  void reset() { m_next = std::chrono::steady_clock::time_point(); }

  // `progress(popped / vertices)`, the fraction of the vertices popped (those whose distance is
  // final, but for the rare vertex popped again), if it is time; throws Propagation_cancelled when
  // it returns false. `popped()` counts them, only then.
  template <class Callback, class Popped>
  void operator()(const Callback& progress, const Popped& popped, std::size_t vertices)
  {
    if(!progress)
      return;
    const auto now = std::chrono::steady_clock::now();
    if(now < m_next)
      return;
    m_next = now + std::chrono::milliseconds(100);
    if(!progress((std::min)(1., double(popped()) / double((std::max)(std::size_t(1), vertices)))))
      throw Propagation_cancelled();
  }

private:
  std::chrono::steady_clock::time_point m_next;
};

} // namespace internal
} // namespace DGG_VTP_3
} // namespace CGAL

#endif // CGAL_DGG_VTP_3_INTERNAL_PROGRESS_REPORT_H
