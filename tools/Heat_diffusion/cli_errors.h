// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The tool's two kinds of failure (bad usage, exit 2; bad input, exit 1) and the
// translation of the package's exceptions into the second.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_CLI_ERRORS_H
#define CGAL_HEAT_DIFFUSION_TOOLS_CLI_ERRORS_H

#include <new>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace heat_diffusion_cli {

// Exit codes of the tool.
enum Exit_code { success = 0, bad_input = 1, bad_usage = 2 };

// Thrown for a wrong command line (exit 2) ...
struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};
// ... and for input the tool cannot process or output it cannot write (exit 1).
struct Input_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// `message` with each phrase of `terms` replaced by its other: the package's advice,
// which names its own named parameters, in the words of a front end (the tool's options,
// the Python module's arguments).
inline std::string in_front_end_terms(std::string message,
                                      const std::vector<std::pair<std::string, std::string> >& terms)
{
  for(const auto& term : terms)
    for(std::size_t at = message.find(term.first); at != std::string::npos;
        at = message.find(term.first, at + term.second.size()))
      message.replace(at, term.first.size(), term.second);
  return message;
}

// Runs a call into the package for the input file `input`: every exception it
// throws (invalid input, a failed eigen solve or factorisation, a logic error, out of
// memory) becomes an Input_error whose message starts with the file's name.
template <typename Function>
auto for_input(const std::string& input, Function&& function) -> decltype(function())
{
  try
  {
    return function();
  }
  catch(const Usage_error&)
  {
    throw;
  }
  catch(const Input_error&)
  {
    throw;
  }
  catch(const std::bad_alloc&)
  {
    throw Input_error(input + ": out of memory");
  }
  catch(const std::exception& e)
  {
    throw Input_error(input + ": " + e.what());
  }
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_CLI_ERRORS_H
