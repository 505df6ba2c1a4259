// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// cgal_heat_diffusion: the package from Python, on numpy arrays. A mesh is given as
// V (n x 3 numbers) and F (m x 3 integers), any array-like that numpy reads (float32 or
// float64, any integer type, C or Fortran order, views, lists), converted once, with a
// copy only where the layout is not already C-contiguous float64 (V) or native integers
// (F); it becomes a Surface_mesh<Epick::Point_3>
// whose vertex i is row i of V, and every result comes back in that order, whatever
// order the package works in internally (large meshes are renumbered along a Hilbert
// curve). The C++ work runs without the GIL; the package's progress callback takes the
// GIL briefly to check for KeyboardInterrupt and to call the user's `progress`.
//
// One translation unit on purpose: CGAL code compiles slowly.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

#include <CGAL/Heat_diffusion/Anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/Edge_weighted_heat_kernel.h>
#include <CGAL/Heat_diffusion/decomposition.h>
#include <CGAL/Heat_diffusion/denoising.h>
#include <CGAL/Heat_diffusion/multiscale_features.h>
#include <CGAL/Heat_diffusion/normal_controlled_coordinates.h>
#include <CGAL/Heat_diffusion/parameter_defaults.h>
#include <CGAL/Heat_diffusion/reconstruction.h>

#include "mesh_repair.h"  // the tool's repair (tools/Heat_diffusion/)
#include "surface_mesh_from_triangles.h"

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace py = pybind11;
namespace HD = CGAL::Heat_diffusion;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index Vertex;
typedef HD::Anisotropic_heat_diffusion<Mesh> Diffusion;
typedef HD::Edge_weighted_heat_kernel<Mesh> Heat_kernel;

// Errors of the binding's own checks carry the function's name, as the package's
// messages carry "CGAL::Heat_diffusion:"; both reach Python as ValueError.
[[noreturn]] void invalid(const std::string& function, const std::string& what)
{
  throw std::invalid_argument("cgal_heat_diffusion." + function + ": " + what);
}

// Runs `work` without the GIL (work that takes no progress callback).
template <typename Work>
auto without_gil(Work&& work) -> decltype(work())
{
  py::gil_scoped_release release;
  return work();
}

std::string type_name(py::handle object) { return py::str(py::type::handle_of(object).attr("__name__")); }

std::string dtype_text(const py::array& a) { return py::str(a.dtype()); }

// `object` as a numpy array (itself if it is one, else what numpy.asarray() makes of it:
// lists, tuples, objects with __array__), refused unless its elements are of one of
// `kinds` (numpy's dtype kinds: "fiu" numbers, "iu" integers).
py::array numeric_array(py::handle object, const std::string& function, const std::string& name, const char* kinds)
{
  py::array a;
  if(py::isinstance<py::array>(object))
    a = py::reinterpret_borrow<py::array>(object);
  else
  {
    try
    {
      a = py::module_::import("numpy").attr("asarray")(object);
    }
    catch(py::error_already_set&)
    {
      invalid(function, name + " must be an array of numbers, not " + type_name(object));
    }
  }
  if(std::strchr(kinds, a.dtype().kind()) == nullptr)
    invalid(function, name + " must be an array of " + (std::strlen(kinds) == 2 ? "integers" : "numbers") +
                          ", not of " + dtype_text(a) + (py::isinstance<py::array>(object) ? "" : " (" + type_name(object) + ")"));
  return a;
}

// A numeric array as C-contiguous float64: the same array where it is one already, else
// one converted copy.
py::array_t<double, py::array::c_style> float64_array(const py::array& a)
{
  return py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
}

std::string shape_text(const py::array& a)
{
  std::ostringstream os;
  os << "(";
  for(py::ssize_t d = 0; d < a.ndim(); ++d)
    os << (d ? ", " : "") << a.shape(d);
  os << (a.ndim() == 1 ? ",)" : ")");
  return os.str();
}

// V as n x 3 doubles (float64_array()), checked.
py::array_t<double, py::array::c_style> vertex_array(py::handle object, const std::string& function,
                                                     const std::string& name = "V")
{
  const py::array V = numeric_array(object, function, name, "fiu");
  if(V.ndim() != 2 || V.shape(1) != 3)
    invalid(function, name + " must have shape (n, 3), not " + shape_text(V));
  py::array_t<double, py::array::c_style> values = float64_array(V);
  const double* p = values.data();
  for(std::size_t i = 0; i < std::size_t(values.shape(0)); ++i)
    if(!std::isfinite(p[3 * i]) || !std::isfinite(p[3 * i + 1]) || !std::isfinite(p[3 * i + 2]))
    {
      std::ostringstream os;
      os << name << "[" << i << "] is (" << p[3 * i] << ", " << p[3 * i + 1] << ", " << p[3 * i + 2]
         << "), not a finite point";
      invalid(function, os.str());
    }
  return values;
}

// F as m x 3 vertex indices in [0, n), each face with three different vertices,
// read as its integer type T (no widening through floating point).
template <typename T>
void read_faces(const py::array& F, std::size_t n, const std::string& function, std::vector<std::uint32_t>& faces,
                bool degenerate_faces)
{
  const T* in = static_cast<const T*>(F.data());
  const std::size_t m = faces.size() / 3;
  for(std::size_t f = 0; f < m; ++f)
  {
    for(std::size_t c = 0; c < 3; ++c)
    {
      const T i = in[3 * f + c];
      bool out_of_range = false;
      if constexpr(std::is_signed<T>::value)
        out_of_range = i < 0 || static_cast<unsigned long long>(i) >= n;
      else
        out_of_range = static_cast<unsigned long long>(i) >= n;
      if(out_of_range)
      {
        std::ostringstream os;
        os << "F[" << f << "] refers to vertex " << +i << ", out of range [0, " << n << ")";
        invalid(function, os.str());
      }
      faces[3 * f + c] = std::uint32_t(i);
    }
    const std::uint32_t* t = &faces[3 * f];
    if(!degenerate_faces && (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]))
    {
      std::ostringstream os;
      os << "face " << f << " (vertices " << t[0] << ", " << t[1] << ", " << t[2]
         << ") is degenerate: it repeats a vertex; cgal_heat_diffusion.repair(V, F) removes such faces";
      invalid(function, os.str());
    }
  }
}

// F checked, as 3 m vertex indices (Surface_mesh numbers its vertices in 32 bits), read
// in its own integer type from a C-contiguous array of native byte order (a copy of F
// where it is not one already); `degenerate_faces`: whether a face may repeat a vertex
// (repair() removes such faces).
std::vector<std::uint32_t> face_array(py::handle object, std::size_t n, const std::string& function,
                                      bool degenerate_faces = false)
{
  py::array F = numeric_array(object, function, "F", "iu");
  if(F.ndim() != 2 || F.shape(1) != 3)
    invalid(function, "F must have shape (m, 3) (triangles), not " + shape_text(F));
  if(!(F.flags() & py::array::c_style) || !F.dtype().attr("isnative").cast<bool>())
    F = py::module_::import("numpy").attr("ascontiguousarray")(F, py::arg("dtype") = F.dtype().attr("newbyteorder")("="));
  const char kind = F.dtype().kind();
  const py::ssize_t size = F.itemsize();
  if(!(size == 1 || size == 2 || size == 4 || size == 8))
    invalid(function, "F must be an array of integers of 8 to 64 bits, not " + dtype_text(F));
  std::vector<std::uint32_t> faces(3 * std::size_t(F.shape(0)));
  if(kind == 'i')
    switch(size)
    {
    case 1: read_faces<std::int8_t>(F, n, function, faces, degenerate_faces); break;
    case 2: read_faces<std::int16_t>(F, n, function, faces, degenerate_faces); break;
    case 4: read_faces<std::int32_t>(F, n, function, faces, degenerate_faces); break;
    default: read_faces<std::int64_t>(F, n, function, faces, degenerate_faces); break;
    }
  else
    switch(size)
    {
    case 1: read_faces<std::uint8_t>(F, n, function, faces, degenerate_faces); break;
    case 2: read_faces<std::uint16_t>(F, n, function, faces, degenerate_faces); break;
    case 4: read_faces<std::uint32_t>(F, n, function, faces, degenerate_faces); break;
    default: read_faces<std::uint64_t>(F, n, function, faces, degenerate_faces); break;
    }
  return faces;
}

