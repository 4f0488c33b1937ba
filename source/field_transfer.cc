#include <deal.II/base/mpi.h>

#include <deal.II/distributed/tria.h>

#include <dualcontact/field_transfer.h>

namespace dualcontact
{
  template <int dim>
  FieldTransfer<dim>::FieldTransfer(const DoFHandler<dim> &dof_handler)
      : dof_handler(dof_handler)
  {}

  template <int dim>
  void
  FieldTransfer<dim>::prepare(
    const std::vector<const TrilinosWrappers::MPI::Vector *> &fields)
  {
    if (dynamic_cast<const parallel::distributed::Triangulation<dim> *>(
          &dof_handler.get_triangulation()) != nullptr)
      {
        distributed = std::make_unique<parallel::distributed::SolutionTransfer<
          dim,
          TrilinosWrappers::MPI::Vector>>(dof_handler);
        distributed->prepare_for_coarsening_and_refinement(fields);
        return;
      }
    // every entry on every rank: each rank writes the ones it owns, the
    // sum over the ranks gathers them (the owned sets are disjoint)
    const MPI_Comm comm = dof_handler.get_communicator();
    whole_fields.assign(fields.size(), Vector<double>(dof_handler.n_dofs()));
    for (unsigned int f = 0; f < fields.size(); ++f)
      {
        for (const types::global_dof_index i : dof_handler.locally_owned_dofs())
          whole_fields[f][i] = (*fields[f])(i);
        Utilities::MPI::sum(whole_fields[f], comm, whole_fields[f]);
      }
    replicated =
      std::make_unique<SolutionTransfer<dim, Vector<double>>>(dof_handler);
    replicated->prepare_for_coarsening_and_refinement(whole_fields);
  }

  template <int dim>
  void
  FieldTransfer<dim>::interpolate(
    const std::vector<TrilinosWrappers::MPI::Vector *> &fields)
  {
    if (distributed)
      {
        std::vector<TrilinosWrappers::MPI::Vector *> out = fields;
        distributed->interpolate(out);
        return;
      }
    std::vector<Vector<double>> carried(whole_fields.size(),
                                        Vector<double>(dof_handler.n_dofs()));
    replicated->interpolate(whole_fields, carried);
    for (unsigned int f = 0; f < fields.size(); ++f)
      {
        for (const types::global_dof_index i : dof_handler.locally_owned_dofs())
          (*fields[f])(i) = carried[f][i];
        fields[f]->compress(VectorOperation::insert);
      }
  }

  template class FieldTransfer<2>;
  template class FieldTransfer<3>;
} // namespace dualcontact
