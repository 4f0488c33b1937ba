// The lower half of a disc of radius R about (xc, yc), as a coarse mesh of 6
// quadrilaterals: the same mesh as dualcontact's built-in 'half disc'
// (deal.II's quarter_hyper_ball, twice). Regenerate the .msh files with
// prm/meshes/make_meshes.sh (Debian: apt-get install gmsh).
//
// Boundary ids (physical curves): 0 the curved part, 1 the flat top y = yc,
// as the built-in half disc. Refinement follows the circle only with
//   set Manifolds = 0: circle center xc, yc radius R
// in the scene (prm/mesh_hertz.prm).

R  = 1;
xc = 0;
yc = 0;
a  = 0.55647 * R;      // deal.II's quarter_hyper_ball: the inner cell
b  = 0.42883 * R;
s  = R / Sqrt(2);      // the outer corner, on the circle at -45 degrees

Point(1)  = {xc,      yc,      0};
Point(2)  = {xc + R,  yc,      0};
Point(3)  = {xc + a,  yc,      0};
Point(4)  = {xc + b,  yc - b,  0};
Point(5)  = {xc + s,  yc - s,  0};
Point(6)  = {xc,      yc - a,  0};
Point(7)  = {xc,      yc - R,  0};
Point(8)  = {xc - R,  yc,      0};
Point(9)  = {xc - a,  yc,      0};
Point(10) = {xc - b,  yc - b,  0};
Point(11) = {xc - s,  yc - s,  0};

// right quarter
Line(1) = {1, 3};
Line(2) = {3, 2};
Line(3) = {3, 4};
Line(4) = {4, 6};
Line(5) = {6, 1};
Line(6) = {4, 5};
Line(7) = {6, 7};
Circle(8) = {2, 1, 5};
Circle(9) = {5, 1, 7};
// left quarter
Line(11) = {1, 9};
Line(12) = {9, 8};
Line(13) = {9, 10};
Line(14) = {10, 6};
Line(16) = {10, 11};
Circle(18) = {8, 1, 11};
Circle(19) = {11, 1, 7};

// every loop counter-clockwise, so that the cells (and the hexahedra of
// half_cylinder.geo's extrusion) are all oriented alike
Curve Loop(1) = {-5, -4, -3, -1};  Plane Surface(1) = {1};
Curve Loop(2) = {3, 6, -8, -2};    Plane Surface(2) = {2};
Curve Loop(3) = {7, -9, -6, 4};    Plane Surface(3) = {3};
Curve Loop(4) = {11, 13, 14, 5};   Plane Surface(4) = {4};
Curve Loop(5) = {12, 18, -16, -13}; Plane Surface(5) = {5};
Curve Loop(6) = {-14, 16, 19, -7}; Plane Surface(6) = {6};

// one cell per surface, quadrilaterals
Transfinite Curve{:} = 2;
Transfinite Surface{:};
Recombine Surface{:};

Physical Curve(0)   = {8, 9, 18, 19};  // curved
Physical Curve(1)   = {1, 2, 11, 12};  // flat top
Physical Surface(1) = {1:6};           // the body (written as material id)
