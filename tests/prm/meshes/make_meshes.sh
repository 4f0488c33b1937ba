#!/usr/bin/env bash
# Regenerate the .msh files of this folder from their .geo sources with Gmsh
# (Debian: apt-get install gmsh). The tests read the .msh files; Gmsh is not
# needed to run them.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"
# the right half of prm/two_cylinders.prm's bodies, quadrilaterals
gmsh -2 -format msh41 two_quarter_discs.geo -o two_quarter_discs.msh
# a quarter of two touching balls, tetrahedra graded toward the contact
gmsh -3 -format msh41 two_sphere_octants.geo -o two_sphere_octants.msh
