// The pressure field of the mixed formulation (mixed_bulk.h).
#include <deal.II/base/mpi.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/solver_minres.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <dualcontact/discretization.h>
#include <dualcontact/input_error.h>
#include <dualcontact/mixed_bulk.h>

#include <cmath>
#include <functional>
#include <memory>

namespace dualcontact
{
  namespace
  {
    template <int dim>
    std::unique_ptr<FiniteElement<dim>>
    make_pressure_element(const CellKind kind, const unsigned int degree)
    {
      const std::string refusal = mixed_pair_refusal(kind, degree);
      if (!refusal.empty())
        throw InputError(refusal, exit_inconsistent);
      if (kind == CellKind::simplex)
        return std::make_unique<FE_SimplexP<dim>>(degree - 1);
      return std::make_unique<FE_Q<dim>>(degree - 1);
    }

    using BlockVector = TrilinosWrappers::MPI::BlockVector;

    /** [[H, B^T], [B, -C]] applied to a block vector (u, p). */
    class SaddlePointOperator
    {
    public:
      SaddlePointOperator(const TrilinosWrappers::SparseMatrix &H,
                          const TrilinosWrappers::SparseMatrix &B,
                          const TrilinosWrappers::SparseMatrix &C)
          : H(H)
          , B(B)
          , C(C)
      {}

      void
      vmult(BlockVector &dst, const BlockVector &src) const
      {
        H.vmult(dst.block(0), src.block(0));
        B.Tvmult_add(dst.block(0), src.block(1));
        B.vmult(dst.block(1), src.block(0));
        tmp.reinit(src.block(1), true);
        C.vmult(tmp, src.block(1));
        dst.block(1) -= tmp;
      }

    private:
      const TrilinosWrappers::SparseMatrix &H, &B, &C;
      mutable TrilinosWrappers::MPI::Vector tmp;
    };

    /**
     * diag(AMG(H), S^{-1}), S^{-1} by one incomplete Cholesky
     * factorisation of S: both fixed SPD operators, as MINRES needs. S is
     * spectrally equivalent to the Schur complement B H^{-1} B^T + C
     * uniformly in h and in kappa while H is the stiffness plus terms
     * local to the contact surface.
     */
    class BlockDiagonalPreconditioner
    {
    public:
      BlockDiagonalPreconditioner(const TrilinosWrappers::PreconditionAMG &amg,
                                  const TrilinosWrappers::PreconditionIC  &mass)
          : amg(amg)
          , mass(mass)
      {}

      void
      vmult(BlockVector &dst, const BlockVector &src) const
      {
        amg.vmult(dst.block(0), src.block(0));
        mass.vmult(dst.block(1), src.block(1));
      }

