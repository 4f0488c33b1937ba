#include <deal.II/base/mpi_remote_point_evaluation.h>

#include <deal.II/numerics/vector_tools_evaluate.h>

#include <dualcontact/input_error.h>
#include <dualcontact/postprocess.h>
#include <dualcontact/probes.h>

#include <fstream>
#include <iomanip>
#include <sstream>

namespace dualcontact
{
  namespace
  {
    // -0 (a stress component that vanishes) as 0
    inline double
    tidy(const double x)
    {
      return x + 0.;
    }

    template <int dim>
    std::string
    point_text(const Point<dim> &p)
    {
      std::ostringstream text;
      text << '(';
      for (unsigned int d = 0; d < dim; ++d)
        text << (d > 0 ? ", " : "") << p[d];
      text << ')';
      return text.str();
    }
  } // namespace

  template <int dim>
  Probes<dim>::Probes(const std::vector<std::vector<double>> &coordinates)
  {
    // the number of coordinates is checked with the other entries
    // (Parameters::check_consistency)
    for (const std::vector<double> &c : coordinates)
      {
        Point<dim> p;
        for (unsigned int d = 0; d < dim && d < c.size(); ++d)
          p[d] = c[d];
        points.push_back(p);
      }
  }

  template <int dim>
  void
  Probes<dim>::check_inside(const Mapping<dim>       &mapping,
                            const Triangulation<dim> &triangulation) const
  {
    if (points.empty())
      return;
    Utilities::MPI::RemotePointEvaluation<dim> cache;
    cache.reinit(points, triangulation, mapping);
    for (unsigned int i = 0; i < points.size(); ++i)
      if (!cache.point_found(i))
        throw InputError("The point " + point_text(points[i]) + " (probe " +
                           std::to_string(i + 1) +
                           ") of <Output/Probe points> lies outside the body.",
                         exit_inconsistent);
  }

  template <int dim>
  void
  Probes<dim>::evaluate(const unsigned int                   cycle,
                        const Mapping<dim>                  &mapping,
                        const DoFHandler<dim>               &dof_handler,
                        const TrilinosWrappers::MPI::Vector &solution,
                        const MaterialParameters            &material)
  {
    if (points.empty())
      return;
    // every rank asks for every point: the values come back to all ranks
    Utilities::MPI::RemotePointEvaluation<dim> cache;
    const auto u = VectorTools::point_values<dim>(
      mapping, dof_handler, solution, points, cache);
    const auto grad =
      VectorTools::point_gradients<dim>(cache, dof_handler, solution);
    const double lambda = material.lambda();
    const double mu     = material.mu();
    for (unsigned int i = 0; i < points.size(); ++i)
      {
        Value value;
        value.cycle = cycle;
        value.probe = i;
        value.point = points[i];
        if (cache.point_found(i))
          {
            value.displacement = u[i];
            value.stress       = stress_from_gradient(grad[i], lambda, mu);
            value.stress_zz    = out_of_plane_stress(grad[i], lambda);
            value.von_mises = von_mises_stress(value.stress, value.stress_zz);
          }
        else // a later mesh lost the point (a curved boundary): no value
          {
            const double nan      = std::numeric_limits<double>::quiet_NaN();
            value.displacement    = Tensor<1, dim>();
            value.displacement[0] = nan;
            value.stress[0][0]    = nan;
            value.stress_zz       = nan;
            value.von_mises       = nan;
          }
        all_values.push_back(value);
      }
  }

  template <int dim>
  void
  Probes<dim>::write_csv(const std::string &filename) const
  {
    static const char axis[] = "xyz";
    std::ofstream     csv(filename);
    csv << "cycle,probe";
    for (unsigned int d = 0; d < dim; ++d)
      csv << ',' << axis[d];
    for (unsigned int d = 0; d < dim; ++d)
      csv << ",u_" << axis[d];
    // the diagonal, then the upper triangle; in 2D sigma_zz of plane strain
    for (unsigned int d = 0; d < 3; ++d)
      csv << ",sigma_" << axis[d] << axis[d];
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i + 1; j < dim; ++j)
        csv << ",sigma_" << axis[i] << axis[j];
    csv << ",von_mises\n";
    csv << std::setprecision(12);
    for (const Value &v : all_values)
      {
        csv << v.cycle << ',' << v.probe + 1;
        for (unsigned int d = 0; d < dim; ++d)
          csv << ',' << tidy(v.point[d]);
        for (unsigned int d = 0; d < dim; ++d)
          csv << ',' << tidy(v.displacement[d]);
        for (unsigned int d = 0; d < dim; ++d)
          csv << ',' << tidy(v.stress[d][d]);
        if (dim == 2)
          csv << ',' << tidy(v.stress_zz);
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = i + 1; j < dim; ++j)
            csv << ',' << tidy(v.stress[i][j]);
        csv << ',' << tidy(v.von_mises) << '\n';
      }
  }

  template class Probes<2>;
  template class Probes<3>;
} // namespace dualcontact
