// Nested iteration: fields carried from a mesh to its refinement.
#ifndef dualcontact_field_transfer_h
#define dualcontact_field_transfer_h

#include <deal.II/distributed/solution_transfer.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <deal.II/numerics/solution_transfer.h>

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
   * of simplices every rank holds all cells: it carries the whole field
   * (deal.II's serial SolutionTransfer on a copy of all entries) and keeps
   * the entries it owns.
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
    std::unique_ptr<SolutionTransfer<dim, Vector<double>>> replicated;
    std::vector<Vector<double>>                            whole_fields;
  };
} // namespace dualcontact

#endif