// The Surface_mesh of V and F face by face, as add_face() builds it: vertex i is row i
// of V (checked), face f is row f of F. Surface_mesh refuses a face that would make an
// edge non-manifold (three faces, or two faces that run along it in the same
// direction); the package itself rejects what the halfedge structure can hold but it
// cannot process (non-manifold vertices, isolated vertices, zero-area faces,
// non-finite coordinates).
void add_faces_one_by_one(const double* points, std::size_t n, const std::vector<std::uint32_t>& faces, Mesh& mesh,
                          const std::string& function)
{
  const std::size_t m = faces.size() / 3;
  mesh.reserve(Mesh::size_type(n), Mesh::size_type(3 * m / 2 + 3), Mesh::size_type(m));
  for(std::size_t i = 0; i < n; ++i)
  {
    const Vertex v = mesh.add_vertex(Point(points[3 * i], points[3 * i + 1], points[3 * i + 2]));
    if(std::size_t(v.idx()) != i)
      throw std::logic_error("cgal_heat_diffusion: Surface_mesh did not number the vertices as V");
  }
  for(std::size_t f = 0; f < m; ++f)
  {
    const std::uint32_t* t = &faces[3 * f];
    if(mesh.add_face(Vertex(t[0]), Vertex(t[1]), Vertex(t[2])) == Mesh::null_face())
    {
      std::ostringstream os;
      os << "face " << f << " (vertices " << t[0] << ", " << t[1] << ", " << t[2]
         << ") makes the mesh non-manifold: one of its edges already has two faces, or a face that runs along "
            "it in the same direction (inconsistent orientation), or it joins two fans at a vertex; "
            "cgal_heat_diffusion.repair(V, F) repairs such soups (CGAL's orient_polygon_soup() and the rest)";
      invalid(function, os.str());
    }
  }
}

// The Surface_mesh of V and F (vertex i is row i of V, face f row f of F), built without
// the GIL: in one pass when F is an oriented manifold, else face by face (which gives
// the same mesh, or the error of the face that Surface_mesh refuses).
std::unique_ptr<Mesh> make_mesh(py::handle V_object, py::handle F_object, const std::string& function)
{
  const py::array_t<double, py::array::c_style> V = vertex_array(V_object, function);
  const double* points = V.data();
  const std::size_t n = std::size_t(V.shape(0));
  if(n >= std::size_t((std::numeric_limits<Mesh::size_type>::max)()))
    invalid(function, "V has too many vertices for a Surface_mesh (32-bit indices)");
  const std::vector<std::uint32_t> faces = face_array(F_object, n, function);
  auto mesh = std::make_unique<Mesh>();
  without_gil([&] {
    if(!cgal_heat_diffusion_python::build_manifold_surface_mesh(points, n, faces.data(), faces.size() / 3, *mesh))
      add_faces_one_by_one(points, n, faces, *mesh, function);
  });
  return mesh;
}

// The connectivity of two Surface_meshes compared element by element; empty if equal,
// else the first difference.
std::string mesh_difference(const Mesh& a, const Mesh& b)
{
  std::ostringstream os;
  if(a.num_vertices() != b.num_vertices() || a.num_halfedges() != b.num_halfedges() ||
     a.num_faces() != b.num_faces() || a.has_garbage() || b.has_garbage())
  {
    os << "sizes: " << a.num_vertices() << " " << a.num_halfedges() << " " << a.num_faces() << " against "
       << b.num_vertices() << " " << b.num_halfedges() << " " << b.num_faces();
    return os.str();
  }
  for(Vertex v : a.vertices())
  {
    if(a.halfedge(v) != b.halfedge(v))
    {
      os << "vertex " << v.idx() << ": halfedge " << a.halfedge(v) << " against " << b.halfedge(v);
      return os.str();
    }
    for(int c = 0; c < 3; ++c)  // bit for bit (a NaN coordinate is kept as given)
    {
      const double x = a.point(v)[c], y = b.point(v)[c];
      if(std::memcmp(&x, &y, sizeof(double)) != 0)
      {
        os << "vertex " << v.idx() << ": point " << a.point(v) << " against " << b.point(v);
        return os.str();
      }
    }
  }
  for(Mesh::Halfedge_index h : a.halfedges())
    if(a.target(h) != b.target(h) || a.next(h) != b.next(h) || a.prev(h) != b.prev(h) || a.face(h) != b.face(h))
    {
      os << "halfedge " << h.idx() << ": target, next, prev, face " << a.target(h) << " " << a.next(h) << " "
         << a.prev(h) << " " << a.face(h) << " against " << b.target(h) << " " << b.next(h) << " " << b.prev(h)
         << " " << b.face(h);
      return os.str();
    }
  for(Mesh::Face_index f : a.faces())
    if(a.halfedge(f) != b.halfedge(f))
    {
      os << "face " << f.idx() << ": halfedge " << a.halfedge(f) << " against " << b.halfedge(f);
      return os.str();
    }
  return std::string();
}

// For the tests: whether the one-pass construction applies to V and F, and if so, how
// its mesh differs from the one add_face() builds face by face (None if in nothing, and
// the mesh is valid).
py::tuple compare_mesh_constructions(py::object V_object, py::object F_object)
{
  const std::string function = "_compare_mesh_constructions";
  const py::array_t<double, py::array::c_style> V = vertex_array(V_object, function);
  const double* points = V.data();
  const std::size_t n = std::size_t(V.shape(0));
  const std::vector<std::uint32_t> faces = face_array(F_object, n, function);
  Mesh fast;
  if(!cgal_heat_diffusion_python::build_manifold_surface_mesh(points, n, faces.data(), faces.size() / 3, fast))
  {
    if(fast.num_vertices() != 0 || fast.num_faces() != 0 || fast.num_halfedges() != 0)
      return py::make_tuple(false, "declined, but the mesh is not left empty");
    return py::make_tuple(false, py::none());
  }
  Mesh one_by_one;
  add_faces_one_by_one(points, n, faces, one_by_one, function);
  const std::string difference = mesh_difference(fast, one_by_one);
  if(!difference.empty())
    return py::make_tuple(true, difference);
  if(!fast.is_valid(false))
    return py::make_tuple(true, "the one-pass mesh is not valid (Surface_mesh::is_valid)");
  return py::make_tuple(true, py::none());
}

// A field given by input vertex order: a 1-D array-like of n finite numbers, as float64.
// (The package checks finiteness too, but its message names its C++ function, and, on
// meshes it renumbers, its own index of the vertex.)
std::vector<double> field_array(py::handle object, std::size_t n, const std::string& function,
                                const std::string& name = "field", const std::string& element = "vertex")
{
  const py::array a = numeric_array(object, function, name, "fiu");
  if(a.ndim() != 1 || std::size_t(a.shape(0)) != n)
  {
    std::ostringstream os;
    os << name << " must have shape (" << n << ",) (one value per " << element << "), not " << shape_text(a);
    invalid(function, os.str());
  }
  const py::array_t<double, py::array::c_style> values = float64_array(a);
  const double* p = values.data();
  for(std::size_t i = 0; i < n; ++i)
    if(!std::isfinite(p[i]))
    {
      std::ostringstream os;
      os << name << " value at " << element << " " << i << " is " << p[i] << ", not a finite number";
      invalid(function, os.str());
    }
  return std::vector<double>(p, p + n);
}

py::array_t<double> make_vector(const std::vector<double>& values)
{
  py::array_t<double> result(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), result.mutable_data());
  return result;
}

py::array_t<double> mesh_points(const Mesh& mesh)
{
  py::array_t<double> result({py::ssize_t(mesh.number_of_vertices()), py::ssize_t(3)});
  double* out = result.mutable_data();
  for(Vertex v : mesh.vertices())
    for(int c = 0; c < 3; ++c)
      out[3 * std::size_t(v.idx()) + std::size_t(c)] = mesh.point(v)[c];
  return result;
}

// The package's progress callback, seen from Python. The package calls it on the
// calling thread, between parallel blocks, while this module has released the GIL:
// it takes the GIL, checks for signals (Ctrl-C), then calls the user's callable (a
// result of None continues, anything false cancels). A Python exception, from the
// signal check or the user's callable, is kept and cancels the C++ work, which
// unwinds with a std::runtime_error; `run` then raises the kept exception instead.
class Python_progress
{
public:
  explicit Python_progress(py::object user) : user_(std::move(user))
  {
    if(!user_.is_none() && !PyCallable_Check(user_.ptr()))
      throw std::invalid_argument("cgal_heat_diffusion: progress must be callable or None, not " + type_name(user_));
  }

