#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/numerics/error_estimator.h>

#include <dualcontact/discretization.h>
#include <dualcontact/refinement.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>

namespace dualcontact
{
  namespace
  {
    /**
     * Which owned cells are among the first n of the global ranking by
     * class, largest first (with `from_bottom`: smallest first), taking a
     * class whole or not at all. The threshold class t is the one ranked
     * lowest such that the classes ranked t or higher hold at least n
     * cells, found by a bisection on global counts (integers: the same on
     * every partition). The classes ranked above t are taken, and t too if
     * that brings the count at least as close to n. `classes` are the owned
     * cells'. Collective.
     */
    std::vector<bool>
    first_in_ranking(const std::vector<std::uint64_t> &classes,
                     const std::uint64_t               max_class,
                     const types::global_cell_index    n,
                     const bool                        from_bottom,
                     const MPI_Comm                    comm)
    {
      std::vector<bool> selected(classes.size(), false);
      if (n == 0)
        return selected;
      // the rank of a class: the larger, the earlier in the ranking
      const auto rank = [&](const std::uint64_t c) {
        return from_bottom ? max_class - c : c;
      };
      const auto count_from = [&](const std::uint64_t r) {
        types::global_cell_index count = 0;
        for (const std::uint64_t c : classes)
          count += (rank(c) >= r ? 1 : 0);
        return Utilities::MPI::sum(count, comm);
      };
      // with_low = count_from(low) >= n > count_from(high) = above
      std::uint64_t            low = 0, high = max_class + 1;
      types::global_cell_index with_low = count_from(0), above = 0;
      while (high - low > 1)
        {
          const std::uint64_t            middle = low + (high - low) / 2;
          const types::global_cell_index count  = count_from(middle);
          if (count >= n)
            {
              low      = middle;
              with_low = count;
            }
          else
            {
              high  = middle;
              above = count;
            }
        }
      const bool take_low = with_low - n <= n - above;
      for (unsigned int i = 0; i < classes.size(); ++i)
        {
          const std::uint64_t r = rank(classes[i]);
          selected[i]           = r > low || (take_low && r == low);
        }
      return selected;
    }
  } // namespace

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
      face_quadrature(dof_handler.get_fe(), dof_handler.get_fe().degree + 1),
      std::map<types::boundary_id, const Function<dim> *>(),
      solution,
      indicator);
    return indicator;
  }

  template <int dim>
  double
  indicator_scale(const Mapping<dim>                  &mapping,
                  const DoFHandler<dim>               &dof_handler,
                  const TrilinosWrappers::MPI::Vector &solution)
  {
    const Quadrature<dim> quadrature =
      cell_quadrature(dof_handler.get_fe(), dof_handler.get_fe().degree + 1);
    FEValues<dim>                    fe_values(mapping,
                            dof_handler.get_fe(),
                            quadrature,
                            update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<2, dim>>      gradients(quadrature.size());
    double                           sum = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_gradients(solution, gradients);
          for (const unsigned int q : fe_values.quadrature_point_indices())
            sum += gradients[q].norm_square() * fe_values.JxW(q);
        }
    const MPI_Comm comm = dof_handler.get_communicator();
    return std::sqrt(Utilities::MPI::sum(sum, comm) /
                     dof_handler.get_triangulation().n_global_active_cells());
  }

  template <int dim>
  void
  mark_fixed_number(Triangulation<dim>  &triangulation,
                    const Vector<float> &indicator,
                    const double         scale,
                    const double         refine_fraction,
                    const double         coarsen_fraction,
                    const double         tie_tolerance)
  {
    const MPI_Comm comm = triangulation.get_communicator();
    std::vector<typename Triangulation<dim>::active_cell_iterator> cells;
    double                                                         largest = 0.;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const double eta = indicator[cell->active_cell_index()];
          AssertThrow(eta >= 0. && std::isfinite(eta),
                      ExcMessage("A refinement indicator is negative or not "
                                 "finite."));
          cells.push_back(cell);
          largest = std::max(largest, eta);
        }
    largest = Utilities::MPI::max(largest, comm);

    // The class width w: a power of 2, so that the round-off of the largest
    // indicator and of the scale changes it only where that value
    // straddles a power of 2, and eta / w is exact. Two values closer than w
    // can still fall into neighbouring classes; for that their round-off
    // must cross a class boundary, which is rare when w is far above the
    // round-off.
    const double reference = std::max(largest, scale);
    const double width =
      reference > 0. ?
        std::exp2(std::floor(std::log2(tie_tolerance * reference))) :
        1.;
    const auto class_of = [width](const double eta) {
      return static_cast<std::uint64_t>(std::floor(eta / width + 0.5));
    };
    std::vector<std::uint64_t> classes;
    for (const auto &cell : cells)
      classes.push_back(class_of(indicator[cell->active_cell_index()]));
    const std::uint64_t max_class = class_of(largest);

    const types::global_cell_index n_cells =
      triangulation.n_global_active_cells();
    const std::vector<bool> refine =
      first_in_ranking(classes,
                       max_class,
                       static_cast<types::global_cell_index>(refine_fraction *
                                                             n_cells),
                       false,
                       comm);
    const std::vector<bool> coarsen =
      first_in_ranking(classes,
                       max_class,
                       static_cast<types::global_cell_index>(coarsen_fraction *
                                                             n_cells),
                       true,
                       comm);
    for (unsigned int i = 0; i < cells.size(); ++i)
      if (refine[i])
        cells[i]->set_refine_flag();
      else if (coarsen[i])
        cells[i]->set_coarsen_flag();
  }

  template Vector<float>
  kelly_indicator(const Mapping<2> &,
                  const DoFHandler<2> &,
                  const TrilinosWrappers::MPI::Vector &);
  template Vector<float>
  kelly_indicator(const Mapping<3> &,
                  const DoFHandler<3> &,
                  const TrilinosWrappers::MPI::Vector &);
  template double
  indicator_scale(const Mapping<2> &,
                  const DoFHandler<2> &,
                  const TrilinosWrappers::MPI::Vector &);
  template double
  indicator_scale(const Mapping<3> &,
                  const DoFHandler<3> &,
                  const TrilinosWrappers::MPI::Vector &);
  template void
  mark_fixed_number(Triangulation<2> &,
                    const Vector<float> &,
                    const double,
                    const double,
                    const double,
                    const double);
  template void
  mark_fixed_number(Triangulation<3> &,
                    const Vector<float> &,
                    const double,
                    const double,
                    const double,
                    const double);
} // namespace dualcontact
