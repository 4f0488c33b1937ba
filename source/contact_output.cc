#include <deal.II/base/mpi.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_tools.h>

#include <deal.II/grid/reference_cell.h>

#include <dualcontact/contact_output.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <numeric>

namespace dualcontact
{
  namespace
  {
    // a number for the CSV files: -0 (a normal's zero component) as 0
    inline double
    tidy(const double x)
    {
      return x + 0.;
    }
  } // namespace

  template <int dim>
  std::vector<ContactNodeRow<dim>>
  gather_contact_rows(const ContactSet<dim>               &contact_set,
                      const TrilinosWrappers::MPI::Vector &displacement,
                      const MPI_Comm                       comm)
  {
    // each row as 3 dim + 6 numbers, gathered on rank 0
    constexpr unsigned int stride = 3 * dim + 6;
    std::vector<double>    local;
    local.reserve(stride * contact_set.n_local_nodes());
    const TrilinosWrappers::MPI::Vector &u =
      contact_set.with_masters(displacement);
    for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
      {
        const ContactNode<dim> &node = contact_set.nodes[s];
        Tensor<1, dim>          l2;
        for (unsigned int k = 0; k < dim - 1; ++k)
          l2 += contact_set.l2[s][k] * node.tangents[k];
        for (unsigned int d = 0; d < dim; ++d)
          local.push_back(node.position[d]);
        local.push_back(node.weight);
        local.push_back(contact_set.l1[s]);
        for (unsigned int d = 0; d < dim; ++d)
          local.push_back(l2[d]);
        local.push_back(contact_set.threshold[s]);
        local.push_back(node.gap0 - contact_set.normal_displacement(u, s));
        for (unsigned int d = 0; d < dim; ++d)
          local.push_back(node.normal[d]);
        local.push_back(contact_set.status(s));
        local.push_back(node.pair_slave_id == numbers::invalid_boundary_id ?
                          -1. :
                          static_cast<double>(node.pair_slave_id));
      }

    std::vector<ContactNodeRow<dim>>       rows;
    const std::vector<std::vector<double>> all =
      Utilities::MPI::gather(comm, local, 0);
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return rows;
    for (const std::vector<double> &part : all)
      for (std::size_t i = 0; i + stride <= part.size(); i += stride)
        {
          const double       *x = part.data() + i;
          ContactNodeRow<dim> row;
          for (unsigned int d = 0; d < dim; ++d)
            row.position[d] = *x++;
          row.weight = *x++;
          row.l1     = *x++;
          for (unsigned int d = 0; d < dim; ++d)
            row.l2[d] = *x++;
          row.threshold = *x++;
          row.gap       = *x++;
          for (unsigned int d = 0; d < dim; ++d)
            row.normal[d] = *x++;
          row.status        = static_cast<unsigned int>(*x++);
          row.pair_slave_id = static_cast<int>(*x++);
          row.along         = row.position * contact_set.tangents[0];
          rows.push_back(row);
        }
    // along the boundary; in 3D along the first mean tangent, then the
    // second
    std::sort(rows.begin(),
              rows.end(),
              [&contact_set](const ContactNodeRow<dim> &a,
                             const ContactNodeRow<dim> &b) {
                if (a.along != b.along)
                  return a.along < b.along;
                return a.position * contact_set.tangents[dim - 2] <
                       b.position * contact_set.tangents[dim - 2];
              });
    return rows;
  }

  template <int dim>
  void
  write_contact_csv(const std::string                      &filename,
                    const std::vector<ContactNodeRow<dim>> &rows,
                    const bool                              friction,
                    const Function<dim>                    *exact_pressure)
  {
    static const char axis[] = "xyz";
    std::ofstream     csv(filename);
    csv << "s";
    for (unsigned int d = 0; d < dim; ++d)
      csv << ',' << axis[d];
    csv << ",weight,l1";
    if (dim == 2)
      csv << ",l2";
    else
      for (unsigned int d = 0; d < dim; ++d)
        csv << ",l2_" << axis[d];
    csv << ",g,gap";
    for (unsigned int d = 0; d < dim; ++d)
      csv << ",n_" << axis[d];
    csv << ",status";
    if (exact_pressure != nullptr)
      csv << ",exact_pressure";
    csv << '\n' << std::setprecision(12);

    const char *status_names[] = {"separated",
                                  friction ? "stick" : "contact",
                                  "slip"};
    for (const ContactNodeRow<dim> &row : rows)
      {
        csv << tidy(row.along);
        for (unsigned int d = 0; d < dim; ++d)
          csv << ',' << tidy(row.position[d]);
        csv << ',' << row.weight << ',' << tidy(row.l1);
        if (dim == 2) // along t_s = (-n_y, n_x)
          csv << ','
              << tidy(-row.l2[0] * row.normal[1] + row.l2[1] * row.normal[0]);
        else
          for (unsigned int d = 0; d < dim; ++d)
            csv << ',' << tidy(row.l2[d]);
        csv << ',' << tidy(row.threshold) << ',' << tidy(row.gap);
        for (unsigned int d = 0; d < dim; ++d)
          csv << ',' << tidy(row.normal[d]);
        csv << ',' << status_names[std::min(row.status, 2u)];
        if (exact_pressure != nullptr)
          csv << ',' << tidy(exact_pressure->value(row.position));
        csv << '\n';
      }
  }