  std::function<bool(double)> callback()
  {
    return [this](double fraction) {
      py::gil_scoped_acquire gil;
      try
      {
        if(PyErr_CheckSignals() != 0)
          throw py::error_already_set();
        if(user_.is_none())
          return true;
        const py::object answer = user_(fraction);
        if(answer.is_none())
          return true;
        const int truth = PyObject_IsTrue(answer.ptr());
        if(truth < 0)
          throw py::error_already_set();
        return truth == 1;
      }
      catch(py::error_already_set& e)
      {
        error_ = std::make_shared<py::error_already_set>(std::move(e));
        return false;
      }
    };
  }

  // Runs `work` without the GIL; raises the Python exception that cancelled it, if any.
  template <typename Work>
  auto run(Work&& work) -> decltype(work())
  {
    try
    {
      py::gil_scoped_release release;
      return work();
    }
    catch(const std::exception&)
    {
      if(error_)
        throw *error_;
      throw;
    }
  }

private:
  py::object user_;
  std::shared_ptr<py::error_already_set> error_;
};

// Runs `work(np)` without the GIL, `np` holding a progress callback through which
// Ctrl-C cancels the work between two diffusion steps.
template <typename Work>
auto interruptible(Work&& work)
{
  Python_progress guard{py::none()};
  const std::function<bool(double)> callback = guard.callback();
  return guard.run([&] { return work(HD::parameters::progress_callback(callback)); });
}

// The diffusion options shared by every function that diffuses, named as the C++
// named parameters and the tool's options: sigma, time, kernel ("local", "spectral" or
// None: the package's Heat_kernel_method::automatic), m (number_of_eigenpairs), coarse
// (coarse_vertex_count), scale_invariant, normalization. Each is empty where the caller
// gave None: the package's default then applies, whatever it is (the binding keeps no
// copy of it).
struct Diffusion_options
{
  std::optional<double> sigma;
  std::optional<double> time;
  std::optional<HD::Heat_kernel_method> method;
  std::optional<double> kernel_tolerance;  // local_kernel_tolerance, checked by the package
  std::optional<long long> eigenpairs;  // checked by the package (number_of_eigenpairs must be positive)
  std::optional<long long> coarse;      // the package checks it; a negative one is refused below
  std::optional<bool> scale_invariant;
  std::optional<HD::Operator_normalization> normalization;
};

// A Python or numpy integer (anything with __index__ but a bool or an array of one or
// more dimensions, which numpy also gives __index__).
bool is_whole_number(const py::handle& value)
{
  if(py::isinstance<py::bool_>(value) || !PyIndex_Check(value.ptr()))
    return false;
  return !py::isinstance<py::array>(value) || py::reinterpret_borrow<py::array>(value).ndim() == 0;
}

// The value of a whole number (is_whole_number()), with a ValueError that names it if it
// does not fit a long long.
long long whole_number_value(const py::handle& value, const std::string& function, const std::string& name)
{
  PyObject* index = PyNumber_Index(value.ptr());
  if(index == nullptr)
  {
    PyErr_Clear();
    invalid(function, name + " must be a whole number, not " + type_name(value));
  }
  const py::object number = py::reinterpret_steal<py::object>(index);
  try
  {
    return number.cast<long long>();
  }
  catch(const py::cast_error&)
  {
    invalid(function, name + " is out of range: " + std::string(py::str(number)));
  }
}

// An optional whole-number argument (None: not given), with a ValueError that names it.
long long whole_number(const py::object& value, const std::string& function, const std::string& name)
{
  if(!is_whole_number(value))
    invalid(function, name + " must be a whole number or None, not " + type_name(value));
  return whole_number_value(value, function, name);
}

std::vector<double> number_list(const py::object& value, const std::string& function, const std::string& name)
{
  try
  {
    return value.cast<std::vector<double> >();
  }
  catch(const py::cast_error&)
  {
    invalid(function, name + " must be a sequence of numbers, not " + type_name(value));
  }
}

// An optional number (None: the C++ function's own default, which then stays the
// package's to choose: the binding does not copy it).
std::optional<double> optional_number(const py::object& value, const std::string& function, const std::string& name)
{
  if(value.is_none())
    return std::nullopt;
  // (numpy's float64 is a float; numpy's other floating-point scalars, float32 among
  // them, are numpy.floating; an array is not a number, although numpy gives it __index__)
  if(py::isinstance<py::float_>(value) || py::isinstance(value, py::module_::import("numpy").attr("floating")))
    return value.cast<double>();
  if(!is_whole_number(value))
    invalid(function, name + " must be a number or None, not " + type_name(value));
  return double(whole_number_value(value, function, name));
}

// A whole number from `lowest` to `highest`, with a ValueError that names it and the range.
long long bounded_whole_number(const py::handle& value, const std::string& function, const std::string& name,
                               long long lowest, long long highest = (std::numeric_limits<long long>::max)())
{
  if(!is_whole_number(value))
    invalid(function, name + " must be a whole number, not " + type_name(value));
  const long long k = whole_number_value(value, function, name);
  if(k < lowest || k > highest)
    invalid(function, name + (highest == (std::numeric_limits<long long>::max)()
                                  ? (lowest == 0 ? " must not be negative" : " must be at least " + std::to_string(lowest))
                                  : " must be from " + std::to_string(lowest) + " to " + std::to_string(highest)) +
                          ", not " + std::to_string(k));
  return k;
}

// decompose()'s levels, as the tool's --levels (None: the package's defaults::detail_levels):
// the bands take levels x n doubles, allocated before any work.
std::size_t checked_levels(const py::handle& levels, const std::string& function)
{
  if(levels.is_none())
    return HD::defaults::detail_levels;
  return std::size_t(bounded_whole_number(levels, function, "levels", 1, 1000));
}

// The package's feature scales (defaults::feature_scales), the steps of features() by default.
std::vector<std::size_t> feature_scales()
{
  return std::vector<std::size_t>(HD::defaults::feature_scales.begin(), HD::defaults::feature_scales.end());
}

// An optional whole number (None: the C++ function's own default).
std::optional<long long> optional_whole_number(const py::object& value, const std::string& function,
                                               const std::string& name)
{
  if(value.is_none())
    return std::nullopt;
  return whole_number(value, function, name);
}

Diffusion_options diffusion_options(const std::string& function, const py::object& sigma, const py::object& time,
                                    const py::object& kernel, const py::object& m, const py::object& coarse,
                                    const py::object& scale_invariant_object,
                                    const py::object& kernel_tolerance = py::none())
{
  Diffusion_options o;
  o.sigma = optional_number(sigma, function, "sigma");
  o.time = optional_number(time, function, "time");
  if(!scale_invariant_object.is_none())
  {
    if(!py::isinstance<py::bool_>(scale_invariant_object))
      invalid(function, "scale_invariant must be True, False or None, not " + type_name(scale_invariant_object));
    o.scale_invariant = scale_invariant_object.cast<bool>();
  }
  const bool scale_invariant = o.scale_invariant.value_or(false);
  // The values of m and coarse are the package's to check, with its messages; only a
  // negative coarse is refused here: the package reads it as its automatic choice,
  // which the Python caller asks for with None.
  if(!m.is_none())
    o.eigenpairs = whole_number(m, function, "m");
  if(!coarse.is_none())
  {
    o.coarse = whole_number(coarse, function, "coarse");
    if(*o.coarse < 0)
      invalid(function, "coarse (coarse_vertex_count) must not be negative (None: the package's automatic "
                        "choice), not " + std::to_string(*o.coarse));
  }
  const bool eigenpairs_requested = !m.is_none() || !coarse.is_none() || scale_invariant;
  if(!kernel.is_none())
  {
    if(!py::isinstance<py::str>(kernel))
      invalid(function, "kernel must be 'local', 'spectral' or None, not " + type_name(kernel));
    const std::string name = kernel.cast<std::string>();
    if(name == "local")
      o.method = HD::Heat_kernel_method::local;
    else if(name == "spectral")
      o.method = HD::Heat_kernel_method::spectral;
    else
      invalid(function, "kernel must be 'local', 'spectral' or None, not '" + name + "'");
  }
  // The local kernel computes no eigenpairs: their options are refused, not ignored.
  if(o.method == HD::Heat_kernel_method::local && eigenpairs_requested)
    invalid(function, "m, coarse and scale_invariant concern the eigenpairs of the spectral kernel; "
                      "kernel='local' computes none");
  // and the spectral kernel has no tolerance (as the tool's --kernel-tolerance)
  o.kernel_tolerance = optional_number(kernel_tolerance, function, "kernel_tolerance");
  if(o.kernel_tolerance && (o.method == HD::Heat_kernel_method::spectral || eigenpairs_requested))
    invalid(function, "kernel_tolerance concerns the local kernel; the spectral kernel has none");
  return o;
}

