// A user's program in a project that adds CGAL Heat_diffusion with add_subdirectory():
// the Normal Signature of an octahedron, whose six vertices are all convex.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Heat_diffusion/normal_controlled_coordinates.h>

#include <iostream>

typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

int main()
{
  Mesh mesh;
  const Mesh::Vertex_index v[6] = {
    mesh.add_vertex(K::Point_3( 1, 0, 0)), mesh.add_vertex(K::Point_3(-1, 0, 0)),
    mesh.add_vertex(K::Point_3( 0, 1, 0)), mesh.add_vertex(K::Point_3( 0,-1, 0)),
    mesh.add_vertex(K::Point_3( 0, 0, 1)), mesh.add_vertex(K::Point_3( 0, 0,-1))};
  const int f[8][3] = {{0,2,4},{2,1,4},{1,3,4},{3,0,4},{2,0,5},{1,2,5},{3,1,5},{0,3,5}};
  for(const auto& t : f)
    mesh.add_face(v[t[0]], v[t[1]], v[t[2]]);

  auto ns = mesh.add_property_map<Mesh::Vertex_index, double>("v:ns", 0.).first;
  CGAL::Heat_diffusion::compute_normal_signature(mesh, ns);
  for(Mesh::Vertex_index u : vertices(mesh))
    if(!(ns[u] > 0)) {
      std::cerr << "vertex " << u << ": Normal Signature " << ns[u] << ", expected > 0" << std::endl;
      return 1;
    }
  std::cout << "6 convex vertices" << std::endl;
  return 0;
}
