#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/distributed/tria_base.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/numerics/vector_tools.h>

#include <dualcontact/discretization.h>
#include <dualcontact/postprocess.h>

#include <iterator>

namespace dualcontact
{
  template <int dim>
  StressPostprocessor<dim>::StressPostprocessor(
    const MaterialParameters &material,
    PressureAt                pressure)
      : material(material)
      , pressure(std::move(pressure))
  {}

  template <int dim>
  void
  StressPostprocessor<dim>::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<dim> &inputs,
    std::vector<Vector<double>>                &computed_quantities) const
  {
    // the material of the cell (<Material/Materials by id>)
    const auto               cell = inputs.template get_cell<dim>();
    const MaterialParameters here = material.of(cell->material_id());
    // in the mixed formulation the deviatoric part from u, and -p I
    const double              lambda = here.block_lambda(), mu = here.mu();
    const std::vector<double> p_values =
      pressure ? pressure(cell, inputs.evaluation_points) :
                 std::vector<double>(inputs.solution_gradients.size(), 0.);
    for (unsigned int p = 0; p < inputs.solution_gradients.size(); ++p)
      {
        Tensor<2, dim> grad;
        for (unsigned int d = 0; d < dim; ++d)
          grad[d] = inputs.solution_gradients[p][d];
        const SymmetricTensor<2, dim> sigma =
          stress_from_gradient(grad, lambda, mu, p_values[p]);
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            computed_quantities[p](i * dim + j) = sigma[i][j];
        computed_quantities[p](dim * dim) =
          von_mises_stress(sigma,
                           out_of_plane_stress(grad, lambda, p_values[p]));
      }
  }

  template <int dim>
  std::vector<std::string>
  StressPostprocessor<dim>::get_names() const
  {
    std::vector<std::string> names(dim * dim, "stress");
    names.emplace_back("von_mises");
    return names;
  }

  template <int dim>
  std::vector<DataComponentInterpretation::DataComponentInterpretation>
  StressPostprocessor<dim>::get_data_component_interpretation() const
  {
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(dim * dim,
                     DataComponentInterpretation::component_is_part_of_tensor);
    interpretation.push_back(DataComponentInterpretation::component_is_scalar);
    return interpretation;
  }

  template <int dim>
  UpdateFlags
  StressPostprocessor<dim>::get_needed_update_flags() const
  {
    return pressure ? update_gradients | update_quadrature_points :
                      update_gradients;
  }

  template <int dim>
  ErrorNorms
  compute_error_norms(const Mapping<dim>                  &mapping,
                      const DoFHandler<dim>               &dof_handler,
                      const TrilinosWrappers::MPI::Vector &solution,
                      const Function<dim>                 *exact)
  {
    const auto           &triangulation = dof_handler.get_triangulation();
    const Quadrature<dim> quadrature =
      cell_quadrature(dof_handler.get_fe(), dof_handler.get_fe().degree + 2);
    Vector<double>                     cellwise(triangulation.n_active_cells());
    const Functions::ZeroFunction<dim> zero(dim);

    const auto norm = [&](const Function<dim>        &reference,
                          const VectorTools::NormType type) {
      VectorTools::integrate_difference(
        mapping, dof_handler, solution, reference, cellwise, quadrature, type);
      return VectorTools::compute_global_error(triangulation, cellwise, type);
    };

    ErrorNorms norms;
    norms.norm_L2 = norm(zero, VectorTools::L2_norm);
    if (exact != nullptr)
      {
        norms.error_L2      = norm(*exact, VectorTools::L2_norm);
        norms.error_H1_semi = norm(*exact, VectorTools::H1_seminorm);
      }
    return norms;
  }

  template class StressPostprocessor<2>;
  template class StressPostprocessor<3>;
  template <int dim>
  double
  compute_pressure_error(const Mapping<dim>                  &mapping,
                         const DoFHandler<dim>               &dof_handler,
                         const TrilinosWrappers::MPI::Vector &multipliers,
                         const std::set<types::boundary_id>  &contact_ids,
                         const Function<dim>                 &exact)
  {
    const Quadrature<dim - 1> quadrature =
      face_quadrature(dof_handler.get_fe(), dof_handler.get_fe().degree + 3);
    FEFaceValues<dim>                fe_face(mapping,
                              dof_handler.get_fe(),
                              quadrature,
                              update_values | update_quadrature_points |
                                update_JxW_values);
    const FEValuesExtractors::Scalar l1(0);
    std::vector<double>              values(quadrature.size());
    double                           sums[2] = {0., 0.}; // error^2, norm^2
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              contact_ids.count(cell->face(f)->boundary_id()))
            {
              fe_face.reinit(cell, f);
              fe_face[l1].get_function_values(multipliers, values);
              for (const unsigned int q : fe_face.quadrature_point_indices())
                {
                  const double p = exact.value(fe_face.quadrature_point(q));
                  sums[0] += std::pow(values[q] - p, 2) * fe_face.JxW(q);
                  sums[1] += p * p * fe_face.JxW(q);
                }
            }
    const MPI_Comm comm = dof_handler.get_triangulation().get_communicator();
    Utilities::MPI::sum(ArrayView<const double>(sums, 2),
                        comm,
                        ArrayView<double>(sums, 2));
    return sums[1] > 0. ? std::sqrt(sums[0] / sums[1]) : std::sqrt(sums[0]);
  }

  template <int dim>
  std::map<types::boundary_id, std::array<double, 3>>
  mean_boundary_displacements(const Mapping<dim>                  &mapping,
                              const DoFHandler<dim>               &dof_handler,
                              const TrilinosWrappers::MPI::Vector &solution,
                              const std::set<types::boundary_id>  &ids)
  {
    const Quadrature<dim - 1> quadrature =
      face_quadrature(dof_handler.get_fe(), dof_handler.get_fe().degree + 1);
    FEFaceValues<dim>                fe_face(mapping,
                              dof_handler.get_fe(),
                              quadrature,
                              update_values | update_JxW_values);
    const FEValuesExtractors::Vector u(0);
    std::vector<Tensor<1, dim>>      values(quadrature.size());
    // per id: the integrals of u_x, u_y, (u_z) and the measure
    std::vector<double> sums(ids.size() * (dim + 1), 0.);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              ids.count(cell->face(f)->boundary_id()))
            {
              const auto    id = ids.find(cell->face(f)->boundary_id());
              double *const sum =
                &sums[std::distance(ids.begin(), id) * (dim + 1)];
              fe_face.reinit(cell, f);
              fe_face[u].get_function_values(solution, values);
              for (const unsigned int q : fe_face.quadrature_point_indices())
                {
                  for (unsigned int c = 0; c < dim; ++c)
                    sum[c] += values[q][c] * fe_face.JxW(q);
                  sum[dim] += fe_face.JxW(q);
                }
            }
    Utilities::MPI::sum(sums,
                        dof_handler.get_triangulation().get_communicator(),
                        sums);
    std::map<types::boundary_id, std::array<double, 3>> means;
    unsigned int                                        i = 0;
    for (const types::boundary_id id : ids)
      {
        std::array<double, 3> &mean = means[id];
        const double          *sum  = &sums[i++ * (dim + 1)];
        for (unsigned int c = 0; c < dim; ++c)
          mean[c] = sum[dim] > 0. ? sum[c] / sum[dim] : 0.;
      }
    return means;
  }

  template std::map<types::boundary_id, std::array<double, 3>>
  mean_boundary_displacements<2>(const Mapping<2> &,
                                 const DoFHandler<2> &,
                                 const TrilinosWrappers::MPI::Vector &,
                                 const std::set<types::boundary_id> &);
  template std::map<types::boundary_id, std::array<double, 3>>
  mean_boundary_displacements<3>(const Mapping<3> &,
                                 const DoFHandler<3> &,
                                 const TrilinosWrappers::MPI::Vector &,
                                 const std::set<types::boundary_id> &);

  template double
  compute_pressure_error<2>(const Mapping<2> &,
                            const DoFHandler<2> &,
                            const TrilinosWrappers::MPI::Vector &,
                            const std::set<types::boundary_id> &,
                            const Function<2> &);
  template double
  compute_pressure_error<3>(const Mapping<3> &,
                            const DoFHandler<3> &,
                            const TrilinosWrappers::MPI::Vector &,
                            const std::set<types::boundary_id> &,
                            const Function<3> &);

  template ErrorNorms
  compute_error_norms<2>(const Mapping<2> &,
                         const DoFHandler<2> &,
                         const TrilinosWrappers::MPI::Vector &,
                         const Function<2> *);
  template ErrorNorms
  compute_error_norms<3>(const Mapping<3> &,
                         const DoFHandler<3> &,
                         const TrilinosWrappers::MPI::Vector &,
                         const Function<3> *);
} // namespace dualcontact