// One type of named parameters for every diffusion (one instantiation of each class).
auto diffusion_parameters(const Diffusion_options& o, std::function<bool(double)> progress)
{
  return HD::parameters::combine(
      HD::parameters::sigma(o.sigma), HD::parameters::time(o.time), HD::parameters::kernel_method(o.method),
      HD::parameters::local_kernel_tolerance(o.kernel_tolerance),
      HD::parameters::number_of_eigenpairs(o.eigenpairs), HD::parameters::scale_invariant_kernel(o.scale_invariant),
      HD::parameters::coarse_vertex_count(o.coarse), HD::parameters::operator_normalization(o.normalization),
      HD::parameters::progress_callback(std::move(progress)));
}

// A field by the package's vertex index, from input order, and back.
template <typename Indexed>
Eigen::VectorXd to_package_order(const Indexed& indexed, const Mesh& mesh, const std::vector<double>& values)
{
  Eigen::VectorXd f(static_cast<Eigen::Index>(values.size()));
  for(Vertex v : mesh.vertices())
    f[Eigen::Index(indexed.vertex_index(v))] = values[v.idx()];
  return f;
}

template <typename Indexed>
py::array_t<double> to_input_order(const Indexed& indexed, const Mesh& mesh, const Eigen::VectorXd& f)
{
  py::array_t<double> result(static_cast<py::ssize_t>(mesh.number_of_vertices()));
  double* out = result.mutable_data();
  for(Vertex v : mesh.vertices())
    out[v.idx()] = f[Eigen::Index(indexed.vertex_index(v))];
  return result;
}

// The steps: a whole number (`single`), or a list of them; None: `default_steps`, a list.
std::vector<std::size_t> step_list(const py::object& steps, const std::string& function, bool& single,
                                   const std::vector<std::size_t>& default_steps)
{
  if(steps.is_none())
  {
    single = false;
    return default_steps;
  }
  // Python and numpy integers (is_whole_number()), or a sequence or array of them.
  auto checked = [&](const py::handle& s) {
    if(!is_whole_number(s))
      invalid(function, "steps must be a whole number or a list of them, not " + type_name(s));
    return std::size_t(bounded_whole_number(s, function, "steps", 0));
  };
  std::vector<std::size_t> result;
  single = is_whole_number(steps);
  if(single)
    result.push_back(checked(steps));
  else
  {
    if(!py::isinstance<py::sequence>(steps) && !py::isinstance<py::array>(steps))
      invalid(function, "steps must be a whole number or a list of them, not " + type_name(steps));
    for(py::handle s : steps)
      result.push_back(checked(s));
  }
  return result;
}

// Readable and writable property maps over vectors by input vertex order.
struct Input_order_field
{
  typedef Vertex key_type;
  typedef double value_type;
  typedef double reference;
  typedef boost::read_write_property_map_tag category;
  double* values;
  friend double get(const Input_order_field& m, Vertex v) { return m.values[v.idx()]; }
  friend void put(const Input_order_field& m, Vertex v, double x) { m.values[v.idx()] = x; }
};

struct Input_order_normals
{
  typedef Vertex key_type;
  typedef Kernel::Vector_3 value_type;
  typedef Kernel::Vector_3 reference;
  typedef boost::readable_property_map_tag category;
  const double* values;
  friend Kernel::Vector_3 get(const Input_order_normals& m, Vertex v)
  {
    const double* p = m.values + 3 * std::size_t(v.idx());
    return Kernel::Vector_3(p[0], p[1], p[2]);
  }
};

py::list features_list(const std::vector<HD::Features_at_scale<Vertex> >& features)
{
  py::list result;
  for(const auto& f : features)
  {
    auto indices = [](const std::vector<Vertex>& vs) {
      py::array_t<std::int64_t> a(static_cast<py::ssize_t>(vs.size()));
      std::int64_t* out = a.mutable_data();
      for(std::size_t i = 0; i < vs.size(); ++i)
        out[i] = std::int64_t(vs[i].idx());
      std::sort(out, out + vs.size());
      return a;
    };
    py::dict d;
    d["steps"] = f.number_of_steps;
    d["convex"] = indices(f.convex);
    d["concave"] = indices(f.concave);
    result.append(d);
  }
  return result;
}

// The sizes of the heat regions, as HeatDiffusion.region_statistics() returns them.
py::dict region_statistics_dict(const HD::Heat_region_statistics& s)
{
  py::dict d;
  d["min_size"] = s.min_size;
  d["mean_size"] = s.mean_size;
  d["max_size"] = s.max_size;
  d["collapsed_regions"] = s.collapsed_regions;
  d["capped_regions"] = s.capped_regions;
  return d;
}

// The Python class HeatDiffusion: the mesh and the operator A_t built on it.
class Heat_diffusion
{
public:
  // `function` names the caller in the binding's errors: the class, or the free
  // function that builds the diffusion.
  Heat_diffusion(py::object V, py::object F, py::object sigma, py::object time, py::object kernel,
                 py::object kernel_tolerance, py::object m, py::object coarse, py::object scale_invariant,
                 py::object normalization, py::object progress, const std::string& function = "HeatDiffusion")
    : mesh_(make_mesh(V, F, function))
  {
    Diffusion_options o = diffusion_options(function, sigma, time, kernel, m, coarse, scale_invariant, kernel_tolerance);
    // operator_normalization: 'balanced' (the default, doubly stochastic) or 'columns' (the paper's)
    if(!normalization.is_none())
    {
      const std::string name = py::isinstance<py::str>(normalization) ? normalization.cast<std::string>() : "";
      if(name == "balanced")
        o.normalization = HD::Operator_normalization::balanced;
      else if(name == "columns")
        o.normalization = HD::Operator_normalization::columns;
      else
        invalid(function, "normalization must be 'balanced', 'columns' or None, not " +
                              (name.empty() ? type_name(normalization) : "'" + name + "'"));
    }
    Python_progress guard(std::move(progress));
    const auto np = diffusion_parameters(o, guard.callback());
    diffusion_ = guard.run([&] { return std::make_unique<Diffusion>(*mesh_, np); });
  }

  std::size_t number_of_vertices() const { return mesh_->number_of_vertices(); }
  double time() const { return diffusion_->time(); }
  std::string kernel() const
  {
    return diffusion_->kernel_method() == HD::Heat_kernel_method::local ? "local" : "spectral";
  }
  std::string normalization() const
  {
    return diffusion_->operator_normalization() == HD::Operator_normalization::balanced ? "balanced" : "columns";
  }

  py::array_t<double> normal_signature() const
  {
    Eigen::VectorXd s(static_cast<Eigen::Index>(number_of_vertices()));
    const auto& ncc = diffusion_->normal_controlled_coordinates();
    for(Vertex v : mesh_->vertices())
      s[Eigen::Index(diffusion_->vertex_index(v))] = ncc.normal_signature(v);
    return to_input_order(*diffusion_, *mesh_, s);
  }

  py::object diffuse(py::object field, py::object steps) const
  {
    bool single = false;
    // None: one result, after the package's defaults::number_of_steps
    const std::vector<std::size_t> ks =
        steps.is_none() ? std::vector<std::size_t>(1, HD::defaults::number_of_steps)
                        : step_list(steps, "HeatDiffusion.diffuse", single, {});
    single = single || steps.is_none();
    const Eigen::VectorXd f0 =
        to_package_order(*diffusion_, *mesh_, field_array(field, number_of_vertices(), "HeatDiffusion.diffuse"));
    const std::vector<Eigen::VectorXd> fields = interruptible_diffusion(f0, ks);
    if(single)
      return to_input_order(*diffusion_, *mesh_, fields.front());
    py::array_t<double> result({py::ssize_t(ks.size()), py::ssize_t(number_of_vertices())});
    double* out = result.mutable_data();
    for(std::size_t s = 0; s < ks.size(); ++s)
      for(Vertex v : mesh_->vertices())
        out[s * number_of_vertices() + v.idx()] = fields[s][Eigen::Index(diffusion_->vertex_index(v))];
    return result;
  }