  namespace
  {
    /**
     * The nodal values of the contact nodes, packed dim to a vector of the
     * displacement element at the node's DoFs (`n_packed` values: l1, with
     * friction g, the gap, the status plus one, then the normal, the slip
     * and with friction the tangential traction), the hanging nodes on
     * Gamma_C interpolated from their masters, with the locally relevant
     * DoFs.
     */
    template <int dim>
    std::vector<TrilinosWrappers::MPI::Vector>
    packed_nodal_values(
      const DoFHandler<dim>               &dof_handler,
      const ContactSet<dim>               &contact_set,
      const TrilinosWrappers::MPI::Vector &displacement,
      const AffineConstraints<double>     &hanging_node_constraints,
      const IndexSet                      &locally_relevant_dofs,
      const bool                           friction,
      const unsigned int                   n_packed)
    {
      const unsigned int n_slots = (n_packed + dim - 1) / dim;
      const MPI_Comm  comm = dof_handler.get_triangulation().get_communicator();
      const IndexSet &owned = dof_handler.locally_owned_dofs();
      std::vector<TrilinosWrappers::MPI::Vector> packed(n_slots);
      for (auto &slot : packed)
        slot.reinit(owned, comm);
      std::vector<double>                  values(n_packed);
      const TrilinosWrappers::MPI::Vector &u =
        contact_set.with_masters(displacement);
      for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
        {
          const ContactNode<dim> &node = contact_set.nodes[s];
          unsigned int            q    = 0;
          values[q++]                  = contact_set.l1[s];
          if (friction)
            values[q++] = contact_set.threshold[s];
          values[q++] = node.gap0 - contact_set.normal_displacement(u, s);
          values[q++] = contact_set.status(s) + 1.;
          const Tensor<1, dim - 1> vt = contact_set.slip(u, s);
          Tensor<1, dim>           slip, traction;
          for (unsigned int k = 0; k < dim - 1; ++k)
            {
              slip += vt[k] * node.tangents[k];
              traction += contact_set.l2[s][k] * node.tangents[k];
            }
          for (const Tensor<1, dim> &v : {node.normal, slip, traction})
            for (unsigned int d = 0; d < dim && q < n_packed; ++d)
              values[q++] = v[d];
          for (q = 0; q < n_packed; ++q)
            packed[q / dim][node.dofs[q % dim]] = values[q];
        }
      for (auto &slot : packed)
        {
          slot.compress(VectorOperation::insert);
          // hanging nodes on Gamma_C: the interpolation of their masters
          hanging_node_constraints.distribute(slot);
          TrilinosWrappers::MPI::Vector owned_slot = slot;
          slot.reinit(owned, locally_relevant_dofs, comm);
          slot = owned_slot;
        }
      return packed;
    }

