#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <dualcontact/contact_functions.h>
#include <dualcontact/uzawa_iteration.h>

#include <algorithm>
#include <cmath>

namespace dualcontact
{
  template <int dim>
  UzawaIteration<dim>::UzawaIteration(const SolverParameters &parameters,
                                      NewtonSolver<dim>      &newton)
      : parameters(parameters)
      , newton(newton)
  {}

  template <int dim>
  NewtonStatistics
  UzawaIteration<dim>::proximal_step(
    const ContactSystem                 &system,
    const ContactSet<dim>               &contact,
    const TrilinosWrappers::MPI::Vector &v_previous,
    TrilinosWrappers::MPI::Vector       &v,
    const unsigned int                   k,
    IterationObserver                   *observer)
  {
    const double final_tolerance =
      parameters.newton_tolerance_factor * parameters.uzawa_tolerance;
    const double envelope =
      std::max(final_tolerance,
               parameters.initial_inner_tolerance *
                 std::pow(parameters.inner_tolerance_reduction, k - 1.));
    return newton.minimise(
      system, contact, v_previous, v, envelope, final_tolerance, k, observer);
  }

  template <int dim>
  IterationRecord
  UzawaIteration<dim>::update_multipliers(
    const ContactSystem                 &system,
    ContactSet<dim>                     &contact,
    const TrilinosWrappers::MPI::Vector &v_previous,
    const TrilinosWrappers::MPI::Vector &v,
    const bool                           update_threshold) const
  {
    const MPI_Comm                  comm = v.get_mpi_communicator();
    std::vector<double>             z;
    std::vector<Tensor<1, dim - 1>> y;
    contact.augmented_state(v, system.r, z, y);

    // sums: |dl1|^2, |l1|^2, |dl2|^2, |l2|^2, |dg|^2, |g|^2
    double                  sums[6] = {0, 0, 0, 0, 0, 0};
    double                  l1_max = 0, violation = 0, complementarity = 0;
    types::global_dof_index counts[3] = {0, 0, 0}; // active, stick, slip
    for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
      {
        const double l1_new = positive_part(z[s]);
        const double gap =
          contact.nodes[s].gap0 - contact.normal_displacement(v, s);
        sums[0] += std::pow(l1_new - contact.l1[s], 2);
        sums[1] += l1_new * l1_new;
        l1_max          = std::max(l1_max, l1_new);
        violation       = std::max(violation, positive_part(-gap));
        complementarity = std::max(complementarity, l1_new * std::abs(gap));
        counts[0] += (l1_new > 0.);
        contact.l1[s] = l1_new;
        if (!contact.friction)
          continue;
        // merged threshold iteration: g from the new pressure first, so
        // that |l2| <= g holds
        if (update_threshold)
          {
            const double g_new = contact.threshold_from_pressure(s);
            sums[4] += std::pow(g_new - contact.threshold[s], 2);
            sums[5] += g_new * g_new;
            contact.threshold[s] = g_new;
          }
        const Tensor<1, dim - 1> l2_new =
          project_onto_disc(y[s], contact.threshold[s]);
        sums[2] += (l2_new - contact.l2[s]).norm_square();
        sums[3] += l2_new.norm_square();
        contact.l2[s] = l2_new;
        if (l1_new > 0.)
          ++counts[y[s].norm() < contact.threshold[s] ? 1 : 2];
      }
    Utilities::MPI::sum(ArrayView<const double>(sums, 6),
                        comm,
                        ArrayView<double>(sums, 6));
    Utilities::MPI::sum(ArrayView<const types::global_dof_index>(counts, 3),
                        comm,
                        ArrayView<types::global_dof_index>(counts, 3));
    l1_max          = Utilities::MPI::max(l1_max, comm);
    violation       = Utilities::MPI::max(violation, comm);
    complementarity = Utilities::MPI::max(complementarity, comm);

    IterationRecord record;
    record.loop      = Loop::uzawa;
    record.n_active  = counts[0];
    record.n_stick   = counts[1];
    record.n_slip    = counts[2];
    record.change_l1 = relative_change(std::sqrt(sums[0]), std::sqrt(sums[1]));
    record.change_l2 = relative_change(std::sqrt(sums[2]), std::sqrt(sums[3]));
    record.change_g  = relative_change(std::sqrt(sums[4]), std::sqrt(sums[5]));
    TrilinosWrappers::MPI::Vector change(v);
    change -= v_previous;
    const double v_norm_inf = v.linfty_norm();
    record.change_v         = relative_change(change.l2_norm(), v.l2_norm());
    record.violation        = relative_change(violation, v_norm_inf);
    record.complementarity =
      relative_change(complementarity, l1_max * v_norm_inf);
    return record;
  }

