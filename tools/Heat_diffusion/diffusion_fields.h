// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The fields a subcommand diffuses: F^0 (the Normal Signature or a field file), F^k,
// and the change between the diffusion's vertex order and the mesh file's.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_DIFFUSION_FIELDS_H
#define CGAL_HEAT_DIFFUSION_TOOLS_DIFFUSION_FIELDS_H

#include "cli_errors.h"
#include "cli_progress.h"
#include "diffusion_options.h"
#include "diffusion_setup.h"
#include "mesh_input.h"

#include <CGAL/Heat_diffusion/parameters.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace heat_diffusion_cli {

namespace HD = CGAL::Heat_diffusion;

// A field file: one finite number per vertex (or per point: `elements` "points").
inline std::vector<double> read_field(const std::string& path, std::size_t n, const std::string& elements = "vertices")
{
  std::ifstream is(path);
  if(!is)
    throw Input_error(path + ": cannot open the field file");
  std::vector<double> field;
  std::string token;
  while(is >> token)
  {
    char* end = nullptr;
    const double x = std::strtod(token.c_str(), &end);
    if(*end != '\0' || !std::isfinite(x))
      throw Input_error(path + ": value " + std::to_string(field.size()) + " ('" + token + "') is not a finite number");
    field.push_back(x);
  }
  if(field.size() != n)
    throw Input_error(path + ": has " + std::to_string(field.size()) + " values, the " +
                      (elements == "points" ? "point set" : "mesh") + " has " + std::to_string(n) + " " + elements);
  return field;
}

// F^0 by the diffusion's vertex index: the Normal Signature, or a field file with one
// number per vertex in the order of the mesh file.
inline Eigen::VectorXd initial_field(const std::string& source, const Mesh& mesh, const Diffusion& diffusion)
{
  Eigen::VectorXd f0(static_cast<Eigen::Index>(mesh.number_of_vertices()));
  if(source == "ns")
    for(auto v : mesh.vertices())
      f0[Eigen::Index(diffusion.vertex_index(v))] = diffusion.normal_controlled_coordinates().normal_signature(v);
  else
  {
    const std::vector<double> values = read_field(source, mesh.number_of_vertices());
    for(auto v : mesh.vertices())
      f0[Eigen::Index(diffusion.vertex_index(v))] = values[v.idx()];
  }
  return f0;
}

// A field by the diffusion's vertex index, back in the order of the mesh's vertices.
inline std::vector<double> in_mesh_order(const Eigen::VectorXd& field, const Mesh& mesh, const Diffusion& diffusion)
{
  std::vector<double> values(mesh.number_of_vertices());
  for(auto v : mesh.vertices())
    values[v.idx()] = field[Eigen::Index(diffusion.vertex_index(v))];
  return values;
}

// F^k = A_t^k F^0 for every k of `steps`, with a progress bar over the steps.
inline std::vector<Eigen::VectorXd> diffuse_fields(const Diffusion& diffusion, const Eigen::VectorXd& f0,
                                                   const std::vector<std::size_t>& steps, const Diffusion_options& o,
                                                   const std::string& input)
{
  Progress_bar progress("diffusion", !o.quiet);
  return for_input(input, [&] {
    return diffusion.diffuse(f0, steps,
                             HD::parameters::progress_callback(std::function<bool(double)>(std::ref(progress))));
  });
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_DIFFUSION_FIELDS_H
