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
    // sum over the ranks gathers them (the owned sets are disjoint); then
    // each cell's values
    const MPI_Comm              comm = dof_handler.get_communicator();
    std::vector<Vector<double>> whole(fields.size(),
                                      Vector<double>(dof_handler.n_dofs()));
    for (unsigned int f = 0; f < fields.size(); ++f)
      {
        for (const types::global_dof_index i : dof_handler.locally_owned_dofs())
          whole[f][i] = (*fields[f])(i);
        Utilities::MPI::sum(whole[f], comm, whole[f]);
      }
    const unsigned int n_dofs = dof_handler.get_fe().n_dofs_per_cell();
    cell_values.clear();
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        std::vector<Vector<double>> &values = cell_values[cell->id()];
        values.assign(fields.size(), Vector<double>(n_dofs));
        for (unsigned int f = 0; f < fields.size(); ++f)
          cell->get_dof_values(whole[f], values[f]);
      }
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
    // each new cell from its nearest ancestor that had values, through
    // the prolongation to each child on the way down
    const FiniteElement<dim> &fe     = dof_handler.get_fe();
    const unsigned int        n_dofs = fe.n_dofs_per_cell();
    Vector<double>            prolongated(n_dofs);
    // (every cell: a DoF this rank owns may lie on others' cells only)
    std::vector<types::global_dof_index> dofs(n_dofs);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        std::vector<unsigned int> path; // child indices, bottom up
        typename DoFHandler<dim>::cell_iterator ancestor = cell;
        while (cell_values.count(ancestor->id()) == 0)
          {
            const auto parent = ancestor->parent();
            for (unsigned int c = 0; c < parent->n_children(); ++c)
              if (parent->child(c) == ancestor)
                path.push_back(c);
            ancestor = parent;
          }
        cell->get_dof_indices(dofs);
        for (unsigned int f = 0; f < fields.size(); ++f)
          {
            Vector<double> values = cell_values.at(ancestor->id())[f];
            auto           parent = ancestor;
            for (auto c = path.rbegin(); c != path.rend(); ++c)
              {
                fe.get_prolongation_matrix(*c, parent->refinement_case())
                  .vmult(prolongated, values);
                values = prolongated;
                parent = parent->child(*c);
              }
            for (unsigned int i = 0; i < n_dofs; ++i)
              if (dof_handler.locally_owned_dofs().is_element(dofs[i]))
                (*fields[f])(dofs[i]) = values[i];
          }
      }
    for (TrilinosWrappers::MPI::Vector *field : fields)
      field->compress(VectorOperation::insert);
    cell_values.clear();
  }

  template class FieldTransfer<2>;
  template class FieldTransfer<3>;
} // namespace dualcontact
