// Linear elasticity: assembly of the stiffness matrix A, the load vector b
// and the lumped L2 mass matrix M, and the CG + algebraic-multigrid solver
// whose near-null space holds all rigid-body modes.
#ifndef dualcontact_elasticity_h
#define dualcontact_elasticity_h

#include <deal.II/base/timer.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/mapping.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <dualcontact/lumped_mass.h>
#include <dualcontact/records.h>
#include <dualcontact/scene.h>

#include <Epetra_MultiVector.h>

#include <array>
#include <functional>
#include <memory>

namespace dualcontact
{
  using namespace dealii;

  /**
   * Assemble the stiffness matrix A of a(u,v) = int sigma(u):eps(v) and the
   * load vector b = int f.v + int_{Gamma_N} T.v, with the constraints
   * (hanging nodes, Dirichlet, sliders) applied. Loads the scene does not
   * have are not assembled. The matrix must already have its sparsity pattern.
   * If `mass` is given, the lumped mass matrix is assembled into it in the
   * same pass, with the same constraints (its vector must have the locally
   * owned DoFs). If `applied_load`
   * is given, it gets the resultant of the applied loads (int f + int T,
   * summed over the ranks), without the lifting of prescribed
   * displacements that b holds.
   */
  template <int dim>
  void
  assemble_elasticity(const Mapping<dim>              &mapping,
                      const DoFHandler<dim>           &dof_handler,
                      const Scene<dim>                &scene,
                      const AffineConstraints<double> &constraints,
                      TrilinosWrappers::SparseMatrix  &system_matrix,
                      TrilinosWrappers::MPI::Vector   &system_rhs,
                      LumpedMass                      *mass         = nullptr,
                      std::array<double, 3>           *applied_load = nullptr);

  /**
   * The reaction forces on the body from its supports: at every 'fixed' and
   * 'normal fixed' boundary id, the residual A u - f of the unconstrained
   * equations summed over the DoFs that `constraints` constrain there, with
   * the hanging DoFs of `hanging_node_constraints` weighted by how much of
   * them their masters on that boundary carry (so that reactions, contact
   * force and loads balance exactly); a DoF two supports share counts for
   * the first. Also the resultant of the applied loads f. `solution` is
   * ghosted. `contact_forces` (owned), if given, is B^T lambda, the forces
   * the body exerts on the contact at its DoFs: at a DoF that a support
   * constrains and the contact also acts on (a slider's end on Gamma_C
   * with friction) A u - f holds both, and the support's part is
   * A u - f + B^T lambda. `pressure_forces` (owned), if given, is the
   * mixed formulation's B^T p at every DoF (MixedBulk), the rest of the
   * stress, which A (then the deviatoric stiffness) does not hold.
   */
  template <int dim>
  ReactionRecord
  compute_reactions(
    const Mapping<dim>                  &mapping,
    const DoFHandler<dim>               &dof_handler,
    const Scene<dim>                    &scene,
    const AffineConstraints<double>     &constraints,
    const AffineConstraints<double>     &hanging_node_constraints,
    const TrilinosWrappers::MPI::Vector &solution,
    const TrilinosWrappers::MPI::Vector *contact_forces  = nullptr,
    const TrilinosWrappers::MPI::Vector *pressure_forces = nullptr);

  /**
   * The potential energy J(u) = 1/2 a(u, u) - f(u) of the ghosted
   * `solution`, f the applied loads (body force and tractions; the contact
   * terms do not enter), integrated cell by cell with the quadrature of the
   * assembly and summed over the ranks (doc/theory.md §4). Collective.
   */
  template <int dim>
  double
  potential_energy(const Mapping<dim>                  &mapping,
                   const DoFHandler<dim>               &dof_handler,
                   const Scene<dim>                    &scene,
                   const TrilinosWrappers::MPI::Vector &solution);

