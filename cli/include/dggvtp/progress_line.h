// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// dggvtp's progress line on stderr, fed by the library's `callback` named parameter: the
// percentage of vertices final, the time elapsed and the time left. On a terminal it is redrawn in
// place, once the run has taken about a second (a quick run shows nothing); --progress shows it
// from the first call, and elsewhere than on a terminal as one line a second.

#ifndef DGGVTP_PROGRESS_LINE_H
#define DGGVTP_PROGRESS_LINE_H

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace dggvtp {

class Progress_line
{
public:
  explicit Progress_line(bool forced) : m_forced(forced), m_terminal(::isatty(2) != 0) {}
  Progress_line(const Progress_line&) = delete;
  Progress_line& operator=(const Progress_line&) = delete;
  // a line ends the progress shown on a terminal, so that what follows starts on its own line
  ~Progress_line()
  {
    if(m_shown && m_terminal)
      std::fputc('\n', stderr);
  }

  // the callback: never cancels
  bool operator()(double fraction)
  {
    const double elapsed = seconds(Clock::now() - m_start);
    if(!m_forced && !(m_terminal && elapsed >= 1.))
      return true;
    if(!m_terminal && m_shown && elapsed < m_last_line + 1.)
      return true;
    const double left = fraction > 0. ? elapsed * (1. - fraction) / fraction : std::numeric_limits<double>::infinity();
    show("dggvtp: " + number(100. * fraction) + "% of the vertices final, " + number(elapsed) + " s elapsed, " +
         (std::isfinite(left) ? "about " + number(left) + " s left" : std::string("time left unknown")));
    m_last_line = elapsed;
    return true;
  }

  // once the propagation is done: its time, where a line was shown
  void finish()
  {
    if(m_shown)
      show("dggvtp: propagation done, " + number(seconds(Clock::now() - m_start)) + " s elapsed");
  }

private:
  using Clock = std::chrono::steady_clock;
  void show(const std::string& line)
  {
    std::fprintf(stderr, m_terminal ? "\r%-79s" : "%s\n", line.c_str());
    std::fflush(stderr);
    m_shown = true;
  }
  static double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }
  static std::string number(double x)
  {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", x);
    return text;
  }

  bool m_forced;                            // --progress: from the first call, on any stderr
  bool m_terminal;                          // stderr is a terminal: one line redrawn
  Clock::time_point m_start = Clock::now(); // the propagation's start
  bool m_shown = false;                     // a line was printed
  double m_last_line = 0.;                  // seconds after the start of the last line printed
};

} // namespace dggvtp

#endif // DGGVTP_PROGRESS_LINE_H
