// The shapes of the cells of a Gmsh file, checked before deal.II's reader
// builds a mesh from them: a cell of zero measure, a quadrilateral or
// hexahedron tangled at its corners, or a cell folded over its neighbours
// would give a wrong answer or a solver that fails for another reason, and
// is refused with its element tag and nodes (doc/meshes.md).
#ifndef dualcontact_cell_shapes_h
#define dualcontact_cell_shapes_h

#include <dualcontact/gmsh_scan.h>

#include <string>

namespace dualcontact
{
  /**
   * Check the cells of dimension `dim` of a scanned Gmsh file: its
   * triangles or quadrilaterals in 2D (their x and y), tetrahedra or
   * hexahedra in 3D. The order in which a cell lists its nodes may turn it
   * either way round (clockwise, left-handed): deal.II's reader turns over
   * each cell of negative measure on its own, so a mesh listed clockwise,
   * wholly or in part, is read as it is meant. That reader cannot tell such
   * a cell from a folded one, which the checks here do:
   * - no cell has zero measure: a simplex's is at most 1e-10 of its longest
   *   edge's square (cube), a quadrilateral's (hexahedron's) Jacobian at a
   *   corner at most 1e-10 of the product of its edges there;
   * - the Jacobian of a quadrilateral (hexahedron) has one sign at all its
   *   corners, else the cell is tangled (it crosses itself, is not convex,
   *   or is turned inside out at a corner);
   * - each cell turned by the sign of its own measure, two cells that share
   *   a face (an edge in 2D) see it turned opposite ways, i.e. they lie on
   *   its two sides; and no face belongs to more than two cells. Otherwise
   *   the cell that disagrees with the largest share of its neighbours is
   *   folded: it overlaps them. The test is on the orientations alone, exact
   *   whatever the cells' sizes, and it also finds a boundary cell turned
   *   inside out against its neighbours.
   * Cells that share no face with the rest (a separate body) may be turned
   * either way. Linear in the cells (the faces are sorted by their
   * smallest node).
   *
   * Throws InputError (exit 3) naming `file`, the element by its tag in
   * the file, its nodes (their tags) and the defect.
   */
  void
  check_cell_shapes(const MshContents &contents,
                    const unsigned int dim,
                    const std::string &file);
} // namespace dualcontact

#endif
