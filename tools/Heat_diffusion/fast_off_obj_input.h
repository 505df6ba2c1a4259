// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The tool's fast readers of OFF (ASCII and binary) and OBJ files into a polygon soup.
// They accept a strict subset of what CGAL's readers accept, and read it to the same
// points and polygons; for everything else they decline (return false) and the tool
// falls back on its pre-checks and CGAL's reader (fast_mesh_soup.h says why).
//
// OFF, accepted: '#' comment lines before the counts; the keyword "OFF" (not COFF,
// NOFF, ...: CGAL stores their colours and normals in property maps); ASCII, one vertex
// of exactly three numbers per line and one face "k i_1 ... i_k" (k >= 3) per line,
// blank lines between elements but no comment; or "BINARY" (big-endian, CGAL's
// binary OFF): float32 coordinates, int32 face sizes and indices. Counts within the
// bounds of the tool's OFF pre-check (a vertex takes 6 bytes at least, a face 2).
//
// OBJ, accepted: "v x y z [ignored]" lines, "f" lines of three or more positive
// indices ("i", "i/t", "i/t/n", "i//n"), and the lines CGAL skips too (comments,
// vt, vn, vp, o, g, s, usemtl, mtllib). Negative (relative) indices, tabs in a face
// line, and every other statement are left to CGAL's reader.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_FAST_OFF_OBJ_INPUT_H
#define CGAL_HEAT_DIFFUSION_TOOLS_FAST_OFF_OBJ_INPUT_H

#include "fast_mesh_soup.h"

#include <cstdint>
#include <cstring>
#include <vector>

