<?xml version='1.0' encoding='UTF-8' standalone='yes' ?>
<!-- The pages of CGAL's manual that the Heat_diffusion documentation refers to with
     \ref; Doxyfile.in maps this file to https://doc.cgal.org/5.5.1 (TAGFILES). -->
<tagfile>
  <compound kind="page">
    <name>PkgPolygonMeshProcessing</name>
    <title>Polygon Mesh Processing</title>
    <filename>Polygon_mesh_processing/index.html</filename>
  </compound>
  <compound kind="page">
    <name>PkgSurfaceMesh</name>
    <title>Surface Mesh</title>
    <filename>Surface_mesh/index.html</filename>
  </compound>
  <compound kind="page">
    <name>PkgBGL</name>
    <title>CGAL and the Boost Graph Library</title>
    <filename>BGL/index.html</filename>
  </compound>
  <compound kind="page">
    <name>PkgHeatMethod</name>
    <title>The Heat Method</title>
    <filename>Heat_method_3/index.html</filename>
  </compound>
  <compound kind="page">
    <name>PkgSurfaceMeshSimplification</name>
    <title>Triangulated Surface Mesh Simplification</title>
    <filename>Surface_mesh_simplification/index.html</filename>
  </compound>
  <compound kind="page">
    <name>PkgKernel23</name>
    <title>2D and 3D Linear Geometry Kernel</title>
    <filename>Kernel_23/index.html</filename>
  </compound>
  <compound kind="page">
    <name>preliminaries</name>
    <title>General Information</title>
    <filename>Manual/preliminaries.html</filename>
    <docanchor file="Manual/preliminaries.html" title="LGPL">licensesLGPL</docanchor>
    <docanchor file="Manual/preliminaries.html" title="GPL">licensesGPL</docanchor>
  </compound>
</tagfile>
