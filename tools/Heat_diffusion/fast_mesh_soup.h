// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What the tool's fast mesh readers share: the file read into memory at once, a
// cursor over it that converts numbers with std::from_chars (no allocation per token,
// no locale, no stream state), the polygon soup in flat arrays, and the construction
// of the Surface_mesh from it by the calls CGAL's own readers make, in the same order.
//
// A fast reader never reports an error: it declines (returns false) whenever the file
// is not one it understands completely and validly, and the tool then reads the file
// as before, with its pre-checks and CGAL's reader, which give today's messages.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_FAST_MESH_SOUP_H
#define CGAL_HEAT_DIFFUSION_TOOLS_FAST_MESH_SOUP_H

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <system_error>
#include <vector>

namespace heat_diffusion_cli {
namespace fast_input {

// The whole file in memory: mapped (the page cache's pages, nothing to copy or to
// clear), or else read in one call. No stream per token.
class File_in_memory
{
public:
  File_in_memory(const File_in_memory&) = delete;
  File_in_memory& operator=(const File_in_memory&) = delete;
  explicit File_in_memory(const std::string& path)
  {
    const int fd = ::open(path.c_str(), O_RDONLY);
    if(fd < 0)
      return;
    struct stat st;
    if(::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0)
    {
      size_ = std::size_t(st.st_size);
      void* p = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
      if(p != MAP_FAILED)
      {
        mapped_ = p;
        data_ = static_cast<const char*>(p);
      }
      else
      {
        std::ifstream is(path, std::ios::binary);
        copy_.resize(size_);
        if(is.read(copy_.data(), std::streamsize(size_)))
          data_ = copy_.data();
      }
    }
    ::close(fd);
  }
  ~File_in_memory()
  {
    if(mapped_)
      ::munmap(mapped_, size_);
  }
  bool ok() const { return data_ != nullptr; }
  const char* begin() const { return data_; }
  const char* end() const { return data_ + size_; }

private:
  void* mapped_ = nullptr;
  const char* data_ = nullptr;
  std::size_t size_ = 0;
  std::vector<char> copy_;
};

// The points and the polygons of a file: polygon f has the vertex indices
// indices[starts[f]] to indices[starts[f + 1]] - 1.
struct Soup
{
  std::vector<double> coordinates;  // x, y, z of each vertex
  std::vector<std::uint32_t> indices;
  std::vector<std::size_t> starts{0};

  std::size_t number_of_vertices() const { return coordinates.size() / 3; }
  std::size_t number_of_faces() const { return starts.size() - 1; }
  void end_face() { starts.push_back(indices.size()); }
};

// A position in a text. The readers ask for exactly the tokens they
// expect; anything else makes them decline.
struct Cursor
{
  const char* p;
  const char* end;