  // F^k for every k of `steps` (package order), in one pass (interruptible()).
  std::vector<Eigen::VectorXd> interruptible_diffusion(const Eigen::VectorXd& f0,
                                                       const std::vector<std::size_t>& steps) const
  {
    return interruptible([&](const auto& progress) { return diffusion_->diffuse(f0, steps, progress); });
  }

  // A_t in the input's vertex order, as scipy.sparse.csc_matrix (sorted row indices).
  py::object operator_matrix() const
  {
    const std::size_t n = number_of_vertices();
    std::vector<std::size_t> input_of(n);  // package index -> input index
    for(Vertex v : mesh_->vertices())
      input_of[diffusion_->vertex_index(v)] = v.idx();
    const Eigen::SparseMatrix<double>& A = without_gil([&]() -> const Eigen::SparseMatrix<double>& {
      return diffusion_->operator_matrix();
    });
    const std::size_t nnz = std::size_t(A.nonZeros());
    py::array_t<double> data(static_cast<py::ssize_t>(nnz));
    py::array_t<std::int64_t> indices(static_cast<py::ssize_t>(nnz)), indptr(py::ssize_t(n + 1));
    double* d = data.mutable_data();
    std::int64_t* r = indices.mutable_data();
    std::int64_t* p = indptr.mutable_data();
    {
      py::gil_scoped_release release;
      std::vector<std::pair<std::int64_t, double> > column;
      std::size_t k = 0;
      p[0] = 0;
      for(std::size_t j = 0; j < n; ++j)  // input column j is package column index(v_j)
      {
        column.clear();
        for(Eigen::SparseMatrix<double>::InnerIterator it(A, Eigen::Index(diffusion_->vertex_index(Vertex(
                                                                  Mesh::size_type(j)))));
            it; ++it)
          column.emplace_back(std::int64_t(input_of[std::size_t(it.row())]), it.value());
        std::sort(column.begin(), column.end());
        for(const auto& e : column)
        {
          r[k] = e.first;
          d[k] = e.second;
          ++k;
        }
        p[j + 1] = std::int64_t(k);
      }
    }
    py::object csc = py::module_::import("scipy.sparse").attr("csc_matrix");
    return csc(py::make_tuple(data, indices, indptr), py::arg("shape") = py::make_tuple(n, n));
  }

  py::dict region_statistics() const { return region_statistics_dict(diffusion_->region_statistics()); }

  py::list features(py::object field, py::object steps, py::object feature_threshold) const
  {
    return features_as("HeatDiffusion.features", field, steps, feature_threshold);
  }

  // features(), with errors in the name of `function` (the method, or the free function
  // that calls it)
  py::list features_as(const std::string& function, py::object field, py::object steps,
                       py::object feature_threshold_object) const
  {
    bool single = false;
    const std::vector<std::size_t> ks = step_list(steps, function, single, feature_scales());
    const std::optional<double> feature_threshold =
        optional_number(feature_threshold_object, function, "feature_threshold");
    std::vector<double> values = field.is_none() ? normal_signature().cast<std::vector<double> >()
                                                 : field_array(field, number_of_vertices(), function);
    const auto features = interruptible([&](const auto& progress) {
      return HD::detect_multiscale_features(
          *diffusion_, Input_order_field{values.data()}, ks,
          HD::parameters::combine(progress, HD::parameters::feature_threshold(feature_threshold)));
    });
    return features_list(features);
  }

  py::tuple decompose(py::object field, py::object levels_object, py::object steps_object) const
  {
    return decompose_as("HeatDiffusion.decompose", field, levels_object, steps_object);
  }

  // decompose(), with errors in the name of `function`
  py::tuple decompose_as(const std::string& function, py::object field, py::object levels_object,
                         py::object steps_object) const
  {
    const std::size_t levels = checked_levels(levels_object, function);
    const std::optional<long long> steps_per_level = optional_whole_number(steps_object, function, "steps_per_level");
    const std::size_t n = number_of_vertices();
    std::vector<double> values = field.is_none() ? normal_signature().cast<std::vector<double> >()
                                                 : field_array(field, n, function);
    py::array_t<double> bands({py::ssize_t(levels), py::ssize_t(n)});
    py::array_t<double> residual(static_cast<py::ssize_t>(n));
    double* band_data = bands.mutable_data();
    double* residual_data = residual.mutable_data();
    interruptible([&](const auto& progress) {
      std::vector<Input_order_field> maps;
      for(std::size_t j = 0; j < levels; ++j)
        maps.push_back(Input_order_field{band_data + j * n});
      // None: decompose_field()'s own default.
      HD::decompose_field(*diffusion_, Input_order_field{values.data()}, maps, Input_order_field{residual_data},
                          HD::parameters::combine(progress, HD::parameters::steps_per_level(steps_per_level)));
    });
    return py::make_tuple(bands, residual);
  }

private:
  std::unique_ptr<Mesh> mesh_;            // must outlive diffusion_, which refers to it
  std::unique_ptr<Diffusion> diffusion_;
};

py::array_t<double> normal_signature(py::object V, py::object F)
{
  const auto mesh = make_mesh(V, F, "normal_signature");
  std::vector<double> ns(mesh->number_of_vertices());
  without_gil([&] {
    HD::compute_normal_signature(*mesh, Input_order_field{ns.data()});
  });
  return make_vector(ns);
}

py::array_t<double> normal_controlled_coordinates(py::object V, py::object F)
{
  const auto mesh = make_mesh(V, F, "normal_controlled_coordinates");
  const std::size_t n = mesh->number_of_vertices();
  py::array_t<double> result({py::ssize_t(n), py::ssize_t(3)});
  double* out = result.mutable_data();
  without_gil([&] {
    const HD::Normal_controlled_coordinates<Mesh> ncc(*mesh);
    for(Vertex v : mesh->vertices())
    {
      const Kernel::Vector_3 d = ncc.ncc(v);
      for(int c = 0; c < 3; ++c)
        out[3 * std::size_t(v.idx()) + std::size_t(c)] = d[c];
    }
  });
  return result;
}

py::list multiscale_features(py::object V, py::object F, py::object field, py::object steps,
                             py::object feature_threshold, py::object sigma, py::object time, py::object kernel,
                             py::object kernel_tolerance, py::object m, py::object coarse, py::object scale_invariant,
                             py::object progress)
{
  const std::string function = "multiscale_features";
  bool single = false;
  step_list(steps, function, single, feature_scales());  // before the diffusion is built
  const Heat_diffusion diffusion(V, F, sigma, time, kernel, kernel_tolerance, m, coarse, scale_invariant, py::none(),
                                 progress, function);
  return diffusion.features_as(function, field, steps, feature_threshold);
}

py::tuple decompose(py::object V, py::object F, py::object field, py::object levels, py::object steps_per_level,
                    py::object sigma, py::object time, py::object kernel, py::object kernel_tolerance, py::object m,
                    py::object coarse, py::object scale_invariant, py::object progress)
{
  const std::string function = "decompose";
  checked_levels(levels, function);  // before the diffusion is built
  const Heat_diffusion diffusion(V, F, sigma, time, kernel, kernel_tolerance, m, coarse, scale_invariant, py::none(),
                                 progress, function);
  return diffusion.decompose_as(function, field, levels, steps_per_level);
}

