// Computes the Normal Signature of a mesh, exaggerates its details by scaling the
// signature, and reconstructs the edited shape (paper, eq. 5 and 23).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Heat_diffusion/normal_controlled_coordinates.h>
#include <CGAL/Heat_diffusion/reconstruction.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;
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

  // One scalar per vertex: positive at convex vertices, negative at concave ones.
  auto ns = mesh.add_property_map<vertex_descriptor, double>("v:ns", 0.).first;
  HD::compute_normal_signature(mesh, ns);
  const auto range = std::minmax_element(ns.begin(), ns.end());
  std::cout << "NS in [" << *range.first << ", " << *range.second << "]" << std::endl;

  // Exaggerate the details: double the signature and move the vertices accordingly.
  for(vertex_descriptor v : mesh.vertices())
    ns[v] *= 2.;
  HD::reconstruct_from_normal_signature(mesh, ns, HD::parameters::anchor_weight(0.1));

  CGAL::IO::write_polygon_mesh("exaggerated.off", mesh, CGAL::parameters::stream_precision(17));
  std::cout << "Wrote exaggerated.off" << std::endl;
  return 0;
}
