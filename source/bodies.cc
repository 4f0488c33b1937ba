// The bodies of a mesh: the connected components of the coarse mesh, found
// by a union-find over the coarse cells' shared vertices.
#include <dualcontact/bodies.h>

#include <algorithm>
#include <map>
#include <numeric>

namespace dualcontact
{
  template <int dim>
  Bodies<dim>::Bodies(const Triangulation<dim> &triangulation)
  {
    const unsigned int        n_cells = triangulation.n_cells(0);
    std::vector<unsigned int> parent(n_cells);
    std::iota(parent.begin(), parent.end(), 0u);
    const auto root = [&parent](unsigned int i) {
      while (parent[i] != i)
        i = parent[i] = parent[parent[i]];
      return i;
    };
    std::map<unsigned int, unsigned int> first_cell_at_vertex;
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      for (const unsigned int v : cell->vertex_indices())
        {
          const auto [it, inserted] =
            first_cell_at_vertex.emplace(cell->vertex_index(v), cell->index());
          if (!inserted)
            {
              const unsigned int a = root(it->second), b = root(cell->index());
              parent[std::max(a, b)] = std::min(a, b);
            }
        }
    // 0, 1, ... in the order of each body's first coarse cell
    body_of_coarse_cell.resize(n_cells);
    std::map<unsigned int, unsigned int> number;
    for (unsigned int i = 0; i < n_cells; ++i)
      body_of_coarse_cell[i] =
        number.emplace(root(i), number.size()).first->second;
    n_bodies = number.size();
  }

  template <int dim>
  TrilinosWrappers::MPI::Vector
  Bodies<dim>::of_dofs_plus_one(const DoFHandler<dim> &dof_handler) const
  {
    const IndexSet               &owned = dof_handler.locally_owned_dofs();
    TrilinosWrappers::MPI::Vector body_plus_one(
      owned, dof_handler.get_triangulation().get_communicator());
    std::vector<types::global_dof_index> dofs(
      dof_handler.get_fe().n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const unsigned int body = of(cell);
          cell->get_dof_indices(dofs);
          for (const types::global_dof_index dof : dofs)
            if (owned.is_element(dof))
              body_plus_one[dof] = body + 1.;
        }
    body_plus_one.compress(VectorOperation::insert);
    return body_plus_one;
  }

  template class Bodies<2>;
  template class Bodies<3>;
} // namespace dualcontact
