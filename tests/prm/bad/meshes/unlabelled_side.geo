// Bad input for tests/prm/bad/mesh_side_without_id.prm: a unit square of
// 2 x 2 quadrilaterals whose right side x = 1 is in no physical group (Gmsh
// then does not write its lines, and deal.II would give it boundary id 0).
// gmsh -2 -format msh41 unlabelled_side.geo
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{:} = 3;
Transfinite Surface{1};
Recombine Surface{1};
Physical Curve(0) = {1};
Physical Curve(1) = {3, 4};
Physical Surface(1) = {1};
