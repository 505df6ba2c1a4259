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
#include <CGAL/boost/graph/IO/OBJ.h>
#include <CGAL/boost/graph/IO/OFF.h>
#include <CGAL/boost/graph/IO/PLY.h>
#include <CGAL/boost/graph/IO/STL.h>

#include "fast_mesh_input.h"

#include <unistd.h>

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
#include <new>
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

  // Parses the command line of the subcommand `command` (argv[2] on), which takes one
  // argument, a `what`. Returns false after printing `help` for -h or --help.
  bool parse_command(int argc, char** argv, const std::string& command, const std::string& what,
                     const std::string& help)
  {
    parse(argc, argv, 2);
    if(flag("-h") || flag("--help"))
    {
      std::cout << help;
      return false;
    }
    if(positional_.size() != 1)
      throw Usage_error(command + " takes exactly one " + what + " argument");
    return true;
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

// A number as the messages print it: 0, 1, 1000000, 0.5.
inline std::string format_number(double x)
{
  std::ostringstream os;
  os << std::setprecision(12) << x;
  return os.str();
}

// Parses a finite number of an option, > lowest (strict) or >= lowest, and <= highest.
// Anything else (text, NaN, infinity, out of range) is a usage error naming the option.
inline double parse_number(const std::string& option, const std::string& text, double lowest, bool strict,
                           double highest = std::numeric_limits<double>::max())
{
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if(text.empty() || *end != '\0' || !std::isfinite(x) || (strict ? !(x > lowest) : !(x >= lowest)) || x > highest)
    throw Usage_error(option + " must be a number " + (strict ? "> " : ">= ") + format_number(lowest) +
                      (highest < std::numeric_limits<double>::max() ? " and <= " + format_number(highest) : "") +
                      ", not '" + text + "'");
  return x;
}

// Parses a whole number of an option in [lowest, highest] (bounds well inside the
// range of std::size_t and of double's exact integers): the conversion to std::size_t
// that follows is always defined. "1e3" is accepted, "2.5", "1e30" and "-1" are not.
inline std::size_t parse_count(const std::string& option, const std::string& text, double lowest, double highest)
{
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if(text.empty() || *end != '\0' || !std::isfinite(x) || x != std::floor(x) || x < lowest || x > highest)
    throw Usage_error(option + " must be a whole number from " + format_number(lowest) + " to " +
                      format_number(highest) + ", not '" + text + "'");
  return std::size_t(x);
}

// A progress bar on stderr: shown when stderr is a terminal and not --quiet, and only
// once the work has lasted a second (short work draws nothing). The environment
// variable HEAT_DIFFUSION_PROGRESS=always shows it at once whatever stderr is (for
// tests), =never hides it.
class Progress_bar
{
public:
  Progress_bar(std::string label, bool enabled) : label_(std::move(label)), enabled_(enabled)
  {
    const char* mode = std::getenv("HEAT_DIFFUSION_PROGRESS");
    const std::string m = mode ? mode : "";
    if(m == "never")
      enabled_ = false;
    else if(m == "always")
      delay_ = 0.;
    else
      enabled_ = enabled_ && isatty(STDERR_FILENO);
  }
  ~Progress_bar() { finish(); }
  Progress_bar(const Progress_bar&) = delete;
  Progress_bar& operator=(const Progress_bar&) = delete;

  // Called with the fraction done, in [0, 1]; always returns true (never cancels).
  bool operator()(double fraction)
  {
    if(!enabled_)
      return true;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if(!shown_ && elapsed < delay_)
      return true;
    const int percent = int(100 * (std::max)(0., (std::min)(1., std::isfinite(fraction) ? fraction : 0.)));
    if(percent != last_)
    {
      last_ = percent;
      shown_ = true;
      std::cerr << "\r" << label_ << " [" << std::string(std::size_t(percent / 5), '#')
                << std::string(std::size_t(20 - percent / 5), ' ') << "] " << percent << "%" << std::flush;
    }
    return true;
  }
  // Clears the bar from the terminal line.
  void finish()
  {
    if(shown_)
      std::cerr << "\r" << std::string(label_.size() + 30, ' ') << "\r" << std::flush;
    shown_ = false;
    last_ = -1;
  }

private:
  std::string label_;
  bool enabled_;
  double delay_ = 1.;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  bool shown_ = false;
  int last_ = -1;
};

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

// Checks a PLY stream of `size` bytes before CGAL's reader sees it, and throws
// Input_error (the message names the element) where that reader would not fail
// cleanly: element counts and list lengths larger than the file can hold. CGAL's
// reader sizes a list from its declared length before reading it: a 150-byte file
// declaring a face of 4e9 vertices made it allocate 16 GB and get killed. Walks the
// body once, property by property (ASCII or binary, either byte order); anything it
// does not understand is left to CGAL's reader, which rejects it cleanly.
// Leaves `is` at an unspecified position.
inline void check_ply_stream(std::istream& is, std::uintmax_t size)
{
  auto fail = [](const std::string& what) { throw Input_error("cannot read the PLY file: " + what); };
  auto type_size = [](const std::string& type) -> std::size_t {
    if(type == "char" || type == "int8" || type == "uchar" || type == "uint8")
      return 1;
    if(type == "short" || type == "int16" || type == "ushort" || type == "uint16")
      return 2;
    if(type == "int" || type == "int32" || type == "uint" || type == "uint32" || type == "float" || type == "float32")
      return 4;
    if(type == "double" || type == "float64")
      return 8;
    return 0;
  };
  struct Property
  {
    bool list;
    std::string count_type, value_type, name;
  };
  struct Element
  {
    std::string name;
    double count;
    std::vector<Property> properties;
  };
  std::string line, format;
  if(!std::getline(is, line) || line.compare(0, 3, "ply") != 0)
    return;
  std::vector<Element> elements;
  bool header_ended = false;
  while(!header_ended && std::getline(is, line))
  {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if(keyword == "format")
      words >> format;
    else if(keyword == "element")
    {
      Element e;
      if(!(words >> e.name >> e.count) || !(e.count >= 0) || e.count != std::floor(e.count))
        fail("the header line '" + line + "' has no valid element count");
      elements.push_back(e);
    }
    else if(keyword == "property")
    {
      Property p{false, "", "", ""};
      std::string type;
      words >> type;
      if(type == "list")
      {
        p.list = true;
        words >> p.count_type >> p.value_type >> p.name;
        if(type_size(p.count_type) == 0 || type_size(p.value_type) == 0)
          return;
      }
      else
      {
        p.value_type = type;
        words >> p.name;
        if(type_size(type) == 0)
          return;
      }
      if(elements.empty())
        return;
      elements.back().properties.push_back(p);
    }
    else if(keyword == "end_header")
      header_ended = true;
  }
  const bool ascii = format == "ascii";
  const bool big_endian = format == "binary_big_endian";
  if(!header_ended || (!ascii && !big_endian && format != "binary_little_endian"))
    return;
  const std::streamoff body = is.tellg();
  if(body < 0)
    return;
  const double remaining = double(size) - double(body);
  // Reads a list length: a whole number from 0 to what the rest of the file can hold.
  auto list_length = [&](const Element& e, double k, const Property& p, double bound) -> std::uintmax_t {
    double x = 0;
    if(ascii)
    {
      if(!(is >> x))
        return std::uintmax_t(-1);  // truncated or garbage: CGAL's reader says so
    }
    else
    {
      const std::size_t bytes = type_size(p.count_type);
      unsigned char b[8] = {0};
      if(!is.read(reinterpret_cast<char*>(b), std::streamsize(bytes)))
        return std::uintmax_t(-1);
      std::uint64_t u = 0;
      for(std::size_t i = 0; i < bytes; ++i)
        u |= std::uint64_t(b[big_endian ? bytes - 1 - i : i]) << (8 * i);
      const bool is_signed = p.count_type[0] != 'u';
      if(is_signed && (u >> (8 * bytes - 1)) != 0)
        x = -1;
      else
        x = double(u);
    }
    if(!(x >= 0) || x != std::floor(x) || x > bound)
    {
      std::ostringstream os;
      os << "the " << e.name << " element " << std::size_t(k) << " has a list '" << p.name << "' of " << x
         << " values, more than the file of " << size << " bytes holds";
      fail(os.str());
    }
    return std::uintmax_t(x);
  };
  for(const Element& e : elements)
  {
    // Every element takes a byte at least (two characters in ASCII).
    if(!e.properties.empty() && e.count > remaining / (ascii ? 2 : 1))
    {
      std::ostringstream os;
      os << "the header declares " << e.count << " " << e.name << " elements, more than the file of " << size
         << " bytes holds";
      fail(os.str());
    }
    for(double k = 0; k < e.count; ++k)
      for(const Property& p : e.properties)
      {
        if(!p.list)
        {
          if(ascii)
          {
            std::string word;
            if(!(is >> word))
              return;
          }
          else if(!is.ignore(std::streamsize(type_size(p.value_type))))
            return;
          continue;
        }
        const std::uintmax_t n = list_length(e, k, p, ascii ? remaining / 2 : remaining / double(type_size(p.value_type)));
        if(n == std::uintmax_t(-1))
          return;
        if(ascii)
        {
          std::string word;
          for(std::uintmax_t i = 0; i < n; ++i)
            if(!(is >> word))
              return;
        }
        else if(!is.ignore(std::streamsize(n * type_size(p.value_type))))
          return;
      }
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
  const bool fast = fast_input::read_mesh_fast(path, mesh);  // declines what it does not read
  if(!fast && (extension == ".off" || extension == ".ply"))
  {
    std::ifstream is(path, std::ios::binary);
    try
    {
      if(extension == ".off")
        check_off_stream(is, fs::file_size(path, ec));
      else
        check_ply_stream(is, fs::file_size(path, ec));
    }
    catch(const Input_error& e)
    {
      throw Input_error(path + ": " + e.what());
    }
  }
  bool read = fast;
  try
  {
    read = read || CGAL::IO::read_polygon_mesh(path, mesh);
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
// `half_range` (default: robust_half_range of that field), into `files`.
template <typename Point>
void write_fields_ply(Output_files& files, const std::string& path, const CGAL::Surface_mesh<Point>& input,
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
  files.add(path, [&](std::ostream& os) {
    CGAL::IO::set_binary_mode(os);  // use_binary_mode() alone is ignored on streams: ASCII, 6 digits
    return CGAL::IO::write_PLY(os, mesh, "written by CGAL Heat_diffusion",
                               CGAL::parameters::use_binary_mode(true));
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

// The distance between two points, without overflow or underflow (coordinates near
// 1e300 or 1e-300 square to infinity or zero).
template <typename Point>
double point_distance(const Point& p, const Point& q)
{
  return std::hypot(CGAL::to_double(p.x()) - CGAL::to_double(q.x()), CGAL::to_double(p.y()) - CGAL::to_double(q.y()),
                    CGAL::to_double(p.z()) - CGAL::to_double(q.z()));
}

// The default output name: the input's stem with `suffix`, in the current folder.
inline std::string default_output(const std::string& input, const std::string& suffix)
{
  return fs::path(input).stem().string() + suffix;
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_CLI_SUPPORT_H
