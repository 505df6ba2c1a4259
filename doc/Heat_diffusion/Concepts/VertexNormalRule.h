/*!
\ingroup PkgHeatDiffusionConcepts
\cgalConcept

A rule that computes one unit normal per vertex of a triangle mesh. The package
measures Normal-Controlled Coordinates against these normals. It is passed with the
named parameter `CGAL::Heat_diffusion::parameters::vertex_normal_rule()`; a
`vertex_normal_map` named parameter, when given, takes precedence over any rule.

\cgalHasModel `CGAL::Heat_diffusion::Area_weighted_vertex_normals` (the default)
\cgalHasModel `CGAL::Heat_diffusion::Polygon_mesh_processing_vertex_normals`
*/
class VertexNormalRule
{
public:
  /// Default constructible and copyable.
  VertexNormalRule();

  /// Writes a unit normal for every vertex of `tm` into `normals`. A vertex whose
  /// normal cannot be defined gets the null vector; the package's functions then
  /// throw `std::invalid_argument` naming that vertex.
  template <typename TriangleMesh, typename VertexPointMap, typename VertexNormalMap, typename GeomTraits>
  void operator()(const TriangleMesh& tm, VertexPointMap vpm, VertexNormalMap normals, const GeomTraits& gt) const;
};
