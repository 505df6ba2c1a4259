// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What every subcommand of the heat_diffusion tool shares: option parsing, reading a
// mesh, writing coloured PLY files atomically, the colour map, JSON summaries, timers.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_CLI_SUPPORT_H
#define CGAL_HEAT_DIFFUSION_TOOLS_CLI_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Heat_diffusion/parameters.h>
#include <CGAL/IO/Color.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <limits>
#include <cstdlib>
#include <iostream>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace heat_diffusion_cli {

namespace fs = std::filesystem;
namespace HD = CGAL::Heat_diffusion;

// The mesh type of the tool.
typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;

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
          values_[a] = argv[++i];
        }
        else
          throw Usage_error("unknown option " + a);
      }
      else
        positional_.push_back(a);
    }
  }

  bool flag(const std::string& name) const
  {
    return std::find(set_flags_.begin(), set_flags_.end(), name) != set_flags_.end();
  }
  bool has(const std::string& name) const { return values_.count(name) != 0; }
  std::string value(const std::string& name, const std::string& fallback) const
  {
    auto it = values_.find(name);
    return it == values_.end() ? fallback : it->second;
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
  std::map<std::string, std::string> values_;
};

// Wall-clock timings of the stages of a run, in milliseconds, in order.
class Stage_timer
{
public:
  void start() { begin_ = std::chrono::steady_clock::now(); }
  void stop(const std::string& stage)
  {
    const auto end = std::chrono::steady_clock::now();
    stages_.emplace_back(stage, std::chrono::duration<double, std::milli>(end - begin_).count());
    begin_ = end;
  }
  const std::vector<std::pair<std::string, double> >& stages() const { return stages_; }

private:
  std::chrono::steady_clock::time_point begin_ = std::chrono::steady_clock::now();
  std::vector<std::pair<std::string, double> > stages_;
};

