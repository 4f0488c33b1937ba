#!/usr/bin/env bash
# Regenerate the .msh files of this folder from their .geo sources with Gmsh
# (Debian: apt-get install gmsh). dualcontact reads the .msh files; Gmsh is
# not needed to run the scenes.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"
# the half disc in both ASCII formats deal.II reads (the unit tests check
# that they give the same mesh); the scenes use format 4.1
gmsh -2 -format msh41 half_disc.geo -o half_disc.msh
gmsh -2 -format msh22 half_disc.geo -o half_disc_v22.msh
gmsh -3 -format msh41 half_cylinder.geo -o half_cylinder.msh
# graded meshes of simplices: triangles (2D), tetrahedra (3D)
gmsh -2 -format msh41 half_disc_triangles.geo -o half_disc_triangles.msh
gmsh -3 -format msh41 ball_octant_tetrahedra.geo -o ball_octant_tetrahedra.msh
