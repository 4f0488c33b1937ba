// step-6: the body of tutorials/step-6, drawn for Gmsh.
//
// An elastic half disc of radius L = 10 below the line y = 0: a piece of a
// half-plane, large against the contact zone (a is about 0.1). The flat top
// is where a rigid cylinder presses; the arc is far away and fixed.
//
// Four patches of four-sided, structured (transfinite) quadrilaterals: a
// rectangle [-1, 1] x [-1, 0] under the contact, and three patches from its
// sides out to the arc, whose cells grow by a factor 1.6 per cell away from
// it. Regenerate the mesh with
//
//   gmsh -2 -format msh41 half_space.geo -o half_space.msh
//
// (Debian: apt-get install gmsh; Gmsh is not needed to run step-6).

L = 10;   // radius of the body
c = 1;    // half-width of the rectangle under the contact
r = 1.6;  // growth of the radial cell size away from the rectangle

// ---------------------------------------------------------------- points
Point(1) = {0, 0, 0};                     // the centre of the arc
Point(2) = {-c, 0, 0};
Point(3) = {c, 0, 0};
Point(4) = {c, -c, 0};
Point(5) = {-c, -c, 0};
Point(6) = {-L, 0, 0};
Point(7) = {L, 0, 0};
Point(8) = {-L / Sqrt(2), -L / Sqrt(2), 0};
Point(9) = {L / Sqrt(2), -L / Sqrt(2), 0};

// ---------------------------------------------------------------- curves
Line(1) = {2, 3};                         // the top of the rectangle
Line(2) = {3, 4};
Line(3) = {4, 5};
Line(4) = {5, 2};
Line(5) = {6, 2};                         // the free top, left ...
Line(6) = {3, 7};                         // ... and right
Line(7) = {5, 8};                         // radial lines to the arc
Line(8) = {4, 9};
Circle(9)  = {6, 1, 8};                   // the arc, in three pieces
Circle(10) = {8, 1, 9};
Circle(11) = {9, 1, 7};

// -------------------------------------------------------------- surfaces
Curve Loop(1) = {1, 2, 3, 4};             // the rectangle
Plane Surface(1) = {1};
Curve Loop(2) = {-5, 9, -7, 4};           // left
Plane Surface(2) = {2};
Curve Loop(3) = {3, 7, 10, -8};           // bottom
Plane Surface(3) = {3};
Curve Loop(4) = {6, -11, -8, -2};         // right
Plane Surface(4) = {4};

// ------------------------------------------ structured quadrilateral cells
// Opposite sides of a patch get the same number of nodes (cells + 1).
Transfinite Curve{1, 3, 10} = 5;          // 4 cells across the rectangle
Transfinite Curve{2, 4, 9, 11} = 3;       // 2 cells down its sides
Transfinite Curve{6, 7, 8} = 5 Using Progression r;  // 4 cells outward
Transfinite Curve{5} = 5 Using Progression 1 / r;    // (drawn inward)
Transfinite Surface{1, 2, 3, 4};
Recombine Surface{1, 2, 3, 4};            // quadrilaterals, not triangles

// ------------------------------------------------------- physical groups
// A physical curve's number is the boundary id the .prm file uses; every
// boundary curve must be in one. The cells need a group too, or Gmsh does
// not write them.
Physical Curve(1) = {1};                  // where contact may occur
Physical Curve(2) = {5, 6};               // the rest of the top: free
Physical Curve(3) = {9, 10, 11};          // the arc: fixed
Physical Surface(1) = {1, 2, 3, 4};
