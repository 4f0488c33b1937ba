// The elastic bodies of a mesh: its connected parts. A scene of one body is
// the case of one part, so code that works body by body (the rigid motions
// each body may keep, the loads and reactions each body balances) needs no
// branch on how many there are.
#ifndef dualcontact_bodies_h
#define dualcontact_bodies_h

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/grid/tria.h>

#include <deal.II/lac/trilinos_vector.h>

#include <vector>

namespace dualcontact
{
  using namespace dealii;

  /**
   * The bodies of a mesh: the connected components of its coarse mesh
   * (coarse cells that share a vertex), which every rank holds whole,
   * numbered 0, 1, ... in the order of each body's first coarse cell. A
   * refined cell belongs to its coarse ancestor's body, so the numbering
   * holds on every mesh refined from the same coarse mesh.
   */
  template <int dim>
  class Bodies
  {
  public:
    explicit Bodies(const Triangulation<dim> &triangulation);

    /** How many bodies the mesh has (1 for a scene of one body). */
    unsigned int
    size() const
    {
      return n_bodies;
    }

    /** The body of each coarse cell, by the cell's index. */
    const std::vector<unsigned int> &
    of_coarse_cells() const
    {
      return body_of_coarse_cell;
    }

    /** The body of a cell (any level): its coarse ancestor's. */
    template <typename Iterator>
    unsigned int
    of(const Iterator &cell) const
    {
      typename Triangulation<dim>::cell_iterator coarse = cell;
      while (coarse->level() > 0)
        coarse = coarse->parent();
      return body_of_coarse_cell[coarse->index()];
    }

    /**
     * Each locally owned DoF's body plus one, from a locally owned cell
     * that holds it; 0 at the DoFs of no such cell.
     */
    TrilinosWrappers::MPI::Vector
    of_dofs_plus_one(const DoFHandler<dim> &dof_handler) const;

  private:
    std::vector<unsigned int> body_of_coarse_cell;
    unsigned int              n_bodies;
  };
} // namespace dualcontact

#endif