    private:
      const TrilinosWrappers::PreconditionAMG &amg;
      const TrilinosWrappers::PreconditionIC  &mass;
    };
    // One Krylov solve of the saddle-point system from x, to `tolerance`
    // relative to the right-hand side and on until `accurate` holds (each
    // MINRES iterate is tested once the tolerance is met); returns whether
    // it converged and its iterations.
    std::pair<bool, unsigned int>
    krylov_solve(const SaddlePointOperator                      &matrix,
                 const BlockDiagonalPreconditioner              &preconditioner,
                 const BlockVector                              &rhs,
                 BlockVector                                    &x,
                 const double                                    tolerance,
                 const unsigned int                              max_iterations,
                 const std::function<bool(const BlockVector &)> &accurate)
    {
      // MINRES measures the residual in the preconditioner's norm, which
      // needs a positive definite preconditioner. An AMG kept from an earlier
      // Newton matrix need not be one (r.P r < 0 seen on a 2D Coulomb load
      // step once the statuses had changed), and then FGMRES, which takes
      // any preconditioner, solves instead.
      BlockVector preconditioned(rhs);
      preconditioner.vmult(preconditioned, rhs);
      const double rhs_energy = preconditioned * rhs;
      if (rhs.l2_norm() == 0. || max_iterations == 0)
        return {max_iterations > 0, 0};
      bool         converged  = rhs_energy > 0.;
      unsigned int iterations = 0;
      if (converged)
        {
          SolverControl             control(max_iterations,
                                tolerance * std::sqrt(rhs_energy),
                                false,
                                false);
          SolverMinRes<BlockVector> minres(control);
          // past the tolerance, on while the iterate is not accurate
          // enough: up to the control's limit (the control itself stops
          // at the tolerance), and not past a residual of exactly zero,
          // where MINRES has nothing left to improve
          minres.connect([&](const unsigned int step,
                             const double       residual,
                             const BlockVector &iterate) {
            if (residual > control.tolerance() || residual == 0.)
              return SolverControl::success;
            if (step >= control.max_steps())
              return SolverControl::failure;
            return accurate(iterate) ? SolverControl::success :
                                       SolverControl::iterate;
          });
          const BlockVector start(x);
          try
            {
              minres.solve(matrix, x, rhs, preconditioner);
            }
          catch (const SolverControl::NoConvergence &)
            {
              converged = false;
            }
          iterations = std::min(control.last_step(), max_iterations);
          if (!std::isfinite(x.l2_norm()))
            {
              x         = start;
              converged = false;
            }
        }
      // deal.II's MINRES divides by zero when its Krylov space holds the
      // exact solution before the tolerance is met (a patch test's uniform
      // state: a few iterations); FGMRES takes over then, where MINRES does
      // not converge, and where it cannot be used.
      if (!converged)
        {
          SolverControl             control(max_iterations,
                                tolerance * rhs.l2_norm(),
                                false,
                                false);
          SolverFGMRES<BlockVector> fgmres(control);
          converged = true;
          try
            {
              fgmres.solve(matrix, x, rhs, preconditioner);
            }
          catch (const SolverControl::NoConvergence &)
            {
              converged = false;
            }
          iterations += control.last_step();
        }
      return {converged, iterations};
    }

  } // namespace

  template <int dim>
  MixedBulk<dim>::MixedBulk(
    const parallel::TriangulationBase<dim> &triangulation,
    const CellKind                          kind,
    const unsigned int                      degree,
    const MaterialParameters               &material)
      : material(material)
      , fe(make_pressure_element<dim>(kind, degree))
      , dof_handler(triangulation)
  {}

  template <int dim>
  void
  MixedBulk<dim>::setup(const DoFHandler<dim>           &u_dofs,
                        const AffineConstraints<double> &u_constraints)
  {
    const MPI_Comm comm = u_dofs.get_communicator();
    dof_handler.distribute_dofs(*fe);
    owned   = dof_handler.locally_owned_dofs();
    owned_u = u_dofs.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    hanging.clear();
    hanging.reinit(relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, hanging);
    hanging.close();

    // B couples each cell's pressure DoFs with its displacement DoFs
    DynamicSparsityPattern               coupling_pattern(dof_handler.n_dofs(),
                                            u_dofs.n_dofs(),
                                            relevant);
    std::vector<types::global_dof_index> p_indices(fe->n_dofs_per_cell()),
      u_indices(u_dofs.get_fe().n_dofs_per_cell());
    for (const auto &cell : u_dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(u_indices);
          pressure_cell(cell)->get_dof_indices(p_indices);
          hanging.add_entries_local_to_global(
            p_indices, u_constraints, u_indices, coupling_pattern, false);
        }
    SparsityTools::distribute_sparsity_pattern(coupling_pattern,
                                               owned,
                                               comm,
                                               relevant);
    coupling.reinit(owned, owned_u, coupling_pattern, comm);

    DynamicSparsityPattern mass_pattern(relevant);
    DoFTools::make_sparsity_pattern(dof_handler, mass_pattern, hanging, false);
    SparsityTools::distribute_sparsity_pattern(mass_pattern,
                                               owned,
                                               comm,
                                               relevant);
    compliance.reinit(owned, owned, mass_pattern, comm);
    scaled_mass.reinit(owned, owned, mass_pattern, comm);
    pressure.reinit(owned, comm);
    increment.reinit(owned, comm);
    lifting.reinit(owned, comm);
    constraint_residual.reinit(owned, comm);
  }

