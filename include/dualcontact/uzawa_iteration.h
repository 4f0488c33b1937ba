// The Uzawa iteration (loop 2, doc/theory.md §3.2) on the modified Lagrangian
// with proximal regularisation. One step k:
//   1. the proximal step  v^{k+1} = argmin_v M_k(v)   (the Newton iteration)
//   2. the multiplier update
//        l1^{k+1} = (l1^k + r (v_n^{k+1} - g0))^+,
//        l2^{k+1} = proj_g(l2^k + r v_t^{k+1}).
// Both are public, so that a program can write the loop itself; solve()
// is that loop with the stopping test of doc/theory.md §6.
#ifndef dualcontact_uzawa_iteration_h
#define dualcontact_uzawa_iteration_h

#include <deal.II/lac/trilinos_vector.h>

#include <dualcontact/contact_set.h>
#include <dualcontact/contact_system.h>
#include <dualcontact/newton_solver.h>

#include <string>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  struct SolverParameters; // parameters.h

  template <int dim>
  class UzawaIteration
  {
  public:
    UzawaIteration(const SolverParameters &parameters,
                   NewtonSolver<dim>      &newton);

    /**
     * The proximal step k (k = 1, 2, ...): minimise M_k from v, with
     * v^k = `v_previous` and the multipliers of `contact`, by the Newton
     * iteration. Its tolerance shrinks geometrically with k, an envelope
     * that keeps the errors summable, as the convergence theorem needs; it
     * never goes below the final tolerance (the Newton tolerance factor
     * times the Uzawa tolerance).
     */
    NewtonStatistics
    proximal_step(const ContactSystem                 &system,
                  const ContactSet<dim>               &contact,
                  const TrilinosWrappers::MPI::Vector &v_previous,
                  TrilinosWrappers::MPI::Vector       &v,
                  const unsigned int                   k,
                  IterationObserver                   *observer = nullptr);

    /**
     * The multiplier update after the proximal step from `v_previous` to
     * `v`, and the measures of convergence, reduced over the ranks: the
     * relative changes of l1, l2 and v, the relative violation and
     * complementarity, the active, stick and slip counts. With
     * `update_threshold` (the merged threshold iteration) also g <- the
     * law's threshold at the new pressure, before l2 is projected.
     */
    IterationRecord
    update_multipliers(const ContactSystem                 &system,
                       ContactSet<dim>                     &contact,
                       const TrilinosWrappers::MPI::Vector &v_previous,
                       const TrilinosWrappers::MPI::Vector &v,
                       const bool update_threshold = false) const;

    /**
     * The stopping test: the relative changes of l1, v (and l2 with
     * friction) and the violation at most the Uzawa tolerance, and the
     * change of g at most `threshold_tolerance` if g was updated.
     */
    bool
    converged(const IterationRecord &record,
              const bool             friction,
              const bool             update_threshold    = false,
              const double           threshold_tolerance = 0.) const;

    /**
     * The whole iteration from v (owned entries, satisfying the
     * constraints) and the multipliers in `contact`, until converged().
     * Every Newton and Uzawa step is reported to `observer`. If the changes
     * contract slowly while v still moves, the proximal weight of the steps
     * is lowered (down to minimum_chi_scale chi); if they stall at the
     * round-off floor of the inner solves with the constraint met, that is
     * accepted as convergence and said. Throws, with the last changes and
     * the likely causes, if it does not converge in <Solver/Maximum Uzawa
     * steps>.
     */
    ContactStatistics
    solve(const ContactSystem           &system,
          ContactSet<dim>               &contact,
          TrilinosWrappers::MPI::Vector &v,
          IterationObserver             *observer            = nullptr,
          const bool                     update_threshold    = false,
          const double                   threshold_tolerance = 0.);

    /**
     * The smallest proximal weight, relative to chi, that solve() lowers it
     * to when the iteration contracts slowly (doc/theory.md §3.2).
     */
    static constexpr double minimum_chi_scale = 1e-4;

  private:
    /**
     * proximal_step(); a Newton failure while v drifts (by `history`)
     * throws with the drift as its cause.
     */
    NewtonStatistics
    proximal_step_unless_drifting(
      const ContactSystem                 &system,
      const ContactSet<dim>               &contact,
      const TrilinosWrappers::MPI::Vector &v_previous,
      TrilinosWrappers::MPI::Vector       &v,
      const unsigned int                   k,
      IterationObserver                   *observer,
      const std::vector<IterationRecord>  &history);

    /**
     * update_multipliers(); with a `threshold_scale` (merged with the
     * threshold iteration on a later step of a load path), the change of g
     * measured against it too.
     */
    IterationRecord
    update_multipliers_on_path(const ContactSystem                 &system,
                               ContactSet<dim>                     &contact,
                               const TrilinosWrappers::MPI::Vector &v_previous,
                               const TrilinosWrappers::MPI::Vector &v,
                               const bool   update_threshold,
                               const double threshold_scale);

    /**
     * Whether solve() stops at the round-off floor of the inner solves
     * with the constraint (and the threshold) met; if so, marks
     * `statistics` and says so to the observer.
     */
    bool
    stop_at_roundoff_floor(const std::vector<IterationRecord> &history,
                           const bool                          friction,
                           const bool                          update_threshold,
                           const double       threshold_tolerance,
                           ContactStatistics &statistics,
                           IterationObserver *observer) const;

    /**
     * Lower the proximal weight of `step_system` tenfold (a new matrix),
     * and say so with the contraction rate of `history`.
     */
    void
    lower_proximal_weight(ContactSystem                      &step_system,
                          const std::vector<IterationRecord> &history,
                          const bool                          friction,
                          IterationObserver                  *observer);

    /** The Newton tolerance of step k, and the one it shrinks to. */
    double
    newton_envelope(const unsigned int k) const;
    double
    final_newton_tolerance() const;

    /**
     * The last steps of `history` sit at the round-off floor of the inner
     * solves: v no longer moves, the constraint holds, and the multiplier
     * changes stay put (doc/theory.md §6).
     */
    bool
    at_roundoff_floor(const std::vector<IterationRecord> &history,
                      const bool                          friction) const;

    /** The last three steps moved v and contracted by less than 30 % each. */
    bool
    contracts_slowly(const std::vector<IterationRecord> &history,
                     const bool                          friction) const;

    /** Which loop failed, its last changes, and the likely causes. */
    std::string
    non_convergence_message(const std::vector<IterationRecord> &history,
                            const bool                          friction,
                            const double chi_scale) const;

    const SolverParameters &parameters;
    NewtonSolver<dim>      &newton;
  };
} // namespace dualcontact

#endif