  template <int dim>
  bool
  UzawaIteration<dim>::converged(const IterationRecord &record,
                                 const bool             friction,
                                 const bool             update_threshold,
                                 const double threshold_tolerance) const
  {
    const double tolerance = parameters.uzawa_tolerance;
    return record.change_l1 <= tolerance && record.change_v <= tolerance &&
           record.violation <= tolerance &&
           (!friction || record.change_l2 <= tolerance) &&
           (!update_threshold || record.change_g <= threshold_tolerance);
  }

  template <int dim>
  ContactStatistics
  UzawaIteration<dim>::solve(const ContactSystem           &system,
                             ContactSet<dim>               &contact,
                             TrilinosWrappers::MPI::Vector &v,
                             IterationObserver             *observer,
                             const bool                     update_threshold,
                             const double                   threshold_tolerance)
  {
    newton.reset(); // a new system: build the preconditioner afresh
    ContactStatistics             statistics;
    TrilinosWrappers::MPI::Vector v_previous(v);
    double                        previous_change = 0.;
    for (unsigned int k = 1; k <= parameters.max_uzawa_steps; ++k)
      {
        Timer timer(v.get_mpi_communicator(), true);
        v_previous = v;
        const NewtonStatistics newton_statistics =
          proximal_step(system, contact, v_previous, v, k, observer);
        IterationRecord record =
          update_multipliers(system, contact, v_previous, v, update_threshold);
        timer.stop();
        record.uzawa_step    = k;
        record.newton_steps  = newton_statistics.newton_steps;
        record.cg_iterations = newton_statistics.cg_iterations;
        record.amg_setups    = newton_statistics.amg_setups;
        record.time          = timer.wall_time();
        if (observer != nullptr)
          observer->uzawa_step(record, contact.friction, update_threshold);

        statistics.uzawa_steps = k;
        statistics.newton_steps += record.newton_steps;
        statistics.cg_iterations += record.cg_iterations;
        statistics.amg_setups += record.amg_setups;
        statistics.n_active = record.n_active;
        statistics.n_stick  = record.n_stick;
        statistics.n_slip   = record.n_slip;
        statistics.change_g = record.change_g;
        // the observed contraction rate, and the error it implies
        if (k > 1 && previous_change > 0.)
          statistics.rate = std::min(record.change_l1 / previous_change, 0.999);
        statistics.estimated_l1_error =
          record.change_l1 * statistics.rate / (1. - statistics.rate);
        previous_change = record.change_l1;

        if (converged(
              record, contact.friction, update_threshold, threshold_tolerance))
          return statistics;
      }

    AssertThrow(false,
                ExcMessage("The Uzawa iteration did not converge in " +
                           std::to_string(parameters.max_uzawa_steps) +
                           " steps (<Solver/Maximum Uzawa steps>). Raise the "
                           "limit or <Solver/Augmentation parameter>, or check "
                           "that the foundation can hold the load."));
    return statistics;
  }

  template class UzawaIteration<2>;
  template class UzawaIteration<3>;
} // namespace dualcontact