  namespace
  {
    /**
     * A cell's blocks: B_K = -(q_i, div phi_j), C_K = (1/kappa)(q_i, q_j)
     * and S_K = (1/(2 mu) + 1/kappa)(q_i, q_j), with the quadrature of the
     * displacement assembly and the cell's material.
     */
    template <int dim>
    class CellBlocks
    {
    public:
      CellBlocks(const Mapping<dim>       &mapping,
                 const FiniteElement<dim> &fe_u,
                 const FiniteElement<dim> &fe_p)
          : quadrature(cell_quadrature(fe_u, fe_u.degree + 1))
          , u_values(mapping,
                     fe_u,
                     quadrature,
                     update_gradients | update_JxW_values)
          , p_values(mapping, fe_p, quadrature, update_values)
          , b(fe_p.n_dofs_per_cell(), fe_u.n_dofs_per_cell())
          , c(fe_p.n_dofs_per_cell(), fe_p.n_dofs_per_cell())
          , s(fe_p.n_dofs_per_cell(), fe_p.n_dofs_per_cell())
          , div(fe_u.n_dofs_per_cell())
      {}

      void
      reinit(const typename DoFHandler<dim>::active_cell_iterator &u_cell,
             const typename DoFHandler<dim>::active_cell_iterator &p_cell,
             const MaterialParameters                             &here,
             const bool                                            with_mass)
      {
        u_values.reinit(u_cell);
        p_values.reinit(p_cell);
        const double inverse_kappa = here.inverse_bulk_modulus();
        const double schur_scale   = 0.5 / here.mu() + inverse_kappa;
        const FEValuesExtractors::Vector displacement(0);
        b = 0;
        c = 0;
        s = 0;
        for (const unsigned int q : u_values.quadrature_point_indices())
          {
            const double JxW = u_values.JxW(q);
            for (unsigned int j = 0; j < b.n(); ++j)
              div[j] = u_values[displacement].divergence(j, q);
            for (unsigned int i = 0; i < b.m(); ++i)
              {
                const double phi_i = p_values.shape_value(i, q);
                for (unsigned int j = 0; j < b.n(); ++j)
                  b(i, j) -= phi_i * div[j] * JxW;
                if (with_mass)
                  for (unsigned int j = 0; j < b.m(); ++j)
                    {
                      const double m = phi_i * p_values.shape_value(j, q) * JxW;
                      c(i, j) += inverse_kappa * m;
                      s(i, j) += schur_scale * m;
                    }
              }
          }
      }

      const Quadrature<dim> quadrature;
      FEValues<dim>         u_values, p_values;
      FullMatrix<double>    b, c, s;

    private:
      std::vector<double> div;
    };
  } // namespace

  template <int dim>
  void
  MixedBulk<dim>::assemble(const Mapping<dim>              &mapping,
                           const DoFHandler<dim>           &u_dofs,
                           const AffineConstraints<double> &u_constraints)
  {
    CellBlocks<dim>    local(mapping, u_dofs.get_fe(), *fe);
    const unsigned int n_u = u_dofs.get_fe().n_dofs_per_cell(),
                       n_p = fe->n_dofs_per_cell();
    Vector<double>                       local_lift(n_p), prescribed(n_u);
    std::vector<types::global_dof_index> p_indices(n_p), u_indices(n_u);
    coupling    = 0;
    compliance  = 0;
    scaled_mass = 0;
    lifting     = 0;
    for (const auto &cell : u_dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto p_cell = pressure_cell(cell);
          local.reinit(cell, p_cell, material.of(cell->material_id()), true);
          cell->get_dof_indices(u_indices);
          p_cell->get_dof_indices(p_indices);
          // the prescribed values of the cell's constrained displacement
          // DoFs: B's columns of those DoFs are condensed away, and b_p
          // carries them
          for (unsigned int j = 0; j < n_u; ++j)
            prescribed(j) = u_constraints.is_constrained(u_indices[j]) ?
                              u_constraints.get_inhomogeneity(u_indices[j]) :
                              0.;
          local.b.vmult(local_lift, prescribed);
          hanging.distribute_local_to_global(
            local.b, p_indices, u_constraints, u_indices, coupling);
          hanging.distribute_local_to_global(local.c, p_indices, compliance);
          hanging.distribute_local_to_global(local.s, p_indices, scaled_mass);
          hanging.distribute_local_to_global(local_lift, p_indices, lifting);
        }
    coupling.compress(VectorOperation::add);
    compliance.compress(VectorOperation::add);
    scaled_mass.compress(VectorOperation::add);
    lifting.compress(VectorOperation::add);
    // A hanging pressure DoF's row of [B, -C] is empty (its value follows
    // its masters'); a diagonal entry in C keeps the system regular there
    // also where C vanishes (nu = 1/2). Its right-hand side is zero, so
    // its q is zero, and distribute() sets it.
    for (const auto &line : hanging.get_lines())
      if (owned.is_element(line.index))
        compliance.set(line.index,
                       line.index,
                       scaled_mass.diag_element(line.index));
    compliance.compress(VectorOperation::insert);
    mass_factors.initialize(scaled_mass);
  }

