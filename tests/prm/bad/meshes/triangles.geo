// Bad input for tests/prm/bad/mesh_triangles.prm: a unit square meshed with
// triangles (no 'Recombine'). gmsh -2 -format msh41 triangles.geo
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{:} = 2;
Physical Curve(0) = {1};
Physical Curve(1) = {2, 3, 4};
Physical Surface(1) = {1};
