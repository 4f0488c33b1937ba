// The Newton iteration (loop 3, doc/theory.md §3.3): one proximal step of the
// Uzawa iteration, i.e. the minimisation of the piecewise-quadratic, C^1,
// strongly convex functional M_k(v) by a semi-smooth Newton method with a
// line search (Armijo's test on the full step, else the minimiser along the
// direction). Each Newton step is one CG solve with algebraic
// multigrid; the AMG hierarchy is reused while the contact statuses hardly
// change.
#ifndef dualcontact_newton_solver_h
#define dualcontact_newton_solver_h

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <dualcontact/contact_set.h>
#include <dualcontact/contact_system.h>
#include <dualcontact/elasticity.h>

#include <vector>

namespace dualcontact
{
  using namespace dealii;

  struct SolverParameters; // parameters.h

  /** What one minimisation took. */
  struct NewtonStatistics
  {
    unsigned int newton_steps  = 0;
    unsigned int cg_iterations = 0;
    unsigned int amg_setups    = 0;
    // it stopped at the round-off floor of the matrix, above its target
    bool       at_floor = false;
    SolveTimes times; // all but `multipliers`
  };

  template <int dim>
  class NewtonSolver
  {
  public:
    NewtonSolver(const SolverParameters &parameters,
                 ElasticSolver<dim>     &linear_solver);

    /**
     * Forget the round-off floor, and the AMG hierarchy unless
     * `keep_preconditioner`: the next minimisation works on a new system.
     * A later step of a load path on the same mesh has the same K, and the
     * hierarchy the previous step built for K plus its contact terms
     * serves as long as the statuses stay near those it was built for
     * (update_preconditioner()).
     */
    void
    reset(const bool keep_preconditioner = false);

    /**
     * Minimise M_k(v) = 1/2 a(v,v) - L(v) + (chi/2)|v - v^k|_M^2
     *   + sum_s m_s/(2r) (((l1_s + r(v_n - g0))^+)^2 - l1_s^2)
     *   + sum_s m_s/r psi_g(l2_s + r v_t)
     * over v, from v, with v^k = `v_previous` and the multipliers of
     * `contact`. Stops when |grad M_k| <= max(final_tolerance F_ref,
     * min(envelope F_ref, gradient reduction |grad_0|)), grad_0 the gradient at
     * the start and F_ref the force scale of doc/theory.md §6 (the smaller
     * of the load and the contact forces), or at the round-off floor of the
     * matrix. Every step is reported
     * to `observer` (may be nullptr). Throws if it does not converge.
     */
    NewtonStatistics
    minimise(const ContactSystem                 &system,
             const ContactSet<dim>               &contact,
             const TrilinosWrappers::MPI::Vector &v_previous,
             TrilinosWrappers::MPI::Vector       &v,
             const double                         envelope,
             const double                         final_tolerance,
             const unsigned int                   uzawa_step,
             IterationObserver                   *observer = nullptr);

    /**
     * For benchmarks: the wall time [s] of one linear solve on the current
     * mesh: AMG set-up plus CG (linear tolerance) on the Newton matrix at
     * the current contact statuses, with right-hand side b, by `solver`
     * (one of its own, so that the Newton iteration's hierarchy survives
     * for the next step of a load path). `iterations` gets the CG count.
     */
    double
    time_reference_solve(const ContactSystem                 &system,
                         const ContactSet<dim>               &contact,
                         const TrilinosWrappers::MPI::Vector &v,
                         ElasticSolver<dim>                  &solver,
                         unsigned int                        &iterations);

  private:
    /**
     * The force scale F_ref the gradient is measured against: the smaller
     * of the load |b| and the contact forces |m_s (l1_s, l2_s)| (the
     * initial overlap's force without a load), not below the previous load
     * step's contact forces.
     */
    double
    force_reference(const ContactSet<dim> &contact) const;

    /**
     * At v: z and y, the gradient (and its smooth part), the branch of the
     * generalised Hessian at every node (`status`, the previous one kept in
     * `previous_status`) and their count in `record`. Returns |grad M_k|.
     */
    double
    evaluate(const ContactSet<dim>               &contact,
             const TrilinosWrappers::MPI::Vector &v,
             IterationRecord                     &record);

    /**
     * Whether the gradient of Newton step j has stalled at the round-off
     * floor of the matrix: full steps that do not halve it, at unchanged
     * statuses, within 10^3 of the target. Notes the floor once.
     */
    bool
    at_roundoff_floor(const unsigned int j,
                      const double       gradient_norm,
                      const double       target,
                      const double       reference,
                      IterationObserver *observer);

