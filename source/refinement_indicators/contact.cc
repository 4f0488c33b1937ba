// The 'contact' refinement indicator: Kelly's estimator plus a residual of
// the contact tractions on Gamma_C, large where the discrete tractions
// disagree with the multipliers: the edges of the contact zone and the
// stick/slip boundary.
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <dualcontact/discretization.h>
#include <dualcontact/refinement.h>
#include <dualcontact/refinement_indicator.h>

#include <cmath>

namespace dualcontact
{
  namespace
  {
    /**
     * Adds the Gamma_C term to Kelly's `indicator` (in squares): for every
     * owned cell and each of its faces F on the contact ids,
     *   eta_F^2 = weight h_F / E^2 int_F |sigma(u_h) n_F + l1 n + l2 . t|^2,
     * the residual of the traction condition sigma(u) n_F = -(l1 n + l2 t)
     * that the multipliers impose (n = the contact set's normal, t its
     * tangents). Dividing by E makes it a strain, as Kelly's jump of the
     * gradient is, so the weight has no units.
     */
    template <int dim>
    void
    add_contact_term(const IndicatorInput<dim>           &input,
                     const TrilinosWrappers::MPI::Vector &multipliers,
                     const double                         weight,
                     Vector<float>                       &indicator)
    {
      const Mapping<dim>                  &mapping     = input.mapping;
      const DoFHandler<dim>               &dof_handler = input.dof_handler;
      const TrilinosWrappers::MPI::Vector &solution    = input.solution;
      const ContactSet<dim>               &contact     = input.contact;
      const std::set<types::boundary_id>  &contact_ids = input.contact_ids;
      const MaterialParameters            &material = input.parameters.material;
      const FiniteElement<dim>            &fe       = dof_handler.get_fe();
      const Quadrature<dim - 1> quadrature = face_quadrature(fe, fe.degree + 1);
      FEFaceValues<dim>         fe_face(mapping,
                                fe,
                                quadrature,
                                update_values | update_gradients |
                                  update_normal_vectors | update_JxW_values |
                                  update_quadrature_points);
      const FEValuesExtractors::Vector     displacement(0);
      std::vector<SymmetricTensor<2, dim>> strain(quadrature.size());
      std::vector<Tensor<1, dim>>          lambda(quadrature.size());
      const auto &pairs = input.parameters.boundary.contact_pairs;

      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            // the cell's material (<Material/Materials by id>)
            const MaterialParameters here   = material.of(cell->material_id());
            const double             E      = here.youngs_modulus;
            const double             lame_l = here.lambda();
            const double             lame_m = here.mu();
            double                   sum    = 0.;
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  contact_ids.count(cell->face(f)->boundary_id()))
                {
                  fe_face.reinit(cell, f);
                  // the multipliers act along the obstacle's normal, or on
                  // a pair's slave side along the body's own
                  const bool paired =
                    pairs.count(cell->face(f)->boundary_id()) > 0;
                  fe_face[displacement].get_function_symmetric_gradients(
                    solution, strain);
                  fe_face[displacement].get_function_values(multipliers,
                                                            lambda);
                  double integral = 0.;
                  for (const unsigned int q :
                       fe_face.quadrature_point_indices())
                    {
                      const SymmetricTensor<2, dim> stress =
                        lame_l * trace(strain[q]) *
                          unit_symmetric_tensor<dim>() +
                        2. * lame_m * strain[q];
                      // lambda[q]: (l1, l2_1, .., l2_{dim-1}) interpolated
                      const Tensor<1, dim> nu = fe_face.normal_vector(q);
                      const auto [n, t] =
                        paired ? std::make_pair(nu, tangent_basis(nu)) :
                                 contact.basis_at(fe_face.quadrature_point(q));
                      Tensor<1, dim> residual =
                        stress * fe_face.normal_vector(q) + lambda[q][0] * n;
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

    template <int dim>
    Vector<float>
    contact_indicator(const IndicatorInput<dim> &input)
    {
      Vector<float> eta =
        kelly_indicator(input.mapping, input.dof_handler, input.solution);
      if (!input.contact_ids.empty())
        add_contact_term(
          input,
          input.multipliers(),
          numbers_of(input.values, "Refinement/Contact indicator weight").at(0),
          eta);
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
       "the outward normal, t the tangent), which is large where the "
       "discrete tractions disagree with the multipliers: the edges of the "
       "contact zone and the stick/slip boundary.",
       declare,
       {"Refinement/Contact indicator weight"},
       contact_indicator<2>,
       contact_indicator<3>});
  } // namespace
} // namespace dualcontact
