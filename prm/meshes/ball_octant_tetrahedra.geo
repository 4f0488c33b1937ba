// A quarter of the lower half of a ball of radius R about (0, 0, zc): the
// part x >= 0, y >= 0, z <= zc, meshed with tetrahedra that grade from the
// size h_c at the bottom point (0, 0, zc - R), where Hertz's contact zone
// lies, to h_far away from it (below). Regenerate the .msh with
// prm/meshes/make_meshes.sh (Debian: apt-get install gmsh).
//
// Boundary ids (physical surfaces): 0 the sphere, 1 the flat top z = zc,
// 2 the symmetry plane x = 0, 3 the symmetry plane y = 0; refinement
// follows the sphere with
//   set Manifolds = 0: sphere center 0, 0, zc radius R
SetFactory("OpenCASCADE");
R     = 1;
zc    = 1;
// the mesh size: h_c within the distance d_c of the bottom point (Hertz's
// contact radius is 0.1 R in prm/hertz_3d.prm's load), then growing by
// `growth` per unit distance, at most h_far
DefineConstant[ h_c = {0.01, Name "h_c"} ];
DefineConstant[ d_c = {0.11, Name "d_c"} ];
DefineConstant[ growth = {1.0, Name "growth"} ];
h_far = 0.25 * R;

Sphere(1) = {0, 0, zc, R};
Box(2)    = {0, 0, zc - R, R, R, R};
BooleanIntersection(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };

e = 1e-6 * R;
top[]    = Surface In BoundingBox{-e, -e, zc - e, R + e, R + e, zc + e};
plane_x[] = Surface In BoundingBox{-e, -e, zc - R - e, e, R + e, zc + e};
plane_y[] = Surface In BoundingBox{-e, -e, zc - R - e, R + e, e, zc + e};
all[]    = Boundary{ Volume{3}; };
sphere[] = all[];
sphere[] -= top[];
sphere[] -= plane_x[];
sphere[] -= plane_y[];

Field[1] = MathEval;
Field[1].F = Sprintf("%g + %g * Max(0, Sqrt(x^2 + y^2 + (z - %g)^2) - %g)", h_c, growth, zc - R, d_c);
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.MeshSizeMax = h_far;

Physical Surface(0) = {sphere[]};
Physical Surface(1) = {top[]};
Physical Surface(2) = {plane_x[]};
Physical Surface(3) = {plane_y[]};
Physical Volume(1)  = {3};
