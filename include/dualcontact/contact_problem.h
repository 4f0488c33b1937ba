// The Problem class, in the shape of a deal.II tutorial: run() loops over
// refinement cycles, then over the later steps of the load path, and calls
// one function per phase, each timed with TimerOutput; each phase returns
// its own record, and the report prints them. The phases are public so that a
// program (a tutorial step) can call them one by one and replace one, e.g.
// write the Uzawa loop itself.
#ifndef dualcontact_contact_problem_h
#define dualcontact_contact_problem_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/timer.h>

#include <deal.II/distributed/tria_base.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <dualcontact/checkpoint.h>
#include <dualcontact/contact_functions.h>
#include <dualcontact/contact_set.h>
#include <dualcontact/contact_system.h>
#include <dualcontact/discretization.h>
#include <dualcontact/elasticity.h>
#include <dualcontact/field_transfer.h>
#include <dualcontact/mixed_bulk.h>
#include <dualcontact/newton_solver.h>
#include <dualcontact/parameters.h>
#include <dualcontact/probes.h>
#include <dualcontact/records.h>
#include <dualcontact/report.h>
#include <dualcontact/scene.h>
#include <dualcontact/step_control.h>
#include <dualcontact/step_predictor.h>
#include <dualcontact/threshold_iteration.h>
#include <dualcontact/uzawa_iteration.h>

