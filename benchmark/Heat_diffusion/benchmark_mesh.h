// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A benchmark's input mesh: read, or the benchmark stops (it measures nothing without it).

#ifndef CGAL_HEAT_DIFFUSION_BENCHMARK_MESH_H
#define CGAL_HEAT_DIFFUSION_BENCHMARK_MESH_H

#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace heat_diffusion_benchmark {

// The mesh of `path`, with at least one face; else a message and exit(EXIT_FAILURE).
template <typename Mesh>
Mesh load_mesh_or_exit(const std::string& path)
{
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || num_faces(mesh) == 0)
  {
    std::fprintf(stderr, "cannot read %s\n", path.c_str());
    std::exit(EXIT_FAILURE);
  }
  return mesh;
}

} // namespace heat_diffusion_benchmark

#endif // CGAL_HEAT_DIFFUSION_BENCHMARK_MESH_H
