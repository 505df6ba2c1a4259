// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// libFuzzer target: arbitrary bytes as a mesh or point file (PLY if they start with
// "ply", OBJ if a line starts with "v ", XYZ if they start with a number, OFF
// otherwise), through
// - the tool's fast reader, compared with its checked reading (the pre-checks, CGAL's
//   soup reader, the face index check) and, for OFF, with CGAL::IO::read_OFF;
// - the tool's whole reading, read_triangle_mesh(), on the bytes as a file, strict and
//   with the repair it applies by default;
// - for OFF, the API user's paths: CGAL::IO::read_OFF into a Surface_mesh, and the
//   documented repair of a soup (repair_polygon_soup, orient_polygon_soup);
// then NCC, the reconstruction, the default denoising, a small heat kernel (m <= 10),
// diffusion and feature detection, with parameters drawn from the input. A file of
// points without faces (the tool's holds_points_only()) goes the tool's point-set way
// instead: read_point_file(), then the point-set NCC, diffusion, features and denoising
// with k neighbours drawn from the input, with the file's normals and without them.
//
// Fine: std::invalid_argument and std::runtime_error from the package, an Input_error
// from the tool's reading (and any std::exception from CGAL's reading and repair on
// the API user's paths). A bug: any other exception, a crash, a sanitizer report, a
// NaN or infinity in an output when nothing was thrown, heat that is not conserved.
//
// Run by scripts/sanitize_and_fuzz.sh; test/Heat_diffusion/fuzz/regressions/ holds
// the inputs that once failed.

#include "mesh_input.h"       // the tool's reading, Input_error, the tool's Mesh
#include "point_set_input.h"  // the tool's reading of point files, its Point_set

#include <CGAL/Heat_diffusion/Anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/Edge_weighted_heat_kernel.h>
#include <CGAL/Heat_diffusion/denoising.h>
#include <CGAL/Heat_diffusion/multiscale_features.h>
#include <CGAL/Heat_diffusion/normal_controlled_coordinates.h>
#include <CGAL/Heat_diffusion/point_set_anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/point_set_denoising.h>
#include <CGAL/Heat_diffusion/point_set_multiscale_features.h>
#include <CGAL/Heat_diffusion/reconstruction.h>

#include <CGAL/IO/OFF.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

namespace HD = CGAL::Heat_diffusion;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef heat_diffusion_cli::Mesh Mesh;
typedef Mesh::Vertex_index Vertex;

// Bounds that keep one execution well below a second under the sanitizers.
const std::size_t maximum_input_bytes = 4096;
const std::size_t maximum_vertices = 64;
const std::size_t maximum_faces = 160;
const std::size_t maximum_points = 64;

[[noreturn]] void bug(const std::string& what)
{
  std::fprintf(stderr, "fuzz_mesh_pipeline: BUG: %s\n", what.c_str());
  std::abort();
}

void require(bool condition, const std::string& what)
{
  if(!condition)
    bug(what);
}

// Parameters drawn from the input bytes (a hash), so that the fuzzer explores them too.
struct Parameters
{
  std::size_t m = 10;
  double sigma = 0.1, time = 1.;
  bool scale_invariant = false;
};

Parameters parameters_of(const std::uint8_t* data, std::size_t size)
{
  std::uint64_t h = 1469598103934665603ull;
  for(std::size_t i = 0; i < size; ++i)
    h = (h ^ data[i]) * 1099511628211ull;
  Parameters p;
  p.m = 1 + std::size_t(h % 10);
  const double sigmas[] = {1e-3, 0.1, 1., std::numeric_limits<double>::infinity()};
  const double times[] = {1e-2, 1., 50.};
  p.sigma = sigmas[(h >> 8) % 4];
  p.time = times[(h >> 16) % 3];
  p.scale_invariant = ((h >> 24) & 1) != 0;
  return p;
}

