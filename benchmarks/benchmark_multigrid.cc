// benchmark_multigrid: what one linear solve of a contact scene's Newton
// matrix costs in memory and time with the algebraic multigrid every solve
// of dualcontact uses (ML, ElasticSolver in elasticity.h), and with a
// geometric multigrid on the levels of the p4est mesh, with assembled level
// matrices or with no matrix at all. It answers one question of
// doc/performance.md: can a solve of this code fit in 1 KB per DoF, what
// does that take, and what does it cost in time?
//
//   mpirun -np 2 build/benchmarks/benchmark_multigrid scene.prm refinements
//          amg|gmg|mf [--half-width a] [--degree k]
//          [--set "Subsection/Entry=value"]...
//
// Built only with cmake -DDUALCONTACT_BUILD_BENCHMARKS=ON
// (benchmarks/CMakeLists.txt).
//
// The matrix is the one the contact solver's last Newton steps solve with
// (and its "reference linear solve" times):
//
//   H = K + chi M + C,
//
// K the stiffness of linear elasticity (assembled by the library's
// assemble_elasticity, as in the program), M the lumped mass, chi the
// proximal weight, and C the normal contact terms r m_s n n^T of the nodes
// on Gamma_C within the half-width a (default 0.1, Hertz's a of prm/hertz.prm
// and prm/hertz_3d.prm) of the foundation's point, r = r_rel (lambda + 2
// mu) / h_C as the program sets it. The right-hand side is the scene's load.
// The mesh is the scene's initial mesh refined globally `refinements` times
// (the meshes of the benchmark pages: prm/hertz.prm with 3 and 4 gives
// 303362 and 1207298 DoFs).
//
// amg: CG with the program's ML hierarchy (the same settings and rigid-body
//   modes), to the relative residual <Solver/Linear solver tolerance>.
// gmg: CG with a V-cycle on the mesh levels (local smoothing: each level
//   holds its own cells, the refinement edges are coupled by interface
//   matrices), level matrices K_l + chi M_l + C_l assembled on the level
//   cells, the contact terms rediscretised on each level (the same r, the
//   level's weights m_s, the same zone), Chebyshev smoothing of the given
//   degree (default 3) with the inverse diagonal, prolongation by the
//   interpolation of the nested spaces, and CG with ML on the coarsest
//   level (1e-12).
// mf: the same multigrid and outer CG with no matrix stored: K applied by
//   quadrature on the cells (FEEvaluation, MatrixFreeOperators::Base, the
//   hanging nodes resolved by MatrixFree), chi M as a diagonal and C as a
//   list of entries (condensed onto the masters of hanging nodes, as the
//   program condenses them), on the active mesh and on each level; the
//   load and the lumped mass by assemble_load() below (the library's
//   CellLoads: the load and mass integrals of assemble_elasticity(),
//   without K);
//   LinearAlgebra::distributed::Vector throughout, and CG without a
//   preconditioner on the coarsest level.
// --set overrides an entry of the scene, as for the program (e.g. --set
// "Material/Poisson's ratio=0.49").
//
// Printed: the DoFs and levels, the peak resident memory summed over the
// ranks after assembly, after the preconditioner's set-up and after the
// solve (and per DoF above the processes' memory at the start), the times,
// the CG iterations, |x|, and how many doubles FEEvaluation works on at once
// (the SIMD width deal.II was built with: 1 for Debian's package; what that
// means for the matrix-free times is in doc/performance.md); the last line,
// "RESULT key value ...", is what benchmarks/benchmark_multigrid.sh reads.
// The program checks nothing itself: the test
// benchmark_multigrid_same_solution (tests/CMakeLists.txt) compares the
// three.

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/diagonal_matrix.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <deal.II/matrix_free/fe_evaluation.h>
#include <deal.II/matrix_free/matrix_free.h>
#include <deal.II/matrix_free/operators.h>
#include <deal.II/matrix_free/tools.h>
#include <deal.II/multigrid/mg_coarse.h>
#include <deal.II/multigrid/mg_constrained_dofs.h>
#include <deal.II/multigrid/mg_matrix.h>
#include <deal.II/multigrid/mg_smoother.h>
#include <deal.II/multigrid/mg_tools.h>
#include <deal.II/multigrid/mg_transfer.h>
#include <deal.II/multigrid/mg_transfer_matrix_free.h>
#include <deal.II/multigrid/multigrid.h>

#include <dualcontact/cell_loads.h>
#include <dualcontact/elasticity.h>
#include <dualcontact/input_error.h>
#include <dualcontact/lumped_mass.h>
#include <dualcontact/parameters.h>
#include <dualcontact/scene.h>

#include <iostream>
#include <memory>
#include <string>
#include <vector>

using namespace dealii;

namespace
{
  using Vector = TrilinosWrappers::MPI::Vector;
  using Matrix = TrilinosWrappers::SparseMatrix;

  /** Peak and current resident memory [MB], summed over the ranks. */
  std::pair<double, double>
  memory_mb()
  {
    Utilities::System::MemoryStats stats;
    Utilities::System::get_memory_stats(stats);
    return {Utilities::MPI::sum(stats.VmHWM / 1024., MPI_COMM_WORLD),
            Utilities::MPI::sum(stats.VmRSS / 1024., MPI_COMM_WORLD)};
  }

