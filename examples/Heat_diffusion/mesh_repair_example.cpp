// Repairs a file that is no mesh the package can process (an STL export, a polygon soup
// with inconsistent orientation, a scan with non-manifold vertices) with CGAL's own
// repair functions, then computes its Normal Signature. The package never repairs by
// itself: it refuses such a mesh with a message that names the repair.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Heat_diffusion/normal_controlled_coordinates.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace HD = CGAL::Heat_diffusion;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char* argv[])
{
  const std::string filename = argc > 1 ? argv[1] : CGAL::data_file_path("meshes/pig.stl");
  // 1. The file as a polygon soup: points, and polygons as indices into them.
  std::vector<K::Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  if(!CGAL::IO::read_polygon_soup(filename, points, polygons) || polygons.empty())
  {
    std::cerr << "Cannot read a polygon soup from " << filename << std::endl;
    return 1;
  }
  // 2. Duplicate points merged; degenerate and duplicate polygons, isolated points removed.
  PMP::repair_polygon_soup(points, polygons);
  // 3. One orientation for neighbouring polygons (copying the points where it takes two).
  const bool orientable = PMP::orient_polygon_soup(points, polygons);
  // 4. The mesh, triangulated, each closed component facing outward.
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  PMP::triangulate_faces(mesh);
  if(CGAL::is_closed(mesh))
    PMP::orient(mesh);
  // 5. What the soup repair cannot see: vertices where several fans meet, and faces of zero area.
  const std::size_t split = PMP::duplicate_non_manifold_vertices(mesh);
  PMP::remove_degenerate_faces(mesh);
  PMP::remove_isolated_vertices(mesh);
  mesh.collect_garbage();
  std::cout << filename << ": " << mesh.number_of_vertices() << " vertices, " << mesh.number_of_faces()
            << " faces; " << (orientable ? "" : "points copied to orient it; ") << split
            << " non-manifold vertices split" << std::endl;

  auto ns = mesh.add_property_map<Mesh::Vertex_index, double>("v:ns", 0.).first;
  HD::compute_normal_signature(mesh, ns);
  const auto range = std::minmax_element(ns.begin(), ns.end());
  std::cout << "NS in [" << *range.first << ", " << *range.second << "]" << std::endl;
  return 0;
}
