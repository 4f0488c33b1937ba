#include <deal.II/base/mpi.h>

#include <dualcontact/friction_iteration.h>
#include <dualcontact/input_error.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace dualcontact
{
  namespace
  {
    void
    add(ContactStatistics &total, const ContactStatistics &part)
    {
      total.uzawa_steps += part.uzawa_steps;
      total.newton_steps += part.newton_steps;
      total.cg_iterations += part.cg_iterations;
      total.amg_setups += part.amg_setups;
      total.n_active           = part.n_active;
      total.n_stick            = part.n_stick;
      total.n_slip             = part.n_slip;
      total.rate               = part.rate;
      total.estimated_l1_error = part.estimated_l1_error;
      total.change_g           = part.change_g;
    }
  } // namespace

  template <int dim>
  FrictionIteration<dim>::FrictionIteration(
    const FrictionParameters &parameters,
    UzawaSolver<dim>         &uzawa_solver,
    ConditionalOStream       &pcout)
      : parameters(parameters)
      , uzawa_solver(uzawa_solver)
      , pcout(pcout)
  {}

  template <int dim>
  ContactStatistics
  FrictionIteration<dim>::solve(const ContactSystem           &system,
                                ContactSet<dim>               &contact,
                                TrilinosWrappers::MPI::Vector &v,
                                std::vector<IterationRecord>  &log,
                                const double held_by_friction_pressure,
                                const bool   warm_start)
  {
    const bool coulomb =
      contact.friction && parameters.law == FrictionLaw::coulomb;
    if (!coulomb)
      return uzawa_solver.solve(system, contact, v, log);

    const MPI_Comm    comm = v.get_mpi_communicator();
    ContactStatistics total;

    // g^0: carried from the previous mesh, zero, or F times the pressure
    // of the frictionless problem
    if (warm_start)
      pcout << "   loop 1: g^0 carried from the previous mesh\n";
    else if (parameters.strategy == FrictionStrategy::nested &&
             held_by_friction_pressure > 0.)
      {
        pcout << "   loop 1: only friction holds the body tangentially, so "
                 "g^0 = F N / |Gamma_C| = F * "
              << held_by_friction_pressure
              << " (g^0 = 0 could not hold the tangential load)\n";
        for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
          contact.threshold[s] =
            contact.coefficient[s] * held_by_friction_pressure;
      }
    else if (parameters.initial_threshold == InitialThreshold::frictionless)
      {
        pcout << "   loop 1: g^0 = F l1 of the frictionless problem\n";
        contact.friction = false;
        add(total, uzawa_solver.solve(system, contact, v, log));
        contact.friction = true;
        for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
          contact.threshold[s] = contact.coefficient[s] * contact.l1[s];
      }
    else
      std::fill(contact.threshold.begin(), contact.threshold.end(), 0.);

    if (parameters.strategy == FrictionStrategy::merged)
      {
        pcout << "   loop 1 merged into loop 2: g = F l1 after every Uzawa "
                 "step\n";
        add(total,
            uzawa_solver.solve(
              system, contact, v, log, true, parameters.tolerance));
        total.friction_steps = total.uzawa_steps;
        return total;
      }

    for (unsigned int step = 1; step <= parameters.max_steps; ++step)
      {
        const ContactStatistics part =
          uzawa_solver.solve(system, contact, v, log);
        add(total, part);

        // the relative change of g = F l1
        double sums[2] = {0., 0.};
        for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
          {
            const double g_new = contact.coefficient[s] * contact.l1[s];
            sums[0] += std::pow(g_new - contact.threshold[s], 2);
            sums[1] += g_new * g_new;
          }
        Utilities::MPI::sum(ArrayView<const double>(sums, 2),
                            comm,
                            ArrayView<double>(sums, 2));
        const double change = sums[1] > 0. ? std::sqrt(sums[0] / sums[1]) :
                                             (sums[0] > 0. ? 1. : 0.);

        IterationRecord record;
        record.loop          = "friction";
        record.index         = step;
        record.uzawa_step    = part.uzawa_steps;
        record.newton_steps  = part.newton_steps;
        record.cg_iterations = part.cg_iterations;
        record.n_active      = part.n_active;
        record.n_stick       = part.n_stick;
        record.n_slip        = part.n_slip;
        record.change_g      = change;
        log.push_back(record);
        total.friction_steps = step;
        total.change_g       = change;

        std::ostringstream line;
        line << "   loop 1, step " << std::setw(3) << step << ": "
             << part.uzawa_steps << " Uzawa steps, stick/slip " << part.n_stick
             << "/" << part.n_slip << ", d(g) " << std::scientific
             << std::setprecision(2) << change;
        pcout << line.str() << std::endl;

        // converged: keep the g the solution was computed with (so that
        // |l2| <= g holds exactly); otherwise g <- F l1 and solve again
        if (change <= parameters.tolerance)
          return total;
        for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
          contact.threshold[s] = contact.coefficient[s] * contact.l1[s];
      }

    AssertThrow(false,
                ExcMessage("The threshold iteration (loop 1) did not converge "
                           "in " +
                           std::to_string(parameters.max_steps) +
                           " steps (<Friction/Maximum threshold steps>); the "
                           "last relative change of g was " +
                           format_number(total.change_g) +
                           ". Coulomb solutions are unique only for small "
                           "friction coefficients; try a smaller F or the "
                           "merged strategy."));
    return total;
  }

  template class FrictionIteration<2>;
  template class FrictionIteration<3>;
} // namespace dualcontact
