// The 'contact' refinement indicator: Kelly's estimator plus a residual of
// the contact tractions on Gamma_C, large where the discrete tractions
// disagree with the multipliers: the edges of the contact zone and the
// stick/slip boundary; on a contact pair on both sides, the master's
// tractions those the slave's multipliers put on it.
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <dualcontact/discretization.h>
#include <dualcontact/parameters.h>
#include <dualcontact/postprocess.h>
#include <dualcontact/refinement.h>
#include <dualcontact/refinement_indicator.h>

#include <cmath>

namespace dualcontact
{
  namespace
  {
    /**
     * sigma(u_h) at the quadrature points of `fe_face`, reinitialised on a
     * face of `cell` (of the material `here`): lambda tr(eps) I + 2 mu eps,
     * and in the mixed formulation 2 mu dev eps - p I with the pressure
     * field at the points (stress_from_strain(), doc/mixed.md).
     */
    template <int dim>
    std::vector<SymmetricTensor<2, dim>>
    face_stresses(const IndicatorInput<dim>                            &input,
                  const typename DoFHandler<dim>::active_cell_iterator &cell,
                  const MaterialParameters                             &here,
                  const FEFaceValues<dim>                              &fe_face)
    {
      std::vector<SymmetricTensor<2, dim>> stress(fe_face.n_quadrature_points);
      fe_face[FEValuesExtractors::Vector(0)].get_function_symmetric_gradients(
        input.solution, stress);
      const std::vector<double> p =
        input.pressure ? input.pressure(cell, fe_face.get_quadrature_points()) :
                         std::vector<double>(stress.size(), 0.);
      for (unsigned int q = 0; q < stress.size(); ++q)
        stress[q] =
          stress_from_strain(stress[q], here.block_lambda(), here.mu(), p[q]);
      return stress;
    }