  bool at_end() const { return p >= end; }
  // spaces and tabs, and the '\r' of a CRLF line end
  void skip_blanks()
  {
    while(p < end && (*p == ' ' || *p == '\t' || *p == '\r'))
      ++p;
  }
  void skip_whitespace()
  {
    while(p < end && (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n' || *p == '\f' || *p == '\v'))
      ++p;
  }
  // the end of the current line: blanks, then '\n' or the end of the file
  bool end_of_line()
  {
    skip_blanks();
    if(p >= end)
      return true;
    if(*p != '\n')
      return false;
    ++p;
    return true;
  }
  void skip_line()
  {
    const void* n = std::memchr(p, '\n', std::size_t(end - p));
    p = n ? static_cast<const char*>(n) + 1 : end;
  }
  // A token must be followed by whitespace or the end of the file: "1.5f" or "3/4" are
  // not numbers here (CGAL's scanners would split them, and the reader declines).
  bool token_ends() const
  {
    return p >= end || *p == ' ' || *p == '\t' || *p == '\r' || *p == '\n' || *p == '\f' || *p == '\v';
  }
  // A finite decimal number, converted as strtod (hence CGAL's sscanf) converts it:
  // correctly rounded, so the coordinates are bit-identical. No sign '+', no "inf" or
  // "nan", no overflow: those files go to CGAL's reader and the pre-checks.
  template <typename Real>
  bool real(Real& x)
  {
    const std::from_chars_result r = std::from_chars(p, end, x);
    if(r.ec != std::errc() || !std::isfinite(x))
      return false;
    p = r.ptr;
    return token_ends();
  }
  // An unsigned decimal integer no larger than `highest`.
  bool whole(std::uint64_t& k, std::uint64_t highest)
  {
    if(p >= end || *p < '0' || *p > '9')
      return false;
    const std::from_chars_result r = std::from_chars(p, end, k);
    if(r.ec != std::errc() || k > highest)
      return false;
    p = r.ptr;
    return token_ends();
  }
  // The keyword `w` as a whole token. Unlike the scanners above, it moves on only when
  // it matches: a caller tries one keyword after another ("BINARY5" is not "BINARY").
  bool word(const char* w)
  {
    const std::size_t n = std::strlen(w);
    if(std::size_t(end - p) < n || std::memcmp(p, w, n) != 0)
      return false;
    const char* const start = p;
    p += n;
    if(token_ends())
      return true;
    p = start;
    return false;
  }
};

// Builds `mesh` from the soup as CGAL's Generic_facegraph_builder (behind
// CGAL::IO::read_polygon_mesh for OFF, OBJ and PLY) does: the vertices in file order,
// each face by CGAL::Euler::add_face in file order, then is_valid(). The same calls
// in the same order give the same halfedges, hence the same circulation order around
// each vertex, hence bit-identical results downstream. Reserving the storage first
// does not change the indices. Returns false (mesh cleared) where that builder fails.
template <typename Mesh>
bool build_mesh(const Soup& soup, Mesh& mesh)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef typename Mesh::Point Point;
  const std::size_t nv = soup.number_of_vertices(), nf = soup.number_of_faces();
  mesh.reserve(typename Mesh::size_type(nv), typename Mesh::size_type(soup.indices.size() / 2 + nf),
               typename Mesh::size_type(nf));
  std::vector<vertex_descriptor> vertices(nv);
  auto vpm = get(CGAL::vertex_point, mesh);
  for(std::size_t i = 0; i < nv; ++i)
  {
    vertices[i] = add_vertex(mesh);
    put(vpm, vertices[i], Point(soup.coordinates[3 * i], soup.coordinates[3 * i + 1], soup.coordinates[3 * i + 2]));
  }
  std::vector<vertex_descriptor> face;
  for(std::size_t f = 0; f < nf; ++f)
  {
    face.clear();
    for(std::size_t j = soup.starts[f]; j < soup.starts[f + 1]; ++j)
      face.push_back(vertices[soup.indices[j]]);
    if(CGAL::Euler::add_face(face, mesh) == boost::graph_traits<Mesh>::null_face())
    {
      mesh.clear();
      return false;
    }
  }
  if(!is_valid(mesh))
  {
    mesh.clear();
    return false;
  }
  return true;
}

// What the fast readers promise, for the tests, the fuzz target and the benchmark: the
// same vertices (bit-identical points, same order), the same faces and halfedges
// (same indices, same next, target and face of each halfedge), the same halfedge of
// each vertex (where circulations start), and, if `same_property_maps`, the same
// property maps (false to compare with CGAL's readers, which add colour maps).
template <typename Mesh>
bool identical_meshes(const Mesh& a, const Mesh& b, bool same_property_maps = true)
{
  if(a.number_of_vertices() != b.number_of_vertices() || a.number_of_faces() != b.number_of_faces() ||
     a.number_of_halfedges() != b.number_of_halfedges() || a.has_garbage() || b.has_garbage())
    return false;
  typedef typename Mesh::Vertex_index Vertex_index;
  typedef typename Mesh::Face_index Face_index;
  if(same_property_maps && (a.template properties<Vertex_index>() != b.template properties<Vertex_index>() ||
                            a.template properties<Face_index>() != b.template properties<Face_index>()))
    return false;
  for(auto v : a.vertices())
    if(std::memcmp(&a.point(v), &b.point(v), sizeof(a.point(v))) != 0 || a.halfedge(v) != b.halfedge(v))
      return false;
  for(auto h : a.halfedges())
    if(a.next(h) != b.next(h) || a.target(h) != b.target(h) || a.face(h) != b.face(h))
      return false;
  for(auto f : a.faces())
    if(a.halfedge(f) != b.halfedge(f))
      return false;
  return true;
}

}  // namespace fast_input
}  // namespace heat_diffusion_cli

#endif  // CGAL_HEAT_DIFFUSION_TOOLS_FAST_MESH_SOUP_H
