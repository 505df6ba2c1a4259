// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The output files of a run: where they may go, written atomically (all of a run's
// outputs or none), meshes by their extension, and scalar fields as coloured PLYs.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_CLI_OUTPUT_H
#define CGAL_HEAT_DIFFUSION_TOOLS_CLI_OUTPUT_H

#include "cli_errors.h"
#include "fast_ply_output.h"

#include <CGAL/IO/Color.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/OBJ.h>
#include <CGAL/boost/graph/IO/OFF.h>
#include <CGAL/boost/graph/IO/PLY.h>
#include <CGAL/boost/graph/IO/STL.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace heat_diffusion_cli {

namespace fs = std::filesystem;

// The default output name: the input's stem with `suffix`, in the current folder.
inline std::string default_output(const std::string& input, const std::string& suffix)
{
  return fs::path(input).stem().string() + suffix;
}

// The output path must not name the input (the tool never overwrites its input), and
// must not name something other than a regular file: checked before any work.
inline void check_output_path(const std::string& output, const std::vector<std::string>& inputs)
{
  std::error_code ec;
  for(const std::string& input : inputs)
    if(fs::absolute(output, ec).lexically_normal() == fs::absolute(input, ec).lexically_normal() ||
       (fs::exists(output, ec) && fs::equivalent(output, input, ec)))
      throw Input_error(output + ": refusing to overwrite the input file");
  if(fs::exists(output, ec) && !fs::is_regular_file(output, ec))
    throw Input_error(output + ": cannot write the output file (it exists and is not a regular file)");
}

// The output files of one run. Each file is written into a temporary file next to its
// target; commit() renames them all at the end, and the destructor removes whatever
// was not committed: a failed run (at any stage, in any file) leaves no output and no
// temporary file. The temporary name is one no file has (an input may be called
// OUT.partial), and a target must be a regular file if it exists: renaming over
// /dev/stdout, run as root, would replace the device with a file.
class Output_files
{
public:
  Output_files() = default;
  Output_files(const Output_files&) = delete;
  Output_files& operator=(const Output_files&) = delete;
  ~Output_files()
  {
    std::error_code ec;
    for(const auto& file : staged_)
      fs::remove(file.first, ec);
  }

  // Writes through `write(std::ostream&)` (which returns the stream or a bool) into
  // the temporary file of `path`.
  template <typename Writer>
  void add(const std::string& path, const Writer& write)
  {
    const fs::path target(path);
    std::error_code ec;
    if(fs::exists(target, ec) && !fs::is_regular_file(target, ec))
      throw Input_error(path + ": cannot write the output file (it exists and is not a regular file)");
    if(target.has_parent_path() && !fs::exists(target.parent_path(), ec))
      fs::create_directories(target.parent_path(), ec);
    fs::path temporary = target.string() + ".partial";
    for(int k = 1; fs::exists(fs::symlink_status(temporary, ec)) || is_staged(temporary); ++k)
      temporary = target.string() + ".partial" + std::to_string(k);
    std::ofstream os(temporary, std::ios::binary);
    if(!os)
      throw Input_error(path + ": cannot write the output file");
    staged_.emplace_back(temporary, target);
    bool written = false;
    written = bool(write(os)) && bool(os.flush());
    os.close();
    if(!written || !os)
      throw Input_error(path + ": cannot write the output file");
  }

  // Renames every temporary file to its target. If one rename fails, the targets
  // already renamed are removed too: all or nothing.
  void commit()
  {
    std::error_code ec;
    for(std::size_t i = 0; i < staged_.size(); ++i)
    {
      fs::rename(staged_[i].first, staged_[i].second, ec);
      if(ec)
      {
        const std::string message = staged_[i].second.string() + ": cannot write the output file (" + ec.message() + ")";
        for(std::size_t j = 0; j < i; ++j)
          fs::remove(staged_[j].second, ec);
        staged_.erase(staged_.begin(), staged_.begin() + std::ptrdiff_t(i));
        throw Input_error(message);
      }
    }
    staged_.clear();
  }

private:
  bool is_staged(const fs::path& temporary) const
  {
    for(const auto& file : staged_)
      if(file.first == temporary)
        return true;
    return false;
  }

  std::vector<std::pair<fs::path, fs::path> > staged_;  // temporary, target
};

// One output file, written atomically (temporary file + rename).
template <typename Writer>
void write_atomically(const std::string& path, const Writer& write)
{
  Output_files files;
  files.add(path, write);
  files.commit();
}