// A JSON object written member by member; values are numbers, strings or nested
// objects given as already formatted JSON.
class Json_object
{
public:
  Json_object& number(const std::string& key, double value)
  {
    std::ostringstream os;
    if(std::isfinite(value))
      os << std::setprecision(17) << value;
    else
      os << "null";  // JSON has no NaN or infinity
    return raw(key, os.str());
  }
  Json_object& integer(const std::string& key, long long value) { return raw(key, std::to_string(value)); }
  Json_object& boolean(const std::string& key, bool value) { return raw(key, value ? "true" : "false"); }
  Json_object& string(const std::string& key, const std::string& value) { return raw(key, quote(value)); }
  Json_object& object(const std::string& key, const Json_object& value) { return raw(key, value.str()); }
  Json_object& raw(const std::string& key, const std::string& json)
  {
    members_.emplace_back(key, json);
    return *this;
  }
  std::string str() const
  {
    std::string s = "{";
    for(std::size_t i = 0; i < members_.size(); ++i)
      s += (i ? ", " : "") + quote(members_[i].first) + ": " + members_[i].second;
    return s + "}";
  }
  static std::string quote(const std::string& s)
  {
    std::string q = "\"";
    for(char c : s)
    {
      if(c == '"' || c == '\\')
        q += std::string("\\") + c;
      else if(static_cast<unsigned char>(c) < 0x20)
      {
        char buffer[8];
        std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
        q += buffer;
      }
      else
        q += c;
    }
    return q + "\"";
  }

private:
  std::vector<std::pair<std::string, std::string> > members_;
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

// Parses a number of an option, with its valid range.
inline double parse_number(const std::string& option, const std::string& text, double lowest, bool strict)
{
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if(text.empty() || *end != '\0' || !std::isfinite(x) || (strict ? !(x > lowest) : !(x >= lowest)))
    throw Usage_error(option + " must be a number " + (strict ? "> " : ">= ") + std::to_string(lowest) + ", not '" +
                      text + "'");
  return x;
}

// A progress bar on stderr, shown only when stderr is a terminal.
class Progress_bar
{
public:
  Progress_bar(std::string label, bool enabled) : label_(std::move(label)), enabled_(enabled) {}
  ~Progress_bar()
  {
    if(shown_)
      std::cerr << "\r" << std::string(label_.size() + 40, ' ') << "\r" << std::flush;
  }
  bool operator()(double fraction)
  {
    if(!enabled_)
      return true;
    const int percent = int(100 * (std::max)(0., (std::min)(1., fraction)));
    if(percent != last_)
    {
      last_ = percent;
      shown_ = true;
      std::cerr << "\r" << label_ << " [" << std::string(std::size_t(percent / 5), '#')
                << std::string(std::size_t(20 - percent / 5), ' ') << "] " << percent << "%" << std::flush;
    }
    return true;
  }

private:
  std::string label_;
  bool enabled_;
  bool shown_ = false;
  int last_ = -1;
};

inline Json_object timings_json(const Stage_timer& timer)
{
  Json_object o;
  for(const auto& stage : timer.stages())
    o.number(stage.first, stage.second);
  return o;
}

// Checks an OFF stream of `size` bytes before CGAL's reader sees it, and throws
// Input_error (the message names the element) where that reader would not fail
// cleanly: counts larger than the file can hold (a 40-byte file declaring a face of
// 2e9 vertices made it allocate 16 GB), negative, fractional or non-finite counts and
// indices (converted to std::size_t or int without a check: undefined behaviour),
// colours out of range, and the variants it mis-reads (texture coordinates "ST",
// homogeneous "4", n-dimensional "n"). Supported: [C][N]OFF, ASCII or BINARY.
// Leaves `is` at an unspecified position.
inline void check_off_stream(std::istream& is, std::uintmax_t size)
{
  auto fail = [](const std::string& what) { throw Input_error("cannot read the OFF file: " + what); };
  auto text = [](double x) {
    std::ostringstream os;
    os << std::setprecision(17) << x;
    return os.str();
  };
  const double byte_bound = double(size);
  // CGAL's header: '#' comment lines, then a keyword [ST][C][N][4][n]OFF (or SKEL).
  char c = 0;
  while((is >> c) && c == '#')
    is.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  if(!is)
    fail("no OFF header");
  std::string keyword(1, c);
  while(keyword.size() < 41 && is.get(c) && std::isalnum(static_cast<unsigned char>(c)))
    keyword += c;
  if(keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0)
    return;  // not an OFF header: CGAL's reader rejects it at once
  const std::string prefix = keyword.substr(0, keyword.size() - 3);
  if(prefix != "" && prefix != "C" && prefix != "N" && prefix != "CN")
    fail("the variant '" + keyword + "' is not supported (OFF, COFF, NOFF, CNOFF are)");
  const bool colors = prefix.find('C') != std::string::npos, normals = prefix.find('N') != std::string::npos;
  while((is >> c) && c == '#')
    is.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  if(!is)
    fail("no vertex and face counts");
  bool binary = false;
  if(!std::isdigit(static_cast<unsigned char>(c)))
  {
    std::string word(1, c);
    while(word.size() < 41 && is.get(c) && std::isalnum(static_cast<unsigned char>(c)))
      word += c;
    if(word != "BINARY")
      fail("'" + word + "' where the vertex count should be");
    if(c != '\n')
      is.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
    if(colors)
      fail("binary OFF with colours is not supported");
    binary = true;
  }
  else
    is.putback(c);

  // Reads one count of the header.
  auto read_count = [&](const char* what, double lowest, double highest) {
    double x = 0;
    if(binary)
    {
      unsigned char b[4];
      if(!is.read(reinterpret_cast<char*>(b), 4))
        fail(std::string("truncated header (no ") + what + ")");
      x = double(std::int32_t(std::uint32_t(b[0]) << 24 | std::uint32_t(b[1]) << 16 | std::uint32_t(b[2]) << 8 |
                              std::uint32_t(b[3])));
    }
    else
    {
      long long k = 0;
      if(!(is >> k))
        fail(std::string("no ") + what + " in the header");
      x = double(k);
    }
    if(!(x >= lowest && x <= highest))
    {
      fail(std::string("the ") + what + " " + text(x) + " is out of range (" + text(lowest) + " to " +
           text(std::floor(highest)) + " for a file of " + std::to_string(size) + " bytes)");
    }
    return x;
  };
  const std::size_t nv = std::size_t(read_count("vertex count", 0, byte_bound / 6));
  const std::size_t nf = std::size_t(read_count("face count", 0, byte_bound / 2));
  read_count("edge count", -1e9, 1e9);

  // The entries of the next non-comment line, as CGAL's scanner reads them.
  std::string line;
  std::vector<double> entries;
  auto next_line = [&](const std::string& element) {
    while((is >> c) && c == '#')
      is.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
    if(!is)
      fail("truncated: " + element + " is missing");
    is.putback(c);
    std::getline(is, line);
    line = line.substr(0, line.find('#'));
    std::istringstream entry_stream(line);
    entries.clear();
    double d;
    while(entry_stream >> d)
      entries.push_back(d);
  };
  auto is_integer_in = [](double x, double lowest, double highest) {
    return x >= lowest && x <= highest && std::floor(x) == x;
  };
  // CGAL reads 1 (an index into its colour map), 3 or 4 colour values: integers in
  // [0, 255] or fractions in [0, 1]; once an element had a colour, it reads one for
  // every later element of that kind.
  auto check_color = [&](std::size_t first, const std::string& element, bool& seen) {
    const std::size_t count = entries.size() - first;
    bool ok = (count == 0 && !seen) || count == 1 || count == 3 || count == 4;
    seen = seen || count > 0;
    if(ok && count == 1)
      ok = is_integer_in(entries[first], 0, 148);
    if(ok && count >= 3)
    {
      bool integers = true;
      for(std::size_t k = first; k < first + 3; ++k)
        integers = integers && std::floor(entries[k]) == entries[k];
      for(std::size_t k = first; k < first + 3; ++k)
        ok = ok && (integers ? is_integer_in(entries[k], 0, 255) : entries[k] >= 0 && entries[k] <= 1);
    }
    if(!ok)
      fail(element + " has an invalid colour");
  };

  if(binary)
  {
    // big-endian float32 coordinates (and normals), then per face an int32 size and indices
    const std::size_t floats_per_vertex = normals ? 6 : 3;
    if(!is.ignore(std::streamsize(nv * floats_per_vertex * 4)) || std::size_t(is.gcount()) != nv * floats_per_vertex * 4)
      fail("truncated: the file ends among its vertices");
    for(std::size_t f = 0; f < nf; ++f)
    {
      const std::string element = "face " + std::to_string(f);
      const std::size_t k = std::size_t(read_count((element + " size").c_str(), 0, byte_bound / 4));
      for(std::size_t j = 0; j < k; ++j)
        read_count((element + " vertex index").c_str(), 0, double(nv) - 1);
    }
    return;
  }
  const std::size_t coordinates = normals ? 6 : 3;
  bool vertex_colors = false, face_colors = false;
  for(std::size_t v = 0; v < nv; ++v)
  {
    const std::string element = "vertex " + std::to_string(v);
    next_line(element);
    if(entries.size() < coordinates)
      fail(element + " has " + std::to_string(entries.size()) + " numbers, expected " + std::to_string(coordinates) +
           " (a non-finite coordinate such as 'nan' ends the numbers of a line)");
    if(colors)
      check_color(coordinates, element, vertex_colors);
  }
  for(std::size_t f = 0; f < nf; ++f)
  {
    const std::string element = "face " + std::to_string(f);
    next_line(element);
    if(entries.empty() || !is_integer_in(entries[0], 0, double(entries.size()) - 1))
      fail(element + " declares " + (entries.empty() ? std::string("no") : text(entries[0])) +
           " vertices, but its line has " + std::to_string(entries.empty() ? 0 : entries.size() - 1) + " indices");
    const std::size_t k = std::size_t(entries[0]);
    for(std::size_t j = 1; j <= k; ++j)
      if(!is_integer_in(entries[j], 0, double(nv) - 1))
        fail(nv == 0 ? element + " has a vertex index, but the file has no vertices"
                     : element + " has the vertex index " + text(entries[j]) + ", not one of 0.." +
                           std::to_string(nv - 1));
    if(colors)
      check_color(k + 1, element, face_colors);
  }
}

// Reads any format CGAL::IO::read_polygon_mesh reads (OFF, OBJ, PLY, STL, VTP, GOCAD,
// ...), repairing the polygon soup on the way, and triangulates polygon faces.
// Returns the number of faces that were triangulated.
template <typename Mesh>
std::size_t read_triangle_mesh(const std::string& path, Mesh& mesh)
{
  std::error_code ec;
  if(!fs::is_regular_file(path, ec))
    throw Input_error(path + ": no such file");
  std::string extension = fs::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char ch) { return char(std::tolower(ch)); });
  if(extension == ".off")
  {
    std::ifstream is(path, std::ios::binary);
    try
    {
      check_off_stream(is, fs::file_size(path, ec));
    }
    catch(const Input_error& e)
    {
      throw Input_error(path + ": " + e.what());
    }
  }
  bool read = false;
  try
  {
    read = CGAL::IO::read_polygon_mesh(path, mesh);
  }
  catch(const std::exception& e)  // std::bad_alloc, CGAL's assertions
  {
    throw Input_error(path + ": cannot read a polygon mesh (" + e.what() + ")");
  }
  if(!read)
    throw Input_error(path + ": cannot read a polygon mesh (unknown format, unreadable or broken file, "
                             "or a polygon soup that is not a manifold mesh)");
  if(is_empty(mesh) || faces(mesh).size() == 0)
    throw Input_error(path + ": the mesh has no faces");
  std::size_t polygons = 0;
  for(auto f : faces(mesh))
    polygons += CGAL::is_triangle(halfedge(f, mesh), mesh) ? 0 : 1;
  if(polygons > 0 && !CGAL::Polygon_mesh_processing::triangulate_faces(mesh))
    throw Input_error(path + ": cannot triangulate its polygon faces");
  return polygons;
}

