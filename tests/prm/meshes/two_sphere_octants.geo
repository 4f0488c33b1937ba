// Two balls of radius R that touch at the origin, cut by their symmetry
// planes x = 0 and y = 0: the quarter x >= 0, y >= 0 of the lower half of
// the upper ball (about (0, 0, R)) and of the upper half of the lower ball
// (about (0, 0, -R)), meshed apart (their nodes at the origin are two)
// with tetrahedra that grade from h_c at the origin, where Hertz's contact
// zone lies, to h_far.
//
// Boundary ids (physical surfaces): the upper body 0 (sphere), 1 (flat top
// z = R), 4 (x = 0), 5 (y = 0); the lower body 2 (sphere), 3 (flat bottom
// z = -R), 6 (x = 0), 7 (y = 0); material ids 1 (upper), 0 (lower).
// Refinement follows the spheres with
//   set Manifolds = 0: sphere center 0, 0, 1 radius 1; 2: sphere center 0, 0, -1 radius 1
SetFactory("OpenCASCADE");
R = 1;
DefineConstant[ h_c = {0.01, Name "h_c"} ];
DefineConstant[ d_c = {0.12, Name "d_c"} ];
DefineConstant[ growth = {1.0, Name "growth"} ];
h_far = 0.3 * R;

Sphere(1) = {0, 0, R, R};
Box(2)    = {0, 0, 0, R, R, R};
BooleanIntersection(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Sphere(4) = {0, 0, -R, R};
Box(5)    = {0, 0, -R, R, R, R};
BooleanIntersection(6) = { Volume{4}; Delete; }{ Volume{5}; Delete; };

e = 1e-6 * R;
top[]     = Surface In BoundingBox{-e, -e, R - e, R + e, R + e, R + e};
bottom[]  = Surface In BoundingBox{-e, -e, -R - e, R + e, R + e, -R + e};
up_x[]    = Surface In BoundingBox{-e, -e, -e, e, R + e, R + e};
up_y[]    = Surface In BoundingBox{-e, -e, -e, R + e, e, R + e};
low_x[]   = Surface In BoundingBox{-e, -e, -R - e, e, R + e, e};
low_y[]   = Surface In BoundingBox{-e, -e, -R - e, R + e, e, e};
upper[]   = Boundary{ Volume{3}; };
lower[]   = Boundary{ Volume{6}; };
up_sphere[] = upper[];
up_sphere[] -= top[];
up_sphere[] -= up_x[];
up_sphere[] -= up_y[];
low_sphere[] = lower[];
low_sphere[] -= bottom[];
low_sphere[] -= low_x[];
low_sphere[] -= low_y[];

Field[1] = MathEval;
Field[1].F = Sprintf("%g + %g * Max(0, Sqrt(x^2 + y^2 + z^2) - %g)", h_c, growth, d_c);
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.MeshSizeMax = h_far;

Physical Surface(0) = {up_sphere[]};
Physical Surface(1) = {top[]};
Physical Surface(4) = {up_x[]};
Physical Surface(5) = {up_y[]};
Physical Surface(2) = {low_sphere[]};
Physical Surface(3) = {bottom[]};
Physical Surface(6) = {low_x[]};
Physical Surface(7) = {low_y[]};
Physical Volume(1)  = {3};
Physical Volume(0)  = {6};
