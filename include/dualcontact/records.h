// The records each phase of a refinement cycle returns, and the record of a
// whole cycle that the report turns into screen output, tables and CSV.
#ifndef dualcontact_records_h
#define dualcontact_records_h

#include <deal.II/base/types.h>

#include <dualcontact/contact_system.h>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  /** setup_system(): the mesh of this cycle. */
  struct MeshRecord
  {
    unsigned int             cycle   = 0;
    types::global_cell_index n_cells = 0;
    types::global_dof_index  n_dofs  = 0;
  };

  /**
   * transfer_fields(): what nested iteration carried from the previous
   * mesh. The carried multipliers before their projection onto the
   * admissible set: the smallest l1 and the largest |l2| - g, relative to
   * the largest multiplier and the largest g (doc/theory.md §7).
   */
  struct TransferRecord
  {
    bool   warm_start         = false;
    double carried_min_l1     = 0.;
    double carried_max_excess = 0.;
  };

  /**
   * solve(): the loops' totals (for linear elasticity alone: the CG
   * iterations), and the constants of the contact problem.
   */
  struct SolveRecord : ContactStatistics
  {
    types::global_dof_index n_contact_nodes   = 0;
    types::global_dof_index n_hanging_contact = 0; // on Gamma_C, all ranks
    unsigned int            n_corner_contact = 0; // beside an obstacle's corner
    // slave nodes of contact pairs that face no master: no contact nodes
    types::global_dof_index n_uncovered = 0;
    // the wall time of pairing the surfaces on this mesh [s] (contact pairs)
    double pairing_time = 0.;
    double r            = 0.; // augmentation used
    double r_t          = 0.; // tangential augmentation (with friction)
    double chi          = 0.; // proximal weight used
    // the applied load toward the foundation (tractions and body force;
    // not the lifting of prescribed displacements)
    double normal_load = 0.;
    // a later load step: the factor of the extrapolation it started from
    // (step_predictor.h), 0 where it started from the last step's state
    double predictor = 0.;
    // Solver/Time a reference linear solve: AMG set-up + CG of one solve
    double       time_reference       = 0.;
    unsigned int reference_iterations = 0;
  };

  /** measure_contact_zone(): the contact zone at convergence. */
  struct ContactZoneRecord
  {
    // obstacle_force plus the pair_force of every pair
    double contact_force = 0.;
    // the force of the body on the obstacle along the mean normal of the
    // obstacle's contact nodes
    double obstacle_force = 0.;
    // each contact pair's (in the order of <Boundary conditions/Contact
    // pairs>): the force of its slave body on its master body along the
    // mean normal of its slave nodes (> 0 where they press)
    std::vector<double> pair_force;
    // the force of the foundation on the body, a vector (a load of the
    // mesh; the forces of contact pairs are inside it)
    std::array<double, 3> resultant{};
    // contact pairs: the forces on the slave and on the master bodies,
    // -sum_s m_s (l1_s n_s + T_s l2_s) and its sum_j c_sj shares
    std::array<double, 3> on_slave_body{};
    std::array<double, 3> on_master_body{};
    // |sum_s m_s T_s l2_s| in the tangent plane of the obstacle's direction,
    // plus each pair's in the plane normal to the pair's
    double tangential_force = 0.;
    double max_pressure     = 0.; // max_s l1_s
    // the half-width (2D) or radius (3D) of the zone: half the extent of
    // the active nodes (along two lines through its centre in 3D), and the
    // same with the edges extrapolated (contact_zone_shape)
    double half_width      = 0.;
    double edge_half_width = 0.;
    double area            = 0.; // 3D: sum of m_s over the active nodes
    double extent          = 0.; // largest distance of an active node from
                                 // the zone's centre
    // lines through the centre that stop there (a model cut by symmetry
    // planes): measured with their mirror image, area times 2 per cut
    unsigned int mirrored = 0;
    // the half-width (2D) or radius (3D) of the stick zone (friction)
    double stick_half_width = 0.;
    double pressure_error   = 0.; // relative L2 on Gamma_C (exact known)
    // relative errors against <Exact solution/Contact half-width> and
    // <Peak pressure> (0 where not known)
    double half_width_error       = 0.;
    double peak_pressure_error    = 0.;
    double stick_half_width_error = 0.; // <Stick half-width>
  };

  /** compare_with_cold_start(): the same mesh solved from zero. */
  struct ColdStartRecord
  {
    unsigned int uzawa_steps     = 0;
    unsigned int newton_steps    = 0;
    unsigned int threshold_steps = 0;
    double       time            = 0.; // [s], apart from the solve's
    double       difference_v    = 0.; // |v - v_cold|_a / |v_cold|_a
    double       difference_l1   = 0.; // the same for l1 (weighted)
  };

  /** postprocess(): norms of the displacement and of its error. */
  struct ErrorNorms
  {
    double norm_L2       = 0.; // ||u||_L2
    double error_L2      = 0.; // ||u - u_exact||_L2 (exact known)
    double error_H1_semi = 0.; // |u - u_exact|_H1
  };

  /** |f|^2 of a force given by its components (unused ones zero). */
  inline double
  norm_square(const std::array<double, 3> &f)
  {
    return f[0] * f[0] + f[1] * f[1] + f[2] * f[2];
  }

  /**
   * compute_reactions(): the force each support ('fixed', 'normal fixed'
   * boundary id) exerts on the body, and the resultant of the applied loads
   * (body force and tractions), components x, y (z) [force, per unit
   * thickness in 2D]. In equilibrium the reactions, the contact force and
   * the loads add up to zero.
   */
  struct ReactionRecord
  {
    std::map<types::boundary_id, std::array<double, 3>> on_id;
    std::array<double, 3>                               applied_load{};
    // on a mesh of more than one body (contact pairs), the reactions and
    // the applied loads of each body (the connected parts of the mesh,
    // numbered as Bodies numbers them, bodies.h)
    std::vector<std::array<double, 3>> on_body, load_on_body;
    // and the contact forces on each body (from the obstacle and the other
    // bodies)
    std::vector<std::array<double, 3>> contact_on_body;
    // |contact force + reactions + applied loads| / the largest of them:
    // the equilibrium of the whole mesh and, where it has several bodies,
    // of each body (the largest; 0 when it holds exactly)
    double imbalance = 0.;
  };

  /** What check_deformed_position() (plausibility.h) found. */
  struct PositionRecord
  {
    double max_displacement = 0.; // max |u| over the support points
    // the deepest point of a boundary without the contact condition below
    // the foundation plane (0: none below it), and its boundary id
    double             penetration    = 0.;
    types::boundary_id penetrating_id = 0;
    // the smallest initial gap of the contact boundary's support points
    double min_initial_gap = 0.;
    // one line each, for the log: what is implausible but not wrong
    std::vector<std::string> warnings;
  };

  /** Wall times of the phases of one cycle [s], from the TimerOutput. */
  struct PhaseTimes
  {
    double refine   = 0.; // marking, refinement, transfer (to this mesh)
    double setup    = 0.;
    double assembly = 0.;
    double solve    = 0.;
    double output   = 0.;
    double total    = 0.; // all phases of all cycles up to here
    double cycle    = 0.; // all phases of this cycle (screen only)
    double elapsed  = 0.; // since the run began, everything included
  };

  /**
   * A step of the load path (doc/theory.md §11): which, at what time, where
   * the obstacle is, and the energy friction dissipated.
   */
  struct StepRecord
  {
    unsigned int step    = 1; // the row of steps.csv: 1, 2, ...
    unsigned int n_steps = 1; // the listed times
    double       time    = 1.;
    // which listed time the step reaches (1 .. n_steps), 0 for a sub-step
    // of adaptive step control that ends short of it; with fixed control
    // every step reaches one (listed = step)
    unsigned int          listed    = 1;
    double                step_size = 0.; // t - the time of the step before
    unsigned int          cuts      = 0; // the failed tries before it converged
    std::array<double, 3> obstacle_displacement{}; // U(t)
    // the mean displacement of each loaded boundary part ('fixed',
    // 'traction'), by boundary id: with the reactions, the force-
    // displacement loop of a path
    std::map<types::boundary_id, std::array<double, 3>> boundary_displacement;
    // sum_s m_s l2_s . (slip of the step), in this step and up to it
    double dissipation       = 0.;
    double dissipation_total = 0.;
  };

  /**
   * One refinement cycle, or one later step of a load path: one row of the
   * cycle table (cycles.csv) or of the step table (steps.csv).
   */
  struct CycleResult
  {
    StepRecord        step;
    MeshRecord        mesh;
    TransferRecord    transfer;
    SolveRecord       solve;
    ContactZoneRecord zone;
    ColdStartRecord   cold;
    ErrorNorms        errors;
    ReactionRecord    reactions;
    PositionRecord    position;
    PhaseTimes        time;
    // the potential energy of the displacement, J(u) = 1/2 a(u, u) - f(u)
    // (potential_energy() of elasticity.h)
    double potential_energy = 0.;
    double memory_mb        = 0.; // peak resident memory, all ranks
  };
} // namespace dualcontact

#endif
