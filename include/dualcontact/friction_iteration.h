// Loop 1 of DESIGN.md §2: successive approximations of the Coulomb friction
// threshold g = F l1 around the given-friction (Tresca) problem, which the
// Uzawa solver (loops 2 and 3) solves.
#ifndef dualcontact_friction_iteration_h
#define dualcontact_friction_iteration_h

#include <deal.II/base/conditional_ostream.h>

#include <dualcontact/contact_set.h>
#include <dualcontact/parameters.h>
#include <dualcontact/uzawa_solver.h>

#include <vector>

namespace dualcontact
{
  using namespace dealii;

  template <int dim>
  class FrictionIteration
  {
  public:
    FrictionIteration(const FrictionParameters &parameters,
                      UzawaSolver<dim>         &uzawa_solver,
                      ConditionalOStream       &pcout);

    /**
     * Solve the contact problem the contact set describes: without friction
     * or with a given threshold, one Uzawa solve; with Coulomb friction,
     * loop 1 in the chosen strategy:
     *  - nested: g^{s+1} = F l1(u^s) after each converged Uzawa solve, until
     *    |g^{s+1} - g^s| <= tol |g^{s+1}|;
     *  - merged: g = F l1 after every Uzawa step, one loop.
     * g^0 is zero, or F times the frictionless pressure. If only friction
     * holds the body tangentially under a tangential load, the problems with
     * those thresholds have no solution; the caller then passes the mean
     * contact pressure N / |Gamma_C| and the nested iteration starts from
     * g^0 = F N / |Gamma_C|, whose capacity F N holds the load. One record
     * per loop-1 step is appended to `log` (loop "friction").
     * With `warm_start` (nested iteration) the thresholds in `contact`,
     * carried from the previous mesh, are g^0.
     */
    ContactStatistics
    solve(const ContactSystem           &system,
          ContactSet<dim>               &contact,
          TrilinosWrappers::MPI::Vector &v,
          std::vector<IterationRecord>  &log,
          const double                   held_by_friction_pressure = 0.,
          const bool                     warm_start                = false);

  private:
    const FrictionParameters &parameters;
    UzawaSolver<dim>         &uzawa_solver;
    ConditionalOStream       &pcout;
  };
} // namespace dualcontact

#endif
