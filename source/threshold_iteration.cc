#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>

#include <dualcontact/contact_functions.h>
#include <dualcontact/input_error.h>
#include <dualcontact/parameters.h>
#include <dualcontact/threshold_iteration.h>

#include <cmath>

namespace dualcontact
{
  template <int dim>
  ThresholdIteration<dim>::ThresholdIteration(
    const FrictionParameters &parameters,
    UzawaIteration<dim>      &uzawa)
      : parameters(parameters)
      , uzawa(uzawa)
  {}

  template <int dim>
  void
  ThresholdIteration<dim>::initial_threshold(
    const ContactSystem           &system,
    ContactSet<dim>               &contact,
    TrilinosWrappers::MPI::Vector &v,
    IterationObserver             *observer,
    const std::vector<double>     &held_by_friction_pressure,
    const WarmStart                start,
    ContactStatistics             &total)
  {
    const auto say = [observer](const std::string &text) {
      if (observer != nullptr)
        observer->note(text);
    };
    double held_pressure = 0.;
    for (const double p : held_by_friction_pressure)
      held_pressure = std::max(held_pressure, p);
    held_pressure =
      Utilities::MPI::max(held_pressure, v.get_mpi_communicator());
    if (start != WarmStart::cold)
      say(std::string("threshold iteration: g^0 carried from the previous ") +
          (start == WarmStart::previous_mesh ? "mesh" : "load step"));
    else if (held_pressure > 0.)
      {
        std::ostringstream text;
        text << "threshold iteration: only friction holds the body "
                "tangentially, so g^0 is the threshold at the mean pressure "
                "N / |Gamma_C| = "
             << held_pressure
             << " (g^0 = 0 could not hold the tangential load)";
        say(text.str());
        for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
          contact.threshold[s] =
            contact.law->threshold(contact.friction_parameter[s],
                                   held_by_friction_pressure[s]);
      }
    else if (parameters.initial_threshold == InitialThreshold::frictionless)
      {
        say("threshold iteration: g^0 from the pressure of the frictionless "
            "problem");
        contact.friction = false;
        total.add(uzawa.solve(system, contact, v, observer));
        contact.friction = true;
        for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
          contact.threshold[s] = contact.threshold_from_pressure(s);
      }
    else
      std::fill(contact.threshold.begin(), contact.threshold.end(), 0.);
  }

  template <int dim>
  ContactStatistics
  ThresholdIteration<dim>::solve(
    const ContactSystem           &system,
    ContactSet<dim>               &contact,
    TrilinosWrappers::MPI::Vector &v,
    IterationObserver             *observer,
    const std::vector<double>     &held_by_friction_pressure,
    const WarmStart                start)
  {
    if (!contact.friction || !contact.law->depends_on_pressure())
      return uzawa.solve(system, contact, v, observer);

    ContactStatistics total;
    initial_threshold(
      system, contact, v, observer, held_by_friction_pressure, start, total);

    if (parameters.strategy == FrictionStrategy::merged)
      {
        if (observer != nullptr)
          observer->note("threshold iteration merged into the Uzawa "
                         "iteration: g updated after every Uzawa step");
        total.add(uzawa.solve(
          system, contact, v, observer, true, parameters.tolerance));
        total.threshold_steps = total.uzawa_steps;
        return total;
      }

    const MPI_Comm comm = v.get_mpi_communicator();
    // On a later step of a load path the change of g is measured against
    // the largest of the new g, g^0 and the previous step's g, as the other
    // tests along a path are (doc/theory.md §11): where the path brings the
    // body back to its start, g is round-off, and a change relative to it
    // alone never falls below the tolerance (nor relative to g^0, the
    // predictor's, round-off as well on a path that unloads to zero).
    double g_start = 0.;
    if (start == WarmStart::previous_step)
      {
        for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
          g_start += contact.threshold[s] * contact.threshold[s];
        g_start = std::max(std::sqrt(Utilities::MPI::sum(g_start, comm)),
                           system.previous.g_norm);
      }
    for (unsigned int step = 1; step <= parameters.max_steps; ++step)
      {
        const ContactStatistics part =
          uzawa.solve(system, contact, v, observer);
        total.add(part);

        // the relative change of g from the new pressure
        double sums[2] = {0., 0.};
        for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
          {
            const double g_new = contact.threshold_from_pressure(s);
            sums[0] += std::pow(g_new - contact.threshold[s], 2);
            sums[1] += g_new * g_new;
          }
        Utilities::MPI::sum(ArrayView<const double>(sums, 2),
                            comm,
                            ArrayView<double>(sums, 2));
        const double change =
          relative_change(std::sqrt(sums[0]),
                          std::max(std::sqrt(sums[1]), g_start));

        IterationRecord record;
        record.loop          = Loop::threshold;
        record.index         = step;
        record.uzawa_steps   = part.uzawa_steps;
        record.newton_steps  = part.newton_steps;
        record.cg_iterations = part.cg_iterations;
        record.n_active      = part.n_active;
        record.n_stick       = part.n_stick;
        record.n_slip        = part.n_slip;
        record.change_g      = change;
        if (observer != nullptr)
          observer->threshold_step(record);
        total.threshold_steps = step;
        total.change_g        = change;

        // converged: keep the g the solution was computed with (so that
        // |l2| <= g holds exactly); otherwise update g and solve again
        if (change <= parameters.tolerance)
          return total;
        for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
          contact.threshold[s] = contact.threshold_from_pressure(s);
      }

    AssertThrow(false,
                ExcMessage(
                  "The threshold iteration (loop 1) did not converge "
                  "in " +
                  std::to_string(parameters.max_steps) +
                  " steps (<Friction/Maximum threshold steps>); the "
                  "last relative change of g was " +
                  format_number(total.change_g) + " (tolerance " +
                  format_number(parameters.tolerance) +
                  "). Likely causes, most likely first: (1) a large "
                  "friction coefficient, for which Coulomb solutions "
                  "need not be unique and the successive "
                  "approximations need not contract: try a smaller "
                  "F or <Friction/Threshold iteration> = merged; (2) too "
                  "few steps allowed: raise <Friction/Maximum threshold "
                  "steps>."));
    return total;
  }

  template class ThresholdIteration<2>;
  template class ThresholdIteration<3>;
} // namespace dualcontact
