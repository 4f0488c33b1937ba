// The Problem class, in the shape of a deal.II tutorial: run() loops over
// refinement cycles and calls setup_system, solve, output_results and
// refine_mesh, each timed.
#ifndef dualcontact_contact_problem_h
#define dualcontact_contact_problem_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/timer.h>

#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <dualcontact/contact_set.h>
#include <dualcontact/elasticity.h>
#include <dualcontact/friction_iteration.h>
#include <dualcontact/parameters.h>
#include <dualcontact/scene.h>
#include <dualcontact/uzawa_solver.h>

#include <iostream>
#include <memory>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  /** What one refinement cycle produced: one row of the cycle table. */
  struct CycleResult
  {
    unsigned int             cycle             = 0;
    types::global_cell_index n_cells           = 0;
    types::global_dof_index  n_dofs            = 0;
    unsigned int             linear_iterations = 0;
    double                   u_l2              = 0.; // ||u||_L2
    double                   l2_error          = 0.; // vs the exact solution
    double                   h1_error          = 0.;
    double                   l2_rate           = 0.; // log2(e_{k-1}/e_k)
    double                   h1_rate           = 0.;
    // contact (zero without a contact boundary)
    types::global_dof_index n_contact_nodes   = 0;
    types::global_dof_index n_active          = 0;
    unsigned int            uzawa_steps       = 0;
    unsigned int            newton_steps      = 0;
    unsigned int            amg_setups        = 0;
    unsigned int            friction_steps    = 0; // loop 1 steps
    types::global_dof_index n_stick           = 0;
    types::global_dof_index n_slip            = 0;
    double                  tangential_force  = 0.; // |sum_s m_s l2_s|
    double                  uzawa_rate        = 0.; // observed contraction
    double                  l1_error_estimate = 0.; // relative, from the rate
    double                  contact_force     = 0.; // sum_s m_s l1_s
    double normal_load        = 0.;      // net load along -n (toward Gamma_C)
    double max_pressure       = 0.;      // max_s l1_s
    double contact_half_width = 0.;      // 2D: half the extent
                                         // of the active nodes
                                         // along t
    double contact_edge_half_width = 0.; // 2D: the same, with the edges
                                         // extrapolated (l1^2 linear)
    double pressure_error = 0.;          // relative L2 on Gamma_C
    // relative errors against Exact solution/Contact half-width and Peak
    // pressure (0 where not known)
    double                  half_width_error    = 0.;
    double                  peak_pressure_error = 0.;
    types::global_dof_index n_hanging_contact   = 0;     // hanging on Gamma_C
    bool                    warm_start          = false; // nested iteration
    // the carried multipliers on this mesh before their projection: the
    // smallest l1 and the largest |l2| - g, relative to the largest
    // multiplier and the largest g
    double carried_min_l1     = 0.;
    double carried_max_excess = 0.;
    // Refinement/Compare with cold start: the same mesh solved from zero
    unsigned int cold_uzawa_steps    = 0;
    unsigned int cold_newton_steps   = 0;
    unsigned int cold_friction_steps = 0;
    double       cold_time_solve     = 0.; // [s], not in time_solve
    double       cold_difference_v   = 0.; // |v - v_cold|_a / |v_cold|_a
    double       cold_difference_l1  = 0.; // the same for l1 (weighted)
    double       r                   = 0.; // augmentation used
    double       chi                 = 0.; // proximal weight used
    double       time_setup          = 0.; // wall times [s]
    double       time_assembly       = 0.;
    double       time_solve          = 0.;
    double       time_output         = 0.;
    double       time_refine = 0.; // marking, refinement, transfer (to here)
    double       time_total  = 0.; // all phases of all cycles up to here
    // benchmarks (Solver/Time a reference linear solve)
    double       time_reference       = 0.; // AMG + CG of one solve
    unsigned int reference_iterations = 0;
    double       memory_mb            = 0.; // peak RSS, all ranks
  };

  template <int dim>
  class ContactProblem
  {
  public:
    /**
     * Builds the scene from the parameters (throws InputError on bad
     * input). Screen output goes to `out` on rank 0 only.
     */
    ContactProblem(const Parameters &parameters,
                   MPI_Comm          mpi_communicator = MPI_COMM_WORLD,
                   std::ostream     &out              = std::cout);

    /**
     * Solve on every cycle. Everything that can be wrong with the input is
     * checked before the first output file is written.
     */
    void
    run();

    const std::vector<CycleResult> &
    results() const
    {
      return cycle_results;
    }

    /** Every Newton and Uzawa step of every cycle (empty without contact). */
    const std::vector<IterationRecord> &
    iterations() const
    {
      return iteration_log;
    }

    /** The contact nodes of this rank with their multipliers (last cycle). */
    const ContactSet<dim> &
    contact() const
    {
      return contact_set;
    }

    /** The displacement of the last cycle (ghosted). */
    const TrilinosWrappers::MPI::Vector &
    displacement() const
    {
      return solution;
    }

    const Scene<dim> &
    get_scene() const
    {
      return scene;
    }

  private:
    void
    make_grid();
    void
    setup_system();
    void
    assemble_system();
    void
    solve();
    void
    solve_linear_elasticity(TrilinosWrappers::MPI::Vector &v);
    void
    solve_contact(TrilinosWrappers::MPI::Vector &v);
    void
    measure_contact_zone(CycleResult &result) const;
    double
    check_equilibrium() const;
    double
    net_load(const Tensor<1, dim> &direction) const;
    void
    postprocess(CycleResult &result);
    void
    output_results(const unsigned int cycle);
    void
    write_cycle_table() const;
    void
    write_iteration_table() const;
    void
    refine_mesh();
    const Vector<float> &
    refinement_indicator();
    void
    mark_cells_for_refinement();
    void
    multiplier_fields(TrilinosWrappers::MPI::Vector &multipliers,
                      TrilinosWrappers::MPI::Vector &threshold) const;
    void
    interpolate_carried_fields();
    void
    print_convergence_table() const;
    void
    print_header() const;

    // MPI and screen
    MPI_Comm           mpi_communicator;
    ConditionalOStream pcout;

    // the scene (built first: bad input throws before anything else exists)
    const Parameters &parameters;
    const Scene<dim>  scene;

    // timing; the summary is printed at the end of a successful run()
    TimerOutput computing_timer;

    // mesh and finite element
    parallel::distributed::Triangulation<dim> triangulation;
    const MappingQ<dim>                       mapping;
    const FESystem<dim>                       fe;
    DoFHandler<dim>                           dof_handler;

    // index sets and constraints: hanging nodes alone; all of them (hanging
    // nodes, then Dirichlet, then sliders); and all with zero values, for
    // Newton updates
    IndexSet                  locally_owned_dofs;
    IndexSet                  locally_relevant_dofs;
    AffineConstraints<double> hanging_node_constraints;
    AffineConstraints<double> constraints;
    AffineConstraints<double> homogeneous_constraints;

    // linear algebra
    TrilinosWrappers::SparseMatrix system_matrix;
    TrilinosWrappers::MPI::Vector  system_rhs;
    TrilinosWrappers::SparseMatrix mass_matrix; // only with contact
    TrilinosWrappers::MPI::Vector  solution;    // ghosted
    ElasticSolver<dim>             elastic_solver;

    // contact: nodes and multipliers, loops 2 and 3, their log
    ContactSet<dim>              contact_set;
    UzawaSolver<dim>             uzawa_solver;
    FrictionIteration<dim>       friction_iteration;
    std::vector<IterationRecord> iteration_log;

    // nested iteration: the transfer of v, the multipliers and the
    // threshold across a refinement, and what it carried to the new mesh
    std::unique_ptr<parallel::distributed::
                      SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>>
                                  transfer;
    bool                          carried = false;
    TrilinosWrappers::MPI::Vector carried_v;
    TrilinosWrappers::MPI::Vector carried_multipliers;
    TrilinosWrappers::MPI::Vector carried_threshold;

    // the refinement indicator of the current solution, per active cell
    Vector<float> indicator;
    bool          indicator_valid = false;

    // per-cycle figures, and the (cycle, file) list of the .pvd record
    std::vector<CycleResult>                    cycle_results;
    std::vector<std::pair<double, std::string>> pvtu_records;
  };
} // namespace dualcontact

#endif
