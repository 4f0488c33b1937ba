// The half disc of half_disc.geo (R = 1 about (0, 0), 6 quadrilaterals)
// extruded along z from z = 0 to z = L: the lower half of a cylinder lying
// on its side, 6 hexahedra. With 'normal fixed' on both end faces it is in
// plane strain, so a Hertz contact on it has the 2D answer
// (prm/mesh_hertz_3d.prm). Regenerate the .msh file with
// prm/meshes/make_meshes.sh (Debian: apt-get install gmsh).
//
// Boundary ids (physical surfaces): 0 the curved surface, 1 the flat top
// y = 0, 2 the end z = 0, 3 the end z = L. Refinement follows the cylinder
// only with
//   set Manifolds = 0: cylinder center 0, 0, 0 axis 0, 0, 1 radius 1
// in the scene.

Include "half_disc.geo";
L = 0.25;
// half_disc.geo's physical groups are for 2D: make new ones for the volume
Delete Physicals;
Extrude {0, 0, L} { Surface{1:6}; Layers{1}; Recombine; }

e = 1e-6;
top[]    = Surface In BoundingBox {-R - e, -e, -e, R + e, e, L + e};
front[]  = Surface In BoundingBox {-R - e, -R - e, -e, R + e, e, e};
back[]   = Surface In BoundingBox {-R - e, -R - e, L - e, R + e, e, L + e};
curved[] = Abs(CombinedBoundary{ Volume{:}; });  // signed tags
curved[] -= {top[], front[], back[]};

Physical Surface(0) = {curved[]};
Physical Surface(1) = {top[]};
Physical Surface(2) = {front[]};
Physical Surface(3) = {back[]};
Physical Volume(1)  = {1:6};
