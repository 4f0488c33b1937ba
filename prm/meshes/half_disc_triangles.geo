// The lower half of a disc of radius R about (xc, yc), meshed with
// triangles that grade from the size h_c at the bottom point (xc, yc - R),
// where Hertz's contact zone lies, to h_far away from it.
// Regenerate the .msh with prm/meshes/make_meshes.sh (Debian: apt-get
// install gmsh).
//
// Boundary ids (physical curves): 0 the curved part, 1 the flat top y = yc,
// as the built-in half disc; refinement follows the circle with
//   set Manifolds = 0: circle center xc, yc radius R
R     = 1;
xc    = 0;
yc    = 0;
h_c   = 0.01 * R;   // at the contact
h_far = 0.2 * R;    // far from it

Point(1) = {xc,     yc,     0, h_far};
Point(2) = {xc + R, yc,     0, h_far};
Point(3) = {xc,     yc - R, 0, h_c};
Point(4) = {xc - R, yc,     0, h_far};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Line(3)   = {4, 2};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};

// the size grows linearly with the distance from the bottom point
Field[1] = Distance;
Field[1].PointsList = {3};
Field[2] = MathEval;
Field[2].F = Sprintf("%g + 0.25 * F1", h_c);
Field[3] = Min;
Field[3].FieldsList = {2};
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.MeshSizeMax = h_far;

Physical Curve(0) = {1, 2};
Physical Curve(1) = {3};
Physical Surface(1) = {1};