// The package on one mesh. Returns normally when it computed finite results or
// threw std::invalid_argument / std::runtime_error; calls bug() otherwise.
void run_package(const Mesh& mesh, const Parameters& p)
{
  const std::size_t n = mesh.number_of_vertices();
  if(n > maximum_vertices || mesh.number_of_faces() > maximum_faces)
    return;
  try
  {
    const HD::Normal_controlled_coordinates<Mesh> ncc(mesh);
    std::map<Vertex, double> ns;
    for(Vertex v : mesh.vertices())
    {
      const auto d = ncc.ncc(v);
      ns[v] = ncc.normal_signature(v);
      require(std::isfinite(ns[v]) && std::isfinite(d.x()) && std::isfinite(d.y()) && std::isfinite(d.z()),
              "NCC not finite");
    }

    {
      Mesh copy = mesh;
      try
      {
        HD::reconstruct_from_normal_signature(copy, boost::make_assoc_property_map(ns));
        for(Vertex v : copy.vertices())
        {
          const auto& q = copy.point(v);
          require(std::isfinite(q.x()) && std::isfinite(q.y()) && std::isfinite(q.z()),
                  "reconstructed position not finite");
        }
      }
      catch(const std::runtime_error&)  // a singular system is reported, not an error here
      {
      }
    }

    {
      Mesh copy = mesh;
      try
      {
        HD::denoise_mesh(copy);
        for(Vertex v : copy.vertices())
        {
          const auto& q = copy.point(v);
          require(std::isfinite(q.x()) && std::isfinite(q.y()) && std::isfinite(q.z()),
                  "denoised position not finite");
        }
      }
      catch(const std::invalid_argument&)  // documented: a degenerate iteration of the signature diffusion
      {
      }
      catch(const std::runtime_error&)  // documented: a failed factorisation
      {
      }
    }

    const HD::Edge_weighted_heat_kernel<Mesh> kernel(
        mesh, HD::parameters::combine(HD::parameters::number_of_eigenpairs(p.m), HD::parameters::sigma(p.sigma),
                                      HD::parameters::scale_invariant_kernel(p.scale_invariant)));
    require(kernel.number_of_eigenpairs() == (std::min)(p.m, n), "m not clamped");
    require(kernel.eigenvalues().allFinite() && kernel.eigenvectors().allFinite(), "eigenpairs not finite");
    // Eigenvalues that are rounding noise come out slightly negative from the solver;
    // the kernel clamps them at 0 so that exp(-rate t) cannot overflow (a fuzzing find).
    for(std::size_t k = 0; k < kernel.number_of_eigenpairs(); ++k)
      require(kernel.decay_rate(k) >= 0, "negative decay rate");
    for(Vertex v : mesh.vertices())
      require(std::isfinite(kernel.heat_kernel_signature(v, p.time)), "HKS not finite");

    const HD::Anisotropic_heat_diffusion<Mesh> diffusion(kernel, p.time);
    Eigen::VectorXd f0(static_cast<Eigen::Index>(n));
    for(Vertex v : mesh.vertices())
      f0[Eigen::Index(kernel.vertex_index(v))] = ns[v] + 1.;
    const std::vector<Eigen::VectorXd> fields = diffusion.diffuse(f0, std::vector<std::size_t>{0, 1, 6});
    const double scale = f0.cwiseAbs().sum();
    for(const Eigen::VectorXd& f : fields)
    {
      require(f.allFinite(), "diffused field not finite");
      require(std::abs(f.sum() - f0.sum()) <= 1e-9 * scale, "heat not conserved");
    }

    std::map<Vertex, double> field;
    for(Vertex v : mesh.vertices())
      field[v] = f0[Eigen::Index(kernel.vertex_index(v))];
    const auto features = HD::detect_multiscale_features(diffusion, boost::make_assoc_property_map(field), {0, 3});
    for(const auto& scale_features : features)
      for(const auto* list : {&scale_features.convex, &scale_features.concave})
        for(Vertex v : *list)
          require(std::size_t(v) < n, "feature vertex out of range");
  }
  catch(const std::invalid_argument&)
  {
  }
  catch(const std::runtime_error&)
  {
  }
  catch(const std::exception& e)
  {
    bug(std::string("unexpected exception from the package: ") + e.what());
  }
}