  /**
   * The nodal vector of the displacement field `field` (a function of the
   * point): its value at the support point of every DoF of the locally
   * owned cells (mapped with `mapping`, so on the curve of a curved cell),
   * in the owned entries of `v`. At any degree this is the interpolant; a
   * rigid motion is exact in it.
   */
  template <int dim>
  void
  interpolate_field(
    const Mapping<dim>                                      &mapping,
    const DoFHandler<dim>                                   &dof_handler,
    const std::function<Tensor<1, dim>(const Point<dim> &)> &field,
    TrilinosWrappers::MPI::Vector                           &v);

  /**
   * The rigid-body modes of the displacement space (dim translations and
   * dim(dim-1)/2 rotations; only the translations if `with_rotations` is
   * false), as columns of an Epetra_MultiVector over the matrix' row map.
   * Rotations are taken about `center` and scaled by 1/`length`.
   */
  template <int dim>
  std::unique_ptr<Epetra_MultiVector>
  rigid_body_modes(const Mapping<dim>                   &mapping,
                   const DoFHandler<dim>                &dof_handler,
                   const TrilinosWrappers::SparseMatrix &matrix,
                   const bool                            with_rotations,
                   const Point<dim>                     &center,
                   const double                          length);

  /**
   * CG preconditioned by Trilinos ML smoothed-aggregation AMG. The AMG
   * hierarchy is built by `initialize` and reused by every `solve` until the
   * next `initialize`.
   */
  template <int dim>
  class ElasticSolver
  {
  public:
    /**
     * `poisson_ratio` only for the message when CG fails: near 1/2 the
     * material locks and the matrix is ill-conditioned.
     */
    explicit ElasticSolver(const SolverParameters &parameters,
                           const double            poisson_ratio = 0.3);

    /**
     * Compute the rigid-body modes handed to the AMG as near-null space;
     * once per mesh, with any matrix that has the mesh's row distribution.
     */
    void
    set_near_null_space(const Mapping<dim>                   &mapping,
                        const DoFHandler<dim>                &dof_handler,
                        const TrilinosWrappers::SparseMatrix &matrix,
                        const Point<dim>                     &center,
                        const double                          length);

    /** Build the AMG hierarchy for `matrix` (after set_near_null_space). */
    void
    initialize(const TrilinosWrappers::SparseMatrix &matrix);

    /**
     * Solve matrix x = rhs by CG to the relative tolerance `tolerance` (the
     * parameter's value if zero), starting from x. Returns the number of CG
     * iterations. Throws if CG does not converge.
     */
    unsigned int
    solve(const TrilinosWrappers::SparseMatrix &matrix,
          TrilinosWrappers::MPI::Vector        &x,
          const TrilinosWrappers::MPI::Vector  &rhs,
          const double                          tolerance = 0.) const;

    /**
     * The same with at most `max_iterations` CG iterations, and without
     * throwing: returns whether CG converged and the iterations it took (x
     * holds the last iterate either way). For a preconditioner built for an
     * earlier matrix, which may have become a poor one for this matrix.
     */
    std::pair<bool, unsigned int>
    try_solve(const TrilinosWrappers::SparseMatrix &matrix,
              TrilinosWrappers::MPI::Vector        &x,
              const TrilinosWrappers::MPI::Vector  &rhs,
              const double                          tolerance,
              const unsigned int                    max_iterations) const;

    /** The AMG hierarchy of the last initialize(). */
    const TrilinosWrappers::PreconditionAMG &
    amg() const
    {
      Assert(preconditioner != nullptr, ExcMessage("initialize() first"));
      return *preconditioner;
    }

  private:
    const SolverParameters                            &parameters;
    const double                                       poisson_ratio;
    bool                                               higher_order = false;
    std::unique_ptr<Epetra_MultiVector>                modes;
    std::unique_ptr<TrilinosWrappers::PreconditionAMG> preconditioner;
  };
} // namespace dualcontact

#endif