  template <int dim>
  TrilinosWrappers::MPI::Vector
  MixedBulk<dim>::unconstrained_pressure_forces(
    const Mapping<dim>    &mapping,
    const DoFHandler<dim> &u_dofs) const
  {
    CellBlocks<dim>                     local(mapping, u_dofs.get_fe(), *fe);
    const TrilinosWrappers::MPI::Vector p = ghosted_pressure();
    TrilinosWrappers::MPI::Vector forces(owned_u, p.get_mpi_communicator());
    Vector<double>                p_local(fe->n_dofs_per_cell()),
      f_local(u_dofs.get_fe().n_dofs_per_cell());
    std::vector<types::global_dof_index> u_indices(f_local.size());
    for (const auto &cell : u_dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto p_cell = pressure_cell(cell);
          local.reinit(cell, p_cell, material.of(cell->material_id()), false);
          p_cell->get_dof_values(p, p_local);
          local.b.Tvmult(f_local, p_local);
          cell->get_dof_indices(u_indices);
          forces.add(u_indices, f_local);
        }
    forces.compress(VectorOperation::add);
    return forces;
  }

  template <int dim>
  typename DoFHandler<dim>::active_cell_iterator
  MixedBulk<dim>::pressure_cell(
    const typename DoFHandler<dim>::active_cell_iterator &cell) const
  {
    return typename DoFHandler<dim>::active_cell_iterator(
      &dof_handler.get_triangulation(),
      cell->level(),
      cell->index(),
      &dof_handler);
  }

  template <int dim>
  double
  MixedBulk<dim>::compliance_product(
    const TrilinosWrappers::MPI::Vector &q) const
  {
    // the hanging entries follow their masters, whose rows of C hold
    // their share; C's diagonal entry in a hanging row is not part of it
    TrilinosWrappers::MPI::Vector free(q), Cq(q);
    hanging.set_zero(free);
    compliance.vmult(Cq, free);
    return free * Cq;
  }

  template <int dim>
  double
  MixedBulk<dim>::compliance_energy() const
  {
    return 0.5 * compliance_product(pressure);
  }

  template <int dim>
  void
  MixedBulk<dim>::add_pressure_forces(
    TrilinosWrappers::MPI::Vector &force) const
  {
    coupling.Tvmult_add(force, pressure);
  }

  template <int dim>
  double
  MixedBulk<dim>::infeasibility(const TrilinosWrappers::MPI::Vector &v) const
  {
    // measured against |B| |v| + |S| |p| (largest row sums and entries;
    // S = (1/(2 mu) + 1/kappa) M_p has the units of B v / p): B v itself
    // vanishes at the constraint when nu = 1/2, and v where the body is
    // confined
    TrilinosWrappers::MPI::Vector Bv(pressure), Cp(pressure);
    coupling.vmult(Bv, v);
    compliance.vmult(Cp, pressure);
    const double size = coupling.linfty_norm() * v.linfty_norm() +
                        lifting.linfty_norm() +
                        scaled_mass.linfty_norm() * pressure.linfty_norm();
    Bv += lifting;
    Bv -= Cp;
    hanging.set_zero(Bv);
    return size > 0. ? Bv.linfty_norm() / size : 0.;
  }