// The package on one point set, as the tool runs it: the point-set diffusion with k
// neighbours, its NCC, F^k and the features, then the point-set denoiser. Returns normally when it computed finite
// results or threw std::invalid_argument / std::runtime_error; calls bug() otherwise.
void run_point_package(const heat_diffusion_cli::Point_set& points, const Parameters& p)
{
  typedef heat_diffusion_cli::Point_set Point_set;
  const std::size_t n = points.size();
  if(n > maximum_points)
    return;
  const unsigned int k = unsigned(2 + p.m % 9);  // 2 to 10
  try
  {
    const HD::Point_set_anisotropic_heat_diffusion<Point_set> diffusion(
        points, k, HD::parameters::combine(HD::parameters::sigma(p.sigma), HD::parameters::time(p.time)));
    const auto& ncc = diffusion.normal_controlled_coordinates();
    require(ncc.number_of_points() == n, "points lost");
    Eigen::VectorXd f0(static_cast<Eigen::Index>(n));
    for(std::size_t i = 0; i < n; ++i)
    {
      const auto d = ncc.ncc(i), normal = ncc.normal(i);
      require(std::isfinite(ncc.normal_signature(i)) && std::isfinite(d.x()) && std::isfinite(d.y()) &&
                  std::isfinite(d.z()) && std::abs(normal.squared_length() - 1) < 1e-9,
              "point-set NCC or normal not finite");
      f0[Eigen::Index(i)] = ncc.normal_signature(i) + 1.;
    }
    const double scale = f0.cwiseAbs().sum();
    for(const Eigen::VectorXd& f : diffusion.diffuse(f0, std::vector<std::size_t>{0, 1, 6}))
    {
      require(f.allFinite(), "diffused point field not finite");
      require(std::abs(f.sum() - f0.sum()) <= 1e-9 * scale, "heat not conserved on the point set");
    }
    for(const auto& scale_features : HD::detect_point_set_multiscale_features(diffusion, f0, {0, 3}))
      for(const auto* list : {&scale_features.convex, &scale_features.concave})
        for(std::size_t i : *list)
          require(i < n, "feature point out of range");
  }
  catch(const std::invalid_argument&)
  {
  }
  catch(const std::runtime_error&)
  {
  }
  catch(const std::exception& e)
  {
    bug(std::string("unexpected exception from the package on a point set: ") + e.what());
  }
  // The point-set denoiser, with the same k.
  try
  {
    Point_set copy = points;
    HD::denoise_point_set(copy, k, HD::parameters::number_of_iterations(3));
    for(auto index : copy)
    {
      const auto& q = copy.point(index);
      require(std::isfinite(q.x()) && std::isfinite(q.y()) && std::isfinite(q.z()), "denoised point not finite");
    }
  }
  catch(const std::invalid_argument&)
  {
  }
  catch(const std::runtime_error&)
  {
  }
  catch(const std::exception& e)
  {
    bug(std::string("unexpected exception from the package on a point set: ") + e.what());
  }
}

// The file format the bytes are read as.
std::string extension_of(const std::string& text)
{
  if(text.compare(0, 3, "ply") == 0)
    return ".ply";
  if(text.compare(0, 2, "v ") == 0 || text.find("\nv ") != std::string::npos)
    return ".obj";
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if(first != std::string::npos && std::string("0123456789+-.").find(text[first]) != std::string::npos)
    return ".xyz";
  return ".off";
}

