// Smooths noisy scalar fields with the anisotropic diffusion (paper, section 7,
// "Scalar field smoothing"). A field without sharp features is smoothed best with a
// large sigma, where the diffusion is nearly isotropic; a field with sharp features
// wants a small sigma, which keeps heat from flowing across the creases of the shape.
// The smooth field here is the height of the vertices, the sharp one the mesh's
// Normal Signature; both get seeded Gaussian noise of 20 % of their RMS value.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Heat_diffusion/Anisotropic_heat_diffusion.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;
typedef Mesh::Property_map<vertex_descriptor, double> Field;
namespace HD = CGAL::Heat_diffusion;

int main(int argc, char* argv[])
{
  const std::string filename = argc > 1 ? argv[1] : CGAL::data_file_path("meshes/fandisk.off");
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Invalid input: " << filename << std::endl;
    return 1;
  }
  const std::size_t n = mesh.number_of_vertices();

  Field height = mesh.add_property_map<vertex_descriptor, double>("v:height", 0.).first;
  for(vertex_descriptor v : mesh.vertices())
    height[v] = mesh.point(v).z();
  Field signature = mesh.add_property_map<vertex_descriptor, double>("v:ns", 0.).first;
  HD::compute_normal_signature(mesh, signature);

  // One step of t = 4, with the default kernel (the local one: no eigenpairs are asked
  // for). Each operator is built once and serves both fields.
  const HD::Anisotropic_heat_diffusion<Mesh> large_sigma(
      mesh, HD::parameters::combine(HD::parameters::sigma(1.), HD::parameters::time(4.)));
  const HD::Anisotropic_heat_diffusion<Mesh> small_sigma(
      mesh, HD::parameters::combine(HD::parameters::sigma(0.1), HD::parameters::time(4.)));

  std::mt19937 generator(42);
  Field noisy = mesh.add_property_map<vertex_descriptor, double>("v:noisy", 0.).first;
  Field smoothed = mesh.add_property_map<vertex_descriptor, double>("v:smoothed", 0.).first;
  for(const auto& named_field : {std::make_pair(std::string("height (smooth)"), height),
                                 std::make_pair(std::string("Normal Signature (sharp)"), signature)})
  {
    const Field& clean = named_field.second;
    double mean = 0, rms = 0;
    for(vertex_descriptor v : mesh.vertices())
      mean += clean[v] / double(n);
    for(vertex_descriptor v : mesh.vertices())
      rms += (clean[v] - mean) * (clean[v] - mean) / double(n);
    rms = std::sqrt(rms);
    std::normal_distribution<double> noise(0., 0.2 * rms);
    for(vertex_descriptor v : mesh.vertices())
      noisy[v] = clean[v] + noise(generator);

    // The sharp part of the field: the 10 % of the vertices farthest from its mean.
    std::vector<double> deviations;
    for(vertex_descriptor v : mesh.vertices())
      deviations.push_back(std::abs(clean[v] - mean));
    std::nth_element(deviations.begin(), deviations.begin() + std::ptrdiff_t(n * 9 / 10), deviations.end());
    const double sharp = deviations[n * 9 / 10];

    // RMS errors against the clean field, relative to its RMS deviation.
    auto report = [&](const std::string& name, const Field& field) {
      double body = 0, tail = 0;
      std::size_t tail_vertices = 0;
      for(vertex_descriptor v : mesh.vertices())
      {
        const double e = (field[v] - clean[v]) * (field[v] - clean[v]);
        if(std::abs(clean[v] - mean) >= sharp)
        {
          tail += e;
          ++tail_vertices;
        }
        else
          body += e;
      }
      std::cout << "  " << name << ": RMS error " << std::sqrt(body / double(n - tail_vertices)) / rms
                << " on 90 % of the vertices, " << std::sqrt(tail / double(tail_vertices)) / rms
                << " on the 10 % farthest from the mean" << std::endl;
    };

    std::cout << named_field.first << ":" << std::endl;
    report("noisy      ", noisy);
    large_sigma.diffuse(noisy, smoothed, 1);
    report("sigma = 1  ", smoothed);
    small_sigma.diffuse(noisy, smoothed, 1);
    report("sigma = 0.1", smoothed);
  }
  return 0;
}