namespace heat_diffusion_cli {
namespace fast_input {

namespace off_detail {

// Skips whitespace and '#' comment lines, as CGAL's OFF header scanner does.
inline void skip_comments(Cursor& c)
{
  for(;;)
  {
    c.skip_whitespace();
    if(c.at_end() || *c.p != '#')
      return;
    c.skip_line();
  }
}

inline std::int64_t big_endian_int32(const char* p)
{
  const unsigned char* b = reinterpret_cast<const unsigned char*>(p);
  return std::int64_t(std::int32_t(std::uint32_t(b[0]) << 24 | std::uint32_t(b[1]) << 16 |
                                   std::uint32_t(b[2]) << 8 | std::uint32_t(b[3])));
}

inline float big_endian_float32(const char* p)
{
  const std::uint32_t u = std::uint32_t(big_endian_int32(p));
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

inline bool parse_binary_off(Cursor& c, Soup& soup, double size)
{
  if(c.end - c.p < 12)
    return false;
  const std::int64_t nv = big_endian_int32(c.p), nf = big_endian_int32(c.p + 4), ne = big_endian_int32(c.p + 8);
  c.p += 12;
  if(nv <= 0 || nf <= 0 || double(nv) > size / 6 || double(nf) > size / 2 || ne < -1000000000 || ne > 1000000000)
    return false;
  if(c.end - c.p < 12 * nv)
    return false;
  soup.coordinates.resize(std::size_t(3 * nv));
  for(std::size_t i = 0; i < std::size_t(3 * nv); ++i, c.p += 4)
  {
    const float x = big_endian_float32(c.p);
    if(!std::isfinite(x))
      return false;
    soup.coordinates[i] = double(x);
  }
  soup.indices.reserve(std::size_t(3 * nf));
  soup.starts.reserve(std::size_t(nf) + 1);
  for(std::int64_t f = 0; f < nf; ++f)
  {
    if(c.end - c.p < 4)
      return false;
    const std::int64_t k = big_endian_int32(c.p);
    c.p += 4;
    if(k < 3 || c.end - c.p < 4 * k)
      return false;
    for(std::int64_t j = 0; j < k; ++j, c.p += 4)
    {
      const std::int64_t i = big_endian_int32(c.p);
      if(i < 0 || i >= nv)
        return false;
      soup.indices.push_back(std::uint32_t(i));
    }
    soup.end_face();
  }
  return true;
}

}  // namespace off_detail

inline bool parse_off(const char* begin, const char* end, Soup& soup)
{
  Cursor c{begin, end};
  const double size = double(end - begin);
  off_detail::skip_comments(c);
  if(!c.word("OFF"))
    return false;
  off_detail::skip_comments(c);
  if(c.word("BINARY"))
  {
    // CGAL's header scanner skips the rest of the keyword's line
    if(!c.at_end() && *c.p == '\n')
      ++c.p;
    else
      c.skip_line();
    return off_detail::parse_binary_off(c, soup, size);
  }
  std::uint64_t nv = 0, nf = 0, ne = 0;
  if(!c.whole(nv, std::uint64_t(size / 6)))
    return false;
  c.skip_whitespace();
  if(!c.whole(nf, std::uint64_t(size / 2)))
    return false;
  c.skip_whitespace();
  if(!c.whole(ne, 1000000000) || !c.end_of_line() || nv == 0 || nf == 0 || nv > 0xffffffffu)
    return false;
  soup.coordinates.resize(3 * nv);
  double* x = soup.coordinates.data();
  for(std::uint64_t v = 0; v < nv; ++v, x += 3)
  {
    c.skip_whitespace();
    if(c.at_end() || *c.p == '#')
      return false;
    if(!c.real(x[0]))
      return false;
    c.skip_blanks();
    if(!c.real(x[1]))
      return false;
    c.skip_blanks();
    if(!c.real(x[2]) || !c.end_of_line())
      return false;
  }
  soup.indices.reserve(3 * nf);
  soup.starts.reserve(nf + 1);
  for(std::uint64_t f = 0; f < nf; ++f)
  {
    c.skip_whitespace();
    if(c.at_end() || *c.p == '#')
      return false;
    std::uint64_t k = 0;
    if(!c.whole(k, std::uint64_t(size / 2)) || k < 3)
      return false;
    for(std::uint64_t j = 0; j < k; ++j)
    {
      c.skip_blanks();
      std::uint64_t i = 0;
      if(!c.whole(i, nv - 1))
        return false;
      soup.indices.push_back(std::uint32_t(i));
    }
    if(!c.end_of_line())
      return false;
    soup.end_face();
  }
  return true;  // what follows the last face is ignored, as CGAL's reader ignores it
}

namespace obj_detail {

// The statements CGAL's OBJ reader accepts and ignores (a subset of its list).
inline bool ignored_statement(const char* p, std::size_t n)
{
  static const char* const names[] = {"vt", "vn", "vp", "o", "g", "s", "usemtl", "mtllib"};
  for(const char* name : names)
    if(std::strlen(name) == n && std::memcmp(name, p, n) == 0)
      return true;
  return n > 0 && p[0] == '#';
}

// One vertex reference of a face line, as CGAL reads it: an integer, then everything
// up to and including the next space (the "/t/n" parts). Returns false to decline.
inline bool face_index(Cursor& c, std::uint64_t& i)
{
  if(c.at_end() || *c.p < '1' || *c.p > '9')
    return false;
  const std::from_chars_result r = std::from_chars(c.p, c.end, i);
  if(r.ec != std::errc() || i > 0xffffffffu)
    return false;
  c.p = r.ptr;
  if(!c.at_end() && *c.p == '/')
  {
    const char* start = c.p;
    while(!c.at_end() && *c.p != ' ' && *c.p != '\n' && *c.p != '\r')
    {
      if(*c.p == '\t' || c.p - start >= 255)
        return false;
      ++c.p;
    }
  }
  if(!c.at_end() && *c.p == ' ')
    ++c.p;
  return c.at_end() || *c.p == ' ' || *c.p == '\n' || *c.p == '\r' || (*c.p >= '1' && *c.p <= '9');
}

}  // namespace obj_detail

inline bool parse_obj(const char* begin, const char* end, Soup& soup)
{
  Cursor c{begin, end};
  // A first pass counts the lines that start with "v " and "f ": no reallocation
  // while reading, and no storage beyond what the file holds.
  std::size_t vertex_lines = 0, face_lines = 0;
  for(const char* p = begin; p < end;)
  {
    if(end - p > 1 && p[1] == ' ')
    {
      vertex_lines += p[0] == 'v' ? 1 : 0;
      face_lines += p[0] == 'f' ? 1 : 0;
    }
    const void* n = std::memchr(p, '\n', std::size_t(end - p));
    p = n ? static_cast<const char*>(n) + 1 : end;
  }
  soup.coordinates.reserve(3 * vertex_lines);
  soup.indices.reserve(3 * face_lines);
  soup.starts.reserve(face_lines + 1);
  while(!c.at_end())
  {
    c.skip_blanks();
    if(c.end_of_line())
      continue;
    const char* keyword = c.p;
    while(!c.at_end() && !c.token_ends())
      ++c.p;
    const std::size_t n = std::size_t(c.p - keyword);
    if(n == 1 && keyword[0] == 'v')
    {
      double x[3];
      for(double& xi : x)
      {
        c.skip_blanks();
        if(!c.real(xi))
          return false;
      }
      soup.coordinates.insert(soup.coordinates.end(), x, x + 3);
      c.skip_line();  // CGAL reads three numbers and ignores the rest of the line
    }
    else if(n == 1 && keyword[0] == 'f')
    {
      if(c.at_end() || *c.p != ' ')
        return false;
      std::size_t k = 0;
      for(;;)
      {
        while(!c.at_end() && (*c.p == ' ' || *c.p == '\r'))
          ++c.p;
        if(c.at_end() || *c.p == '\n')
          break;
        std::uint64_t i = 0;
        if(!obj_detail::face_index(c, i))
          return false;
        soup.indices.push_back(std::uint32_t(i - 1));
        ++k;
      }
      if(k < 3)
        return false;
      soup.end_face();
      c.skip_line();
    }
    else if(obj_detail::ignored_statement(keyword, n))
      c.skip_line();
    else
      return false;
  }
  const std::size_t nv = soup.number_of_vertices();
  if(nv == 0 || soup.number_of_faces() == 0)
    return false;
  for(std::uint32_t i : soup.indices)
    if(i >= nv)
      return false;
  return true;
}

}  // namespace fast_input
}  // namespace heat_diffusion_cli

#endif  // CGAL_HEAT_DIFFUSION_TOOLS_FAST_OFF_OBJ_INPUT_H
