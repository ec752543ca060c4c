// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

#ifndef DGGVTP_COMMAND_LINE_H
#define DGGVTP_COMMAND_LINE_H

// What dggvtp and dggvtp-batch share of their command lines: the options of the propagation
// (--exact, --epsilon, --precision), number parsing, and the pieces of their --stats files.

#include <CGAL/DGG_VTP_3/parameters.h>

#include <sys/resource.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace dggvtp {

// Bad usage: `error: <message>`, exit status 1.
struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// The whole of `text` as a number: a double, or a non-negative integer written with digits only.
template <class T>
T parse_number(const std::string& option, const std::string& text)
{
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  T value{};
  if(std::is_floating_point<T>::value)
    value = T(std::strtod(begin, &end));
  else if(!text.empty() && text[0] != '-' && text[0] != '+' && !std::isspace(static_cast<unsigned char>(text[0])))
    value = T(std::strtoull(begin, &end, 10));
  if(end == begin || end == nullptr || *end != '\0' || errno == ERANGE)
    throw Usage_error("invalid value '" + text + "' for " + option);
  return value;
}

// --exact, --epsilon E and --precision P
struct Propagation_options
{
  double epsilon = 0.;
  std::string precision = "double";
  bool exact_given = false, epsilon_given = false;

  // Takes `arg` if it is one of these options (`value` gives its value); false otherwise.
  template <class Value>
  bool parse(const std::string& arg, Value value)
  {
    if(arg == "--exact")
      exact_given = true;
    else if(arg == "--epsilon")
    {
      const std::string given = value();
      epsilon = parse_number<double>(arg, given);
      if(!(epsilon >= 0. && epsilon <= CGAL::DGG_VTP_3::maximal_accuracy))
        throw Usage_error("--epsilon must be in [0, 1] (0: exact); got " + given +
                          (epsilon > CGAL::DGG_VTP_3::maximal_accuracy
                             ? ": a relative error above 1 is not an approximation of a distance"
                             : ""));
      epsilon_given = true;
    }
    else if(arg == "--precision")
    {
      precision = value();
      if(precision != "double" && precision != "float")
        throw Usage_error("--precision must be double or float");
    }
    else
      return false;
    return true;
  }

  // once every option is read
  void check() const
  {
    if(exact_given && epsilon_given && epsilon > 0.)
      throw Usage_error("--exact and --epsilon E > 0 contradict each other");
  }
};

// An argument that is no option (Argument_reader refused the unknown ones): the MESH, given once.
inline void parse_mesh_argument(const std::string& arg, std::string& mesh)
{
  if(!mesh.empty())
    throw Usage_error("more than one MESH given ('" + mesh + "' and '" + arg + "')");
  mesh = arg;
}

inline double peak_rss_mb()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.;
}

inline std::string json_string(const std::string& s)
{
  std::string out = "\"";
  for(char c : s)
  {
    if(c == '"' || c == '\\')
      out += '\\';
    if(static_cast<unsigned char>(c) < 0x20)
    {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
      out += buffer;
    }
    else
      out += c;
  }
  return out + "\"";
}

} // namespace dggvtp

#endif // DGGVTP_COMMAND_LINE_H
