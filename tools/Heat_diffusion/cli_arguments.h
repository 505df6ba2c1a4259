// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The command line of a subcommand: its options, checked numbers and lists, and the
// layout of its --help text.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_CLI_ARGUMENTS_H
#define CGAL_HEAT_DIFFUSION_TOOLS_CLI_ARGUMENTS_H

#include "cli_errors.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace heat_diffusion_cli {

// Options of one subcommand: positional arguments, flags and valued options, each
// declared before parsing so that unknown options are usage errors.
class Arguments
{
public:
  Arguments(std::vector<std::string> flags, std::vector<std::string> valued)
    : flags_(std::move(flags)), valued_(std::move(valued))
  {}

  void parse(int argc, char** argv, int first)
  {
    for(int i = first; i < argc; ++i)
    {
      const std::string a = argv[i];
      if(a.size() > 1 && a[0] == '-' && !is_number(a))
      {
        if(std::find(flags_.begin(), flags_.end(), a) != flags_.end())
          set_flags_.push_back(a);
        else if(std::find(valued_.begin(), valued_.end(), a) != valued_.end())
        {
          if(i + 1 >= argc)
            throw Usage_error("option " + a + " needs a value");
          values_[a].push_back(argv[++i]);
        }
        else
          throw Usage_error("unknown option " + a);
      }
      else
        positional_.push_back(a);
    }
  }

  // Parses the command line of the subcommand `command` (argv[2] on), which takes one
  // argument, a `what`. Returns false after printing `help` for -h or --help.
  bool parse_command(int argc, char** argv, const std::string& command, const std::string& what,
                     const std::string& help)
  {
    parse(argc, argv, 2);
    if(flag("-h") || flag("--help"))
    {
      std::cout << help;
      return false;
    }
    if(positional_.size() != 1)
      throw Usage_error(command + " takes exactly one " + what + " argument");
    return true;
  }

  bool flag(const std::string& name) const
  {
    return std::find(set_flags_.begin(), set_flags_.end(), name) != set_flags_.end();
  }
  bool has(const std::string& name) const { return values_.count(name) != 0; }
  // The option's value (its last, if it is repeated), or `fallback`.
  std::string value(const std::string& name, const std::string& fallback) const
  {
    auto it = values_.find(name);
    return it == values_.end() ? fallback : it->second.back();
  }
  // Every value of a repeated option, in the order given.
  std::vector<std::string> values(const std::string& name) const
  {
    auto it = values_.find(name);
    return it == values_.end() ? std::vector<std::string>() : it->second;
  }
  const std::vector<std::string>& positional() const { return positional_; }

private:
  static bool is_number(const std::string& s)
  {
    char* end = nullptr;
    std::strtod(s.c_str(), &end);
    return end != s.c_str() && *end == '\0';
  }

  std::vector<std::string> flags_, valued_, set_flags_, positional_;
  std::map<std::string, std::vector<std::string> > values_;
};

// Parses a comma-separated list of non-negative integers ("0,10,40").
inline std::vector<std::size_t> parse_steps(const std::string& text)
{
  std::vector<std::size_t> steps;
  std::stringstream ss(text);
  std::string item;
  while(std::getline(ss, item, ','))
  {
    char* end = nullptr;
    const long long k = std::strtoll(item.c_str(), &end, 10);
    if(item.empty() || *end != '\0' || k < 0 || k > 1000000)
      throw Usage_error("-k takes a comma-separated list of steps between 0 and 1000000, not '" + text + "'");
    steps.push_back(std::size_t(k));
  }
  if(steps.empty())
    throw Usage_error("-k needs at least one step");
  return steps;
}

// A number as the messages print it: 0, 1, 1000000, 0.5.
inline std::string format_number(double x)
{
  std::ostringstream os;
  os << std::setprecision(12) << x;
  return os.str();
}

// Parses a finite number of an option, > lowest (strict) or >= lowest, and <= highest.
// Anything else (text, NaN, infinity, out of range) is a usage error naming the option.
inline double parse_number(const std::string& option, const std::string& text, double lowest, bool strict,
                           double highest = std::numeric_limits<double>::max())
{
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if(text.empty() || *end != '\0' || !std::isfinite(x) || (strict ? !(x > lowest) : !(x >= lowest)) || x > highest)
    throw Usage_error(option + " must be a number " + (strict ? "> " : ">= ") + format_number(lowest) +
                      (highest < std::numeric_limits<double>::max() ? " and <= " + format_number(highest) : "") +
                      ", not '" + text + "'");
  return x;
}

// Parses a whole number of an option in [lowest, highest] (bounds well inside the
// range of std::size_t and of double's exact integers): the conversion to std::size_t
// that follows is always defined. "1e3" is accepted, "2.5", "1e30" and "-1" are not.
inline std::size_t parse_count(const std::string& option, const std::string& text, double lowest, double highest)
{
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if(text.empty() || *end != '\0' || !std::isfinite(x) || x != std::floor(x) || x < lowest || x > highest)
    throw Usage_error(option + " must be a whole number from " + format_number(lowest) + " to " +
                      format_number(highest) + ", not '" + text + "'");
  return std::size_t(x);
}

// One option of a --help text: the name in a column of 20 characters, the text
// wrapped at 92 columns ('\n' in the text starts a new line).
inline std::string help_option(const std::string& name, const std::string& text)
{
  const std::size_t indent = 22, width = 92;
  std::string result, line = "  " + name;
  if(line.size() + 1 > indent)
  {
    result += line + "\n";
    line.clear();
  }
  line.resize(indent, ' ');
  bool empty = true, first = true;
  std::istringstream paragraphs(text);
  std::string paragraph;
  while(std::getline(paragraphs, paragraph, '\n'))
  {
    if(!first)
    {
      result += line + "\n";
      line.assign(indent, ' ');
      empty = true;
    }
    first = false;
    std::istringstream words(paragraph);
    std::string word;
    while(words >> word)
    {
      if(!empty && line.size() + 1 + word.size() > width)
      {
        result += line + "\n";
        line.assign(indent, ' ');
        empty = true;
      }
      line += (empty ? "" : " ") + word;
      empty = false;
    }
  }
  return result + line + "\n";
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_CLI_ARGUMENTS_H
