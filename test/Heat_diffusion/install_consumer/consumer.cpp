// Uses an installed CGAL Heat_diffusion: the Normal Signature of a mesh (the file
// given on the command line, or an octahedron), as a user program would compute it.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Heat_diffusion/normal_controlled_coordinates.h>

#include <cmath>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace HD = CGAL::Heat_diffusion;

int main(int argc, char** argv)
{
  Mesh mesh;
  if(argc > 1) {
    if(!CGAL::IO::read_polygon_mesh(argv[1], mesh)) {
      std::cerr << "cannot read " << argv[1] << std::endl;
      return 1;
    }
  } else {
    // An octahedron: every vertex is convex.
    const Mesh::Vertex_index v[6] = {
      mesh.add_vertex(K::Point_3( 1, 0, 0)), mesh.add_vertex(K::Point_3(-1, 0, 0)),
      mesh.add_vertex(K::Point_3( 0, 1, 0)), mesh.add_vertex(K::Point_3( 0,-1, 0)),
      mesh.add_vertex(K::Point_3( 0, 0, 1)), mesh.add_vertex(K::Point_3( 0, 0,-1))};
    const int f[8][3] = {{0,2,4},{2,1,4},{1,3,4},{3,0,4},{2,0,5},{1,2,5},{3,1,5},{0,3,5}};
    for(const auto& t : f)
      mesh.add_face(v[t[0]], v[t[1]], v[t[2]]);
  }

  auto ns = mesh.add_property_map<Mesh::Vertex_index, double>("v:ns", 0.).first;
  HD::compute_normal_signature(mesh, ns);

  std::size_t convex = 0, concave = 0;
  double sum = 0;
  for(Mesh::Vertex_index v : vertices(mesh)) {
    if(!std::isfinite(ns[v])) {
      std::cerr << "non-finite Normal Signature at vertex " << v << std::endl;
      return 1;
    }
    sum += ns[v];
    if(ns[v] > 1e-12) ++convex;
    if(ns[v] < -1e-12) ++concave;
  }
  std::cout << num_vertices(mesh) << " vertices: " << convex << " convex, " << concave
            << " concave, mean NS " << sum / num_vertices(mesh) << std::endl;
  if(argc == 1 && convex != 6) {
    std::cerr << "expected 6 convex vertices on the octahedron" << std::endl;
    return 1;
  }
  return 0;
}