// Eq. 26 on arrays: residual + sum_j weights[j] bands[j].
py::array_t<double> synthesize(py::object bands_object, py::object residual_object, py::object weights_object)
{
  const std::string function = "synthesize";
  const py::array residual_array = numeric_array(residual_object, function, "residual", "fiu");
  if(residual_array.ndim() != 1)
    invalid(function, "residual must have shape (n,), not " + shape_text(residual_array));
  const std::size_t n = std::size_t(residual_array.shape(0));
  const std::vector<double> residual = field_array(residual_object, n, function, "residual");
  const py::array bands_input = numeric_array(bands_object, function, "bands", "fiu");
  if(bands_input.ndim() != 2 || std::size_t(bands_input.shape(1)) != n)
    invalid(function, "bands must have shape (L, " + std::to_string(n) + ") (one row per band), not " +
                          shape_text(bands_input));
  const py::array_t<double, py::array::c_style> bands_array = float64_array(bands_input);
  const std::vector<double> weights =
      HD::internal::checked_weights(number_list(weights_object, function, "weights"), "synthesize");
  const std::size_t levels = std::size_t(bands_array.shape(0));
  if(weights.size() != levels)
  {
    std::ostringstream os;
    os << weights.size() << " weights for " << levels << " detail bands";
    invalid(function, os.str());
  }
  std::vector<Eigen::VectorXd> bands(levels + 1);
  const double* b = bands_array.data();
  for(std::size_t j = 0; j < levels; ++j)
    bands[j] = Eigen::Map<const Eigen::VectorXd>(b + j * n, Eigen::Index(n));
  bands[levels] = Eigen::Map<const Eigen::VectorXd>(residual.data(), Eigen::Index(n));
  for(const Eigen::VectorXd& band : bands)
    for(Eigen::Index i = 0; i < band.size(); ++i)
      if(!std::isfinite(band[i]))
        invalid(function, "the bands and the residual must be finite (value " + std::to_string(i) + " is not)");
  const Eigen::VectorXd result = HD::internal::synthesize(bands, weights);
  return make_vector(std::vector<double>(result.data(), result.data() + result.size()));
}

// The weights of a shape filter, as the tool's --weights: one band per weight.
std::vector<double> checked_shape_weights(const py::object& weights_object, const std::string& function)
{
  const std::vector<double> weights = number_list(weights_object, function, "weights");
  if(weights.empty() || weights.size() > 1000)
    invalid(function, "weights must have 1 to 1000 values (one per detail band), not " +
                          std::to_string(weights.size()));
  return weights;
}

py::array_t<double> filter_shape(py::object V, py::object F, py::object weights_object, py::object steps_object,
                                 py::object anchor_object, py::object sigma, py::object time, py::object kernel,
                                 py::object kernel_tolerance, py::object m, py::object coarse,
                                 py::object scale_invariant, py::object progress)
{
  const std::string function = "filter_shape";
  auto mesh = make_mesh(V, F, function);
  const Diffusion_options o =
      diffusion_options(function, sigma, time, kernel, m, coarse, scale_invariant, kernel_tolerance);
  const std::vector<double> weights = checked_shape_weights(weights_object, function);
  const std::optional<long long> steps_per_level = optional_whole_number(steps_object, function, "steps_per_level");
  const std::optional<double> anchor_weight = optional_number(anchor_object, function, "anchor_weight");
  Python_progress guard(std::move(progress));
  const auto np = diffusion_parameters(o, guard.callback());
  // None: filter_shape()'s own defaults.
  guard.run([&] {
    HD::filter_shape(*mesh, weights,
                     HD::parameters::combine(np, HD::parameters::steps_per_level(steps_per_level),
                                             HD::parameters::anchor_weight(anchor_weight)));
  });
  return mesh_points(*mesh);
}

// The classical signature's sigma and t where None (defaults::heat_kernel_signature).
py::array_t<double> heat_kernel_signature(py::object V, py::object F, py::object time_object, py::object sigma,
                                          py::object m, py::object coarse, py::object scale_invariant,
                                          py::object progress)
{
  const std::string function = "heat_kernel_signature";
  const auto mesh = make_mesh(V, F, function);
  Diffusion_options o = diffusion_options(function, sigma, py::none(), py::str("spectral"), m, coarse, scale_invariant);
  if(!o.sigma)
    o.sigma = HD::defaults::heat_kernel_signature::sigma;
  const double time =
      optional_number(time_object, function, "time").value_or(HD::defaults::heat_kernel_signature::time);
  if(!(time > 0) || !std::isfinite(time))
    invalid(function, "time must be positive and finite");
  Python_progress guard(std::move(progress));
  const auto np = diffusion_parameters(o, guard.callback());
  std::vector<double> hks(mesh->number_of_vertices());
  guard.run([&] {
    const Heat_kernel kernel(*mesh, np);
    for(Vertex v : mesh->vertices())
      hks[v.idx()] = kernel.heat_kernel_signature(v, time);
  });
  return make_vector(hks);
}

// The options that denoise_mesh() and denoise_point_set() share, checked; None is left
// empty, for the package's own default.
struct Denoising_options
{
  std::optional<unsigned> iterations;
  std::optional<std::size_t> steps;
  std::optional<double> normal_sigma;
  std::optional<double> displacement_limit;
};

Denoising_options denoising_options(const std::string& function, const py::object& iterations,
                                    const py::object& steps, const py::object& normal_sigma,
                                    const py::object& displacement_limit)
{
  Denoising_options o;
  if(!iterations.is_none())
    o.iterations = unsigned(
        bounded_whole_number(iterations, function, "number_of_iterations", 0, (std::numeric_limits<unsigned>::max)()));
  if(!steps.is_none())
    o.steps = std::size_t(bounded_whole_number(steps, function, "number_of_steps", 0));
  o.normal_sigma = optional_number(normal_sigma, function, "normal_sigma");
  o.displacement_limit = optional_number(displacement_limit, function, "displacement_limit");
  return o;
}

// Every argument None is left to denoise_mesh(), whose defaults depend on the method
// and, for the normal widths and the stop, on the mesh.
py::array_t<double> denoise(py::object V, py::object F, py::object method_object, py::object iterations_object,
                            py::object steps_object, py::object sigma, py::object time, py::object kernel,
                            py::object m, py::object coarse, py::object anchor_object, py::object normal_sigma,
                            py::object displacement_object, py::object progress)
{
  const std::string function = "denoise";
  auto mesh = make_mesh(V, F, function);
  std::optional<HD::Denoising_method> method;
  if(!method_object.is_none())
  {
    const std::string name = py::isinstance<py::str>(method_object) ? method_object.cast<std::string>() : "";
    if(name == "normal_filtering")
      method = HD::Denoising_method::normal_filtering;
    else if(name == "signature_diffusion")
      method = HD::Denoising_method::signature_diffusion;
    else
      invalid(function, "method must be 'normal_filtering', 'signature_diffusion' or None, not " +
                            (name.empty() ? type_name(method_object) : "'" + name + "'"));
  }
  const Denoising_options options =
      denoising_options(function, iterations_object, steps_object, normal_sigma, displacement_object);
  const Diffusion_options o = diffusion_options(function, sigma, time, kernel, m, coarse, py::none());
  const std::optional<double> anchor_weight = optional_number(anchor_object, function, "anchor_weight");
  Python_progress guard(std::move(progress));
  const auto np = HD::parameters::combine(
      HD::parameters::denoising_method(method), CGAL::parameters::number_of_iterations(options.iterations),
      HD::parameters::number_of_steps(options.steps), HD::parameters::displacement_limit(options.displacement_limit),
      HD::parameters::normal_sigma(options.normal_sigma), HD::parameters::sigma(o.sigma), HD::parameters::time(o.time),
      HD::parameters::kernel_method(o.method), HD::parameters::number_of_eigenpairs(o.eigenpairs),
      HD::parameters::coarse_vertex_count(o.coarse), HD::parameters::anchor_weight(anchor_weight),
      HD::parameters::progress_callback(guard.callback()));
  guard.run([&] { HD::denoise_mesh(*mesh, np); });
  return mesh_points(*mesh);
}

py::array_t<double> reconstruct(py::object V, py::object F, py::object ns_object, py::object anchor_object,
                                py::object normals_object)
{
  const std::string function = "reconstruct";
  auto mesh = make_mesh(V, F, function);
  const std::size_t n = mesh->number_of_vertices();
  std::vector<double> ns = field_array(ns_object, n, function, "ns");
  const std::optional<double> anchor_weight = optional_number(anchor_object, function, "anchor_weight");
  if(normals_object.is_none())
    without_gil([&] {
      HD::reconstruct_from_normal_signature(*mesh, Input_order_field{ns.data()},
                                            HD::parameters::anchor_weight(anchor_weight));
    });
  else
  {
    const py::array_t<double, py::array::c_style> normals = vertex_array(normals_object, function, "normals");
    if(std::size_t(normals.shape(0)) != n)
      invalid(function, "normals must have shape (" + std::to_string(n) + ", 3) (one per vertex), not " +
                            shape_text(normals));
    std::vector<double> copy(normals.data(), normals.data() + 3 * n);
    without_gil([&] {
      HD::reconstruct_from_normal_signature(
          *mesh, Input_order_field{ns.data()},
          HD::parameters::combine(HD::parameters::anchor_weight(anchor_weight),
                                  CGAL::parameters::vertex_normal_map(Input_order_normals{copy.data()})));
    });
  }
  return mesh_points(*mesh);
}

