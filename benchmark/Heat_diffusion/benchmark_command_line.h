// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The command line of a benchmark, read by the tool's parser: a benchmark runs for
// minutes, so a typing error must stop it at once, not run it with other settings.

#ifndef CGAL_HEAT_DIFFUSION_BENCHMARK_COMMAND_LINE_H
#define CGAL_HEAT_DIFFUSION_BENCHMARK_COMMAND_LINE_H

#include "cli_arguments.h"

#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace heat_diffusion_benchmark {

namespace cli = heat_diffusion_cli;

// Parses argv[1..] with the options `flags` and `valued` (-h and --help are added),
// then calls read_options(arguments), which reads the values into the benchmark's
// settings (cli::parse_number and cli::parse_count throw cli::Usage_error for a value
// out of range). Returns the exit code when the benchmark must not run: 0 after printing
// `usage` for -h or --help; 2 after printing the message and `usage` for an unknown
// option, an option without its value or a bad value. An empty optional otherwise.
template <typename Read_options>
std::optional<int> read_command_line(int argc, char** argv, std::vector<std::string> flags,
                                     std::vector<std::string> valued, const std::string& usage,
                                     Read_options read_options)
{
  flags.push_back("-h");
  flags.push_back("--help");
  cli::Arguments arguments(std::move(flags), std::move(valued));
  try
  {
    arguments.parse(argc, argv, 1);
    if(arguments.flag("-h") || arguments.flag("--help"))
    {
      std::cout << usage;
      return 0;
    }
    read_options(arguments);
  }
  catch(const cli::Usage_error& error)
  {
    std::cerr << argv[0] << ": " << error.what() << "\n" << usage;
    return int(cli::bad_usage);
  }
  return std::nullopt;
}

// The meshes of the option --meshes a.off,b.off (empty names skipped); a usage error if
// it names none.
inline std::vector<std::string> mesh_names(const cli::Arguments& arguments)
{
  std::vector<std::string> names;
  std::stringstream list(arguments.value("--meshes", ""));
  for(std::string name; std::getline(list, name, ',');)
    if(!name.empty())
      names.push_back(name);
  if(names.empty())
    throw cli::Usage_error("--meshes needs at least one mesh");
  return names;
}

// The one optional argument of a benchmark (`what`: DATA_DIR, the directory of CGAL's
// meshes, or TOOL), or `fallback` without it.
inline std::string optional_argument(const cli::Arguments& arguments, const std::string& what,
                                     const std::string& fallback)
{
  const std::vector<std::string>& given = arguments.positional();
  if(given.size() > 1)
    throw cli::Usage_error("one " + what + " at most, not " + std::to_string(given.size()) + " arguments (" +
                           given[0] + ", " + given[1] + ", ...)");
  return given.empty() ? fallback : given[0];
}

} // namespace heat_diffusion_benchmark

#endif // CGAL_HEAT_DIFFUSION_BENCHMARK_COMMAND_LINE_H
