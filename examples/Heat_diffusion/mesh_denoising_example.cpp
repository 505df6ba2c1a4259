// Denoises a triangle mesh by anisotropic diffusion of its Normal Signature, and
// writes the result. Usage: mesh_denoising_example [mesh.off] [iterations]

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

  // The package's parameters and CGAL's own, merged: two outer iterations (by default), each
  // diffusing the Normal Signature with sigma = 1 (the default for noisy meshes).
  const unsigned int iterations = argc > 2 ? unsigned(std::atoi(argv[2])) : 2u;
  HD::denoise_mesh(mesh, HD::parameters::combine(HD::parameters::sigma(1.),
                                                 CGAL::parameters::number_of_iterations(iterations)));

  if(!CGAL::IO::write_polygon_mesh("denoised.off", mesh, CGAL::parameters::stream_precision(17)))
    return EXIT_FAILURE;
  std::cout << "Denoised " << num_vertices(mesh) << " vertices in " << iterations
            << " iterations, written to denoised.off" << std::endl;
  return EXIT_SUCCESS;
}
