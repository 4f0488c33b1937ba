// Quantities derived from the displacement: stress and von Mises stress for
// the graphical output, and errors against an exact solution.
#ifndef dualcontact_postprocess_h
#define dualcontact_postprocess_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/mapping.h>

#include <deal.II/lac/trilinos_vector.h>

#include <deal.II/numerics/data_postprocessor.h>

#include <dualcontact/material_parameters.h>
#include <dualcontact/records.h>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <set>

namespace dualcontact
{
  using namespace dealii;

  /**
   * The pressure p of the mixed formulation at real points of a cell
   * (MixedBulk::values_at()); empty in displacements.
   */
  template <int dim>
  using PressureAt = std::function<std::vector<double>(
    const typename Triangulation<dim>::active_cell_iterator &,
    const std::vector<Point<dim>> &)>;

  /**
   * The Cauchy stress sigma = lambda tr(eps) I + 2 mu eps - p I. In
   * displacements p = 0; in the mixed formulation lambda is -2 mu/3
   * (MaterialParameters::block_lambda()), so that sigma = 2 mu dev eps - p I
   * with p the pressure field (doc/mixed.md).
   */
  template <int dim>
  inline SymmetricTensor<2, dim>
  stress_from_strain(const SymmetricTensor<2, dim> &eps,
                     const double                   lambda,
                     const double                   mu,
                     const double                   pressure = 0.)
  {
    SymmetricTensor<2, dim> sigma =
      lambda * trace(eps) * unit_symmetric_tensor<dim>() + 2. * mu * eps;
    for (unsigned int i = 0; i < dim; ++i)
      sigma[i][i] -= pressure;
    return sigma;
  }

  /**
   * stress_from_strain() of the symmetric part eps of the displacement
   * gradient.
   */
  template <int dim>
  inline SymmetricTensor<2, dim>
  stress_from_gradient(const Tensor<2, dim> &gradient,
                       const double          lambda,
                       const double          mu,
                       const double          pressure = 0.)
  {
    return stress_from_strain(symmetrize(gradient), lambda, mu, pressure);
  }

  /**
   * The out-of-plane stress of plane strain, sigma_zz = lambda tr(eps) - p
   * (2D; in 3D it is a component of the stress and this returns 0).
   */
  template <int dim>
  inline double
  out_of_plane_stress(const Tensor<2, dim> &gradient,
                      const double          lambda,
                      const double          pressure = 0.)
  {
    return dim == 2 ? lambda * trace(gradient) - pressure : 0.;
  }

  /**
   * The von Mises stress sqrt(3/2) |dev sigma| of the full 3x3 stress: in 2D
   * (plane strain) with sigma_zz from out_of_plane_stress().
   */
  template <int dim>
  inline double
  von_mises_stress(const SymmetricTensor<2, dim> &sigma, const double sigma_zz)
  {
    SymmetricTensor<2, 3> s3;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        s3[i][j] = sigma[i][j];
    if (dim == 2)
      s3[2][2] = sigma_zz;
    return std::sqrt(1.5) * deviator(s3).norm();
  }

  /**
   * Cauchy stress sigma = lambda tr(eps) I + 2 mu eps as a tensor field, and
   * the von Mises stress. In 2D (plane strain) the out-of-plane stress
   * sigma_zz = lambda tr(eps) enters the von Mises stress.
   */
  template <int dim>
  class StressPostprocessor : public DataPostprocessor<dim>
  {
  public:
    /**
     * The pressure p of the mixed formulation at real points of a cell:
     * the stress is then 2 mu dev eps(u) - p I (material_parameters.h,
     * block_lambda()). Empty in displacements.
     */
    using PressureAt = dualcontact::PressureAt<dim>;

    explicit StressPostprocessor(const MaterialParameters &material,
                                 PressureAt pressure = PressureAt());

    void
    evaluate_vector_field(
      const DataPostprocessorInputs::Vector<dim> &inputs,
      std::vector<Vector<double>> &computed_quantities) const override;

    std::vector<std::string>
    get_names() const override;

    std::vector<DataComponentInterpretation::DataComponentInterpretation>
    get_data_component_interpretation() const override;

    UpdateFlags
    get_needed_update_flags() const override;

  private:
    const MaterialParameters &material;
    const PressureAt          pressure;
  };

  /**
   * Integrate the error of the ghosted `solution` against `exact` (nullptr:
   * only ||u||_L2 is computed), with a Gauss rule of degree + 2 points.
   */
  template <int dim>
  ErrorNorms
  compute_error_norms(const Mapping<dim>                  &mapping,
                      const DoFHandler<dim>               &dof_handler,
                      const TrilinosWrappers::MPI::Vector &solution,
                      const Function<dim>                 *exact);

  /**
   * The relative L2 error on Gamma_C (the faces with `contact_ids`) of the
   * contact pressure l1_h, the interpolant of the nodal multipliers (the
   * ghosted field of ContactSet::write_fields, hanging nodes filled),
   * against `exact`: |l1_h - p|_L2 / |p|_L2, with a Gauss rule of degree + 3
   * points per face, so that the square-root edge of a Hertz pressure is
   * integrated well.
   */
  template <int dim>
  double
  compute_pressure_error(const Mapping<dim>                  &mapping,
                         const DoFHandler<dim>               &dof_handler,
                         const TrilinosWrappers::MPI::Vector &multipliers,
                         const std::set<types::boundary_id>  &contact_ids,
                         const Function<dim>                 &exact);

  /**
   * The mean displacement |Gamma_i|^{-1} int_{Gamma_i} u ds of the ghosted
   * `solution` over each boundary part i of `ids`: where a clamp was moved
   * to, or how far a loaded face moved (the displacement of a load path's
   * force-displacement loop), components x, y (z). Collective.
   */
  template <int dim>
  std::map<types::boundary_id, std::array<double, 3>>
  mean_boundary_displacements(const Mapping<dim>                  &mapping,
                              const DoFHandler<dim>               &dof_handler,
                              const TrilinosWrappers::MPI::Vector &solution,
                              const std::set<types::boundary_id>  &ids);
} // namespace dualcontact

#endif