    /** Throws if step j is past the steps allowed, naming likely causes. */
    void
    check_step_limit(const unsigned int     j,
                     const ContactSet<dim> &contact,
                     const IterationRecord &record,
                     const double           relative_target) const;

    /**
     * The Newton direction H d = -grad by CG with AMG to the relative
     * tolerance `forcing`, with H = K + the contact terms at `status`;
     * reuses the AMG hierarchy where it serves. Fills `direction`. In the
     * mixed formulation the saddle-point system with H, by MINRES, at v.
     */
    void
    solve_for_direction(const ContactSet<dim>               &contact,
                        const TrilinosWrappers::MPI::Vector &v,
                        const double                         forcing,
                        IterationRecord                     &record,
                        NewtonStatistics                    &statistics);


    /**
     * grad M_k(v) = K v - b - chi M v^k + sum_s m_s ((z_s)^+ n + T
     * proj_g(y_s)), condensed (constrained rows zero). `smooth` gets the
     * first part alone (the line search needs it).
     */
    void
    compute_gradient(const ContactSet<dim>               &contact,
                     const TrilinosWrappers::MPI::Vector &v,
                     TrilinosWrappers::MPI::Vector       &smooth,
                     TrilinosWrappers::MPI::Vector       &gradient) const;

    /**
     * Turn K into the Newton matrix, in place:
     * H = K + sum_{z_s >= 0} m_s r n n^T + sum_s m_s r T D(y_s) T^T
     * (+ (chi_scale - 1) chi M), condensed, with T the tangent basis and D
     * the derivative of the projection onto the disc of radius g (I when
     * sticking). The entries added are kept for remove_contact_terms().
     * Without a second matrix the Newton solve needs the memory of one
     * (doc/performance.md); the terms touch only the rows of contact nodes.
     */
    void
    add_contact_terms(const ContactSet<dim> &contact);

    /** Take off what add_contact_terms() added: K = A + chi M again. */
    void
    remove_contact_terms();

    /**
     * Build the AMG hierarchy for the Newton matrix only when the node
     * statuses moved enough since the last set-up, or CG slowed down.
     * Returns whether it was built.
     */
    bool
    update_preconditioner(const std::vector<unsigned char> &status,
                          const types::global_dof_index     n_active);

    /** The step length along `direction` that minimises M_k. */
    double
    line_search(const ContactSet<dim>               &contact,
                const TrilinosWrappers::MPI::Vector &smooth_gradient,
                const TrilinosWrappers::MPI::Vector &direction);

    const SolverParameters &parameters;
    ElasticSolver<dim>     &linear_solver;

    // the system of the current minimisation: set by minimise()
    const ContactSystem            *system = nullptr;
    TrilinosWrappers::MPI::Vector   rhs; // b + chi M v^k
    std::vector<double>             z;   // l1 + r (v_n - g0) per node
    std::vector<Tensor<1, dim - 1>> y;   // l2 + r v_t per node
    // the gradient, its smooth part, the Newton direction and -gradient
    TrilinosWrappers::MPI::Vector smooth_gradient, gradient, direction,
      newton_rhs;
    // the Hessian's branch per node at this and at the previous step
    std::vector<unsigned char> status, previous_status;
    // the previous step's length and gradient, how many full steps in a
    // row have stalled (at unchanged statuses, and at any), and how many
    // steps the line search cut short
    struct Progress
    {
      double       previous_alpha    = 0.;
      double       previous_gradient = 0.;
      unsigned int stalled           = 0;
      unsigned int stalled_switching = 0;
      unsigned int short_steps       = 0;
    };
    Progress progress;

    // the entries add_contact_terms() added to K, and the multiple of M
    struct ContactEntry
    {
      types::global_dof_index row, column;
      double                  value;
    };
    std::vector<ContactEntry> contact_terms;
    double                    proximal_added = 0.;
    // the statuses the Newton matrix had when its AMG preconditioner was
    // last built
    std::vector<unsigned char> amg_status;
    bool                       amg_valid                 = false;
    double                     amg_chi_scale             = 1.; // of its K
    unsigned int               cg_iterations_after_setup = 0;
    unsigned int               last_cg_iterations        = 0;
    // the round-off floor of the gradient found since reset(), over F_ref,
    // and whether it was reported
    double roundoff_floor    = 0.;
    bool   roundoff_reported = false;
  };
} // namespace dualcontact

#endif
