// Nested iteration: fields carried from a mesh to its refinement.
#ifndef dualcontact_field_transfer_h
#define dualcontact_field_transfer_h

#include <deal.II/distributed/solution_transfer.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/grid/cell_id.h>

#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <map>
#include <memory>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  /**
   * Carries finite element fields across a refinement of the mesh by
   * interpolation, exact for a field of the coarse space since the meshes
   * are nested (doc/theory.md §7). On a p4est mesh each rank carries its own
   * cells (parallel::distributed::SolutionTransfer). On a replicated mesh
   * of simplices every rank holds all cells: it keeps each cell's values of
   * the whole field, prolongates them to the cell's children with the
   * element's prolongation matrices, and keeps the entries it owns. (deal.II
   * 9.4's serial SolutionTransfer asks that two cells give a shared DoF the
   * same value to 1e5 times the machine epsilon relative to that value,
   * which P2's prolongation misses by round-off where a component is near
   * zero.)
   */
  template <int dim>
  class FieldTransfer
  {
  public:
    explicit FieldTransfer(const DoFHandler<dim> &dof_handler);

    /**
     * After the cells are flagged and the triangulation prepared, before it
     * is refined. The fields need the locally relevant entries (ghosted)
     * on a p4est mesh, the owned ones on a replicated mesh; they must live
     * until the refinement is executed.
     */
    void
    prepare(const std::vector<const TrilinosWrappers::MPI::Vector *> &fields);

    /**
     * After the refinement and the new DoFs: the fields on the new mesh,
     * into vectors of the locally owned entries, in the order of prepare().
     */
    void
    interpolate(const std::vector<TrilinosWrappers::MPI::Vector *> &fields);

  private:
    const DoFHandler<dim> &dof_handler;
    std::unique_ptr<parallel::distributed::
                      SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>>
      distributed;
    // the replicated mesh: each active cell's values of each field
    std::map<CellId, std::vector<Vector<double>>> cell_values;
  };
} // namespace dualcontact

#endif
