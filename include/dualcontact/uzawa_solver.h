// Loops 2 and 3 of DESIGN.md §2: the Uzawa method on the modified
// Lagrangian with proximal regularisation, and the semi-smooth Newton method
// with backtracking line search that solves each Uzawa step.
#ifndef dualcontact_uzawa_solver_h
#define dualcontact_uzawa_solver_h

#include <deal.II/base/conditional_ostream.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <dualcontact/contact_set.h>
#include <dualcontact/elasticity.h>
#include <dualcontact/parameters.h>

#include <string>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  /**
   * The discrete problem one Uzawa solve works on, all condensed with the
   * constraints: K = A + chi M, the mass matrix M, the load b, and r, chi.
   */
  struct ContactSystem
  {
    const TrilinosWrappers::SparseMatrix &stiffness; // K = A + chi M
    const TrilinosWrappers::SparseMatrix &mass;      // M
    const TrilinosWrappers::MPI::Vector  &load;      // b
    const AffineConstraints<double>      &homogeneous_constraints;
    double                                r;   // augmentation [stress/length]
    double                                chi; // proximal [stress/length^2]
  };

  /** One row of the iteration log: a Newton step or an Uzawa step. */
  struct IterationRecord
  {
    std::string             loop; // "newton" or "uzawa"
    unsigned int            cycle         = 0;
    unsigned int            uzawa_step    = 0;
    unsigned int            index         = 0; // Newton step (newton rows)
    unsigned int            newton_steps  = 0; // uzawa rows: steps of loop 3
    unsigned int            cg_iterations = 0;
    unsigned int            amg_setups    = 0;
    types::global_dof_index n_active      = 0;
    double gradient        = 0.; // newton: |grad M_k| / |b| before the step
    double step_length     = 0.; // newton: alpha of the line search
    double change_l1       = 0.; // uzawa: |l1_new - l1| / |l1_new|
    double change_v        = 0.; // uzawa: |v_new - v| / |v_new|
    double violation       = 0.; // uzawa: max (v_n - g0)^+ / |v|_inf
    double complementarity = 0.; // uzawa: max l1 |g0 - v_n| / (max l1 |v|_inf)
    double change_l2       = 0.; // uzawa: |l2_new - l2| / |l2_new|
    double change_g        = 0.; // uzawa (merged) and friction rows:
                                 // |g_new - g| / |g_new|
    types::global_dof_index n_stick = 0;  // in contact and sticking
    types::global_dof_index n_slip  = 0;  // in contact and slipping
    double                  time    = 0.; // wall time of the step [s]
  };

  /** Totals of one call of UzawaSolver::solve. */
  struct ContactStatistics
  {
    unsigned int            uzawa_steps   = 0;
    unsigned int            newton_steps  = 0;
    unsigned int            cg_iterations = 0;
    unsigned int            amg_setups    = 0;
    types::global_dof_index n_active      = 0;
    // The last relative change of l1 understates its error: with the
    // observed contraction rate rho = d_k / d_{k-1} the remaining error is
    // about d_k rho / (1 - rho) (DESIGN.md §3).
    double rate               = 0.;
    double estimated_l1_error = 0.;
    // friction
    types::global_dof_index n_stick        = 0;
    types::global_dof_index n_slip         = 0;
    unsigned int            friction_steps = 0;  // loop 1 (nested) steps
    double                  change_g       = 0.; // last change of g
  };

  template <int dim>
  class UzawaSolver
  {
  public:
    UzawaSolver(const SolverParameters &parameters,
                ElasticSolver<dim>     &linear_solver,
                ConditionalOStream     &pcout,
                const bool              print_timing);

    /**
     * Loop 2. Starting from v (owned entries, satisfying the constraints)
     * and the multipliers in `contact`, iterate
     *   v^{k+1} = argmin M_k(v),  l1^{k+1} = (l1^k + r (v_n^{k+1} - g0))^+
     * until the relative changes of l1 and v and the relative violation are
     * below the Uzawa tolerance. Appends one record per Newton and per Uzawa
     * step to `log`. Throws if it does not converge.
     */
    ContactStatistics
    solve(const ContactSystem           &system,
          ContactSet<dim>               &contact,
          TrilinosWrappers::MPI::Vector &v,
          std::vector<IterationRecord>  &log,
          const bool                     update_threshold    = false,
          const double                   threshold_tolerance = 0.);

    /**
     * For benchmarks: the wall time of one linear solve on the current
     * mesh, i.e. AMG set-up plus CG (linear tolerance) on the Newton matrix
     * at the current active set, with right-hand side b. Returns the time
     * [s]; `iterations` gets the CG count.
     */
    double
    time_reference_solve(const ContactSystem                 &system,
                         const ContactSet<dim>               &contact,
                         const TrilinosWrappers::MPI::Vector &v,
                         unsigned int                        &iterations);

  private:
    /**
     * H = K + sum_{z_s >= 0} m_s r n n^T + sum_s m_s r T D(y_s) T^T,
     * condensed, with T the tangent basis and D the derivative of the
     * projection onto the disc of radius g (I when sticking).
     */
    void
    assemble_newton_matrix(const ContactSystem                   &system,
                           const ContactSet<dim>                 &contact,
                           const std::vector<double>             &z,
                           const std::vector<Tensor<1, dim - 1>> &y);

    /**
     * Loop 3: minimise M_k(v) = 1/2 a(v,v) - L(v) + (chi/2)|v - v^k|_M^2
     * + sum_s m_s/(2r) (((l1_s + r(v_n - g0))^+)^2 - l1_s^2)
     * + sum_s m_s/r psi_g(l2_s + r v_t) over v (psi_g: the Huber function
     * whose gradient is the projection onto the disc of radius g), by
     * semi-smooth Newton until |grad| <= max(final_tolerance |b|,
     * min(envelope |b|, factor |grad_0|)), grad_0 the gradient at the start.
     */
    void
    minimise(const ContactSystem                 &system,
             const ContactSet<dim>               &contact,
             const TrilinosWrappers::MPI::Vector &v_previous,
             TrilinosWrappers::MPI::Vector       &v,
             const double                         envelope,
             const double                         final_tolerance,
             const unsigned int                   uzawa_step,
             IterationRecord                     &step_record,
             std::vector<IterationRecord>        &log);

    /**
     * At every local contact node: z_s = l1_s + r (v_n(s) - g0_s) and, with
     * friction, y_s = l2_s + r v_t(s).
     */
    void
    nodal_state(const ContactSet<dim>               &contact,
                const TrilinosWrappers::MPI::Vector &v,
                const double                         r,
                std::vector<double>                 &z,
                std::vector<Tensor<1, dim - 1>>     &y) const;

    const SolverParameters &parameters;
    ElasticSolver<dim>     &linear_solver;
    ConditionalOStream     &pcout;
    const bool              print_timing;

    // the Newton matrix H = K + sum_active m_s r n n^T, and the active set
    // it had when its AMG preconditioner was last built
    TrilinosWrappers::SparseMatrix newton_matrix;
    std::vector<unsigned char>     amg_status; // per node, see minimise()
    bool                           amg_valid                 = false;
    unsigned int                   cg_iterations_after_setup = 0;
    unsigned int                   last_cg_iterations        = 0;
    // whether loop 3 has reported stopping at round-off in this solve
    bool roundoff_reported = false;
    // the round-off floor of the gradient found in this solve, over |b|
    double roundoff_floor = 0.;
  };
} // namespace dualcontact

#endif