// The tool's repair on arrays (repair_polygon_soup_to_mesh(), CGAL's repair functions):
// the repaired V and F, and for every row of the new V the row of the input it comes from.
py::tuple repair(py::object V_object, py::object F_object)
{
  const std::string function = "repair";
  const py::array_t<double, py::array::c_style> V = vertex_array(V_object, function);
  const std::size_t n = std::size_t(V.shape(0));
  const std::vector<std::uint32_t> faces = face_array(F_object, n, function, true);
  std::vector<Point> points;
  points.reserve(n);
  for(std::size_t i = 0; i < n; ++i)
    points.emplace_back(V.data()[3 * i], V.data()[3 * i + 1], V.data()[3 * i + 2]);
  std::vector<std::vector<std::size_t> > polygons;
  polygons.reserve(faces.size() / 3);
  for(std::size_t f = 0; 3 * f < faces.size(); ++f)
    polygons.push_back({faces[3 * f], faces[3 * f + 1], faces[3 * f + 2]});
  Mesh mesh;
  heat_diffusion_cli::Repair_report report;
  try
  {
    without_gil([&] { report = heat_diffusion_cli::repair_polygon_soup_to_mesh(std::move(points), std::move(polygons), mesh); });
  }
  catch(const heat_diffusion_cli::Input_error& e)
  {
    invalid(function, std::string("cannot be repaired into a mesh: ") + e.what());
  }
  py::array_t<std::int64_t> repaired_faces({py::ssize_t(mesh.number_of_faces()), py::ssize_t(3)});
  std::int64_t* out = repaired_faces.mutable_data();
  std::size_t k = 0;
  for(auto f : mesh.faces())
    for(Vertex v : vertices_around_face(mesh.halfedge(f), mesh))
      out[k++] = std::int64_t(v.idx());
  py::array_t<std::int64_t> origin(static_cast<py::ssize_t>(report.origin.size()));
  std::copy(report.origin.begin(), report.origin.end(), origin.mutable_data());
  return py::make_tuple(mesh_points(mesh), repaired_faces, origin);
}

// Loop subdivision (CGAL::Subdivision_method_3): the benchmark makes its large meshes
// with it, as the C++ benchmarks do.
py::tuple loop_subdivision(py::object V, py::object F, int iterations)
{
  if(iterations < 0)
    invalid("loop_subdivision", "iterations must not be negative");
  auto mesh = make_mesh(V, F, "loop_subdivision");
  without_gil([&] {
    CGAL::Subdivision_method_3::Loop_subdivision(*mesh, CGAL::parameters::number_of_iterations(iterations));
  });
  py::array_t<std::int64_t> faces({py::ssize_t(mesh->number_of_faces()), py::ssize_t(3)});
  std::int64_t* out = faces.mutable_data();
  std::size_t k = 0;
  for(auto f : mesh->faces())
    for(Vertex v : vertices_around_face(mesh->halfedge(f), *mesh))
      out[k++] = std::int64_t(v.idx());
  return py::make_tuple(mesh_points(*mesh), faces);
}

// A number as the docstrings print it: 0.1, 150, inf.
std::string number_text(double x)
{
  std::ostringstream os;
  os << x;
  return os.str();
}

// The defaults the docstrings state, read from the package (defaults::).
std::string diffusion_arguments_doc()
{
  namespace D = HD::defaults;
  return "Every keyword left out or None takes the package's default (the C++ function's own):\n"
         "sigma: edge-weight width of eq. 10 (default " + number_text(D::sigma) + "; small keeps features);\n"
         "time: t of one step, on the mesh rescaled to area = vertex count (default " + number_text(D::time) + ");\n"
         "kernel: 'local', 'spectral' or None (Heat_kernel_method::automatic: local unless m, coarse or\n"
         "scale_invariant asks for eigenpairs); kernel_tolerance: local_kernel_tolerance, the local kernel's\n"
         "accuracy (default " + number_text(D::local_kernel_tolerance) + "; 1e-4 was the earlier default);\n"
         "m: number_of_eigenpairs of the spectral kernel (default " +
         std::to_string(D::number_of_eigenpairs) + ");\n"
         "coarse: coarse_vertex_count of its eigen solve (None: automatic, 0: none); scale_invariant: the\n"
         "kernel of eq. 14 (spectral); normalization (HeatDiffusion): 'balanced' (the default: A_t doubly\n"
         "stochastic) or 'columns' (the paper's); progress: None or a callable f(fraction) called during the\n"
         "construction; returning False cancels it with RuntimeError (None continues). Ctrl-C cancels it too\n"
         "(KeyboardInterrupt).\n";
}

std::string feature_scales_text()
{
  std::string text;
  for(std::size_t k : HD::defaults::feature_scales)
    text += (text.empty() ? "" : ", ") + std::to_string(k);
  return "[" + text + "]";
}

} // namespace

#include "point_set_functions.h"  // (it uses the helpers above)