// The output path must not name the input: the tool never overwrites its input.
inline void check_output_path(const std::string& output, const std::vector<std::string>& inputs)
{
  std::error_code ec;
  for(const std::string& input : inputs)
    if(fs::absolute(output, ec).lexically_normal() == fs::absolute(input, ec).lexically_normal() ||
       (fs::exists(output, ec) && fs::equivalent(output, input, ec)))
      throw Input_error(output + ": refusing to overwrite the input file");
}

// Writes through `write(std::ostream&)` into a temporary file next to `path`, then
// renames it: a failed run leaves no half-written output. The temporary name is
// one no file has (an input may be called OUT.partial), and the target must be a
// regular file if it exists: renaming over /dev/stdout, run as root, would replace
// the device with a file.
template <typename Writer>
void write_atomically(const std::string& path, const Writer& write)
{
  const fs::path target(path);
  std::error_code ec;
  if(fs::exists(target, ec) && !fs::is_regular_file(target, ec))
    throw Input_error(path + ": cannot write the output file (it exists and is not a regular file)");
  if(target.has_parent_path() && !fs::exists(target.parent_path(), ec))
    fs::create_directories(target.parent_path(), ec);
  fs::path temporary = target.string() + ".partial";
  for(int k = 1; fs::exists(fs::symlink_status(temporary, ec)); ++k)
    temporary = target.string() + ".partial" + std::to_string(k);
  {
    std::ofstream os(temporary, std::ios::binary);
    bool written = false;
    try
    {
      written = os && write(os) && os.flush();
    }
    catch(...)
    {
      os.close();
      fs::remove(temporary, ec);
      throw;
    }
    if(!written)
    {
      os.close();
      fs::remove(temporary, ec);
      throw Input_error(path + ": cannot write the output file");
    }
  }
  fs::rename(temporary, target, ec);
  if(ec)
  {
    fs::remove(temporary, ec);
    throw Input_error(path + ": cannot write the output file (" + ec.message() + ")");
  }
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

struct Field_statistics
{
  double min = 0, max = 0, mean = 0;
  Json_object json() const
  {
    Json_object o;
    o.number("min", min).number("max", max).number("mean", mean);
    return o;
  }
};

inline Field_statistics statistics(const std::vector<double>& values)
{
  Field_statistics s;
  if(values.empty())
    return s;
  s.min = *std::min_element(values.begin(), values.end());
  s.max = *std::max_element(values.begin(), values.end());
  double sum = 0;
  for(double v : values)
    sum += v;
  s.mean = sum / double(values.size());
  return s;
}

// Writes `mesh` as a binary PLY with the given per-vertex scalar fields as double
// properties, and the first one also as the per-vertex colour, saturated at
// `half_range` (default: robust_half_range of that field).
template <typename Point>
void write_fields_ply(const std::string& path, const CGAL::Surface_mesh<Point>& input,
                      const std::vector<std::pair<std::string, std::vector<double> > >& fields,
                      double half_range = 0.)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  Mesh mesh = input;  // the property maps are added to a copy
  for(const auto& field : fields)
  {
    auto map = mesh.template add_property_map<typename Mesh::Vertex_index, double>("v:" + field.first, 0.).first;
    for(auto v : mesh.vertices())
      map[v] = field.second[v.idx()];
  }
  if(!fields.empty())
  {
    if(!(half_range > 0))
      half_range = robust_half_range(fields.front().second);
    auto colors = mesh.template add_property_map<typename Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
    for(auto v : mesh.vertices())
      colors[v] = diverging_color(fields.front().second[v.idx()], half_range);
  }
  write_atomically(path, [&](std::ostream& os) {
    CGAL::IO::set_binary_mode(os);  // use_binary_mode() alone is ignored on streams: ASCII, 6 digits
    return CGAL::IO::write_PLY(os, mesh, "written by CGAL Heat_diffusion",
                               CGAL::parameters::use_binary_mode(true));
  });
}

// The default output name: the input's stem with `suffix`, in the current folder.
inline std::string default_output(const std::string& input, const std::string& suffix)
{
  return fs::path(input).stem().string() + suffix;
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_CLI_SUPPORT_H