  using DistributedVector = LinearAlgebra::distributed::Vector<double>;

  /**
   * The load b = int f.v + int_{Gamma_N} T.v (only the loads the scene has)
   * and the lumped mass (the row sums of int u.v), each cell's by the
   * library's CellLoads, the terms assemble_elasticity() assembles besides
   * K: the right-hand side and M of the matrix-free solve. The constraints
   * are homogeneous (hanging nodes), so there is no lifting of prescribed
   * values to assemble. The vectors have the locally owned DoFs and ghosts
   * for every DoF the constraints write to.
   */
  template <int dim>
  void
  assemble_load(const Mapping<dim>              &mapping,
                const DoFHandler<dim>           &dof_handler,
                const dualcontact::Scene<dim>   &scene,
                const AffineConstraints<double> &constraints,
                DistributedVector               &load,
                DistributedVector               &mass)
  {
    Assert(!constraints.has_inhomogeneities(),
           ExcMessage("assemble_load() assembles no lifting"));
    dualcontact::CellLoads<dim>          cell_loads(mapping,
                                           dof_handler.get_fe(),
                                           scene);
    std::vector<types::global_dof_index> indices(
      dof_handler.get_fe().n_dofs_per_cell());
    load = 0.;
    mass = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell_loads.reinit(cell, true);
          cell->get_dof_indices(indices);
          constraints.distribute_local_to_global(cell_loads.rhs, indices, load);
          constraints.distribute_local_to_global(cell_loads.mass,
                                                 indices,
                                                 mass);
        }
    load.compress(VectorOperation::add);
    mass.compress(VectorOperation::add);
  }

  /** An entry (row, column, value) of a matrix, in global DoF indices. */
  struct Entry
  {
    types::global_dof_index row, column;
    double                  value;
  };

  /**
   * H = K + D + C without a stored matrix: K (linear elasticity, Q1) by
   * cell quadrature (FEEvaluation), D a diagonal (the lumped chi M), C the
   * contact terms as a list of entries. One per level and one on the active
   * mesh (where hanging nodes are resolved by the MatrixFree object and C
   * holds the entries condensed onto the masters).
   */
  template <int dim>
  class MatrixFreeElasticity
      : public MatrixFreeOperators::Base<dim, DistributedVector>
  {
  public:
    void
    set_terms(const double              lambda_,
              const double              mu_,
              const DistributedVector  &diagonal_,
              const std::vector<Entry> &contact_)
    {
      lambda   = lambda_;
      mu       = mu_;
      diagonal = diagonal_;
      contact  = contact_;
      this->initialize_dof_vector(contact_product);
    }

    void
    compute_diagonal() override
    {
      this->inverse_diagonal_entries =
        std::make_shared<DiagonalMatrix<DistributedVector>>();
      DistributedVector &d = this->inverse_diagonal_entries->get_vector();
      this->initialize_dof_vector(d);
      MatrixFreeTools::compute_diagonal(*this->data,
                                        d,
                                        &MatrixFreeElasticity::cell_operation,
                                        this);
      add_entries(d, nullptr);
      for (unsigned int i = 0; i < d.locally_owned_size(); ++i)
        {
          const double value = d.local_element(i) + diagonal.local_element(i);
          d.local_element(i) = value > 0. ? 1. / value : 1.;
        }
    }

  private:
    void
    apply_add(DistributedVector       &dst,
              const DistributedVector &src) const override
    {
      this->data->cell_loop(&MatrixFreeElasticity::local_apply, this, dst, src);
      for (unsigned int i = 0; i < dst.locally_owned_size(); ++i)
        dst.local_element(i) +=
          diagonal.local_element(i) * src.local_element(i);
      add_entries(dst, &src);
    }

    // dst += C src (with src) or the diagonal of C (without); collective.
    // src is left with its ghost values as it came.
    void
    add_entries(DistributedVector &dst, const DistributedVector *src) const
    {
      const bool had_ghosts = src != nullptr && src->has_ghost_elements();
      if (src != nullptr && !had_ghosts)
        src->update_ghost_values();
      contact_product = 0.;
      for (const Entry &entry : contact)
        if (src != nullptr)
          contact_product(entry.row) += entry.value * (*src)(entry.column);
        else if (entry.row == entry.column)
          contact_product(entry.row) += entry.value;
      contact_product.compress(VectorOperation::add);
      if (src != nullptr && !had_ghosts)
        src->zero_out_ghost_values();
      dst.add(1., contact_product);
    }

    void
    cell_operation(FEEvaluation<dim, 1, 2, dim, double> &phi) const
    {
      phi.evaluate(EvaluationFlags::gradients);
      for (const unsigned int q : phi.quadrature_point_indices())
        {
          auto       sigma = phi.get_symmetric_gradient(q);
          const auto div   = trace(sigma);
          sigma *= 2. * mu;
          for (unsigned int d = 0; d < dim; ++d)
            sigma[d][d] += lambda * div;
          phi.submit_symmetric_gradient(sigma, q);
        }
      phi.integrate(EvaluationFlags::gradients);
    }

    void
    local_apply(const MatrixFree<dim, double>               &data,
                DistributedVector                           &dst,
                const DistributedVector                     &src,
                const std::pair<unsigned int, unsigned int> &cells) const
    {
      FEEvaluation<dim, 1, 2, dim, double> phi(data);
      for (unsigned int cell = cells.first; cell < cells.second; ++cell)
        {
          phi.reinit(cell);
          phi.read_dof_values(src);
          cell_operation(phi);
          phi.distribute_local_to_global(dst);
        }
    }

    double                    lambda = 0., mu = 0.;
    DistributedVector         diagonal;
    std::vector<Entry>        contact;
    mutable DistributedVector contact_product;
  };

  /** The preconditioner (and, for mf, the operator) of a run. */
  enum class Kind
  {
    amg, // the program's ML hierarchy on the assembled matrix
    gmg, // geometric multigrid with assembled level matrices
    mf   // geometric multigrid, no matrix stored anywhere
  };

  template <int dim>
  class MultigridBenchmark
  {
  public:
    MultigridBenchmark(const dualcontact::Parameters &parameters,
                       unsigned int                   refinements,
                       Kind                           kind,
                       double                         half_width,
                       unsigned int                   chebyshev_degree);

    void
    run();

  private:
    void
    make_mesh_and_dofs();
    void
    assemble_system();
    void
    setup_algebraic();
    void
    setup_geometric();
    void
    assemble_matrix_free();
    void
    setup_matrix_free();
    /** Solve H x = b; return the CG iterations and |x|. */
    std::pair<unsigned int, double>
    solve();

    void
    make_constraints_and_coefficients();

    /** The entries of a cell's C, condensed by `condense` (if given). */
    template <typename CellIterator>
    void
    add_contact_entries(const CellIterator                         &cell,
                        const std::vector<types::global_dof_index> &indices,
                        const AffineConstraints<double>            *condense,
                        std::vector<Entry>                         &entries);

    /** K + chi M of one cell (level or active). */
    template <typename CellIterator>
    void
    cell_matrix(const CellIterator &cell, FullMatrix<double> &local);

    /**
     * chi times the lumped mass of shape function i (the row sum of int
     * u.v) on the cell fe_values was last reinit'ed on.
     */
    double
    lumped_mass(unsigned int i) const;

    /** The MatrixFree data of the active mesh, or of a level. */
    std::shared_ptr<const MatrixFree<dim, double>>
    make_matrix_free(const AffineConstraints<double> &constraints,
                     unsigned int level = numbers::invalid_unsigned_int) const;

    /** C on the cell's faces on Gamma_C (zero elsewhere). */
    template <typename CellIterator>
    void
    contact_matrix(const CellIterator &cell, FullMatrix<double> &local);

    void
    print_memory(const std::string &after);

    const dualcontact::Parameters &parameters;
    const dualcontact::Scene<dim>  scene;
    const unsigned int             refinements;
    const Kind                     kind;
    const double                   half_width;
    const unsigned int             chebyshev_degree;
    const double                   lambda, mu;
    Tensor<1, dim>                 normal; // of the foundation
    Point<dim>                     first_contact;
    std::set<types::boundary_id>   contact_ids;
    double                         r = 0., chi = 0.;

    parallel::distributed::Triangulation<dim> triangulation;
    const MappingQ<dim>                       mapping;
    const FESystem<dim>                       fe;
    DoFHandler<dim>                           dof_handler;
    AffineConstraints<double>                 constraints;
    Matrix                                    matrix;
    Vector                                    rhs;

    // the cell and face integrals
    FEValues<dim>      fe_values;
    FEFaceValues<dim>  fe_face_values;
    FullMatrix<double> contact_local;

    // algebraic multigrid: the program's own solver
    std::unique_ptr<dualcontact::ElasticSolver<dim>> algebraic;

    // geometric multigrid
    using Smoother =
      PreconditionChebyshev<Matrix,
                            Vector,
                            TrilinosWrappers::PreconditionJacobi>;
    MGConstrainedDoFs     mg_constrained_dofs;
    MGLevelObject<Matrix> level_matrices, interface_matrices;
    std::unique_ptr<MGTransferPrebuilt<Vector>>      transfer;
    ReductionControl                                 coarse_control;
    SolverCG<Vector>                                 coarse_cg;
    TrilinosWrappers::PreconditionAMG                coarse_amg;
    std::unique_ptr<MGCoarseGridBase<Vector>>        coarse;
    MGSmootherPrecondition<Matrix, Smoother, Vector> smoother;
    mg::Matrix<Vector>                               mg_matrix, mg_interface;
    std::unique_ptr<Multigrid<Vector>>               multigrid;
    std::unique_ptr<PreconditionMG<dim, Vector, MGTransferPrebuilt<Vector>>>
      preconditioner;

    // matrix-free geometric multigrid
    using MatrixFreeSmoother =
      PreconditionChebyshev<MatrixFreeElasticity<dim>, DistributedVector>;
    MatrixFreeElasticity<dim>                          mf_operator;
    DistributedVector                                  mf_rhs;
    MGLevelObject<MatrixFreeElasticity<dim>>           mf_levels;
    std::unique_ptr<MGTransferMatrixFree<dim, double>> mf_transfer;
    MGSmootherPrecondition<MatrixFreeElasticity<dim>,
                           MatrixFreeSmoother,
                           DistributedVector>
                                                         mf_smoother;
    SolverCG<DistributedVector>                          mf_coarse_cg;
    PreconditionIdentity                                 mf_identity;
    std::unique_ptr<MGCoarseGridBase<DistributedVector>> mf_coarse;
    MGLevelObject<
      MatrixFreeOperators::MGInterfaceOperator<MatrixFreeElasticity<dim>>>
                                                  mf_interface;
    mg::Matrix<DistributedVector>                 mf_mg_matrix, mf_mg_interface;
    std::unique_ptr<Multigrid<DistributedVector>> mf_multigrid;
    std::unique_ptr<
      PreconditionMG<dim, DistributedVector, MGTransferMatrixFree<dim, double>>>
      mf_preconditioner;

    ConditionalOStream pcout;
    double             memory_at_start = 0.;
    double             time_assembly = 0., time_setup = 0., time_cg = 0.;
  };

  template <int dim>
  MultigridBenchmark<dim>::MultigridBenchmark(
    const dualcontact::Parameters &parameters,
    const unsigned int             refinements,
    const Kind                     kind,
    const double                   half_width,
    const unsigned int             chebyshev_degree)
      : parameters(parameters)
      , scene(parameters)
      , refinements(refinements)
      , kind(kind)
      , half_width(half_width)
      , chebyshev_degree(chebyshev_degree)
      , lambda(parameters.material.lambda())
      , mu(parameters.material.mu())
      , contact_ids(scene.ids_with(dualcontact::BoundaryCondition::contact))
      // the program's mesh smoothing; the levels for the geometric multigrid
      , triangulation(
          MPI_COMM_WORLD,
          typename Triangulation<dim>::MeshSmoothing(
            Triangulation<dim>::smoothing_on_refinement |
            Triangulation<dim>::smoothing_on_coarsening),
          kind != Kind::amg ?
            parallel::distributed::Triangulation<
              dim>::construct_multigrid_hierarchy :
            parallel::distributed::Triangulation<dim>::default_setting)
      , mapping(1)
      , fe(FE_Q<dim>(1), dim)
      , dof_handler(triangulation)
      , fe_values(mapping,
                  fe,
                  QGauss<dim>(2),
                  update_values | update_gradients | update_JxW_values)
      , fe_face_values(mapping,
                       fe,
                       QGauss<dim - 1>(2),
                       update_values | update_JxW_values)
      , contact_local(fe.n_dofs_per_cell(), fe.n_dofs_per_cell())
      , coarse_control(2000, 1e-300, 1e-12, false, false)
      , coarse_cg(coarse_control)
      , mf_coarse_cg(coarse_control)
      , pcout(std::cout, Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
  {
    if (contact_ids.empty())
      throw dualcontact::InputError("the scene has no contact boundary.",
                                    dualcontact::exit_invalid_value);
    if (parameters.obstacle.type != "plane")
      throw dualcontact::InputError(
        "the obstacle must be the plane foundation, not '" +
          parameters.obstacle.type + "'.",
        dualcontact::exit_invalid_value);
    const auto n =
      dualcontact::numbers_of(parameters.obstacle.values, "Foundation/Normal");
    const auto p =
      dualcontact::numbers_of(parameters.obstacle.values, "Foundation/Point");
    for (unsigned int d = 0; d < dim; ++d)
      {
        normal[d]        = n[d];
        first_contact[d] = p[d];
      }
    normal /= normal.norm();
  }

  template <int dim>
  void
  MultigridBenchmark<dim>::print_memory(const std::string &after)
  {
    const auto [peak, now] = memory_mb();
    pcout << "  after " << after << ": peak memory " << peak << " MB (now "
          << now << " MB), "
          << 1024. * (peak - memory_at_start) / dof_handler.n_dofs()
          << " KB per DoF above the start" << std::endl;
  }

  template <int dim>
  void
  MultigridBenchmark<dim>::make_mesh_and_dofs()
  {
    scene.create_mesh(triangulation);
    triangulation.refine_global(refinements);
    dof_handler.distribute_dofs(fe);
    if (kind != Kind::amg)
      dof_handler.distribute_mg_dofs();
    pcout << (kind == Kind::amg ? "algebraic multigrid" :
              kind == Kind::gmg ? "geometric multigrid" :
                                  "matrix-free geometric multigrid")
          << ": " << triangulation.n_global_active_cells() << " cells, "
          << dof_handler.n_dofs() << " DoFs, "
          << triangulation.n_global_levels() << " levels" << std::endl;
  }

  template <int dim>
  template <typename CellIterator>
  void
  MultigridBenchmark<dim>::cell_matrix(const CellIterator &cell,
                                       FullMatrix<double> &local)
  {
    const FEValuesExtractors::Vector displacement(0);
    fe_values.reinit(cell);
    local = 0;
    for (const unsigned int q : fe_values.quadrature_point_indices())
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        {
          const SymmetricTensor<2, dim> eps_i =
            fe_values[displacement].symmetric_gradient(i, q);
          for (unsigned int j = 0; j < fe.n_dofs_per_cell(); ++j)
            {
              const SymmetricTensor<2, dim> eps_j =
                fe_values[displacement].symmetric_gradient(j, q);
              local(i, j) += (lambda * trace(eps_i) * trace(eps_j) +
                              2. * mu * (eps_i * eps_j)) *
                             fe_values.JxW(q);
            }
        }
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      local(i, i) += lumped_mass(i);
  }

  template <int dim>
  double
  MultigridBenchmark<dim>::lumped_mass(const unsigned int i) const
  {
    double m = 0.;
    for (const unsigned int q : fe_values.quadrature_point_indices())
      m += fe_values.shape_value(i, q) * fe_values.JxW(q);
    return chi * m;
  }

  template <int dim>
  std::shared_ptr<const MatrixFree<dim, double>>
  MultigridBenchmark<dim>::make_matrix_free(
    const AffineConstraints<double> &constraints,
    const unsigned int               level) const
  {
    typename MatrixFree<dim, double>::AdditionalData data;
    data.tasks_parallel_scheme = MatrixFree<dim, double>::AdditionalData::none;
    data.mapping_update_flags  = update_gradients | update_JxW_values;
    data.mg_level              = level;
    auto matrix_free           = std::make_shared<MatrixFree<dim, double>>();
    matrix_free->reinit(mapping, dof_handler, constraints, QGauss<1>(2), data);
    return matrix_free;
  }

  template <int dim>
  template <typename CellIterator>
  void
  MultigridBenchmark<dim>::contact_matrix(const CellIterator &cell,
                                          FullMatrix<double> &local)
  {
    local = 0;
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary() &&
          contact_ids.count(cell->face(f)->boundary_id()))
        {
          fe_face_values.reinit(cell, f);
          for (unsigned int k = 0; k < cell->face(f)->n_vertices(); ++k)
            {
              const unsigned int v = GeometryInfo<dim>::face_to_cell_vertices(
                f,
                k,
                cell->face_orientation(f),
                cell->face_flip(f),
                cell->face_rotation(f));
              // in the zone: the distance from the point of first contact
              // along the foundation
              Tensor<1, dim> along = cell->vertex(v) - first_contact;
              along -= (along * normal) * normal;
              if (along.norm() >= half_width)
                continue;
              // r m_s n n^T, m_s = int phi_s over the face (lumped)
              const unsigned int first = fe.component_to_system_index(0, v);
              double             m     = 0.;
              for (const unsigned int q :
                   fe_face_values.quadrature_point_indices())
                m += fe_face_values.shape_value_component(first, q, 0) *
                     fe_face_values.JxW(q);
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int b = 0; b < dim; ++b)
                  local(fe.component_to_system_index(a, v),
                        fe.component_to_system_index(b, v)) +=
                    r * m * normal[a] * normal[b];
            }
        }
  }

  template <int dim>
  void
  MultigridBenchmark<dim>::make_constraints_and_coefficients()
  {
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    constraints.reinit(relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    constraints.close();

    // r and chi as the program sets them (contact_problem.cc)
    double h_C = std::numeric_limits<double>::max();
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && contact_ids.count(face->boundary_id()))
            h_C = std::min(h_C, face->diameter());
    h_C = Utilities::MPI::min(h_C, MPI_COMM_WORLD);
    r   = parameters.solver.augmentation * (lambda + 2. * mu) / h_C;
    chi = parameters.solver.proximal * parameters.material.youngs_modulus /
          std::pow(scene.characteristic_length(), 2);
  }

  template <int dim>
  template <typename CellIterator>
  void
  MultigridBenchmark<dim>::add_contact_entries(
    const CellIterator                         &cell,
    const std::vector<types::global_dof_index> &indices,
    const AffineConstraints<double>            *condense,
    std::vector<Entry>                         &entries)
  {
    contact_matrix(cell, contact_local);
    // a DoF as the condensed space sees it: itself, or the masters of a
    // hanging node with their weights
    const auto expand = [condense](const types::global_dof_index i) {
      std::vector<std::pair<types::global_dof_index, double>> terms;
      if (condense == nullptr || !condense->is_constrained(i))
        terms.emplace_back(i, 1.);
      else if (const auto *masters = condense->get_constraint_entries(i))
        terms = *masters;
      return terms;
    };
    for (unsigned int i = 0; i < indices.size(); ++i)
      for (unsigned int j = 0; j < indices.size(); ++j)
        if (contact_local(i, j) != 0.)
          for (const auto &[row, row_weight] : expand(indices[i]))
            for (const auto &[column, column_weight] : expand(indices[j]))
              entries.push_back(
                {row,
                 column,
                 row_weight * column_weight * contact_local(i, j)});
  }

  template <int dim>
  void
  MultigridBenchmark<dim>::assemble_system()
  {
    make_constraints_and_coefficients();
    const IndexSet &owned = dof_handler.locally_owned_dofs();
    {
      IndexSet relevant;
      DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
      DynamicSparsityPattern dsp(relevant);
      DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
      SparsityTools::distribute_sparsity_pattern(dsp,
                                                 owned,
                                                 MPI_COMM_WORLD,
                                                 relevant);
      matrix.reinit(owned, owned, dsp, MPI_COMM_WORLD);
    }
    rhs.reinit(owned, MPI_COMM_WORLD);

    // K, M and the load as the program assembles them, then chi M and C
    dualcontact::LumpedMass mass;
    mass.diagonal.reinit(owned, MPI_COMM_WORLD);
    dualcontact::assemble_elasticity<dim>(
      mapping, dof_handler, scene, constraints, matrix, rhs, &mass, nullptr);
    mass.add_to(matrix, chi);
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary())
        {
          contact_matrix(cell, contact_local);
          if (contact_local.frobenius_norm() == 0.)
            continue;
          cell->get_dof_indices(indices);
          constraints.distribute_local_to_global(contact_local,
                                                 indices,
                                                 matrix);
        }
    matrix.compress(VectorOperation::add);
  }

  template <int dim>
  void
  MultigridBenchmark<dim>::setup_algebraic()
  {
    algebraic = std::make_unique<dualcontact::ElasticSolver<dim>>(
      parameters.solver, parameters.material.poissons_ratio);
    algebraic->set_near_null_space(mapping,
                                   dof_handler,
                                   matrix,
                                   scene.center(),
                                   scene.characteristic_length());
    algebraic->initialize(matrix);
  }

  template <int dim>
  void
  MultigridBenchmark<dim>::setup_geometric()
  {
    const unsigned int n_levels = triangulation.n_global_levels();
    mg_constrained_dofs.initialize(dof_handler);
    level_matrices.resize(0, n_levels - 1);
    interface_matrices.resize(0, n_levels - 1);

    // The DoFs on a refinement edge (where a level's cells end at coarser
    // active cells) are zero on the level: they are coupled to the rest by
    // the interface matrices.
    std::vector<AffineConstraints<double>> edge_constraints(n_levels);
    for (unsigned int level = 0; level < n_levels; ++level)
      {
        IndexSet relevant;
        DoFTools::extract_locally_relevant_level_dofs(dof_handler,
                                                      level,
                                                      relevant);
        edge_constraints[level].reinit(relevant);
        edge_constraints[level].add_lines(
          mg_constrained_dofs.get_refinement_edge_indices(level));
        edge_constraints[level].close();

        const IndexSet        &owned = dof_handler.locally_owned_mg_dofs(level);
        DynamicSparsityPattern dsp(relevant);
        MGTools::make_sparsity_pattern(dof_handler, dsp, level);
        SparsityTools::distribute_sparsity_pattern(dsp,
                                                   owned,
                                                   MPI_COMM_WORLD,
                                                   relevant);
        level_matrices[level].reinit(owned, owned, dsp, MPI_COMM_WORLD);

        DynamicSparsityPattern interface_dsp(relevant);
        MGTools::make_interface_sparsity_pattern(dof_handler,
                                                 mg_constrained_dofs,
                                                 interface_dsp,
                                                 level);
        SparsityTools::distribute_sparsity_pattern(interface_dsp,
                                                   owned,
                                                   MPI_COMM_WORLD,
                                                   relevant);
        interface_matrices[level].reinit(owned,
                                         owned,
                                         interface_dsp,
                                         MPI_COMM_WORLD);
      }

    FullMatrix<double> local(fe.n_dofs_per_cell(), fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.mg_cell_iterators())
      if (cell->level_subdomain_id() == triangulation.locally_owned_subdomain())
        {
          cell_matrix(cell, local);
          if (cell->at_boundary())
            {
              contact_matrix(cell, contact_local);
              local.add(1., contact_local);
            }
          cell->get_mg_dof_indices(indices);
          const unsigned int level = cell->level();
          edge_constraints[level].distribute_local_to_global(
            local, indices, level_matrices[level]);
          for (unsigned int i = 0; i < indices.size(); ++i)
            for (unsigned int j = 0; j < indices.size(); ++j)
              if (mg_constrained_dofs.is_interface_matrix_entry(level,
                                                                indices[i],
                                                                indices[j]))
                interface_matrices[level].add(indices[i],
                                              indices[j],
                                              local(i, j));
        }
    for (unsigned int level = 0; level < n_levels; ++level)
      {
        level_matrices[level].compress(VectorOperation::add);
        interface_matrices[level].compress(VectorOperation::add);
      }

    transfer =
      std::make_unique<MGTransferPrebuilt<Vector>>(mg_constrained_dofs);
    transfer->build(dof_handler);

    coarse_amg.initialize(level_matrices[0]);
    coarse = std::make_unique<
      MGCoarseGridIterativeSolver<Vector,
                                  SolverCG<Vector>,
                                  Matrix,
                                  TrilinosWrappers::PreconditionAMG>>(
      coarse_cg, level_matrices[0], coarse_amg);

    // Chebyshev with the inverse diagonal of each level, its largest
    // eigenvalue estimated by a few CG steps
    MGLevelObject<typename Smoother::AdditionalData> data(0, n_levels - 1);
    for (unsigned int level = 0; level < n_levels; ++level)
      {
        auto jacobi = std::make_shared<TrilinosWrappers::PreconditionJacobi>();
        jacobi->initialize(level_matrices[level]);
        data[level].preconditioner      = jacobi;
        data[level].degree              = chebyshev_degree;
        data[level].smoothing_range     = 20.;
        data[level].eig_cg_n_iterations = 12;
      }
    smoother.initialize(level_matrices, data);

    mg_matrix.initialize(level_matrices);
    mg_interface.initialize(interface_matrices);
    multigrid = std::make_unique<Multigrid<Vector>>(
      mg_matrix, *coarse, *transfer, smoother, smoother);
    multigrid->set_edge_matrices(mg_interface, mg_interface);
    preconditioner =
      std::make_unique<PreconditionMG<dim, Vector, MGTransferPrebuilt<Vector>>>(
        dof_handler, *multigrid, *transfer);
  }

  template <int dim>
  void
  MultigridBenchmark<dim>::assemble_matrix_free()
  {
    make_constraints_and_coefficients();
    mf_operator.initialize(make_matrix_free(constraints));

    // the load and the lumped M as the program assembles them (without K),
    // and C condensed as the program condenses it
    DistributedVector mass;
    mf_operator.initialize_dof_vector(mass);
    mf_operator.initialize_dof_vector(mf_rhs);
    assemble_load<dim>(mapping, dof_handler, scene, constraints, mf_rhs, mass);
    mass *= chi;
    std::vector<Entry>                   entries;
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary())
        {
          cell->get_dof_indices(indices);
          add_contact_entries(cell, indices, &constraints, entries);
        }
    mf_operator.set_terms(lambda, mu, mass, entries);
  }

  template <int dim>
  void
  MultigridBenchmark<dim>::setup_matrix_free()
  {
    const unsigned int n_levels = triangulation.n_global_levels();
    mg_constrained_dofs.initialize(dof_handler);
    mf_levels.resize(0, n_levels - 1);
    for (unsigned int level = 0; level < n_levels; ++level)
      {
        IndexSet relevant;
        DoFTools::extract_locally_relevant_level_dofs(dof_handler,
                                                      level,
                                                      relevant);
        AffineConstraints<double> level_constraints;
        level_constraints.reinit(relevant);
        level_constraints.close();
        mf_levels[level].initialize(make_matrix_free(level_constraints, level),
                                    mg_constrained_dofs,
                                    level);
      }

    // each level's lumped chi M and C, on the level cells
    std::vector<DistributedVector>  mass(n_levels);
    std::vector<std::vector<Entry>> entries(n_levels);
    for (unsigned int level = 0; level < n_levels; ++level)
      mf_levels[level].initialize_dof_vector(mass[level]);
    const unsigned int                   n = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> indices(n);
    for (const auto &cell : dof_handler.mg_cell_iterators())
      if (cell->level_subdomain_id() == triangulation.locally_owned_subdomain())
        {
          const unsigned int level = cell->level();
          cell->get_mg_dof_indices(indices);
          fe_values.reinit(cell);
          for (unsigned int i = 0; i < n; ++i)
            mass[level](indices[i]) += lumped_mass(i);
          if (cell->at_boundary())
            add_contact_entries(cell, indices, nullptr, entries[level]);
        }
    for (unsigned int level = 0; level < n_levels; ++level)
      {
        mass[level].compress(VectorOperation::add);
        mf_levels[level].set_terms(lambda, mu, mass[level], entries[level]);
        mf_levels[level].compute_diagonal();
      }

    mf_transfer =
      std::make_unique<MGTransferMatrixFree<dim, double>>(mg_constrained_dofs);
    mf_transfer->build(dof_handler);

    MGLevelObject<typename MatrixFreeSmoother::AdditionalData> data(0,
                                                                    n_levels -
                                                                      1);
    for (unsigned int level = 0; level < n_levels; ++level)
      {
        data[level].preconditioner =
          mf_levels[level].get_matrix_diagonal_inverse();
        data[level].degree              = chebyshev_degree;
        data[level].smoothing_range     = 20.;
        data[level].eig_cg_n_iterations = 12;
      }
    mf_smoother.initialize(mf_levels, data);
    mf_coarse =
      std::make_unique<MGCoarseGridIterativeSolver<DistributedVector,
                                                   SolverCG<DistributedVector>,
                                                   MatrixFreeElasticity<dim>,
                                                   PreconditionIdentity>>(
        mf_coarse_cg, mf_levels[0], mf_identity);
    mf_mg_matrix.initialize(mf_levels);
    mf_interface.resize(0, n_levels - 1);
    for (unsigned int level = 0; level < n_levels; ++level)
      mf_interface[level].initialize(mf_levels[level]);
    mf_mg_interface.initialize(mf_interface);
    mf_multigrid = std::make_unique<Multigrid<DistributedVector>>(
      mf_mg_matrix, *mf_coarse, *mf_transfer, mf_smoother, mf_smoother);
    mf_multigrid->set_edge_matrices(mf_mg_interface, mf_mg_interface);
    mf_preconditioner =
      std::make_unique<PreconditionMG<dim,
                                      DistributedVector,
                                      MGTransferMatrixFree<dim, double>>>(
        dof_handler, *mf_multigrid, *mf_transfer);
  }

  template <int dim>
  std::pair<unsigned int, double>
  MultigridBenchmark<dim>::solve()
  {
    if (kind == Kind::mf)
      {
        DistributedVector x;
        mf_operator.initialize_dof_vector(x);
        SolverControl control(parameters.solver.max_linear_iterations,
                              parameters.solver.linear_tolerance *
                                mf_rhs.l2_norm());
        SolverCG<DistributedVector> cg(control);
        cg.solve(mf_operator, x, mf_rhs, *mf_preconditioner);
        constraints.distribute(x);
        return {control.last_step(), x.l2_norm()};
      }
    Vector x(rhs);
    x                       = 0.;
    unsigned int iterations = 0;
    if (kind == Kind::amg)
      iterations = algebraic->solve(matrix, x, rhs);
    else
      {
        SolverControl    control(parameters.solver.max_linear_iterations,
                              parameters.solver.linear_tolerance *
                                rhs.l2_norm());
        SolverCG<Vector> cg(control);
        cg.solve(matrix, x, rhs, *preconditioner);
        iterations = control.last_step();
      }
    constraints.distribute(x);
    return {iterations, x.l2_norm()};
  }

  template <int dim>
  void
  MultigridBenchmark<dim>::run()
  {
    memory_at_start = memory_mb().second;
    make_mesh_and_dofs();

    Timer timer(MPI_COMM_WORLD, true);
    if (kind == Kind::mf)
      assemble_matrix_free();
    else
      assemble_system();
    time_assembly = timer.wall_time();
    print_memory("assembly");

    timer.restart();
    if (kind == Kind::amg)
      setup_algebraic();
    else if (kind == Kind::gmg)
      setup_geometric();
    else
      setup_matrix_free();
    time_setup = timer.wall_time();
    print_memory("the set-up");

    timer.restart();
    const auto [iterations, x_norm] = solve();
    time_cg                         = timer.wall_time();
    print_memory("the solve");

    const double peak = memory_mb().first;
    pcout << "  assembly " << time_assembly << " s, set-up " << time_setup
          << " s, CG " << iterations << " iterations " << time_cg
          << " s, |x| = " << x_norm << std::endl;
    pcout << std::setprecision(10) << "RESULT preconditioner "
          << (kind == Kind::amg ? "amg" :
              kind == Kind::gmg ? "gmg" :
                                  "mf")
          << " dim " << dim << " dofs " << dof_handler.n_dofs() << " levels "
          << triangulation.n_global_levels() << " cg " << iterations
          << " time_assembly " << time_assembly << " time_setup " << time_setup
          << " time_cg " << time_cg << " peak_mb " << peak << " start_mb "
          << memory_at_start << " x_norm " << x_norm << " simd_doubles "
          << VectorizedArray<double>::size() << std::endl;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  const std::string usage =
    "Usage: benchmark_multigrid scene.prm refinements amg|gmg|mf [--half-width "
    "a] [--degree k] [--set \"Subsection/Entry=value\" ...]\n(see the head "
    "of benchmarks/benchmark_multigrid.cc)\n";
  try
    {
      if (argc < 4)
        throw dualcontact::InputError("too few arguments.",
                                      dualcontact::exit_usage);
      const std::string name = argv[3];
      if (name != "amg" && name != "gmg" && name != "mf")
        throw dualcontact::InputError("the preconditioner is 'amg', 'gmg' or "
                                      "'mf', not '" +
                                        name + "'.",
                                      dualcontact::exit_usage);
      const Kind               kind        = name == "amg" ? Kind::amg :
                                             name == "gmg" ? Kind::gmg :
                                                             Kind::mf;
      const int                refinements = std::stoi(argv[2]);
      double                   half_width  = 0.1;
      int                      degree      = 3;
      std::vector<std::string> overrides;
      for (int i = 4; i < argc; i += 2)
        {
          const std::string option = argv[i];
          if (i + 1 >= argc)
            throw dualcontact::InputError(option + " needs a value.",
                                          dualcontact::exit_usage);
          if (option == "--half-width")
            half_width = std::stod(argv[i + 1]);
          else if (option == "--degree")
            degree = std::stoi(argv[i + 1]);
          else if (option == "--set")
            overrides.emplace_back(argv[i + 1]);
          else
            throw dualcontact::InputError("unknown option '" + option + "'.",
                                          dualcontact::exit_usage);
        }
      if (refinements < 0 || !(half_width > 0.) || degree < 1)
        throw dualcontact::InputError(
          "refinements >= 0, half-width > 0 and degree >= 1 are needed.",
          dualcontact::exit_usage);

      dualcontact::Parameters parameters;
      parameters.read_file(argv[1], overrides);
      if (parameters.geometry.dimension == 2)
        MultigridBenchmark<2>(parameters, refinements, kind, half_width, degree)
          .run();
      else
        MultigridBenchmark<3>(parameters, refinements, kind, half_width, degree)
          .run();
    }
  catch (const dualcontact::InputError &error)
    {
      if (root)
        std::cerr << "benchmark_multigrid: " << error.what() << '\n'
                  << (error.code == dualcontact::exit_usage ? usage : "");
      return error.code;
    }
  catch (const std::exception &error)
    {
      if (root)
        std::cerr << "benchmark_multigrid: " << error.what() << '\n' << usage;
      return dualcontact::exit_usage;
    }
  return 0;
}
