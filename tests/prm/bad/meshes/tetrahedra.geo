// A unit cube meshed with tetrahedra, for
// tests/prm/bad/mesh_tetrahedra_degree_2.prm. gmsh -3 -format msh41
// tetrahedra.geo
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Mesh.MeshSizeMin = 1;
Mesh.MeshSizeMax = 1;
Physical Surface(0) = {1:6};
Physical Volume(1) = {1};
