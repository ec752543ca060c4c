// Copyright (c) 2026 The DGG-VTP for CGAL authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s): DGG-VTP for CGAL team

// The words of a command line as dggvtp and dggvtp-batch read them, with the conventions people
// have in their fingers: `--opt=value` as well as `--opt value`, short names (`-o` for --output),
// and an unknown option refused with the nearest known one ("did you mean --sources?").

#ifndef DGGVTP_ARGUMENTS_H
#define DGGVTP_ARGUMENTS_H

#include <dggvtp/command_line.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace dggvtp {

// The options a --help text lists: the first word of each of its lines that start with "  -".
// The usage text is the one list of options, so that the suggestions cannot drift from it.
inline std::vector<std::string> options_of_usage(const std::string& usage)
{
  std::vector<std::string> options;
  std::istringstream lines(usage);
  for(std::string line; std::getline(lines, line);)
    if(line.compare(0, 3, "  -") == 0)
      options.push_back(line.substr(2, line.find(' ', 2) - 2));
  return options;
}

// Edit distance with transpositions (optimal string alignment): "--soruce" is one from "--source".
inline std::size_t edit_distance(const std::string& a, const std::string& b)
{
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for(std::size_t i = 0; i <= a.size(); ++i)
    d[i][0] = i;
  for(std::size_t j = 0; j <= b.size(); ++j)
    d[0][j] = j;
  for(std::size_t i = 1; i <= a.size(); ++i)
    for(std::size_t j = 1; j <= b.size(); ++j)
    {
      const std::size_t change = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = (std::min)({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + change});
      if(i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = (std::min)(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

// The known option nearest to `word`, or "" when none is near: at most 2 edits, and fewer than a
// third of the name's letters, so that --frobnicate suggests nothing. Dashes and case are free
// (-output, --Output: --output).
inline std::string nearest_option(const std::string& word, const std::vector<std::string>& known)
{
  const auto name = [](const std::string& s) {
    std::string n = s.substr(s.find_first_not_of('-') == std::string::npos ? s.size() : s.find_first_not_of('-'));
    for(char& c : n)
      c = char(std::tolower(static_cast<unsigned char>(c)));
    return n;
  };
  const std::string wanted = name(word);
  std::string best;
  std::size_t best_distance = 3;
  for(const std::string& option : known)
  {
    const std::string candidate = name(option);
    const std::size_t distance = edit_distance(wanted, candidate);
    if(distance < best_distance && 3 * distance < candidate.size())
    {
      best = option;
      best_distance = distance;
    }
  }
  return best;
}

// Reads argv one word at a time. An option comes out under its long name, with the value written
// after its '=' kept for value(); a word that looks like an option and is none is a Usage_error.
class Argument_reader
{
public:
  // `short_names`: e.g. {"-o", "--output"}; `usage`: the --help text, whose option lines are the
  // known options
  Argument_reader(int argc, char** argv, std::map<std::string, std::string> short_names, const std::string& usage)
    : m_words(argv + 1, argv + argc), m_short_names(std::move(short_names)), m_known(options_of_usage(usage))
  {
  }

  // Moves to the next word; false after the last one. Throws when the option before took no
  // value but was given one with '='.
  bool next()
  {
    check_value_used();
    if(m_next == m_words.size())
      return false;
    m_word = m_words[m_next++];
    m_attached.clear();
    m_has_attached = false;
    if(m_word.size() < 2 || m_word[0] != '-')
      return true; // an argument (or '-')
    const std::size_t equals = m_word.compare(0, 2, "--") == 0 ? m_word.find('=') : std::string::npos;
    if(equals != std::string::npos)
    {
      m_attached = m_word.substr(equals + 1);
      m_has_attached = true;
      m_word.resize(equals);
    }
    const auto short_name = m_short_names.find(m_word);
    if(short_name != m_short_names.end())
      m_word = short_name->second;
    if(std::find(m_known.begin(), m_known.end(), m_word) == m_known.end())
    {
      const std::string near = nearest_option(m_word, m_known);
      throw Usage_error("unknown option " + m_word + (near.empty() ? std::string() : " (did you mean " + near + "?)"));
    }
    return true;
  }

  // the current word: an option's long name, or an argument
  const std::string& word() const { return m_word; }

  // The current option's next value: the text after its '=', then the words that follow.
  std::string value()
  {
    if(m_has_attached)
    {
      m_has_attached = false;
      return m_attached;
    }
    if(m_next == m_words.size())
      throw Usage_error(m_word + " needs a value");
    return m_words[m_next++];
  }

  // Once every word is read: an '=' value the last option did not take is an error.
  void finish() { check_value_used(); }

private:
  void check_value_used() const
  {
    if(m_has_attached)
      throw Usage_error(m_word + " takes no value (given '" + m_word + "=" + m_attached + "')");
  }

  std::vector<std::string> m_words;
  std::map<std::string, std::string> m_short_names;
  std::vector<std::string> m_known;
  std::size_t m_next = 0;   // index of the next word in m_words
  std::string m_word;       // the current word
  std::string m_attached;   // the value after '=' of the current option
  bool m_has_attached = false; // m_attached is given and not yet taken
};

} // namespace dggvtp

#endif // DGGVTP_ARGUMENTS_H
