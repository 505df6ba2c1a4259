// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// heat_diffusion: the command-line tool of the CGAL Heat_diffusion package.
// One subcommand per capability; see `heat_diffusion --help`.

// Each subcommand lives in command_<name>.h and defines its table entry, <name>_command().
#include "command.h"
#include "command_diffuse.h"
#include "command_decompose.h"
#include "command_denoise.h"
#include "command_enhance.h"
#include "command_features.h"
#include "command_hks.h"
#include "command_ncc.h"

#include <exception>
#include <iostream>
#include <string>
#include <vector>

using namespace heat_diffusion_cli;

namespace {

// The subcommands, in the order of the tool's --help.
const std::vector<Command>& commands()
{
  static const std::vector<Command> table = {ncc_command(),       diffuse_command(), features_command(),
                                             hks_command(),       decompose_command(), enhance_command(),
                                             denoise_command()};
  return table;
}

std::string general_help()
{
  std::string help = "heat_diffusion - multi-scale anisotropic heat diffusion on triangle meshes (CGAL Heat_diffusion)\n"
                     "\n"
                     "Usage: heat_diffusion COMMAND [OPTIONS]\n"
                     "       heat_diffusion COMMAND --help\n"
                     "\n"
                     "Commands:\n";
  for(const Command& command : commands())
    help += "  " + command.overview + "\n";
  return help +
         "\n"
         "The subcommands that diffuse (diffuse, features, hks, decompose, enhance, denoise) share\n"
         "their options, with the same meaning and checks: --sigma S, --time T, --kernel spectral|local,\n"
         "-m M (eigenpairs), --coarse N (coarse level of the eigen solve), -k (diffusion steps),\n"
         "-o, --json, --quiet. A progress bar on stderr follows long work when stderr is a terminal.\n"
         "\n"
         "MESH is any file CGAL::IO::read_polygon_mesh reads (OFF, OBJ, PLY, STL, VTP, TS, ...);\n"
         "polygon faces are triangulated. ncc, diffuse and features also run on POINTS, a file of\n"
         "points without faces (XYZ, PWN, or PLY or OFF without faces; normals read if it has them),\n"
         "with --neighbors K (see their --help); the others refuse it. Exit status: 0 success, 1 bad input (the message names\n"
         "the file and the problem), 2 bad usage (the message names the option). Outputs are written\n"
         "atomically (all of a run's outputs, or none) and never over an input file.\n";
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    const std::string command = argc > 1 ? argv[1] : "";
    if(command == "-h" || command == "--help" || command == "help")
    {
      std::cout << general_help();
      return success;
    }
    for(const Command& c : commands())
      if(c.name == command)
        return run_command(c, argc, argv);
    throw Usage_error(command.empty() ? "missing COMMAND" : "unknown command '" + command + "'");
  }
  catch(const Usage_error& e)
  {
    std::cerr << "heat_diffusion: " << e.what() << "\n(see heat_diffusion --help)\n";
    return bad_usage;
  }
  catch(const Input_error& e)
  {
    std::cerr << "heat_diffusion: " << e.what() << "\n";
    return bad_input;
  }
  catch(const std::exception& e)
  {
    std::cerr << "heat_diffusion: error: " << e.what() << "\n";
    return bad_input;
  }
}
