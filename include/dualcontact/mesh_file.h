// Coarse meshes from Gmsh files (<Geometry/Type> = mesh file): reading and
// checking the file, its boundary ids, and the manifolds that keep curved
// boundaries curved under refinement (doc/meshes.md).
#ifndef dualcontact_mesh_file_h
#define dualcontact_mesh_file_h

#include <deal.II/base/types.h>

#include <deal.II/grid/tria.h>

#include <functional>
#include <set>
#include <string>

namespace dualcontact
{
  using namespace dealii;

  struct BoundaryManifold;   // parameters.h
  struct GeometryParameters; // parameters.h
  struct Parameters;         // parameters.h

  /**
   * Read <Geometry/Mesh file> into `mesh` (a serial triangulation, the
   * coarse mesh). The file is checked before deal.II's GridIn sees it, so
   * that every problem is one InputError naming the entry: a missing or
   * unreadable file, one that is not a Gmsh ASCII mesh of format 2 or 4
   * (exit 3); triangles or tetrahedra, with how to recombine them in Gmsh,
   * second-order elements, or no cells at all (exit 5); a mesh of the other
   * dimension, or boundary faces in no physical group (exit 6). A file
   * that deal.II's reader would misread is refused first (exit 3): counts
   * that do not match what follows them, malformed lines, node tags that
   * repeat or that an element names but $Nodes does not define, an element
   * with the wrong number of nodes or a repeated one, sections out of the
   * order the reader takes them; and a cell of zero measure, tangled or
   * folded over its neighbours (check_cell_shapes()).
   *
   * `before_building`, if given, gets the number of cells of the file (its
   * quadrilaterals in 2D, hexahedra in 3D) once the file is checked and
   * before the mesh is built from it: the caller can stop a mesh too large
   * for the memory.
   */
  template <int dim>
  void
  read_mesh_file(const GeometryParameters          &geometry,
                 Triangulation<dim>                &mesh,
                 const std::function<void(double)> &before_building = {});

  /** The boundary ids the faces of `mesh` carry. */
  template <int dim>
  std::set<types::boundary_id>
  boundary_ids(const Triangulation<dim> &mesh);

  /**
   * Throw InputError (exit 6) if a boundary id of <Boundary conditions/
   * Conditions> or <Geometry/Manifolds> is not in `ids` (the mesh's), or
   * if a vertex of a face on which <Geometry/Manifolds> puts a manifold is
   * off that circle, sphere or cylinder by more than 1e-5 R.
   */
  template <int dim>
  void
  check_mesh_against_parameters(const Parameters         &parameters,
                                const Triangulation<dim> &mesh);

  /**
   * Give the faces of each id of <Geometry/Manifolds> (and their edges) its
   * circle, sphere or cylinder, and every cell next to them a transfinite
   * interpolation of its boundary (as the built-in half disc does; on
   * simplices the cells stay flat); nothing if there are no manifolds. Call
   * on the coarse mesh, before any refinement.
   */
  template <int dim>
  void
  attach_manifolds(const GeometryParameters &geometry,
                   Triangulation<dim>       &triangulation);

  /**
   * Move every vertex of a boundary face of each manifold's id onto the
   * manifold, along the radius (of the circle or sphere; of the cylinder,
   * normal to its axis): for the vertices that splitting quadrilaterals
   * into triangles (hexahedra into tetrahedra) puts at the middle of a
   * curved face's chord.
   */
  template <int dim>
  void
  snap_to_manifolds(const std::vector<BoundaryManifold> &manifolds,
                    Triangulation<dim>                  &triangulation);
} // namespace dualcontact

#endif