// The tool reads files: the bytes go to a file of this process's own, removed after
// the input (a crash leaves it, next to libFuzzer's own copy of the input).
class Scratch_file
{
public:
  Scratch_file(const std::string& text, const std::string& extension)
    : path_("/tmp/fuzz_mesh_pipeline_" + std::to_string(::getpid()) + extension)
  {
    std::ofstream os(path_, std::ios::binary | std::ios::trunc);
    os.write(text.data(), std::streamsize(text.size()));
    require(bool(os.flush()), "cannot write " + path_);
  }
  Scratch_file(const Scratch_file&) = delete;
  Scratch_file& operator=(const Scratch_file&) = delete;
  ~Scratch_file() { std::remove(path_.c_str()); }
  const std::string& path() const { return path_; }

private:
  std::string path_;
};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size > maximum_input_bytes)
    return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const Parameters p = parameters_of(data, size);
  const std::string extension = extension_of(text);
  const Scratch_file scratch(text, extension);
  const std::string& path = scratch.path();
  namespace fi = heat_diffusion_cli::fast_input;

  // A file of points goes the tool's point-set way: the points, or an Input_error; then
  // the package with the file's normals, and without them.
  if(heat_diffusion_cli::holds_points_only(path))
  {
    heat_diffusion_cli::Point_set points;
    try
    {
      heat_diffusion_cli::read_point_file(path, points);
    }
    catch(const heat_diffusion_cli::Input_error&)
    {
      return 0;
    }
    catch(const std::exception& e)
    {
      bug(std::string("the tool's point reading threw something other than an Input_error: ") + e.what());
    }
    run_point_package(points, p);
    if(points.has_normal_map())
    {
      points.remove_normal_map();
      run_point_package(points, p);
    }
    return 0;
  }

  // The tool's fast reader reads a subset of what its checked reading accepts, to the
  // identical mesh: what it accepts, that must accept.
  Mesh fast;
  if(fi::read_mesh_fast(path, fast))
  {
    Mesh checked;
    try
    {
      require(heat_diffusion_cli::read_checked_polygon_mesh(path, checked),
              "the fast reader accepts what CGAL's reader rejects");
    }
    catch(const heat_diffusion_cli::Input_error& e)
    {
      bug(std::string("the fast reader accepts what the checks reject: ") + e.what());
    }
    require(fi::identical_meshes(fast, checked), "the fast reader's mesh differs from the checked reading's");
    if(extension == ".off")  // and the mesh is CGAL's, built by CGAL's own code
    {
      std::istringstream is(text);
      Mesh cgal;
      require(CGAL::IO::read_OFF(is, cgal), "the fast reader accepts what CGAL's OFF reader rejects");
      require(fi::identical_meshes(fast, cgal), "the fast reader's mesh differs from CGAL's");
    }
  }

  // The tool's reading: the mesh, or an Input_error.
  {
    Mesh mesh;
    bool read = false;
    try
    {
      heat_diffusion_cli::read_triangle_mesh(path, mesh);
      read = true;
    }
    catch(const heat_diffusion_cli::Input_error&)
    {
    }
    catch(const std::exception& e)
    {
      bug(std::string("the tool's reading threw something other than an Input_error: ") + e.what());
    }
    if(read && mesh.number_of_faces() <= maximum_faces)
      run_package(mesh, p);
  }
  // The same with the repair the tool applies by default (CGAL's repair functions): a
  // mesh, or an Input_error; a repair renumbers the vertices only as its origin says.
  {
    Mesh mesh;
    heat_diffusion_cli::Repair_report repair;
    bool read = false;
    try
    {
      heat_diffusion_cli::read_triangle_mesh(path, mesh, &repair);
      read = true;
    }
    catch(const heat_diffusion_cli::Input_error&)
    {
    }
    catch(const std::exception& e)
    {
      bug(std::string("the repairing read threw something other than an Input_error: ") + e.what());
    }
    if(read && repair.changed())  // (a mesh that needs no repair is the strict reading's, run above)
    {
      require(repair.origin.size() == mesh.number_of_vertices(), "the repair's origin misses vertices");
      if(mesh.number_of_faces() <= maximum_faces)
        run_package(mesh, p);
    }
  }
  if(extension != ".off")
    return 0;

  // CGAL's OFF reader is unsafe on hostile files (huge allocations, unchecked
  // conversions); the tool checks the file first, and so does this target.
  {
    std::istringstream is(text);
    try
    {
      heat_diffusion_cli::check_off_stream(is, size);
    }
    catch(const heat_diffusion_cli::Input_error&)
    {
      return 0;
    }
  }

  // The API user's path: a Surface_mesh read as it is.
  {
    std::istringstream is(text);
    Mesh mesh;
    bool read = false;
    try
    {
      read = CGAL::IO::read_OFF(is, mesh) && mesh.number_of_vertices() <= maximum_vertices;
    }
    catch(const std::exception&)
    {
    }
    if(read)
      run_package(mesh, p);
  }

  // The documented repair of a polygon soup, then the tool's triangulation.
  {
    std::istringstream is(text);
    std::vector<Mesh::Point> points;
    std::vector<std::vector<std::size_t> > polygons;
    Mesh mesh;
    try
    {
      if(!CGAL::IO::read_OFF(is, points, polygons) || points.size() > maximum_vertices ||
         polygons.size() > maximum_faces)
        return 0;
      PMP::repair_polygon_soup(points, polygons);
      if(!PMP::orient_polygon_soup(points, polygons))
        return 0;
      PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
      if(is_empty(mesh) || faces(mesh).size() == 0)
        return 0;
      std::size_t polygon_faces = 0;
      for(auto f : faces(mesh))
        polygon_faces += CGAL::is_triangle(halfedge(f, mesh), mesh) ? 0 : 1;
      if(polygon_faces > 0 && !heat_diffusion_cli::triangulate_polygon_faces(mesh))
        return 0;
    }
    catch(const std::exception&)
    {
      return 0;
    }
    run_package(mesh, p);
  }
  return 0;
}