    /**
     * One patch per contact face of a locally owned cell, subdivided k
     * times in each direction for FE_Q(k): its points are the face's
     * support points in lexicographic order, where the mapping puts them
     * (on the curve of a curved face). A triangle face (of a tetrahedron,
     * P1 only) is one patch of its 3 vertices, in the face's order. Each
     * patch's data: the `n_packed` values, the status (row `status_row`)
     * less one again, the displacement, then the points' coordinates (row
     * `n_names` on).
     */
    template <int dim>
    std::vector<DataOutBase::Patch<dim - 1, dim>>
    contact_face_patches(
      const Mapping<dim>                               &mapping,
      const DoFHandler<dim>                            &dof_handler,
      const std::set<types::boundary_id>               &contact_ids,
      const std::vector<TrilinosWrappers::MPI::Vector> &packed,
      const TrilinosWrappers::MPI::Vector              &displacement,
      const unsigned int                                n_packed,
      const unsigned int                                n_names,
      const unsigned int                                status_row)
    {
      const FiniteElement<dim> &fe = dof_handler.get_fe();
      const ReferenceCell       face_cell =
        fe.reference_cell().face_reference_cell(0);
      const bool                triangles = !face_cell.is_hyper_cube();
      const unsigned int        k         = triangles ? 1 : fe.degree;
      std::vector<unsigned int> lexicographic(face_cell.n_vertices());
      if (triangles)
        std::iota(lexicographic.begin(), lexicographic.end(), 0u);
      else
        lexicographic =
          FETools::hierarchic_to_lexicographic_numbering<dim - 1>(k);
      std::map<types::global_dof_index, Point<dim>> where;
      DoFTools::map_dofs_to_support_points(mapping, dof_handler, where);
      std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
      std::vector<DataOutBase::Patch<dim - 1, dim>> patches;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() && cell->at_boundary())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                contact_ids.count(cell->face(f)->boundary_id()))
              {
                const auto                       face = cell->face(f);
                DataOutBase::Patch<dim - 1, dim> patch;
                patch.reference_cell = face_cell;
                patch.n_subdivisions = k;
                patch.patch_index    = patches.size();
                for (const unsigned int v : face->vertex_indices())
                  patch.vertices[v] = face->vertex(v);
                // the data, then the points' coordinates
                patch.points_are_available = true;
                patch.data.reinit(n_names + dim, lexicographic.size());
                face->get_dof_indices(face_dofs);
                for (unsigned int i = 0; i < face_dofs.size(); ++i)
                  {
                    const auto [c, j] = fe.face_system_to_component_index(i, f);
                    const unsigned int            p   = lexicographic[j];
                    const types::global_dof_index dof = face_dofs[i];
                    for (unsigned int q = c; q < n_packed; q += dim)
                      patch.data(q, p) = packed[q / dim](dof);
                    if (status_row % dim == c)
                      patch.data(status_row, p) -= 1.;
                    patch.data(n_packed + c, p) = displacement(dof);
                    patch.data(n_names + c, p)  = where.at(dof)[c];
                  }
                patches.push_back(std::move(patch));
              }
      return patches;
    }
  } // namespace

  template <int dim>
  void
  ContactBoundaryOutput<dim>::build_patches(
    const Mapping<dim>                  &mapping,
    const DoFHandler<dim>               &dof_handler,
    const std::set<types::boundary_id>  &contact_ids,
    const ContactSet<dim>               &contact_set,
    const TrilinosWrappers::MPI::Vector &displacement,
    const AffineConstraints<double>     &hanging_node_constraints,
    const IndexSet                      &locally_relevant_dofs)
  {
    const bool friction =
      contact_set.law != nullptr && contact_set.law->has_friction();
    // The nodal values, packed dim to a vector of the displacement element
    // at the node's DoFs: the scalars, then the vectors. The status is
    // stored plus one, so that a node that is no contact node reads -1.
    std::vector<std::string> scalars = {"contact_pressure",
                                        "gap",
                                        "contact_status"};
    std::vector<std::string> vectors = {"normal", "tangential_slip"};
    if (friction)
      {
        scalars.insert(scalars.begin() + 1, "friction_threshold");
        vectors.emplace_back("tangential_traction");
      }
    const unsigned int n_packed = scalars.size() + dim * vectors.size();
    const std::vector<TrilinosWrappers::MPI::Vector> packed =
      packed_nodal_values(dof_handler,
                          contact_set,
                          displacement,
                          hanging_node_constraints,
                          locally_relevant_dofs,
                          friction,
                          n_packed);

    // the names: the scalars, the vectors, then the displacement
    names = scalars;
    vector_ranges.clear();
    vectors.emplace_back("displacement");
    for (const std::string &name : vectors)
      {
        vector_ranges.emplace_back(
          names.size(),
          names.size() + dim - 1,
          name,
          DataComponentInterpretation::component_is_part_of_vector);
        names.insert(names.end(), dim, name);
      }
    const unsigned int status_row = friction ? 3 : 2;

    patches = contact_face_patches(mapping,
                                   dof_handler,
                                   contact_ids,
                                   packed,
                                   displacement,
                                   n_packed,
                                   names.size(),
                                   status_row);
  }

  template std::vector<ContactNodeRow<2>>
  gather_contact_rows(const ContactSet<2> &,
                      const TrilinosWrappers::MPI::Vector &,
                      const MPI_Comm);
  template std::vector<ContactNodeRow<3>>
  gather_contact_rows(const ContactSet<3> &,
                      const TrilinosWrappers::MPI::Vector &,
                      const MPI_Comm);
  template void
  write_contact_csv(const std::string &,
                    const std::vector<ContactNodeRow<2>> &,
                    const bool,
                    const Function<2> *);
  template void
  write_contact_csv(const std::string &,
                    const std::vector<ContactNodeRow<3>> &,
                    const bool,
                    const Function<3> *);
  template class ContactBoundaryOutput<2>;
  template class ContactBoundaryOutput<3>;
} // namespace dualcontact