  template <int dim>
  std::pair<bool, unsigned int>
  MixedBulk<dim>::solve(const TrilinosWrappers::SparseMatrix    &H,
                        const TrilinosWrappers::PreconditionAMG &amg,
                        const TrilinosWrappers::MPI::Vector     &v,
                        const TrilinosWrappers::MPI::Vector     &f,
                        TrilinosWrappers::MPI::Vector           &direction,
                        const double                             tolerance,
                        const unsigned int                       max_iterations)
  {
    const MPI_Comm comm = f.get_mpi_communicator();
    BlockVector    x(std::vector<IndexSet>{owned_u, owned}, comm);
    BlockVector    rhs(x);
    rhs.block(0) = f;
    // -(B v + b_p - C p): the step restores the constraint
    coupling.vmult(rhs.block(1), v);
    rhs.block(1) += lifting;
    compliance.vmult(x.block(1), pressure);
    rhs.block(1) -= x.block(1);
    hanging.set_zero(rhs.block(1));
    constraint_residual = rhs.block(1);
    rhs.block(1) *= -1.;
    x = 0;

    const SaddlePointOperator         matrix(H, coupling, compliance);
    const BlockDiagonalPreconditioner preconditioner(amg, mass_factors);
    // The line search measures the penalty on the constraint at the step's
    // end (update_pressure()), so what the inexact solve leaves of the
    // second row must be small against what the step gains: MINRES goes on
    // past the tolerance until it is (accurate_enough()), and FGMRES, whose
    // iterate is formed only at the end, at a tolerance 10 times smaller.
    // Left at the first tolerance, a 2D Coulomb load step at nu = 1/2
    // cycled between two iterates, each claiming the other's residual as
    // progress.
    const auto accurate = [&](const BlockVector &iterate) {
      return accurate_enough(H, iterate);
    };
    unsigned int iterations = 0;
    bool         converged  = true;
    for (double relative = tolerance;; relative *= 1e-1)
      {
        const auto [done, steps] =
          krylov_solve(matrix,
                       preconditioner,
                       rhs,
                       x,
                       relative,
                       max_iterations - std::min(iterations, max_iterations),
                       accurate);
        iterations += steps;
        converged = done;
        if (!converged || relative < 1e-12 || iterations >= max_iterations ||
            accurate(x))
          break;
      }
    direction = x.block(0);
    increment = x.block(1);
    hanging.distribute(increment);
    return {converged, iterations};
  }

  template <int dim>
  bool
  MixedBulk<dim>::accurate_enough(const TrilinosWrappers::SparseMatrix &H,
                                  const BlockVector                    &x) const
  {
    // With a = h - C q and e = a + B d the second row's residual, the merit
    // function's slope along d is at most
    //   -d.H d + |e1.d| - |p + q| |a| + 3 |p + q| |e|
    // (penalty weight 2 |p + q|, e1 the first row's residual), so a
    // residual with 3 |e| <= |a| + d.H d / (2 |p + q|) keeps d a descent
    // direction as the first row's tolerance does without a pressure.
    // Below 1e-10 of the second row's terms the residual is round-off,
    // which no iteration reduces: it counts as accurate there.
    const TrilinosWrappers::MPI::Vector &d = x.block(0);
    TrilinosWrappers::MPI::Vector q(x.block(1)), a(pressure), e(pressure);
    hanging.set_zero(q);
    compliance.vmult(a, q);
    a.sadd(-1., 1., constraint_residual);
    hanging.set_zero(a);
    coupling.vmult(e, d);
    hanging.set_zero(e);
    const double step_size = e.l2_norm(); // |B d|
    e += a;
    TrilinosWrappers::MPI::Vector Hd(d);
    H.vmult(Hd, d);
    q += pressure;
    hanging.set_zero(q);
    const double multiplier = q.l2_norm();
    const double residual   = e.l2_norm();
    return 3. * multiplier * residual <=
             multiplier * a.l2_norm() + 0.5 * (d * Hd) ||
           residual <= 1e-10 * (a.l2_norm() + step_size);
  }

