// The threshold iteration (loop 1, doc/theory.md §3.1): successive
// approximations of the friction threshold g when the friction law makes it
// depend on the contact pressure (Coulomb: g = F l1), around the
// given-threshold (Tresca) problem that the Uzawa iteration solves.
#ifndef dualcontact_threshold_iteration_h
#define dualcontact_threshold_iteration_h

#include <dualcontact/contact_set.h>
#include <dualcontact/contact_system.h>
#include <dualcontact/uzawa_iteration.h>

namespace dualcontact
{
  using namespace dealii;

  struct FrictionParameters; // parameters.h

  /**
   * Where a solve starts: from zero, or from the fields carried from the
   * previous mesh (nested iteration) or from the previous load step.
   */
  enum class WarmStart
  {
    cold,
    previous_mesh,
    previous_step
  };

  template <int dim>
  class ThresholdIteration
  {
  public:
    ThresholdIteration(const FrictionParameters &parameters,
                       UzawaIteration<dim>      &uzawa);

    /**
     * Solve the contact problem `contact` describes. If its friction law
     * does not depend on the pressure (none, given threshold): one Uzawa
     * iteration. Otherwise the threshold iteration in the chosen strategy:
     *  - nested: g^{s+1} = g(l1(u^s)) after each converged Uzawa iteration,
     *    until |g^{s+1} - g^s| <= tol |g^{s+1}|;
     *  - merged: g updated after every Uzawa step, one loop.
     * g^0 is zero, or the law's threshold at the frictionless pressure, or,
     * with a warm start, the thresholds in `contact`, carried from the
     * previous mesh or load step. If only friction holds the body
     * tangentially under a tangential load, the problems with g^0 = 0 have
     * no solution (nested) or let the body slide first (merged); the caller
     * then passes, for each contact node of this rank, the mean contact
     * pressure N / |Gamma_C| of the contact that holds its body (0 at the
     * other nodes) as `held_by_friction_pressure`, and both strategies
     * start from the threshold at that pressure, which holds the load
     * (doc/theory.md §8); empty or all 0 on every rank: none.
     * Every step of every loop is reported to `observer`.
     */
    ContactStatistics
    solve(const ContactSystem           &system,
          ContactSet<dim>               &contact,
          TrilinosWrappers::MPI::Vector &v,
          IterationObserver             *observer                  = nullptr,
          const std::vector<double>     &held_by_friction_pressure = {},
          const WarmStart                start = WarmStart::cold);

  private:
    /** g^0, as solve() says; may solve the frictionless problem first. */
    void
    initial_threshold(const ContactSystem           &system,
                      ContactSet<dim>               &contact,
                      TrilinosWrappers::MPI::Vector &v,
                      IterationObserver             *observer,
                      const std::vector<double>     &held_by_friction_pressure,
                      const WarmStart                start,
                      ContactStatistics             &total);

    const FrictionParameters &parameters;
    UzawaIteration<dim>      &uzawa;
  };
} // namespace dualcontact

#endif
