// Denoises a triangle mesh and writes the result.
// Usage: mesh_denoising_example [mesh.off] [displacement_limit]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Heat_diffusion/denoising.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <cstdlib>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
namespace HD = CGAL::Heat_diffusion;

int main(int argc, char** argv)
{
  const std::string filename = argc > 1 ? argv[1] : CGAL::data_file_path("meshes/fandisk.off");
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "Invalid input: " << filename << std::endl;
    return EXIT_FAILURE;
  }

  // The default method filters the face normals with anisotropic weights and fits the
  // vertices to them, until the vertices have moved as far as the noise level it
  // estimates, times `displacement_limit` (default 1; smaller keeps more of the input's
  // shape). The package's parameters and CGAL's own can be merged in any order.
  const double limit = argc > 2 ? std::atof(argv[2]) : 1.;
  HD::denoise_mesh(mesh, HD::parameters::combine(HD::parameters::displacement_limit(limit),
                                                 CGAL::parameters::number_of_iterations(40)));

  // The paper's own pipeline (eq. 22-23: the Normal Signature diffused with the
  // edge-weighted heat kernel, then the least-squares reconstruction) is
  // HD::denoise_mesh(mesh, HD::parameters::denoising_method(HD::Denoising_method::signature_diffusion)).

  if(!CGAL::IO::write_polygon_mesh("denoised.off", mesh, CGAL::parameters::stream_precision(17)))
    return EXIT_FAILURE;
  std::cout << "Denoised " << num_vertices(mesh) << " vertices, written to denoised.off" << std::endl;
  return EXIT_SUCCESS;
}