    /**
     * Adds the Gamma_C term to Kelly's `indicator` (in squares): for every
     * owned cell and each of its faces F on the contact ids,
     *   eta_F^2 = weight h_F / E^2 int_F |sigma(u_h) n_F + l1 n + l2 . t|^2,
     * the residual of the traction condition sigma(u) n_F = -(l1 n + l2 t)
     * that the multipliers impose (n = the contact set's normal, t its
     * tangents; sigma(u_h) of face_stresses(), with -p n_F in the mixed
     * formulation). Dividing by E makes it a strain, as Kelly's jump of the
     * gradient is, so the weight has no units.
     */
    template <int dim>
    void
    add_contact_term(const IndicatorInput<dim>           &input,
                     const TrilinosWrappers::MPI::Vector &multipliers,
                     const double                         weight,
                     Vector<float>                       &indicator)
    {
      const Mapping<dim>                 &mapping     = input.mapping;
      const DoFHandler<dim>              &dof_handler = input.dof_handler;
      const ContactSet<dim>              &contact     = input.contact;
      const std::set<types::boundary_id> &contact_ids = input.contact_ids;
      const MaterialParameters           &material = input.parameters.material;
      const FiniteElement<dim>           &fe       = dof_handler.get_fe();
      const Quadrature<dim - 1> quadrature = face_quadrature(fe, fe.degree + 1);
      FEFaceValues<dim>         fe_face(mapping,
                                fe,
                                quadrature,
                                update_values | update_gradients |
                                  update_normal_vectors | update_JxW_values |
                                  update_quadrature_points);
      const FEValuesExtractors::Vector displacement(0);
      std::vector<Tensor<1, dim>>      lambda(quadrature.size());
      const auto &pairs = input.parameters.boundary.contact_pairs;

      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            // the cell's material (<Material/Materials by id>)
            const MaterialParameters here = material.of(cell->material_id());
            const double             E    = here.youngs_modulus;
            double                   sum  = 0.;
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  contact_ids.count(cell->face(f)->boundary_id()))
                {
                  fe_face.reinit(cell, f);
                  // the multipliers act along the obstacle's normal, or on
                  // a pair's slave side along the body's own
                  const bool paired =
                    pairs.count(cell->face(f)->boundary_id()) > 0;
                  const std::vector<SymmetricTensor<2, dim>> stress =
                    face_stresses(input, cell, here, fe_face);
                  fe_face[displacement].get_function_values(multipliers,
                                                            lambda);
                  double integral = 0.;
                  for (const unsigned int q :
                       fe_face.quadrature_point_indices())
                    {
                      // lambda[q]: (l1, l2_1, .., l2_{dim-1}) interpolated
                      const Tensor<1, dim> nu = fe_face.normal_vector(q);
                      const auto [n, t] =
                        paired ? std::make_pair(nu, tangent_basis(nu)) :
                                 contact.basis_at(fe_face.quadrature_point(q));
                      Tensor<1, dim> residual =
                        stress[q] * fe_face.normal_vector(q) + lambda[q][0] * n;
                      for (unsigned int k = 0; k < dim - 1; ++k)
                        residual += lambda[q][k + 1] * t[k];
                      integral += residual.norm_square() * fe_face.JxW(q);
                    }
                  sum += cell->face(f)->diameter() * integral / (E * E);
                }
            if (sum > 0.)
              {
                float &eta = indicator[cell->active_cell_index()];
                eta        = std::sqrt(eta * eta + weight * sum);
              }
          }
    }

    /**
     * The tractions that the contact pairs put on their master faces, as
     * a nodal field, ghosted (component c of master node j on its DoF of
     * component c): the forces sum_s c_sj m_s (l1_s n_s + l2_s . t_s) of the
     * slave nodes s that see j, equal and opposite to theirs, divided by
     * j's face weight m_j = int_{master} phi_j.
     */
    template <int dim>
    TrilinosWrappers::MPI::Vector
    master_tractions(const IndicatorInput<dim>          &input,
                     const std::set<types::boundary_id> &master_ids)
    {
      const DoFHandler<dim>    &dof_handler = input.dof_handler;
      const ContactSet<dim>    &contact     = input.contact;
      const FiniteElement<dim> &fe          = dof_handler.get_fe();
      const MPI_Comm  comm = dof_handler.get_triangulation().get_communicator();
      const IndexSet &owned = dof_handler.locally_owned_dofs();
      TrilinosWrappers::MPI::Vector forces(owned, comm), weights(owned, comm);
      for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
        {
          const ContactNode<dim> &node  = contact.nodes[s];
          Tensor<1, dim>          force = contact.l1[s] * node.normal;
          for (unsigned int k = 0; k + 1 < dim; ++k)
            force += contact.l2[s][k] * node.tangents[k];
          force *= node.weight;
          for (const MasterTerm<dim> &master : node.masters)
            for (unsigned int c = 0; c < dim; ++c)
              forces(master.dofs[c]) += master.coefficient * force[c];
        }
      // m_j: the same weight on each component of a node
      FEFaceValues<dim>                    fe_face(input.mapping,
                                fe,
                                face_quadrature(fe, fe.degree + 1),
                                update_values | update_JxW_values);
      Vector<double>                       local(fe.n_dofs_per_cell());
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                master_ids.count(cell->face(f)->boundary_id()))
              {
                fe_face.reinit(cell, f);
                local = 0.;
                for (const unsigned int q : fe_face.quadrature_point_indices())
                  for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                    local(i) += fe_face.shape_value(i, q) * fe_face.JxW(q);
                cell->get_dof_indices(dof_indices);
                weights.add(dof_indices, local);
              }
      forces.compress(VectorOperation::add);
      weights.compress(VectorOperation::add);
      for (const types::global_dof_index i : owned)
        forces(i) = weights(i) > 0. ? forces(i) / weights(i) : 0.;
      forces.compress(VectorOperation::insert);
      IndexSet relevant;
      DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
      TrilinosWrappers::MPI::Vector ghosted(owned, relevant, comm);
      ghosted = forces;
      return ghosted;
    }

    /**
     * Adds the master side's term of the contact pairs to `indicator`: for
     * every owned cell and each of its faces F on a pair's master id,
     *   eta_F^2 = weight h_F / E^2 int_F |sigma(u_h) n_F - tau|^2,
     * the residual of the traction tau that the slave's multipliers put on
     * the master (master_tractions()), interpolated on F. Nothing
     * without pairs.
     */
    template <int dim>
    void
    add_master_term(const IndicatorInput<dim> &input,
                    const double               weight,
                    Vector<float>             &indicator)
    {
      std::set<types::boundary_id> master_ids;
      for (const auto &[slave, master] : input.contact.pairs().list())
        master_ids.insert(master);
      if (master_ids.empty())
        return;
      const TrilinosWrappers::MPI::Vector tau =
        master_tractions(input, master_ids);
      const FiniteElement<dim> &fe         = input.dof_handler.get_fe();
      const Quadrature<dim - 1> quadrature = face_quadrature(fe, fe.degree + 1);
      FEFaceValues<dim>         fe_face(input.mapping,
                                fe,
                                quadrature,
                                update_values | update_gradients |
                                  update_normal_vectors | update_JxW_values |
                                  update_quadrature_points);
      const FEValuesExtractors::Vector displacement(0);
      std::vector<Tensor<1, dim>>      traction(quadrature.size());
      for (const auto &cell : input.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const MaterialParameters here =
              input.parameters.material.of(cell->material_id());
            double sum = 0.;
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  master_ids.count(cell->face(f)->boundary_id()))
                {
                  fe_face.reinit(cell, f);
                  const std::vector<SymmetricTensor<2, dim>> stress =
                    face_stresses(input, cell, here, fe_face);
                  fe_face[displacement].get_function_values(tau, traction);
                  double integral = 0.;
                  for (const unsigned int q :
                       fe_face.quadrature_point_indices())
                    integral +=
                      (stress[q] * fe_face.normal_vector(q) - traction[q])
                        .norm_square() *
                      fe_face.JxW(q);
                  sum += cell->face(f)->diameter() * integral /
                         (here.youngs_modulus * here.youngs_modulus);
                }
            if (sum > 0.)
              {
                float &eta = indicator[cell->active_cell_index()];
                eta        = std::sqrt(eta * eta + weight * sum);
              }
          }
    }

    template <int dim>
    Vector<float>
    contact_indicator(const IndicatorInput<dim> &input)
    {
      Vector<float> eta =
        kelly_indicator(input.mapping, input.dof_handler, input.solution);
      const double weight =
        numbers_of(input.values, "Refinement/Contact indicator weight").at(0);
      if (!input.contact_ids.empty())
        add_contact_term(input, input.multipliers(), weight, eta);
      add_master_term(input, weight, eta);
      return eta;
    }

    void
    declare(EntryDeclarer &declarer)
    {
      declarer.enter_subsection("Refinement");
      declarer.declare_entry(
        "Contact indicator weight",
        "1",
        EntryPattern::number(0.),
        "'contact': the weight of the Gamma_C term against Kelly's volume "
        "term [-]. Both are measured in strain^2 * length, so the weight has "
        "no units; 0 gives 'kelly'.");
      declarer.leave_subsection();
    }

    const bool registered = register_refinement_indicator(
      "contact",
      {"adds to Kelly's indicator a term on Gamma_C: the residual of the "
       "contact tractions, h_F/E^2 int_F |sigma(u_h) n + l1 n + l2 t|^2 (n "
       "the outward normal, t the tangent; with <Material/Formulation> = "
       "mixed, sigma(u_h) = 2 mu dev eps(u_h) - p_h I), which is large where "
       "the "
       "discrete tractions disagree with the multipliers: the edges of the "
       "contact zone and the stick/slip boundary. On a contact pair the "
       "master faces get the same term with the tractions that the slave's "
       "multipliers put on them.",
       declare,
       {"Refinement/Contact indicator weight"},
       contact_indicator<2>,
       contact_indicator<3>});
  } // namespace
} // namespace dualcontact