// A diverging colour map (Moreland's cool-warm): blue for negative values (concave
// for the NS), white at 0, red for positive ones (convex), symmetric about 0.
inline CGAL::IO::Color diverging_color(double value, double half_range)
{
  static const double blue[3] = {59, 76, 192}, white[3] = {221, 221, 221}, red[3] = {180, 4, 38};
  double x = half_range > 0 ? value / half_range : 0.;
  x = std::isfinite(x) ? (std::max)(-1., (std::min)(1., x)) : 0.;
  const double* end = x < 0 ? blue : red;
  const double a = std::abs(x);
  unsigned char rgb[3];
  for(int k = 0; k < 3; ++k)
    rgb[k] = static_cast<unsigned char>(std::lround((1 - a) * white[k] + a * end[k]));
  return CGAL::IO::Color(rgb[0], rgb[1], rgb[2]);
}

// The half range of the colour map: the 98th percentile of |value|, so that a few
// extreme vertices do not wash out the picture.
inline double robust_half_range(std::vector<double> values)
{
  for(double& v : values)
    v = std::abs(v);
  if(values.empty())
    return 1.;
  const std::size_t k = static_cast<std::size_t>(0.98 * double(values.size() - 1));
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
  return values[k] > 0 ? values[k] : 1.;
}

// Writes `mesh` as a binary PLY with the given per-vertex scalar fields as double
// properties, and the first one also as the per-vertex colour, saturated at
// `half_range` (default: robust_half_range of that field), into `files`.
template <typename Point>
void write_fields_ply(Output_files& files, const std::string& path, const CGAL::Surface_mesh<Point>& input,
                      const std::vector<std::pair<std::string, std::vector<double> > >& fields,
                      double half_range = 0.)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  const char* const comment = "written by CGAL Heat_diffusion";
  if(!fields.empty() && !(half_range > 0))
    half_range = robust_half_range(fields.front().second);
  auto color_of = [&](std::size_t v) { return diverging_color(fields.front().second[v], half_range); };
  files.add(path, [&](std::ostream& os) {
    CGAL::IO::set_binary_mode(os);  // use_binary_mode() alone is ignored on streams: ASCII, 6 digits
    if(fast_output::write_fields_ply(os, input, comment, fields, color_of))
      return true;
    Mesh mesh = input;  // the property maps are added to a copy
    for(const auto& field : fields)
    {
      auto map = mesh.template add_property_map<typename Mesh::Vertex_index, double>("v:" + field.first, 0.).first;
      for(auto v : mesh.vertices())
        map[v] = field.second[v.idx()];
    }
    if(!fields.empty())
    {
      auto colors = mesh.template add_property_map<typename Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
      for(auto v : mesh.vertices())
        colors[v] = color_of(v.idx());
    }
    return CGAL::IO::write_PLY(os, mesh, comment, CGAL::parameters::use_binary_mode(true));
  });
}

// The same, as a single output file.
template <typename Point>
void write_fields_ply(const std::string& path, const CGAL::Surface_mesh<Point>& input,
                      const std::vector<std::pair<std::string, std::vector<double> > >& fields,
                      double half_range = 0.)
{
  Output_files files;
  write_fields_ply(files, path, input, fields, half_range);
  files.commit();
}

// The mesh format of an output path, from its extension: a usage error if the tool
// cannot write it.
inline std::string mesh_format(const std::string& path)
{
  std::string extension = fs::path(path).extension().string();
  for(char& ch : extension)
    ch = char(std::tolower(static_cast<unsigned char>(ch)));
  if(extension != ".off" && extension != ".obj" && extension != ".ply" && extension != ".stl")
    throw Usage_error("the output " + path + " must end in .off, .obj, .ply or .stl");
  return extension;
}

// Writes a mesh atomically, by the extension of `path`: OFF and OBJ as text with 17
// significant digits (exact doubles), PLY and STL binary.
template <typename Point>
void write_mesh(const std::string& path, const CGAL::Surface_mesh<Point>& mesh)
{
  const std::string format = mesh_format(path);
  write_atomically(path, [&](std::ostream& os) {
    const auto np = CGAL::parameters::stream_precision(17);
    if(format == ".off")
      return CGAL::IO::write_OFF(os, mesh, np);
    if(format == ".obj")
      return CGAL::IO::write_OBJ(os, mesh, np);
    CGAL::IO::set_binary_mode(os);
    if(format == ".ply")
      return CGAL::IO::write_PLY(os, mesh, "written by CGAL Heat_diffusion", CGAL::parameters::use_binary_mode(true));
    return CGAL::IO::write_STL(os, mesh, CGAL::parameters::use_binary_mode(true));
  });
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_CLI_OUTPUT_H