#include <iostream>
#include <map>
#include <memory>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  template <int dim>
  class ContactProblem
  {
  public:
    /**
     * Builds the scene from a copy of the parameters (throws InputError on
     * bad input). Screen output goes to `out` on rank 0 only.
     */
    ContactProblem(const Parameters &parameters,
                   MPI_Comm          mpi_communicator = MPI_COMM_WORLD,
                   std::ostream     &out              = std::cout);

    /**
     * Solve on every cycle at the first time of the load path, then at each
     * later time from the state the step before reached (doc/theory.md
     * §11). Everything that can be wrong with the input is checked before
     * the first output file is written.
     */
    void
    run();

    // ---------------------------------------------------------- the phases

    /**
     * The initial mesh; refuses one whose finest cycle would not fit in the
     * memory (run_size.h) before building it, warns above half of it;
     * checks that no rigid motion is left unheld.
     */
    void
    make_grid();

    /** DoFs, constraints (hanging nodes, Dirichlet, sliders), matrices. */
    MeshRecord
    setup_system(const unsigned int cycle);

    /**
     * The constraints of the mesh: hanging nodes, then the prescribed
     * displacements at the scene's time, then the sliders. With
     * `contact_set_built` (the contact set is set up on this mesh) also
     * those of the master DoFs that this rank's slave nodes couple to on a
     * contact pair, from their owners (collective; nothing more without
     * pairs).
     */
    void
    make_constraints(const bool contact_set_built = false);

    /**
     * Nested iteration: interpolate v, the multipliers and the threshold
     * carried across the last refinement onto the new DoFs (nothing on the
     * first mesh, or without <Refinement/Nested iteration>).
     */
    TransferRecord
    transfer_fields();

    /**
     * K = A + chi M (with contact), M, and the load b; the rigid-body
     * modes for the AMG of every linear solve on this mesh.
     */
    void
    assemble_system();

    /**
     * Assemble and solve at the scene's time, then measure: the position,
     * the contact zone, the errors, the potential energy, the reactions,
     * the balance and the energy friction dissipated.
     */
    void
    solve_and_measure(CycleResult &result);

    /**
     * The next step of the load path (row `step` of steps.csv, 2, 3, ...),
     * to the time `control` gives: the scene at its time (loads,
     * obstacle), the mesh (the same, or adapted with <Load path/Adapt at
     * every step>), the state of the step before as the first guess, and
     * the slip origin of the friction law.
     */
    StepRecord
    start_step(const unsigned int step,
               const StepControl &control,
               CycleResult       &result);

    /**
     * Solve and measure a later step. With adaptive <Load path/Step
     * control> a solve that fails is tried again from the state the step
     * started from, at the smaller size `control` gives, until it
     * converges or the size would fall below the minimum step.
     */
    void
    solve_step(StepControl &control, CycleResult &result);

    /**
     * After the later step `step` (every <Output/Checkpoint interval>-th):
     * the mesh, u, u^{n-1}, the multipliers and the threshold on it, and the
     * state of the path and of the report, into the folder checkpoint/ of
     * the output folder (checkpoint.h), which it replaces only once it is
     * whole. The run then goes on from the mesh and fields it reads back,
     * as a resumed run does (doc/theory.md §11, "Restart"): the next step
     * starts without the predictor's extrapolation, with a new
     * preconditioner, and with the cells in the forest's order.
     */
    void
    write_checkpoint(const StepRecord &step, const StepControl &control);

    /**
     * Instead of the refinement cycles: the state of the checkpoint in the
     * output folder, checked against this run's parameters and number of
     * ranks (InputError if it differs, naming the first entry), with
     * steps.csv, iterations.csv and probes_steps.csv cut back to its step.
     * Returns that step; `control` goes on from it. A damaged checkpoint (a
     * field of state.txt missing, not a number, out of its range or not
     * holding together with the others or with the mesh; a file of the
     * forest missing, or not of the size and CRC-32 written) is an
     * InputError (exit_cannot_read_file) that names the file, before any
     * value of it is used.
     */
    unsigned int
    load_checkpoint(StepControl &control);

    /**
     * The same mesh at the time of the step: the constraints, and the
     * contact nodes at the obstacle's place.
     */
    void
    move_to_step_time();

    /**
     * The slip origin of the step to `step` (doc/theory.md §11): u^{n-1}
     * at the nodes in contact, the point where the gap closes at those that
     * touch during the step.
     */
    void
    set_slip_origins(const StepRecord &step);

    /**
     * The step that `control` gives next: its row, the count of listed
     * times, its time and size; the first step at the first listed time.
     */
    StepRecord
    step_record(const unsigned int step, const StepControl *control) const;

    /**
     * A solved step of the load path: the energy dissipated up to it, the
     * loaded boundaries' mean displacements, the probes (probes_steps.csv),
     * its files (every <Load path/Output interval>-th and the last), its
     * row of steps.csv and line on screen; the predictor keeps its state.
     */
    void
    finish_step(CycleResult &result);

    /**
     * One linear elasticity solve, or the contact solve: the threshold
     * iteration around the Uzawa iteration around the Newton iteration, from
     * the carried fields or from zero.
     */
    SolveRecord
    solve();

    /**
     * The first part of the contact solve: the contact nodes and their
     * weights, r, the equilibrium check. solve() calls it; a program that
     * writes its own loops calls it, then works on contact_system() and
     * contact().
     */
    SolveRecord
    prepare_contact_solve();

    /** Contact force, peak pressure, width of the zone, pressure errors. */
    ContactZoneRecord
    measure_contact_zone() const;

    /**
     * The energy friction dissipated in the load step, sum_s m_s l2_s .
     * (v_t(s) - o_t(s)) over all ranks (doc/theory.md §11); 0 without
     * friction.
     */
    double
    dissipation() const;

    /**
     * With <Refinement/Compare with cold start>: the current mesh solved
     * again from v = 0, l1 = l2 = 0, and the difference of the solutions.
     */
    ColdStartRecord
    compare_with_cold_start();

    /**
     * The deformed body against the foundation and the small-strain model
     * (plausibility.h): stops if a boundary without the contact condition
     * passes through the foundation, warns if displacements are large.
     */
    PositionRecord
    check_position();

    /**
     * The reaction force of each 'fixed' and 'normal fixed' boundary id on
     * the body (no extra pass over the cells in a scene without such ids),
     * the resultant of the applied loads, and how far the contact force
     * `zone` measured, the reactions and the loads are from balancing.
     */
    ReactionRecord
    compute_reactions(const ContactZoneRecord &zone) const;

    /** Norms of u and of its error against an exact solution. */
    ErrorNorms
    postprocess() const;

    /**
     * The potential energy J(u) = 1/2 a(u, u) - f(u) of the solution, f the
     * body force and the tractions (elasticity.h).
     */
    double
    potential_energy() const;

    /**
     * The files of this cycle: probes.csv (every cycle so far), with contact
     * contact_NN.csv (one row per contact node), and if asked for the
     * volume fields (solution_NN.pvtu, solution.pvd) and the contact fields
     * on Gamma_C (contact_NN.pvtu, contact.pvd). On the first cycle the
     * files of an earlier run in the output folder are removed first and
     * parameters.prm is written.
     */
    void
    output_results(const unsigned int cycle);

    /** The probe points and what they found on every cycle so far. */
    const Probes<dim> &
    get_probes() const
    {
      return probes;
    }

    /** Mark (globally or by an indicator), prepare the transfer, refine. */
    void
    refine_mesh();

    /**
     * The files of a step of the load path, named by the step
     * (contact_step_NNN.csv, solution_step_NNN.pvtu, contact_step_NNN.pvtu)
     * with .pvd records over the steps that give each its time.
     */
    void
    output_step(const StepRecord &step);

    // ------------------------------------------------------- what it holds

    const std::vector<CycleResult> &
    results() const
    {
      return report.cycles();
    }

    /** The steps of a load path of several steps (empty otherwise). */
    const std::vector<CycleResult> &
    steps() const
    {
      return report.steps();
    }

    /**
     * Every Newton, Uzawa and threshold step of every cycle, and of a load
     * path's last step (iterations.csv has those of every step: a long
     * path keeps its memory flat).
     */
    const std::vector<IterationRecord> &
    iterations() const
    {
      return report.iterations();
    }

    /** The pressure of the mixed formulation; null in displacements. */
    const MixedBulk<dim> *
    mixed_bulk() const
    {
      return mixed.get();
    }

    /** The contact nodes of this rank with their multipliers. */
    const ContactSet<dim> &
    contact() const
    {
      return contact_set;
    }
    ContactSet<dim> &
    contact()
    {
      return contact_set;
    }

    /** The displacement (ghosted). */
    const TrilinosWrappers::MPI::Vector &
    displacement() const
    {
      return solution;
    }

    /** The contact problem's system, after prepare_contact_solve(). */
    ContactSystem
    contact_system();

    /**
     * A first guess for the contact solve: the carried displacement or zero,
     * with the prescribed boundary values (owned entries).
     */
    TrilinosWrappers::MPI::Vector
    initial_displacement() const;

    /** Store `v` (owned entries) as the solution of this mesh. */
    void
    set_displacement(const TrilinosWrappers::MPI::Vector &v);

    ElasticSolver<dim> &
    linear_solver()
    {
      return elastic_solver;
    }

    Report<dim> &
    get_report()
    {
      return report;
    }

    /**
     * Text written as parameters.prm beside the first results (rank 0):
     * dualcontact gives the parameter file it read, overrides applied. By
     * default nothing is written: a program that changes the parameters
     * after reading them has no file that describes them.
     */
    void
    record_parameters(const std::string &parameter_file)
    {
      recorded_parameters = parameter_file;
    }

    /**
     * Make run() go on from the checkpoint in <Output/Directory>
     * (load_checkpoint()) instead of starting the path at its first time.
     */
    void
    continue_from_checkpoint()
    {
      resume = true;
    }

  private:
    /**
     * The mesh and fields of the checkpoint in `folder`, with its record:
     * the coarse mesh refined as the saved forest and set up, u, u^{n-1},
     * the multipliers and the threshold; the next step starts without the
     * predictor, with a new preconditioner. Files that deal.II cannot read,
     * or a mesh without the cells and DoFs of the record's 'mesh', are a
     * damaged checkpoint (InputError).
     */
    /**
     * The scalars of the path and of the report at the later step `step`,
     * as write_checkpoint() keeps them in state.txt.
     */
    CheckpointRecord
    checkpoint_record(const StepRecord &step, const StepControl &control) const;

    void
    load_mesh_and_fields(const std::string      &folder,
                         const CheckpointRecord &record);
    /** The size of the solution now (ContactSystem::previous). */
    SolutionSize
    solution_size() const;
    /** "At load step n (t = ...; ...): ", the head of its failure. */
    std::string
    step_failure(const unsigned int step, const double t) const;
    SolveRecord
    solve_linear_elasticity(TrilinosWrappers::MPI::Vector &v);
    /** The mixed formulation's linear solve from v; MINRES's iterations. */
    unsigned int
    solve_mixed_elasticity(TrilinosWrappers::MPI::Vector &v);
    SolveRecord
    solve_contact(TrilinosWrappers::MPI::Vector &v);
    /** Throws if no equilibrium can exist; returns, for each contact node
     * of this rank, N / |Gamma_C| of the contact that holds its body where
     * only friction holds a tangential load (see ThresholdIteration), else
     * 0 (an empty vector if at no node). */
    std::vector<double>
    check_equilibrium() const;
    /** Throws if only the contact holds the body on a plane and the loads'
     * moment needs a centre of pressure outside the contact boundary. */
    void
    check_moment(const LoadBalance &balance) const;
    /** Throws (a runtime failure) if the solution does not balance the
     * loads to the solver tolerances. */
    void
    check_balance(const ReactionRecord &reactions) const;
    double
    net_load(const Tensor<1, dim> &direction) const;
    /** The rigid motions that neither the prescribed displacements nor the
     * contact hold, into free_motions (doc/theory.md §6); each body moves
     * on its own. */
    void
    find_free_motions();
    const Vector<float> &
    refinement_indicator();
    void
    multiplier_fields(TrilinosWrappers::MPI::Vector &multipliers,
                      TrilinosWrappers::MPI::Vector &threshold) const;
    /**
     * contact<tag>_<number>.csv, and with <Output/Write vtu> the volume and
     * contact fields as solution<tag>_<number>.pvtu, contact<tag>_... with
     * the records solution<tag>.pvd, contact<tag>.pvd at `pvd_time`.
     */
    void
    write_fields(const std::string &tag,
                 unsigned int       number,
                 unsigned int       digits,
                 double             pvd_time);

    // MPI, and the screen of rank 0 (for the timer's summary; everything
    // else is printed by the report)
    MPI_Comm           mpi_communicator;
    ConditionalOStream pcout;

    // the scene (built first: bad input throws before anything else exists);
    // the problem keeps its own copy of the parameters, which the solvers
    // below refer to
    const Parameters parameters;
    Scene<dim>       scene; // at the time of the load step
    // the times of the load path
    const std::vector<double> step_times;

    // timing and everything the run tells
    mutable TimerOutput computing_timer; // const phases are timed too
    Report<dim>         report;

    // mesh and finite element, of the kind of cells the scene has
    // (discretization.h)
    const std::unique_ptr<parallel::TriangulationBase<dim>> triangulation_ptr;
    const std::unique_ptr<const Mapping<dim>>               mapping_ptr;
    const std::unique_ptr<const FiniteElement<dim>>         fe_ptr;
    parallel::TriangulationBase<dim>                       &triangulation;
    const Mapping<dim>                                     &mapping;
    const FiniteElement<dim>                               &fe;
    DoFHandler<dim>                                         dof_handler;

    // index sets and constraints: hanging nodes alone; all of them (hanging
    // nodes, then Dirichlet, then sliders); and all with zero values, for
    // Newton updates
    IndexSet                  locally_owned_dofs;
    IndexSet                  locally_relevant_dofs;
    AffineConstraints<double> hanging_node_constraints;
    AffineConstraints<double> constraints;
    AffineConstraints<double> homogeneous_constraints;

    // linear algebra
    TrilinosWrappers::SparseMatrix system_matrix; // K = A (+ chi M)
    TrilinosWrappers::MPI::Vector  system_rhs;
    LumpedMass                     mass;     // only with contact
    TrilinosWrappers::MPI::Vector  solution; // ghosted
    ElasticSolver<dim>             elastic_solver;
    // the pressure of the mixed formulation, its DoFs and its matrices
    // (mixed_bulk.h); null in displacements
    std::unique_ptr<MixedBulk<dim>> mixed;

    // contact: the nodes and multipliers, the constants r and chi, and the
    // three loops (doc/theory.md §3)
    ContactSet<dim> contact_set;
    double          r   = 0.;
    double          r_t = 0.;
    double          chi = 0.;
    // the resultant of the applied loads (tractions, body force), from the
    // assembly
    std::array<double, 3> applied_load{};
    std::vector<double>   held_by_friction_pressure;
    // the rigid motions that nothing holds (ContactSystem::free_motions),
    // and which of them keep the start's value
    // (ContactSystem::anchored_at_start)
    std::vector<TrilinosWrappers::MPI::Vector> free_motions;
    std::vector<bool>                          anchored_at_start;
    NewtonSolver<dim>                          newton;
    UzawaIteration<dim>                        uzawa;
    ThresholdIteration<dim>                    threshold_iteration;

    // nested iteration: the transfer of v, the multipliers and the
    // threshold across a refinement, and what it carried to the new mesh
    std::unique_ptr<FieldTransfer<dim>> transfer;
    bool                                carried = false;
    // ... or from the previous load step
    bool carried_from_step = false;
    // ... on the same mesh: K is the matrix of the previous step's solve
    bool same_stiffness = false;
    // the friction history: the obstacle's translation at the previous
    // step, and the energy dissipated so far
    Tensor<1, dim> previous_obstacle_displacement;
    double         dissipated = 0.;
    // the last two steps on this mesh, for the next step's start
    StepPredictor<dim> predictor;
    // the mesh the later steps are solved on, and the time the last step
    // started at
    MeshRecord path_mesh;
    double     last_step_start = 0.;
    // run() goes on from a checkpoint; the state was just written to one
    // or read from it (the next step starts without the predictor and
    // with a new preconditioner, alike in both runs)
    bool resume          = false;
    bool at_a_checkpoint = false;
    // u^{n-1} on the step's mesh, where the slip of the step is counted from,
    // and u^{n-2} (0 before the second step), for the free motion of the
    // nodes that touch during a step; empty on a mesh adapted for the step
    TrilinosWrappers::MPI::Vector step_start_u, step_before_u;
    double                        step_before_time = 0.;
    // the size of the previous step's solution (ContactSystem::previous)
    SolutionSize                  previous_size;
    TrilinosWrappers::MPI::Vector carried_v;
    TrilinosWrappers::MPI::Vector carried_multipliers;
    TrilinosWrappers::MPI::Vector carried_threshold;

    // the refinement indicator of the current solution, per active cell
    Vector<float> indicator;
    bool          indicator_valid = false;

    // the probe points, checked on the first mesh
    Probes<dim> probes;

    // the .pvd record of each output ("solution", "contact", and
    // "solution_step", "contact_step" over the load steps): its (cycle or
    // time, .pvtu file) list; and the parameter listing written with the
    // output
    std::map<std::string, std::vector<std::pair<double, std::string>>>
                pvd_records;
    std::string recorded_parameters;
  };
} // namespace dualcontact

#endif
