// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// Options that take one value refuse to be given twice: "the last one wins" hides a typo in a
// long command line (two --output files, two --epsilon values) behind a run that looks right.

#ifndef DGGVTP_SINGLE_VALUE_OPTIONS_H
#define DGGVTP_SINGLE_VALUE_OPTIONS_H

#include <dggvtp/command_line.h>

#include <initializer_list>
#include <set>
#include <string>

namespace dggvtp {

class Single_value_options
{
public:
  Single_value_options(std::initializer_list<const char*> names) : m_names(names.begin(), names.end()) {}
  // throws Usage_error when `arg` is one of the names and was seen before
  void check(const std::string& arg)
  {
    if(m_names.count(arg) != 0 && !m_seen.insert(arg).second)
      throw Usage_error(arg + " is given more than once: it takes one value");
  }

private:
  std::set<std::string> m_names;
  std::set<std::string> m_seen;
};

} // namespace dggvtp

#endif // DGGVTP_SINGLE_VALUE_OPTIONS_H
