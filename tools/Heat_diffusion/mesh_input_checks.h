// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The checks of OFF and PLY files that run before CGAL's readers see them: where those
// readers would not fail cleanly (huge allocations, undefined conversions), the tool
// rejects the file with a message that names the element.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_MESH_INPUT_CHECKS_H
#define CGAL_HEAT_DIFFUSION_TOOLS_MESH_INPUT_CHECKS_H

#include "cli_errors.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <istream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace heat_diffusion_cli {

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
// Input_error (the message names the element or header line) where that reader would
// not fail cleanly:
// - a property declared before any element: it added it to the last of no elements;
// - a property of a type PLY does not have: it skipped the declaration and misread
//   the body;
// - element counts and list lengths larger than the file can hold: it sizes a list
//   from its declared length before reading it, and a 150-byte file declaring a face
//   of 4e9 vertices made it allocate 16 GB and get killed; it also loops over the
//   elements of a type without properties, and adds a point for each vertex;
// - list lengths their type does not hold, which it wraps around;
// - a header without an end_header line, or a body that ends (or stops being
//   numbers) before its last element: it reads on from the failed stream, takes the
//   list length it could not read from uninitialised memory and sized the list from
//   it (an allocation of 5.7 GB, found by fuzzing);
// - vertex coordinates x, y, z missing, or not of type float or double (a crash).
// The header is read as that reader reads it (the format is the second word of the
// second line, whatever the first), so that no file passes unchecked.
// Walks the body once, property by property (ASCII or binary, either byte order);
// anything else it does not understand is left to CGAL's reader, which rejects it
// cleanly. Leaves `is` at an unspecified position.
inline void check_ply_stream(std::istream& is, std::uintmax_t size)
{
  auto fail = [](const std::string& what) { throw Input_error("cannot read the PLY file: " + what); };
  // The bytes of a PLY type and its largest value (0 bytes: not a PLY type).
  struct Type
  {
    std::size_t bytes;
    double largest;
  };
  auto type_of = [](const std::string& type) -> Type {
    if(type == "char" || type == "int8")
      return {1, 127.};
    if(type == "uchar" || type == "uint8")
      return {1, 255.};
    if(type == "short" || type == "int16")
      return {2, 32767.};
    if(type == "ushort" || type == "uint16")
      return {2, 65535.};
    if(type == "int" || type == "int32")
      return {4, 2147483647.};
    if(type == "uint" || type == "uint32")
      return {4, 4294967295.};
    if(type == "float" || type == "float32")
      return {4, std::numeric_limits<double>::infinity()};
    if(type == "double" || type == "float64")
      return {8, std::numeric_limits<double>::infinity()};
    return {0, 0.};
  };
  auto type_size = [&](const std::string& type) { return type_of(type).bytes; };
  struct Property
  {
    bool list;
    std::string count_type, value_type, name;
  };
  struct Element
  {
    std::string name;
    std::string declared;  // the count as the header writes it
    double count;
    std::vector<Property> properties;
  };
  // The first two lines as CGAL's reader reads them: the first word "ply", and the
  // format as the second word of the second line, whatever its first.
  std::string line, first_word, format;
  if(!std::getline(is, line) || !(std::istringstream(line) >> first_word) || first_word != "ply" ||
     !std::getline(is, line) || !(std::istringstream(line) >> first_word >> format))
    return;  // CGAL's reader rejects the file itself
  std::vector<Element> elements;
  bool header_ended = false;
  while(!header_ended && std::getline(is, line))
  {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if(keyword == "element")
    {
      // Digits only: CGAL's reader takes the count as an unsigned integer, and would read
      // "1e3" as 1 and "-5" as 2^64 - 5.
      Element e;
      if(!(words >> e.name >> e.declared) || e.declared.size() > 19 ||
         e.declared.find_first_not_of("0123456789") != std::string::npos)
        fail("the header line '" + line + "' has no valid element count");
      e.count = std::stod(e.declared);
      elements.push_back(e);
    }
    else if(keyword == "property")
    {
      if(elements.empty())  // CGAL's reader would add it to the last of no elements
        fail("the header line '" + line + "' declares a property before any element");
      Property p{false, "", "", ""};
      std::string type;
      words >> type;
      if(type == "list")
      {
        p.list = true;
        words >> p.count_type >> p.value_type >> p.name;
        if(type_size(p.count_type) == 0 || type_size(p.value_type) == 0)
          fail("the header line '" + line + "' has a type that is not a PLY type");
      }
      else
      {
        p.value_type = type;
        words >> p.name;
        if(type_size(type) == 0)  // CGAL's reader skips the declaration and misreads the body
          fail("the header line '" + line + "' has a type that is not a PLY type");
      }
      elements.back().properties.push_back(p);
    }
    else if(keyword == "end_header")
      header_ended = true;
  }
  const bool ascii = format == "ascii";
  const bool big_endian = format == "binary_big_endian";
  if(!ascii && !big_endian && format != "binary_little_endian")
    return;  // CGAL's reader rejects the format itself
  if(!header_ended)
    fail("the header has no end_header line");
  // CGAL's reader takes the first property of each name as a coordinate of type float or
  // double; another type made it dereference a null pointer (a crash), and a missing
  // one gave the coordinate 0.
  for(const Element& e : elements)
    if(e.name == "vertex" || e.name == "vertices")
      for(const char* coordinate : {"x", "y", "z"})
      {
        auto p = std::find_if(e.properties.begin(), e.properties.end(),
                              [&](const Property& q) { return q.name == coordinate; });
        if(p == e.properties.end())
          fail("the " + e.name + " element has no property '" + coordinate + "'");
        const std::string& type = p->value_type;
        if(p->list || !(type == "float" || type == "float32" || type == "double" || type == "float64"))
          fail("the " + e.name + " property '" + coordinate + "' is " + (p->list ? "a list" : "of type " + p->value_type) +
               "; the reader takes coordinates of type float or double");
      }
  const std::streamoff body = is.tellg();
  if(body < 0)
    return;
  const double remaining = double(size) - double(body);
  auto ends_before = [&](const Element& e, double k) {
    std::ostringstream os;
    os << "the file ends" << (ascii && !is.eof() ? ", or has something that is not a number," : "") << " in the "
       << e.name << " element " << std::size_t(k) << " (the header declares " << e.declared << ")";
    fail(os.str());
  };
  // Skips `n` values of the given type.
  auto skip = [&](const Element& e, double k, std::uintmax_t n, const std::string& type) {
    if(ascii)
    {
      std::string word;
      for(std::uintmax_t i = 0; i < n; ++i)
        if(!(is >> word))
          ends_before(e, k);
    }
    else
    {
      const std::streamsize bytes = std::streamsize(n * type_size(type));
      if(!is.ignore(bytes) || is.gcount() != bytes)
        ends_before(e, k);
    }
  };
  // Reads a list length: a whole number from 0 to what the rest of the file can hold.
  auto list_length = [&](const Element& e, double k, const Property& p, double bound) -> std::uintmax_t {
    double x = 0;
    if(ascii)
    {
      if(!(is >> x))
        ends_before(e, k);
    }
    else
    {
      const std::size_t bytes = type_size(p.count_type);
      unsigned char b[8] = {0};
      if(!is.read(reinterpret_cast<char*>(b), std::streamsize(bytes)))
        ends_before(e, k);
      std::uint64_t u = 0;
      for(std::size_t i = 0; i < bytes; ++i)
        u |= std::uint64_t(b[big_endian ? bytes - 1 - i : i]) << (8 * i);
      const bool is_signed = p.count_type[0] != 'u';
      if(is_signed && (u >> (8 * bytes - 1)) != 0)
        x = -1;
      else
        x = double(u);
    }
    // CGAL's reader would wrap a length its type does not hold: char 200 to 2^64 - 56.
    if(ascii && x > type_of(p.count_type).largest)
    {
      std::ostringstream os;
      os << "the " << e.name << " element " << std::size_t(k) << " has a list '" << p.name << "' of length " << x
         << ", more than its type " << p.count_type << " holds";
      fail(os.str());
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
    // Every element takes a byte at least (two characters in ASCII). An element without
    // properties takes none, but CGAL's reader still loops over it (and adds a point
    // per vertex): its count is bounded the same way.
    if(e.count > remaining / (ascii ? 2 : 1))
    {
      std::ostringstream os;
      os << "the header declares " << e.declared << " " << e.name << " elements, more than the file of " << size
         << " bytes holds";
      fail(os.str());
    }
    if(e.properties.empty())
      continue;
    for(double k = 0; k < e.count; ++k)
      for(const Property& p : e.properties)
      {
        const std::uintmax_t n =
            p.list ? list_length(e, k, p, ascii ? remaining / 2 : remaining / double(type_size(p.value_type))) : 1;
        skip(e, k, n, p.value_type);
      }
  }
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_MESH_INPUT_CHECKS_H