  template <int dim>
  PressureCoupling::LineTerms
  MixedBulk<dim>::update_pressure(const TrilinosWrappers::MPI::Vector &d)
  {
    // (hanging rows left out: their entries follow the masters')
    LineTerms                     terms;
    TrilinosWrappers::MPI::Vector w(pressure), free(pressure);
    coupling.vmult(w, d);
    hanging.set_zero(w);
    free = pressure;
    hanging.set_zero(free);
    terms.slope = -(free * w);
    pressure += increment;
    // the constraint's residual along the line, a + alpha B d, with
    // a = h - C q at the start of the line (the new p)
    free = increment;
    hanging.set_zero(free);
    TrilinosWrappers::MPI::Vector a(pressure);
    compliance.vmult(a, free);
    a.sadd(-1., 1., constraint_residual);
    hanging.set_zero(a);
    free = pressure;
    hanging.set_zero(free);
    terms.weight = 2. * free.l2_norm();
    terms.aa     = a * a;
    terms.ab     = a * w;
    terms.bb     = w * w;
    return terms;
  }

  template <int dim>
  TrilinosWrappers::MPI::Vector
  MixedBulk<dim>::ghosted_pressure() const
  {
    TrilinosWrappers::MPI::Vector ghosted(owned,
                                          relevant,
                                          pressure.get_mpi_communicator());
    ghosted = pressure;
    return ghosted;
  }

  template <int dim>
  std::vector<double>
  MixedBulk<dim>::values_at(
    const Mapping<dim>                                      &mapping,
    const TrilinosWrappers::MPI::Vector                     &p,
    const typename Triangulation<dim>::active_cell_iterator &cell,
    const std::vector<Point<dim>>                           &points) const
  {
    const typename DoFHandler<dim>::active_cell_iterator p_cell(
      &dof_handler.get_triangulation(),
      cell->level(),
      cell->index(),
      &dof_handler);
    Vector<double> local(fe->n_dofs_per_cell());
    p_cell->get_dof_values(p, local);
    std::vector<double> values(points.size(), 0.);
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        const Point<dim> unit =
          mapping.transform_real_to_unit_cell(cell, points[k]);
        for (unsigned int i = 0; i < local.size(); ++i)
          values[k] += local[i] * fe->shape_value(i, unit);
      }
    return values;
  }

  template <int dim>
  void
  MixedBulk<dim>::prepare_transfer()
  {
    // FieldTransfer takes the ghosted field on a p4est mesh, the owned one
    // on a replicated mesh
    if (dynamic_cast<const parallel::distributed::Triangulation<dim> *>(
          &dof_handler.get_triangulation()) != nullptr)
      transfer_source = ghosted_pressure();
    else
      transfer_source = pressure;
    transfer = std::make_unique<FieldTransfer<dim>>(dof_handler);
    transfer->prepare({&transfer_source});
  }

  template <int dim>
  void
  MixedBulk<dim>::finish_transfer()
  {
    if (!transfer)
      return;
    transfer->interpolate({&pressure});
    transfer.reset();
    transfer_source.clear();
    hanging.distribute(pressure);
  }

  template <int dim>
  void
  MixedBulk<dim>::prepare_checkpoint()
  {
    // (the source must live until the forest is saved)
    transfer_source = ghosted_pressure();
    checkpoint_transfer =
      std::make_unique<parallel::distributed::
                         SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>>(
        dof_handler);
    checkpoint_transfer->prepare_for_serialization(transfer_source);
  }

  template <int dim>
  void
  MixedBulk<dim>::read_checkpoint()
  {
    transfer_source.clear();
    checkpoint_transfer =
      std::make_unique<parallel::distributed::
                         SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>>(
        dof_handler);
    checkpoint_transfer->deserialize(pressure);
    checkpoint_transfer.reset();
  }

  template <int dim>
  PressureAt<dim>
  MixedBulk<dim>::pressure_at(const Mapping<dim> &mapping) const
  {
    const auto p =
      std::make_shared<const TrilinosWrappers::MPI::Vector>(ghosted_pressure());
    return [this, &mapping, p](const auto &cell, const auto &points) {
      return values_at(mapping, *p, cell, points);
    };
  }

  template class MixedBulk<2>;
  template class MixedBulk<3>;
} // namespace dualcontact
