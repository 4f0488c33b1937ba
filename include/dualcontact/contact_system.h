// What the three loops of the contact solver share: the discrete system they
// work on, the record of one step of any loop, the totals of a solve, and
// the observer that is told of every step (the report prints and logs
// them; a tutorial may print its own).
#ifndef dualcontact_contact_system_h
#define dualcontact_contact_system_h

#include <deal.II/base/types.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <dualcontact/lumped_mass.h>

#include <string>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  class PressureCoupling; // pressure_coupling.h

  /**
   * The size of a contact solution: the nodal Euclidean norms of l1, of the
   * friction thresholds g and of v, the largest entries of l1 and v, the norm
   * of the nodal contact forces m_s (l1_s, l2_s), and the total contact force.
   */
  struct SolutionSize
  {
    double l1_norm       = 0.;
    double l1_max        = 0.;
    double g_norm        = 0.;
    double v_norm        = 0.;
    double v_max         = 0.;
    double force_norm    = 0.;
    double contact_force = 0.; // sum_s m_s l1_s
  };

  /**
   * The discrete problem one contact solve works on, all condensed with the
   * constraints: K = A + chi M, the lumped mass matrix M, the load b, and
   * r, chi (doc/theory.md §3, §5). The proximal weight of a step may be
   * lowered below the chi that K holds (doc/theory.md §3.2): it is
   * chi_scale chi, and the Newton iteration adds (chi_scale - 1) chi M where
   * it needs it.
   *
   * K is not const: the Newton iteration adds its contact terms to K for
   * each linear solve, and takes them off again before anything else reads
   * it (no second matrix; doc/performance.md). Outside a Newton step K is
   * always A + chi M.
   */
  struct ContactSystem
  {
    TrilinosWrappers::SparseMatrix      &stiffness; // K = A + chi M
    const LumpedMass                    &mass;      // M
    const TrilinosWrappers::MPI::Vector &load;      // b
    const AffineConstraints<double>     &homogeneous_constraints;
    double r;              // normal augmentation [stress/length]
    double r_t;            // tangential augmentation [stress/length]
    double chi;            // proximal [stress/length^2]
    double chi_scale = 1.; // the step's proximal weight is chi_scale chi
    // The rigid motions that nothing holds (neither the prescribed
    // displacements nor the contact), orthonormal, condensed: the problem
    // does not determine v along them, and the Uzawa iteration's d(v)
    // leaves them out (doc/theory.md §6). Empty, or null, if there are none.
    const std::vector<TrilinosWrappers::MPI::Vector> *free_motions = nullptr;
    // Along a load path, the size of the previous step's solution: the
    // stopping tests measure changes against the larger of it and this
    // step's own, so that a step whose solution vanishes (everything
    // unloaded) stops at the round-off of the path's scale (doc/theory.md
    // §11). Zero on a first step and in a static scene.
    SolutionSize previous;
    // K is the matrix of the previous contact solve (a later step of a
    // load path on the same mesh): the Newton iteration may start with the
    // preconditioner it built then.
    bool same_stiffness = false;
    // Which of the free motions keep the start's value: along them the
    // proximal term pulls toward the start of the solve, not toward the
    // last v (doc/theory.md §6). Those that something holds, however weakly
    // (between two bodies, the normals' discretisation error), and in a
    // scene of several bodies all. Null: none.
    const std::vector<bool> *anchored_at_start = nullptr;
    // The pressure of the mixed formulation (pressure_coupling.h): K is
    // then the deviatoric stiffness, each Newton step a saddle-point
    // solve, and the pressure moves with v. Null in displacements.
    PressureCoupling *pressure = nullptr;

    /** The proximal weight of the step [stress/length^2]. */
    double
    proximal_weight() const
    {
      return chi_scale * chi;
    }

    /** What K lacks for the step's weight: (chi_scale - 1) chi. */
    double
    proximal_correction() const
    {
      return (chi_scale - 1.) * chi;
    }
  };

  /** The three loops, named by what they do (doc/theory.md §3). */
  enum class Loop
  {
    threshold, // loop 1: successive approximations of g
    uzawa,     // loop 2: the multipliers l1, l2
    newton     // loop 3: the proximal minimisation in v
  };

  /** "threshold", "uzawa" or "newton". */
  std::string
  to_string(const Loop loop);

  /** One step of one loop: a row of iterations.csv. */
  struct IterationRecord
  {
    Loop         loop         = Loop::newton;
    unsigned int cycle        = 0;
    unsigned int step         = 1; // of the load path
    unsigned int uzawa_step   = 0;
    unsigned int index        = 0;     // Newton or threshold step
    unsigned int newton_steps = 0;     // uzawa, threshold rows
    bool newton_at_floor      = false; // uzawa: its Newton iteration stopped at
                                       // the round-off floor of the matrix
    unsigned int            uzawa_steps   = 0; // threshold rows
    unsigned int            cg_iterations = 0;
    unsigned int            amg_setups    = 0;
    types::global_dof_index n_active      = 0;
    double gradient        = 0.; // newton: |grad M_k| / F_ref before the step
    double step_length     = 0.; // newton: alpha of the line search
    double change_l1       = 0.; // uzawa: |l1_new - l1| / |l1_new|
    double change_v        = 0.; // uzawa: |v_new - v| / |v_new|
    double norm_v          = 0.; // uzawa: |v_new| (Euclidean, nodal)
    double violation       = 0.; // uzawa: max (v_n - g0)^+ / |v|_inf
    double complementarity = 0.; // uzawa: max l1 |g0 - v_n| / (max l1 |v|_inf)
    double change_l2       = 0.; // uzawa: |l2_new - l2| / max(|l2_new|,
                                 // |l1_new|)
    double change_g = 0.;        // uzawa (merged) and threshold rows:
                                 // |g_new - g| / |g_new|
    types::global_dof_index n_stick = 0;  // in contact and sticking
    types::global_dof_index n_slip  = 0;  // in contact and slipping
    double                  time    = 0.; // wall time of the step [s]
  };

  /**
   * Where the wall time of a contact solve goes [s], summed over its steps
   * (rank 0's clock: the ranks meet at every reduction).
   */
  struct SolveTimes
  {
    double newton_matrix = 0.; // H = K + chi M + the contact terms
    double amg_setup     = 0.; // AMG hierarchies built
    double cg            = 0.; // CG iterations
    double gradient      = 0.; // gradients, statuses, line searches
    double multipliers   = 0.; // multiplier updates and stopping tests

    SolveTimes &
    operator+=(const SolveTimes &other);
  };

  /** Totals of a contact solve (all three loops). */
  struct ContactStatistics
  {
    unsigned int            threshold_steps = 0; // loop 1
    unsigned int            uzawa_steps     = 0;
    unsigned int            newton_steps    = 0;
    unsigned int            cg_iterations   = 0;
    unsigned int            amg_setups      = 0;
    types::global_dof_index n_active        = 0;
    types::global_dof_index n_stick         = 0;
    types::global_dof_index n_slip          = 0;
    // The last relative change of l1 understates its error: with the
    // observed contraction rate rho = d_k / d_{k-1} the remaining error is
    // about d_k rho / (1 - rho) (doc/theory.md §6).
    double rate               = 0.;
    double estimated_l1_error = 0.;
    double change_g           = 0.; // last change of g
    // the proximal weight the iteration ended with, relative to chi (< 1
    // if a slow mode made the Uzawa iteration lower it, doc/theory.md §3.2)
    double chi_scale = 1.;
    // the Uzawa iteration stopped at the round-off floor of its inner
    // solves rather than at its tolerance (doc/theory.md §6)
    bool       at_roundoff_floor = false;
    SolveTimes times;

    /** Add the counts of `part`, a later solve; keep its final state. */
    void
    add(const ContactStatistics &part);
  };

  /**
   * Told of every step of every loop, and of the few things a loop has to
   * say (which g^0 the threshold iteration starts from, a round-off floor
   * the Newton iteration accepted). Every method does nothing by default;
   * a warning is a note unless the observer tells them apart.
   */
  class IterationObserver
  {
  public:
    virtual ~IterationObserver() = default;

    virtual void
    newton_step(const IterationRecord &)
    {}

    /** `friction`: the step has tangential terms; `merged`: g was updated. */
    virtual void
    uzawa_step(const IterationRecord &, const bool, const bool)
    {}

    virtual void
    threshold_step(const IterationRecord &)
    {}

    virtual void
    note(const std::string &)
    {}

    /** Something the user must see, whatever the verbosity. */
    virtual void
    warning(const std::string &text)
    {
      note(text);
    }
  };
} // namespace dualcontact

#endif
