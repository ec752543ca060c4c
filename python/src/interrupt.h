// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// Ctrl-C during a call. Python's SIGINT handler only sets a flag; the KeyboardInterrupt is
// raised when the main thread next runs Python code, which a call that released the GIL does
// not do until it returns (16.7 s after SIGINT for a local matrix of the bunny). So the calls
// ask Python for pending signals themselves, from the propagation's progress callback and
// between rows, and cancel the query when one raised.
//
// The test hook below (DGGVTP_TEST_SIGINT_AT_CHECK) is compiled only with DGGVTP_PYTHON_TEST_HOOKS,
// which CMake defines for the module of a build with BUILD_TESTING (python/CMakeLists.txt, option
// DGG_VTP_3_PYTHON_TEST_HOOKS): the module that pip installs (setup.py: BUILD_TESTING=OFF) has none.

#ifndef DGGVTP_PYTHON_INTERRUPT_H
#define DGGVTP_PYTHON_INTERRUPT_H

#include <CGAL/DGG_VTP_3/Propagation_cancelled.h>

#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <thread>
#include <utility>

namespace dggvtp {
namespace python {

class Interrupt_check
{
public:
  // made where the GIL is held, on the thread that called from Python
#ifdef DGGVTP_PYTHON_TEST_HOOKS
  Interrupt_check() : m_caller(std::this_thread::get_id()), m_test_raise_at(test_sigint_check()) {}
#else
  Interrupt_check() : m_caller(std::this_thread::get_id()) {}
#endif

#ifdef DGGVTP_PYTHON_TEST_HOOKS
  // For tests only (DGGVTP_TEST_SIGINT_AT_CHECK=N): the caller's N-th check sends SIGINT to the
  // process, as Ctrl-C would, and asks Python at once; the end of the call says on stderr how many
  // checks it made, so that a test knows the call stopped at that check and not at its end,
  // whatever the speed of the machine (a Ctrl-C from outside races the call).
  ~Interrupt_check()
  {
    if(m_test_raise_at != 0)
      std::fprintf(stderr, "dggvtp test hook: SIGINT at check %zu, %zu checks in the call\n", m_test_raise_at, m_checks);
  }
#endif

  // Whether the call must stop, from any thread, the GIL released: the caller's thread asks
  // Python for its pending signals (at most every 20 ms: it takes the GIL); the other threads
  // only learn what it found.
  bool operator()()
  {
    if(m_raised.load(std::memory_order_relaxed))
      return true;
    if(std::this_thread::get_id() != m_caller)
      return false;
#ifdef DGGVTP_PYTHON_TEST_HOOKS
    const bool test_raise = ++m_checks == m_test_raise_at;
    if(test_raise)
      std::raise(SIGINT);
#else
    constexpr bool test_raise = false;
#endif
    const auto now = std::chrono::steady_clock::now();
    if(!test_raise && now - m_last < std::chrono::milliseconds(20))
      return false;
    m_last = now;
    pybind11::gil_scoped_acquire gil;
    if(PyErr_CheckSignals() == 0)
      return false;
    m_error.emplace(); // takes the exception the handler raised (KeyboardInterrupt)
    m_raised.store(true, std::memory_order_relaxed);
    return true;
  }

  // Runs `f` with the GIL released; when a signal handler raised while it ran, raises that
  // exception instead of what `f` threw on learning it (Propagation_cancelled).
  template <class F>
  void run_released(F&& f)
  {
    try
    {
      pybind11::gil_scoped_release unlocked;
      std::forward<F>(f)();
    }
    catch(const CGAL::DGG_VTP_3::Propagation_cancelled&)
    {
      if(m_error)
        throw *m_error;
      throw;
    }
  }

private:
#ifdef DGGVTP_PYTHON_TEST_HOOKS
  static std::size_t test_sigint_check()
  {
    const char* n = std::getenv("DGGVTP_TEST_SIGINT_AT_CHECK");
    return n != nullptr ? std::size_t(std::strtoull(n, nullptr, 10)) : 0;
  }
#endif

  std::thread::id m_caller;
#ifdef DGGVTP_PYTHON_TEST_HOOKS
  std::size_t m_test_raise_at; // see ~Interrupt_check()
  std::size_t m_checks = 0;    // by the caller's thread
#endif
  std::chrono::steady_clock::time_point m_last{};
  std::atomic<bool> m_raised{false};
  std::optional<pybind11::error_already_set> m_error;
};

} // namespace python
} // namespace dggvtp

#endif // DGGVTP_PYTHON_INTERRUPT_H
