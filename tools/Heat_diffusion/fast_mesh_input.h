// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The tool's fast mesh input: OFF, PLY and OBJ files read in one pass over the file in
// memory, to the same Surface_mesh CGAL::IO::read_polygon_mesh builds from them.
// CGAL's reader goes through an istream, a string and a stringstream per line and a
// vector per face; on a mesh of millions of vertices it took a third of the tool's run.
//
// read_mesh_fast() either reads the file (true) or declines (false, mesh left empty):
// other extensions, variants it does not read (colours, normals, comments among the
// elements, ...; the parsers list what they accept) and every invalid or suspicious
// file. The tool then reads the file as before, so that what it accepts, and the
// message of what it rejects, do not depend on this reader.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_FAST_MESH_INPUT_H
#define CGAL_HEAT_DIFFUSION_TOOLS_FAST_MESH_INPUT_H

#include "fast_mesh_soup.h"
#include "fast_off_obj_input.h"
#include "fast_ply_input.h"

#include <algorithm>
#include <cctype>
#include <new>
#include <string>
#include <vector>

namespace heat_diffusion_cli {
namespace fast_input {

// The polygon soup of the file at `path`, if a fast parser accepts it.
inline bool read_soup(const std::string& path, Soup& soup)
{
  const std::size_t dot = path.find_last_of('.');
  if(dot == std::string::npos || path.find_first_of("/\\", dot) != std::string::npos)
    return false;
  std::string extension = path.substr(dot + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char ch) { return char(std::tolower(ch)); });
  bool (*parse)(const char*, const char*, Soup&) = nullptr;
  if(extension == "off")
    parse = &parse_off;
  else if(extension == "ply")
    parse = &parse_ply;
  else if(extension == "obj")
    parse = &parse_obj;
  else
    return false;
  const File_in_memory file(path);
  return file.ok() && parse(file.begin(), file.end(), soup);
}

template <typename Mesh>
bool read_mesh_fast(const std::string& path, Mesh& mesh)
{
  if(!is_empty(mesh))
    return false;
  try
  {
    Soup soup;
    if(!read_soup(path, soup))
      return false;
    return build_mesh(soup, mesh);
  }
  catch(const std::bad_alloc&)  // CGAL's reader reports it as before
  {
    mesh.clear();
    return false;
  }
}

}  // namespace fast_input
}  // namespace heat_diffusion_cli

#endif  // CGAL_HEAT_DIFFUSION_TOOLS_FAST_MESH_INPUT_H
