// Decomposes the Normal Signature into detail bands and a residual (paper, eq. 24-25),
// then edits the shape by reweighting the bands (eq. 26, Fig. 10): the paper's
// smoothing filter w = (0, 0, 1) and enhancement filter w = (1, 3, 3).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Heat_diffusion/decomposition.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;
typedef Mesh::Property_map<vertex_descriptor, double> Field;
namespace HD = CGAL::Heat_diffusion;

int main(int argc, char* argv[])
{
  const std::string filename = argc > 1 ? argv[1] : CGAL::data_file_path("meshes/elephant.off");
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Invalid input: " << filename << std::endl;
    return 1;
  }

  Field ns = mesh.add_property_map<vertex_descriptor, double>("v:ns", 0.).first;
  HD::compute_normal_signature(mesh, ns);

  // Three bands of five diffusion steps each, with sigma = 0.5 as in the paper's Fig. 9.
  const HD::Anisotropic_heat_diffusion<Mesh> diffusion(mesh, HD::parameters::sigma(0.5));
  std::vector<Field> bands;
  for(int j = 1; j <= 3; ++j)
    bands.push_back(mesh.add_property_map<vertex_descriptor, double>("v:band" + std::to_string(j), 0.).first);
  Field residual = mesh.add_property_map<vertex_descriptor, double>("v:residual", 0.).first;
  HD::decompose_field(diffusion, ns, bands, residual, HD::parameters::steps_per_level(5));

  // Every band sums to zero: the diffusion conserves heat.
  double total = 0;
  for(vertex_descriptor v : mesh.vertices())
    total += std::abs(ns[v]);
  for(std::size_t j = 0; j < bands.size(); ++j)
  {
    double sum = 0;
    for(vertex_descriptor v : mesh.vertices())
      sum += bands[j][v];
    std::cout << "band " << j + 1 << ": sum " << sum << " (" << std::abs(sum) / total << " of sum |NS|)" << std::endl;
  }

  // Re-synthesis with band weights: here the finest band halved.
  Field edited = mesh.add_property_map<vertex_descriptor, double>("v:edited", 0.).first;
  HD::synthesize_field(mesh, bands, residual, std::vector<double>{0.5, 1., 1.}, edited);
  double change = 0;
  for(vertex_descriptor v : mesh.vertices())
    change = (std::max)(change, std::abs(edited[v] - ns[v]));
  std::cout << "finest band halved: the NS changes by up to " << change << std::endl;

  // Shape editing: NS -> bands -> weighted re-synthesis -> reconstruction.
  for(const auto& filter : {std::make_pair(std::string("smoothed.off"), std::vector<double>{0., 0., 1.}),
                            std::make_pair(std::string("enhanced.off"), std::vector<double>{1., 3., 3.})})
  {
    Mesh shape = mesh;
    HD::filter_shape(shape, filter.second, HD::parameters::steps_per_level(5));
    CGAL::IO::write_polygon_mesh(filter.first, shape, CGAL::parameters::stream_precision(17));
    std::cout << "Wrote " << filter.first << std::endl;
  }
  return 0;
}
