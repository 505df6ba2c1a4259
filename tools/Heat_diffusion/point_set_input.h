// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The tool's point sets: which input files hold points without faces, and their
// reading into a CGAL::Point_set_3, with the file's normals where it has some.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_POINT_SET_INPUT_H
#define CGAL_HEAT_DIFFUSION_TOOLS_POINT_SET_INPUT_H

#include "cli_errors.h"
#include "mesh_input.h"
#include "mesh_input_checks.h"

#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace heat_diffusion_cli {

// The tool's point set: its points, and a normal map where the file gives normals.
typedef CGAL::Point_set_3<Kernel::Point_3, Kernel::Vector_3> Point_set;

// Whether `path` is a file of points without faces: an XYZ or PWN file (formats of
// points only), or a PLY or OFF file whose header declares vertices and no face (a PLY
// without a face element or with "element face 0", as CGAL's and VCG's point files
// are; an OFF file whose face count is 0). Only the header is read. A file with faces,
// or whose header cannot be read, is not: it takes the mesh path, which reports it.
inline bool holds_points_only(const std::string& path)
{
  std::error_code ec;
  if(!std::filesystem::is_regular_file(path, ec))
    return false;  // (the mesh path says so)
  const std::string extension = lower_case_extension(path);
  if(extension == ".xyz" || extension == ".pwn")
    return true;
  if(extension != ".ply" && extension != ".off")
    return false;
  std::ifstream is(path, std::ios::binary);
  std::string line;
  if(extension == ".ply")
  {
    // "element NAME COUNT" lines up to end_header (a header has a few dozen lines)
    long long vertices = -1, faces = 0;
    for(int n = 0; n < 1000 && std::getline(is, line); ++n)
    {
      std::istringstream words(line);
      std::string keyword, name, count;
      words >> keyword;
      if(n == 0 && keyword != "ply")
        return false;
      if(keyword == "end_header")
        return vertices > 0 && faces == 0;
      if(keyword != "element")
        continue;
      words >> name >> count;
      if(count.empty() || count.find_first_not_of("0123456789") != std::string::npos || count.size() > 18)
        return false;
      if(name == "vertex")
        vertices = std::stoll(count);
      else if(name == "face")
        faces = std::stoll(count);
    }
    return false;
  }
  // OFF: the keyword ([ST][C][N]OFF, not binary), then the counts of vertices and faces
  std::vector<std::string> tokens;
  for(int n = 0; n < 1000 && tokens.size() < 3 && std::getline(is, line); ++n)
  {
    std::istringstream words(line.substr(0, line.find('#')));
    std::string word;
    while(tokens.size() < 3 && words >> word)
      tokens.push_back(word);
  }
  if(tokens.size() < 3 || tokens[0].size() < 3 || tokens[0].compare(tokens[0].size() - 3, 3, "OFF") != 0 ||
     tokens[0].find_first_of("4n") != std::string::npos)
    return false;
  const auto is_count = [](const std::string& s) {
    return !s.empty() && s.size() < 18 && s.find_first_not_of("0123456789") == std::string::npos;
  };
  return is_count(tokens[1]) && is_count(tokens[2]) && std::stoll(tokens[1]) > 0 && std::stoll(tokens[2]) == 0;
}

// Reads the points of `path` (holds_points_only()) with CGAL::IO::read_point_set(),
// which reads XYZ, PWN and OFF with CGAL::IO::read_points() and PLY with the point
// set's own reader, and keeps a normal map where the file has normals (nx, ny, nz in a
// PLY; three more numbers per line in XYZ, PWN and OFF). PLY and OFF files are checked
// first (check_ply_stream(), check_off_stream()) against what CGAL's readers do not
// read cleanly. Throws Input_error, naming the file, where nothing is read.
inline void read_point_file(const std::string& path, Point_set& points)
{
  std::error_code ec;
  if(!std::filesystem::is_regular_file(path, ec))
    throw Input_error(path + ": no such file");
  const std::string extension = lower_case_extension(path);
  std::string note;
  bool read = false;
  try
  {
    if(extension == ".ply" || extension == ".off")
    {
      std::ifstream is(path, std::ios::binary);
      if(extension == ".ply")
        check_ply_stream(is, std::filesystem::file_size(path, ec));
      else
        check_off_stream(is, std::filesystem::file_size(path, ec));
    }
    const Captured_error_stream errors;
    read = CGAL::IO::read_point_set(path, points);
    note = errors.note();
  }
  catch(const Input_error& e)
  {
    throw Input_error(path + ": " + e.what());
  }
  catch(const std::exception& e)  // std::bad_alloc, CGAL's assertions
  {
    throw Input_error(path + ": cannot read the points (" + e.what() + ")");
  }
  if(!read)
    throw Input_error(path + ": cannot read the points (unreadable or broken file)" + note);
  if(points.empty())
    throw Input_error(path + ": the file holds no points");
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_POINT_SET_INPUT_H