PYBIND11_MODULE(cgal_heat_diffusion, module)
{
  namespace D = HD::defaults;
  module.doc() =
      "CGAL Heat_diffusion (multi-scale anisotropic heat diffusion) on numpy arrays.\n\n"
      "A mesh is V (n x 3 numbers) and F (m x 3 integer triangles): any array-like that numpy reads\n"
      "(float32 or float64 coordinates, any integer type for the faces, C or Fortran order, slices and\n"
      "views, nested lists), converted once; a copy is made only where V is not C-contiguous float64 or\n"
      "F not C-contiguous integers of native byte order. Fields are 1-D array-likes of numbers.\n"
      "Results are in the order of the rows of V. Every keyword left out or None takes the C++ function's\n"
      "own default. Invalid input (shapes, non-numeric or non-integer arrays, NaN, indices out of range,\n"
      "non-manifold or degenerate meshes, parameters) raises ValueError naming the argument.\n\n"
      "A point set is P (n x 3 numbers, as V) and optionally its oriented normals N (n x 3): the point_set_*\n"
      "functions and PointSetHeatDiffusion take them where the others take V and F.";

  const std::string diffusion_doc = diffusion_arguments_doc();
  py::class_<Heat_diffusion>(module, "HeatDiffusion",
                             ("The operator A_t of the mesh (V, F), built once, applied many times.\n" + diffusion_doc)
                                 .c_str())
      .def(py::init<py::object, py::object, py::object, py::object, py::object, py::object, py::object, py::object,
                    py::object, py::object, py::object>(),
           py::arg("V"), py::arg("F"), py::kw_only(), py::arg("sigma") = py::none(), py::arg("time") = py::none(),
           py::arg("kernel") = py::none(), py::arg("kernel_tolerance") = py::none(), py::arg("m") = py::none(), py::arg("coarse") = py::none(),
           py::arg("scale_invariant") = py::none(), py::arg("normalization") = py::none(),
           py::arg("progress") = py::none())
      .def("diffuse", &Heat_diffusion::diffuse, py::arg("field"), py::arg("steps") = py::none(),
           ("F^k = A_t^k F^0. steps: one k (returns an (n,) array) or a list of them (returns a (len, n) array);\n"
            "None: k = " + std::to_string(D::number_of_steps) + " (anisotropic_heat_diffusion()'s default).")
               .c_str())
      .def("operator_matrix", &Heat_diffusion::operator_matrix,
           "A_t as a scipy.sparse.csc_matrix in the input's vertex order: symmetric, every row and column\n"
           "summing to 1 (normalization 'balanced', the default), or every column (normalization 'columns').")
      .def("region_statistics", &Heat_diffusion::region_statistics,
           "Sizes of the heat regions: min_size, mean_size, max_size, collapsed_regions, capped_regions.")
      .def("normal_signature", &Heat_diffusion::normal_signature, "The Normal Signature of the mesh, (n,).")
      .def("features", &Heat_diffusion::features, py::arg("field") = py::none(), py::arg("steps") = py::none(),
           py::kw_only(), py::arg("feature_threshold") = py::none(),
           ("Convex and concave features of the diffused field (default: the NS) at each k of steps (default " +
            feature_scales_text() + "): a list\nof dicts {'steps', 'convex', 'concave'} with sorted vertex indices; "
            "feature_threshold: the paper's c (default " + number_text(D::feature_threshold) + ").")
               .c_str())
      .def("decompose", &Heat_diffusion::decompose, py::arg("field") = py::none(), py::arg("levels") = py::none(),
           py::kw_only(), py::arg("steps_per_level") = py::none(),
           ("Detail bands (levels, n) and residual (n,) of the field (default: the NS), eq. 24; levels default " +
            std::to_string(D::detail_levels) + ",\nsteps_per_level decompose_field()'s (" +
            std::to_string(D::decomposition_steps_per_level) + ").")
               .c_str())
      .def_property_readonly("number_of_vertices", &Heat_diffusion::number_of_vertices)
      .def_property_readonly("time", &Heat_diffusion::time)
      .def_property_readonly("kernel", &Heat_diffusion::kernel, "'local' or 'spectral'")
      .def_property_readonly("normalization", &Heat_diffusion::normalization, "'balanced' or 'columns'");

  module.def("normal_signature", &normal_signature, py::arg("V"), py::arg("F"),
             "The Normal Signature (n,): > 0 convex, < 0 concave, 0 flat.");
  module.def("normal_controlled_coordinates", &normal_controlled_coordinates, py::arg("V"), py::arg("F"),
             "The Normal-Controlled Coordinates (n, 3), parallel to the vertex normals.");
  module.def("multiscale_features", &multiscale_features, py::arg("V"), py::arg("F"), py::arg("field") = py::none(),
             py::arg("steps") = py::none(), py::kw_only(), py::arg("feature_threshold") = py::none(),
             py::arg("sigma") = py::none(), py::arg("time") = py::none(), py::arg("kernel") = py::none(),
             py::arg("kernel_tolerance") = py::none(),
             py::arg("m") = py::none(), py::arg("coarse") = py::none(), py::arg("scale_invariant") = py::none(),
             py::arg("progress") = py::none(),
             ("Features of the diffused field (default: the NS), as HeatDiffusion.features.\n" + diffusion_doc)
                 .c_str());
  module.def("decompose", &decompose, py::arg("V"), py::arg("F"), py::arg("field") = py::none(),
             py::arg("levels") = py::none(), py::kw_only(), py::arg("steps_per_level") = py::none(),
             py::arg("sigma") = py::none(), py::arg("time") = py::none(), py::arg("kernel") = py::none(),
             py::arg("kernel_tolerance") = py::none(),
             py::arg("m") = py::none(), py::arg("coarse") = py::none(), py::arg("scale_invariant") = py::none(),
             py::arg("progress") = py::none(),
             ("Detail bands (levels, n) and residual (n,) of the field (default: the NS), as\n"
              "HeatDiffusion.decompose.\n" + diffusion_doc)
                 .c_str());
  module.def("synthesize", &synthesize, py::arg("bands"), py::arg("residual"), py::arg("weights"),
             "residual + sum_j weights[j] bands[j] (eq. 26).");
  module.def("filter_shape", &filter_shape, py::arg("V"), py::arg("F"), py::arg("weights"), py::kw_only(),
             py::arg("steps_per_level") = py::none(), py::arg("anchor_weight") = py::none(),
             py::arg("sigma") = py::none(), py::arg("time") = py::none(), py::arg("kernel") = py::none(),
             py::arg("kernel_tolerance") = py::none(),
             py::arg("m") = py::none(), py::arg("coarse") = py::none(), py::arg("scale_invariant") = py::none(),
             py::arg("progress") = py::none(),
             ("New vertex positions (n, 3): the NS bands reweighted, the shape reconstructed; steps_per_level\n"
              "(default " + std::to_string(D::shape_filter_steps_per_level) + ") and anchor_weight (default " +
              number_text(D::shape_filter_anchor_weight) + ") are filter_shape()'s.\n" + diffusion_doc)
                 .c_str());
  module.def("heat_kernel_signature", &heat_kernel_signature, py::arg("V"), py::arg("F"), py::kw_only(),
             py::arg("time") = py::none(), py::arg("sigma") = py::none(), py::arg("m") = py::none(),
             py::arg("coarse") = py::none(), py::arg("scale_invariant") = py::none(), py::arg("progress") = py::none(),
             ("The heat kernel signature h_t(i, i) (n,) of the spectral kernel; by default the classical HKS:\n"
              "time " + number_text(D::heat_kernel_signature::time) + ", sigma " +
              number_text(D::heat_kernel_signature::sigma) + " (the plain Laplacian).")
                 .c_str());
  module.def("denoise", &denoise, py::arg("V"), py::arg("F"), py::kw_only(), py::arg("method") = py::none(),
             py::arg("number_of_iterations") = py::none(), py::arg("number_of_steps") = py::none(),
             py::arg("sigma") = py::none(), py::arg("time") = py::none(), py::arg("kernel") = py::none(),
             py::arg("m") = py::none(), py::arg("coarse") = py::none(), py::arg("anchor_weight") = py::none(),
             py::arg("normal_sigma") = py::none(), py::arg("displacement_limit") = py::none(),
             py::arg("progress") = py::none(),
             ("New vertex positions (n, 3) of the denoised mesh (denoise_mesh()). Every keyword None is\n"
              "denoise_mesh()'s own default: method 'normal_filtering' (or 'signature_diffusion'), at most " +
              std::to_string(D::denoising::normal_filtering_iterations) + " iterations (" +
              std::to_string(D::denoising::signature_diffusion_iterations) +
              " for signature diffusion),\nthe noise level, the normal widths and the stop estimated from the mesh "
              "(displacement_limit " + number_text(D::denoising::displacement_limit) + "); signature\ndiffusion: sigma " +
              number_text(D::denoising::sigma) + ", time " + number_text(D::denoising::time) + ", anchor_weight " +
              number_text(D::denoising::anchor_weight) + ".")
                 .c_str());
  module.def("reconstruct", &reconstruct, py::arg("V"), py::arg("F"), py::arg("ns"), py::kw_only(),
             py::arg("anchor_weight") = py::none(), py::arg("normals") = py::none(),
             ("New vertex positions (n, 3) whose NCC match the Normal Signature ns (eq. 23); anchor_weight\n"
              "default " + number_text(D::reconstruction_anchor_weight) + "; normals: (n, 3) array-like, None: the mesh's.")
                 .c_str());
  module.def("repair", &repair, py::arg("V"), py::arg("F"),
             "(V2, F2, origin): the mesh (V, F) repaired with CGAL's repair functions, as the tool repairs its\n"
             "input: duplicate points merged, degenerate and duplicate faces removed, faces reoriented to agree\n"
             "with their neighbours, non-manifold vertices split, isolated vertices and faces of zero area\n"
             "removed. origin[i] is the row of V that row i of V2 comes from (the first row at its position): a\n"
             "per-vertex result r on V2 is, per row of V, out = np.full(len(V), np.nan); out[origin] = r (a split\n"
             "row takes one of its copies' values, a removed row none). A mesh that needs no repair comes back as\n"
             "it is (origin = arange(n)). The other functions do not repair: they refuse such a mesh with a\n"
             "ValueError that names this function.");
  // The package's refusals of what repair() repairs name it.
  py::register_exception_translator([](std::exception_ptr p) {
    try
    {
      if(p)
        std::rethrow_exception(p);
    }
    catch(const std::invalid_argument& e)
    {
      const std::string message = e.what();
      const bool repairable = message.rfind("CGAL::Heat_diffusion:", 0) == 0 &&
                              (message.find("is non-manifold") != std::string::npos ||
                               message.find("is isolated") != std::string::npos ||
                               message.find("has zero area") != std::string::npos);
      PyErr_SetString(PyExc_ValueError,
                      (point_set_binding::in_module_terms(message) +
                       (repairable ? "; cgal_heat_diffusion.repair(V, F) repairs the mesh" : ""))
                          .c_str());
    }
  });
  point_set_binding::add_point_set_functions(module);
  module.def("loop_subdivision", &loop_subdivision, py::arg("V"), py::arg("F"), py::arg("iterations") = 1,
             "(V, F) of the mesh Loop-subdivided `iterations` times.");
  module.def("_compare_mesh_constructions", &compare_mesh_constructions, py::arg("V"), py::arg("F"),
             "For the tests: (whether the one-pass Surface_mesh construction applies to V and F, how its mesh\n"
             "differs from the one add_face() builds face by face: None if in nothing and valid).");
}
