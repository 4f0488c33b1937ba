// The Problem class, in the shape of a deal.II tutorial: run() loops over
// refinement cycles and calls setup_system, solve, output_results and
// refine_mesh, each timed.
#ifndef dualcontact_contact_problem_h
#define dualcontact_contact_problem_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/timer.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <dualcontact/elasticity.h>
#include <dualcontact/parameters.h>
#include <dualcontact/scene.h>

#include <iostream>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  /** What one refinement cycle produced: one row of the cycle table. */
  struct CycleResult
  {
    unsigned int            cycle             = 0;
    types::global_cell_index n_cells          = 0;
    types::global_dof_index n_dofs            = 0;
    unsigned int            linear_iterations = 0;
    double                  u_l2              = 0.; // ||u||_L2
    double                  l2_error          = 0.; // vs the exact solution
    double                  h1_error          = 0.;
    double                  l2_rate           = 0.; // log2(e_{k-1}/e_k)
    double                  h1_rate           = 0.;
    double                  time_setup        = 0.; // wall times [s]
    double                  time_assembly     = 0.;
    double                  time_solve        = 0.;
    double                  time_output       = 0.;
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
    postprocess(CycleResult &result);
    void
    output_results(const unsigned int cycle);
    void
    write_cycle_table() const;
    void
    refine_mesh();
    void
    print_header() const;

    // MPI, screen, timing
    MPI_Comm           mpi_communicator;
    ConditionalOStream pcout;
    TimerOutput        computing_timer;

    // the scene
    const Parameters &parameters;
    const Scene<dim>  scene;

    // mesh and finite element
    parallel::distributed::Triangulation<dim> triangulation;
    const MappingQ<dim>                       mapping;
    const FESystem<dim>                       fe;
    DoFHandler<dim>                           dof_handler;

    // index sets and constraints (hanging nodes, then Dirichlet, then sliders)
    IndexSet                  locally_owned_dofs;
    IndexSet                  locally_relevant_dofs;
    AffineConstraints<double> constraints;

    // linear algebra
    TrilinosWrappers::SparseMatrix system_matrix;
    TrilinosWrappers::MPI::Vector  system_rhs;
    TrilinosWrappers::MPI::Vector  solution; // ghosted
    ElasticSolver<dim>             elastic_solver;

    // per-cycle figures, and the (cycle, file) list of the .pvd record
    std::vector<CycleResult>                      cycle_results;
    std::vector<std::pair<double, std::string>> pvtu_records;
  };
} // namespace dualcontact

#endif
