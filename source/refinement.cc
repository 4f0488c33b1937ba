#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/numerics/error_estimator.h>

#include <dualcontact/refinement.h>

#include <map>

namespace dualcontact
{
  template <int dim>
  Vector<float>
  kelly_indicator(const Mapping<dim>                  &mapping,
                  const DoFHandler<dim>               &dof_handler,
                  const TrilinosWrappers::MPI::Vector &solution)
  {
    Vector<float> indicator(dof_handler.get_triangulation().n_active_cells());
    KellyErrorEstimator<dim>::estimate(
      mapping,
      dof_handler,
      QGauss<dim - 1>(dof_handler.get_fe().degree + 1),
      std::map<types::boundary_id, const Function<dim> *>(),
      solution,
      indicator);
    return indicator;
  }

  template <int dim>
  void
  add_contact_indicator(const Mapping<dim>                  &mapping,
                        const DoFHandler<dim>               &dof_handler,
                        const TrilinosWrappers::MPI::Vector &solution,
                        const TrilinosWrappers::MPI::Vector &multipliers,
                        const ContactSet<dim>               &contact,
                        const std::set<types::boundary_id>  &contact_ids,
                        const MaterialParameters            &material,
                        const double                         weight,
                        Vector<float>                       &indicator)
  {
    const FiniteElement<dim>            &fe = dof_handler.get_fe();
    const QGauss<dim - 1>                quadrature(fe.degree + 1);
    FEFaceValues<dim>                    fe_face(mapping,
                              fe,
                              quadrature,
                              update_values | update_gradients |
                                update_normal_vectors | update_JxW_values |
                                update_quadrature_points);
    const FEValuesExtractors::Vector     displacement(0);
    std::vector<SymmetricTensor<2, dim>> strain(quadrature.size());
    std::vector<Tensor<1, dim>>          lambda(quadrature.size());
    const double                         E      = material.youngs_modulus;
    const double                         lame_l = material.lambda();
    const double                         lame_m = material.mu();

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          double sum = 0.;
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                contact_ids.count(cell->face(f)->boundary_id()))
              {
                fe_face.reinit(cell, f);
                fe_face[displacement].get_function_symmetric_gradients(solution,
                                                                       strain);
                fe_face[displacement].get_function_values(multipliers, lambda);
                double integral = 0.;
                for (const unsigned int q : fe_face.quadrature_point_indices())
                  {
                    const SymmetricTensor<2, dim> stress =
                      lame_l * trace(strain[q]) * unit_symmetric_tensor<dim>() +
                      2. * lame_m * strain[q];
                    // lambda[q]: (l1, l2_1, .., l2_{dim-1}) interpolated
                    const auto [n, t] =
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

  template Vector<float>
  kelly_indicator(const Mapping<2> &,
                  const DoFHandler<2> &,
                  const TrilinosWrappers::MPI::Vector &);
  template Vector<float>
  kelly_indicator(const Mapping<3> &,
                  const DoFHandler<3> &,
                  const TrilinosWrappers::MPI::Vector &);
  template void
  add_contact_indicator(const Mapping<2> &,
                        const DoFHandler<2> &,
                        const TrilinosWrappers::MPI::Vector &,
                        const TrilinosWrappers::MPI::Vector &,
                        const ContactSet<2> &,
                        const std::set<types::boundary_id> &,
                        const MaterialParameters &,
                        const double,
                        Vector<float> &);
  template void
  add_contact_indicator(const Mapping<3> &,
                        const DoFHandler<3> &,
                        const TrilinosWrappers::MPI::Vector &,
                        const TrilinosWrappers::MPI::Vector &,
                        const ContactSet<3> &,
                        const std::set<types::boundary_id> &,
                        const MaterialParameters &,
                        const double,
                        Vector<float> &);
} // namespace dualcontact
