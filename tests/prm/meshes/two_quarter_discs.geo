// Two discs of radius R that touch at the origin, cut by their symmetry
// line x = 0: the right half of prm/two_cylinders.prm's bodies, each the
// right quarter of dualcontact's built-in 'half disc' mesh (deal.II's
// quarter_hyper_ball: 3 quadrilaterals), so that the half model's mesh is
// the right half of the whole model's on every refinement.
//
// Boundary ids (physical curves): the upper body (the lower quarter of the
// disc about (0, R)) 0 curved, 1 flat top y = R, 4 the symmetry line; the
// lower body (the upper quarter of the disc about (0, -R)) 2 curved, 3 flat
// bottom y = -R, 5 the symmetry line; material ids 1 (upper), 0 (lower).
// Refinement follows the circles with
//   set Manifolds = 0: circle center 0, 1 radius 1; 2: circle center 0, -1 radius 1
R = 1;
a = 0.55647 * R;      // deal.II's quarter_hyper_ball: the inner cell
b = 0.42883 * R;
s = R / Sqrt(2);      // the outer corner, on the circle at 45 degrees

// the upper body, about (0, R)
Point(1) = {0, R, 0};
Point(2) = {R, R, 0};
Point(3) = {a, R, 0};
Point(4) = {b, R - b, 0};
Point(5) = {s, R - s, 0};
Point(6) = {0, R - a, 0};
Point(7) = {0, 0, 0};
Line(1) = {1, 3};
Line(2) = {3, 2};
Line(3) = {3, 4};
Line(4) = {4, 6};
Line(5) = {6, 1};
Line(6) = {4, 5};
Line(7) = {6, 7};
Circle(8) = {2, 1, 5};
Circle(9) = {5, 1, 7};
Curve Loop(1) = {-5, -4, -3, -1};  Plane Surface(1) = {1};
Curve Loop(2) = {3, 6, -8, -2};    Plane Surface(2) = {2};
Curve Loop(3) = {7, -9, -6, 4};    Plane Surface(3) = {3};

// the lower body, about (0, -R): the upper one mirrored, its loops turned
// to stay counter-clockwise
Point(11) = {0, -R, 0};
Point(12) = {R, -R, 0};
Point(13) = {a, -R, 0};
Point(14) = {b, -R + b, 0};
Point(15) = {s, -R + s, 0};
Point(16) = {0, -R + a, 0};
Point(17) = {0, 0, 0};
Line(11) = {11, 13};
Line(12) = {13, 12};
Line(13) = {13, 14};
Line(14) = {14, 16};
Line(15) = {16, 11};
Line(16) = {14, 15};
Line(17) = {16, 17};
Circle(18) = {12, 11, 15};
Circle(19) = {15, 11, 17};
Curve Loop(11) = {11, 13, 14, 15};   Plane Surface(11) = {11};
Curve Loop(12) = {12, 18, -16, -13};  Plane Surface(12) = {12};
Curve Loop(13) = {-14, 16, 19, -17};  Plane Surface(13) = {13};

Transfinite Curve{:} = 2;
Transfinite Surface{:};
Recombine Surface{:};

Physical Curve(0)   = {8, 9};    // upper: curved
Physical Curve(1)   = {1, 2};    // upper: flat top
Physical Curve(4)   = {5, 7};    // upper: symmetry line x = 0
Physical Curve(2)   = {18, 19};  // lower: curved
Physical Curve(3)   = {11, 12};  // lower: flat bottom
Physical Curve(5)   = {15, 17};  // lower: symmetry line x = 0
Physical Surface(1) = {1, 2, 3};
Physical Surface(0) = {11, 12, 13};
