// The pressure field of the mixed displacement-pressure formulation
// (doc/mixed.md): its own DoFHandler on the body's mesh (FE_Q(k-1) beside
// the displacement's FE_Q(k)^dim, FE_SimplexP(k-1) beside FE_SimplexP(k):
// Taylor-Hood), the coupling B = -(q, div u), the compliance C = (1/kappa)
// (p, q) and the scaled pressure mass S that preconditions the Schur
// complement, and the MINRES solve of the saddle-point system. The
// displacement's DoFHandler, constraints and matrix are the displacement
// formulation's, with the deviatoric stiffness: the contact set, the
// multipliers, the displacement's output and the load path work on them
// unchanged.
#ifndef dualcontact_mixed_bulk_h
#define dualcontact_mixed_bulk_h

#include <deal.II/base/index_set.h>

#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria_base.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <dualcontact/cell_kind.h>
#include <dualcontact/field_transfer.h>
#include <dualcontact/material_parameters.h>
#include <dualcontact/postprocess.h>
#include <dualcontact/pressure_coupling.h>

#include <memory>
#include <string>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  /**
   * The pressure p = -kappa div u of a mixed body (positive in
   * compression) and the matrices that couple it to the displacement.
   * Each cell takes its material's mu and 1/kappa (<Material/Materials by
   * id>), so that bodies of different nu, up to 1/2, share one system.
   */
  template <int dim>
  class MixedBulk : public PressureCoupling
  {
  public:
    /**
     * The pressure element beside displacement degree `degree` on cells
     * of `kind`; throws InputError for a pair mixed_pair_refusal()
     * refuses.
     */
    MixedBulk(const parallel::TriangulationBase<dim> &triangulation,
              CellKind                                kind,
              unsigned int                            degree,
              const MaterialParameters               &material);

    /**
     * The pressure DoFs of the present mesh, their hanging-node
     * constraints, and the patterns of B (rows: pressure, columns: the
     * displacement DoFs of `u_dofs` under `u_constraints`), C and S. p
     * becomes zero (finish_transfer() carries it across a refinement).
     */
    void
    setup(const DoFHandler<dim>           &u_dofs,
          const AffineConstraints<double> &u_constraints);

    /**
     * B, C, S, and the lifting b_p = -B g of the prescribed displacements
     * g of `u_constraints`, with the quadrature of the displacement
     * assembly.
     */
    void
    assemble(const Mapping<dim>              &mapping,
             const DoFHandler<dim>           &u_dofs,
             const AffineConstraints<double> &u_constraints);

    /**
     * B^T p at every displacement DoF, constrained ones included (the
     * pressure's share of the residual that the reactions are made of).
     */
    TrilinosWrappers::MPI::Vector
    unconstrained_pressure_forces(const Mapping<dim>    &mapping,
                                  const DoFHandler<dim> &u_dofs) const;

    /** (1/2) p.C p, the pressure's share of the stored energy. */
    double
    compliance_energy() const;

    void
    add_pressure_forces(TrilinosWrappers::MPI::Vector &force) const override;

    /**
     * How far (v, p) is from the constraint: |B v + b_p - C p| over |B|
     * |v| + |b_p| + |S| |p| (largest entries and row sums). Collective.
     */
    double
    infeasibility(const TrilinosWrappers::MPI::Vector &v) const;

    std::pair<bool, unsigned int>
    solve(const TrilinosWrappers::SparseMatrix    &H,
          const TrilinosWrappers::PreconditionAMG &amg,
          const TrilinosWrappers::MPI::Vector     &v,
          const TrilinosWrappers::MPI::Vector     &f,
          TrilinosWrappers::MPI::Vector           &direction,
          double                                   tolerance,
          unsigned int                             max_iterations) override;

    LineTerms
    update_pressure(const TrilinosWrappers::MPI::Vector &direction) override;

    /**
     * Carry p across the refinement the triangulation is prepared for
     * (after prepare_coarsening_and_refinement(), before the refinement
     * is executed); finish_transfer() after the next setup() sets it on
     * the new mesh, so that the multiplier starts where the coarse mesh
     * left it (as v does).
     */
    void
    prepare_transfer();
    void
    finish_transfer();

    /**
     * Attach p to the cells for a checkpoint: after the displacement's
     * fields, before the forest is saved. read_checkpoint(), after setup()
     * on the mesh loaded from it and after the displacement's fields are
     * read, sets p as it was written (doc/theory.md §11, "Restart").
     * Throws what deal.II throws on data it cannot read.
     */
    void
    prepare_checkpoint();
    void
    read_checkpoint();

    /** The pressure element's DoFs on the mesh. */
    const DoFHandler<dim> &
    dofs() const
    {
      return dof_handler;
    }

    /**
     * The values at the real `points` of `cell` (a locally owned or ghost
     * cell) of the ghosted pressure `p` (ghosted_pressure()).
     */
    std::vector<double>
    values_at(const Mapping<dim>                                      &mapping,
              const TrilinosWrappers::MPI::Vector                     &p,
              const typename Triangulation<dim>::active_cell_iterator &cell,
              const std::vector<Point<dim>> &points) const;

    /** p with the ghost entries the output and the probes read. */
    TrilinosWrappers::MPI::Vector
    ghosted_pressure() const;

    /**
     * values_at() of the present p as a function of a cell and real
     * points, which keeps its own ghosted copy of p (the stress of the
     * output and of the refinement indicator).
     */
    PressureAt<dim>
    pressure_at(const Mapping<dim> &mapping) const;

    /** The owned pressure, for a transfer or a checkpoint to set. */
    TrilinosWrappers::MPI::Vector pressure;

  private:
    /**
     * Whether the solve's second-row residual is small enough for the
     * line search's measured penalty (solve()).
     */
    bool
    accurate_enough(const TrilinosWrappers::SparseMatrix     &H,
                    const TrilinosWrappers::MPI::BlockVector &x) const;

    /** The pressure DoFHandler's iterator of a displacement cell. */
    typename DoFHandler<dim>::active_cell_iterator
    pressure_cell(
      const typename DoFHandler<dim>::active_cell_iterator &cell) const;

    /** q.C q of a pressure vector. */
    double
    compliance_product(const TrilinosWrappers::MPI::Vector &q) const;

    const MaterialParameters                 &material;
    const std::unique_ptr<FiniteElement<dim>> fe;
    DoFHandler<dim>                           dof_handler;
    IndexSet                                  owned, relevant, owned_u;
    AffineConstraints<double>                 hanging;
    // B (pressure rows, displacement columns), C, S and the incomplete
    // Cholesky factors of S, the lifting b_p, and the pressure part q of
    // the last solve
    TrilinosWrappers::SparseMatrix   coupling, compliance, scaled_mass;
    TrilinosWrappers::PreconditionIC mass_factors;
    TrilinosWrappers::MPI::Vector    lifting, increment;
    // h = B v + b_p - C p at the v of the last solve
    TrilinosWrappers::MPI::Vector constraint_residual;
    // p on the mesh before a refinement, and its transfer; p attached to
    // a checkpoint's cells
    TrilinosWrappers::MPI::Vector       transfer_source;
    std::unique_ptr<FieldTransfer<dim>> transfer;
    std::unique_ptr<parallel::distributed::
                      SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>>
      checkpoint_transfer;
  };
} // namespace dualcontact

#endif
