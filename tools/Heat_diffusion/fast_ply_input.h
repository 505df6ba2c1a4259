// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The tool's fast reader of PLY files (ASCII, binary little- and big-endian) into a
// polygon soup. It accepts a strict subset of what CGAL's reader accepts, and reads it
// to the same points and polygons; for everything else it declines (returns false)
// and the tool falls back on its pre-check and CGAL's reader (fast_mesh_soup.h).
//
// Accepted: exactly two elements, "vertex" then "face". The vertex element has the
// scalar properties x, y and z of type float or double, and any other scalar
// properties (normals, colours, ...), which are read and dropped, as CGAL's reader
// drops them for a Surface_mesh. The face element has one property, a list named
// vertex_indices or vertex_index of int or uint indices (the types CGAL's reader
// takes) with an integer length type; every face has three vertices or more.
// Coordinates must be finite.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_FAST_PLY_INPUT_H
#define CGAL_HEAT_DIFFUSION_TOOLS_FAST_PLY_INPUT_H

#include "fast_mesh_soup.h"

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace heat_diffusion_cli {
namespace fast_input {

namespace ply_detail {

enum class Type { none, int8, uint8, int16, uint16, int32, uint32, float32, float64 };

inline Type type_of(const std::string& t)
{
  if(t == "char" || t == "int8")
    return Type::int8;
  if(t == "uchar" || t == "uint8")
    return Type::uint8;
  if(t == "short" || t == "int16")
    return Type::int16;
  if(t == "ushort" || t == "uint16")
    return Type::uint16;
  if(t == "int" || t == "int32")
    return Type::int32;
  if(t == "uint" || t == "uint32")
    return Type::uint32;
  if(t == "float" || t == "float32")
    return Type::float32;
  if(t == "double" || t == "float64")
    return Type::float64;
  return Type::none;
}

inline std::size_t size_of(Type t)
{
  switch(t)
  {
  case Type::int8:
  case Type::uint8:
    return 1;
  case Type::int16:
  case Type::uint16:
    return 2;
  case Type::int32:
  case Type::uint32:
  case Type::float32:
    return 4;
  case Type::float64:
    return 8;
  default:
    return 0;
  }
}

// The range of an integer type, for ASCII values and list lengths.
inline void range_of(Type t, std::int64_t& lowest, std::int64_t& highest)
{
  const int bits = int(8 * size_of(t));
  const bool is_signed = t == Type::int8 || t == Type::int16 || t == Type::int32;
  lowest = is_signed ? -(std::int64_t(1) << (bits - 1)) : 0;
  highest = is_signed ? (std::int64_t(1) << (bits - 1)) - 1 : (std::int64_t(1) << bits) - 1;
}

// What the reader does with a vertex property: a coordinate (0, 1, 2) or nothing (-1).
struct Property
{
  Type type;
  int coordinate;
};

struct Body
{
  const char* p;
  const char* end;
  bool ascii, big_endian;

  // the next value as a double (binary: of `t`, in the file's byte order)
  bool binary_value(Type t, double& x)
  {
    const std::size_t n = size_of(t);
    if(std::size_t(end - p) < n)
      return false;
    unsigned char b[8];
    for(std::size_t i = 0; i < n; ++i)
      b[i] = static_cast<unsigned char>(p[big_endian ? n - 1 - i : i]);  // to little-endian
    p += n;
    std::uint64_t u = 0;
    for(std::size_t i = 0; i < n; ++i)
      u |= std::uint64_t(b[i]) << (8 * i);
    switch(t)
    {
    case Type::int8: x = double(std::int8_t(u)); return true;
    case Type::uint8: x = double(u); return true;
    case Type::int16: x = double(std::int16_t(u)); return true;
    case Type::uint16: x = double(u); return true;
    case Type::int32: x = double(std::int32_t(u)); return true;
    case Type::uint32: x = double(u); return true;
    case Type::float32:
    {
      float f;
      const std::uint32_t v = std::uint32_t(u);
      std::memcpy(&f, &v, 4);
      x = double(f);
      return std::isfinite(f);
    }
    case Type::float64:
      std::memcpy(&x, &u, 8);
      return std::isfinite(x);
    default:
      return false;
    }
  }
  // the next value of type `t` as a double; integer values must fit their type
  bool value(Type t, double& x)
  {
    if(!ascii)
      return binary_value(t, x);
    Cursor c{p, end};
    c.skip_whitespace();
    if(t == Type::float32)
    {
      // read as a float, as CGAL's reader does: the double rounding of a double
      // converted to float could differ
      float f;
      if(!c.real(f))
        return false;
      x = double(f);
    }
    else if(t == Type::float64)
    {
      if(!c.real(x))
        return false;
    }
    else
    {
      std::int64_t lowest, highest, k = 0;
      range_of(t, lowest, highest);
      const std::from_chars_result r = std::from_chars(c.p, c.end, k);
      if(r.ec != std::errc() || k < lowest || k > highest)
        return false;
      c.p = r.ptr;
      if(!c.token_ends())
        return false;
      x = double(k);
    }
    p = c.p;
    return true;
  }
};

}  // namespace ply_detail

inline bool parse_ply(const char* begin, const char* end, Soup& soup)
{
  using namespace ply_detail;
  // The header, line by line, as CGAL's reader splits it into words.
  Cursor c{begin, end};
  std::vector<std::string> words;
  auto next_line = [&]() {
    words.clear();
    if(c.at_end())
      return false;
    const char* line_end = static_cast<const char*>(std::memchr(c.p, '\n', std::size_t(c.end - c.p)));
    if(!line_end)
      return false;
    const char* q = c.p;
    while(q < line_end)
    {
      while(q < line_end && (*q == ' ' || *q == '\t' || *q == '\r'))
        ++q;
      const char* w = q;
      while(q < line_end && *q != ' ' && *q != '\t' && *q != '\r')
        ++q;
      if(q > w)
        words.emplace_back(w, q);
    }
    c.p = line_end + 1;
    return true;
  };
  if(!next_line() || words.empty() || words[0] != "ply")
    return false;
  if(!next_line() || words.size() != 3 || words[0] != "format")
    return false;
  const bool ascii = words[1] == "ascii", big_endian = words[1] == "binary_big_endian";
  if(!ascii && !big_endian && words[1] != "binary_little_endian")
    return false;
  std::vector<Property> vertex_properties;
  Type length_type = Type::none, index_type = Type::none;
  std::uint64_t nv = 0, nf = 0;
  int element = 0;  // 1: vertex, 2: face
  bool seen[3] = {false, false, false};
  for(;;)
  {
    if(!next_line() || words.empty())
      return false;
    if(words[0] == "end_header")
      break;
    if(words[0] == "comment" || words[0] == "obj_info")
      continue;
    if(words[0] == "element" && words.size() == 3)
    {
      Cursor count{words[2].data(), words[2].data() + words[2].size()};
      std::uint64_t n = 0;
      if(!count.whole(n, std::uint64_t(end - begin)) || !count.at_end() || n == 0)
        return false;
      if(element == 0 && words[1] == "vertex")
        nv = n;
      else if(element == 1 && words[1] == "face")
        nf = n;
      else
        return false;
      ++element;
    }
    else if(words[0] == "property" && words.size() == 3 && element == 1)
    {
      const Type t = type_of(words[1]);
      int coordinate = -1;
      for(int k = 0; k < 3; ++k)
        if(words[2] == std::string(1, char('x' + k)))
          coordinate = k;
      if(t == Type::none || (coordinate >= 0 && (seen[coordinate] || (t != Type::float32 && t != Type::float64))))
        return false;
      if(coordinate >= 0)
        seen[coordinate] = true;
      vertex_properties.push_back(Property{t, coordinate});
    }
    else if(words[0] == "property" && words.size() == 5 && element == 2 && words[1] == "list" &&
            length_type == Type::none && (words[4] == "vertex_indices" || words[4] == "vertex_index"))
    {
      length_type = type_of(words[2]);
      index_type = type_of(words[3]);
      if(length_type == Type::none || length_type == Type::float32 || length_type == Type::float64 ||
         (index_type != Type::int32 && index_type != Type::uint32))
        return false;
    }
    else
      return false;
  }
  if(element != 2 || !seen[0] || !seen[1] || !seen[2] || length_type == Type::none || nv > 0xffffffffu)
    return false;

  Body body{c.p, end, ascii, big_endian};
  const std::size_t remaining = std::size_t(end - c.p);
  // a vertex takes a byte at least, a face 4 (both twice that in ASCII)
  if(nv > remaining || nf > remaining / 4)
    return false;
  soup.coordinates.resize(3 * nv);
  for(std::uint64_t v = 0; v < nv; ++v)
    for(const Property& property : vertex_properties)
    {
      double x;
      if(!body.value(property.type, x))
        return false;
      if(property.coordinate >= 0)
        soup.coordinates[3 * v + std::size_t(property.coordinate)] = x;
    }
  soup.indices.reserve(3 * nf);
  soup.starts.reserve(nf + 1);
  for(std::uint64_t f = 0; f < nf; ++f)
  {
    double k = 0;
    if(!body.value(length_type, k) || k < 3 || k > double(std::size_t(end - body.p)))
      return false;
    for(std::size_t j = 0; j < std::size_t(k); ++j)
    {
      double i = 0;
      if(!body.value(index_type, i) || i < 0 || i >= double(nv))
        return false;
      soup.indices.push_back(std::uint32_t(i));
    }
    soup.end_face();
  }
  return true;
}

}  // namespace fast_input
}  // namespace heat_diffusion_cli

#endif  // CGAL_HEAT_DIFFUSION_TOOLS_FAST_PLY_INPUT_H
