// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// heat_diffusion: the command-line tool of the CGAL Heat_diffusion package.
// One subcommand per capability; see `heat_diffusion --help`.

// Each subcommand lives in command_<name>.h and defines run_<name>(argc, argv).
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

using namespace heat_diffusion_cli;

namespace {

const char* const general_help =
    "heat_diffusion - multi-scale anisotropic heat diffusion on triangle meshes (CGAL Heat_diffusion)\n"
    "\n"
    "Usage: heat_diffusion COMMAND [OPTIONS]\n"
    "       heat_diffusion COMMAND --help\n"
    "\n"
    "Commands:\n"
    "  ncc MESH     Normal-Controlled Coordinates and the Normal Signature (NS) of a mesh\n"
    "  diffuse MESH Anisotropic, heat-conserving multi-scale diffusion of the NS or of a field\n"
    "  features MESH  Convex and concave features of the diffused NS (or a field) at scales k\n"
    "  hks MESH       The heat kernel signature and its maxima (the paper's baseline)\n"
    "  decompose MESH Detail bands and residual of the NS (or a field), each band of sum 0\n"
    "  enhance MESH   Shape editing: reweighted NS detail bands, e.g. --weights 1,3,3\n"
    "  denoise NOISY  Mesh denoising by diffusion of the NS (eq. 22-23), writes OFF, OBJ, PLY or STL\n"
    "\n"
    "The subcommands that diffuse (diffuse, features, hks, decompose, enhance, denoise) share\n"
    "their options, with the same meaning and checks: --sigma S, --time T, --kernel spectral|local,\n"
    "-m M (eigenpairs), --coarse N (coarse level of the eigen solve), -k (diffusion steps),\n"
    "-o, --json, --quiet. A progress bar on stderr follows long work when stderr is a terminal.\n"
    "\n"
    "MESH is any file CGAL::IO::read_polygon_mesh reads (OFF, OBJ, PLY, STL, VTP, TS, ...);\n"
    "polygon faces are triangulated. Exit status: 0 success, 1 bad input (the message names\n"
    "the file and the problem), 2 bad usage (the message names the option). Outputs are written\n"
    "atomically (all of a run's outputs, or none) and never over an input file.\n";

} // namespace

int main(int argc, char** argv)
{
  try
  {
    const std::string command = argc > 1 ? argv[1] : "";
    if(command == "-h" || command == "--help" || command == "help")
    {
      std::cout << general_help;
      return success;
    }
    if(command == "ncc")
      return run_ncc(argc, argv);
    if(command == "diffuse")
      return run_diffuse(argc, argv);
    if(command == "features")
      return run_features(argc, argv);
    if(command == "hks")
      return run_hks(argc, argv);
    if(command == "decompose")
      return run_decompose(argc, argv);
    if(command == "enhance")
      return run_enhance(argc, argv);
    if(command == "denoise")
      return run_denoise(argc, argv);
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
