// What the Newton iteration needs of a body in the mixed displacement-
// pressure formulation (doc/mixed.md): the pressure's forces on the
// displacement DoFs, the saddle-point solve that replaces CG, and the
// pressure's share of the line search. The contact terms and the proximal
// term act on the displacement alone; the pressure is the multiplier of
// the (perturbed) incompressibility constraint B u - C p = 0 and moves
// with the displacement so that the constraint holds at every iterate.
#ifndef dualcontact_pressure_coupling_h
#define dualcontact_pressure_coupling_h

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <array>
#include <cmath>
#include <utility>

namespace dualcontact
{
  using namespace dealii;

  /**
   * The pressure field p of a mixed body, coupled to the displacement v
   * by the saddle-point system
   *
   *     [ H  B^T ] [d]   [f]
   *     [ B  -C  ] [q] = [-(B v + b_p - C p)],
   *
   * H the displacement block (the deviatoric stiffness, with the proximal
   * and contact terms of a Newton step), B = -(q, div u), C = (1/kappa)
   * (p, q), b_p the lifting of prescribed displacements. On the constraint
   * B v + b_p = C p the functional the Newton iteration minimises has the
   * smooth part 1/2 v.K v + 1/2 p.C p - rhs.v, its gradient in v is
   * K v + B^T p - rhs, and along a direction (d, q) its curvature is
   * d.K d + q.C q; at nu = 1/2 (C = 0) it is the energy on the discretely
   * divergence-free displacements. The Newton step is a step of
   * sequential quadratic programming with p as the constraint's
   * multiplier: it also restores the constraint where an inexact solve
   * left some of it.
   */
  class PressureCoupling
  {
  public:
    virtual ~PressureCoupling() = default;

    /** force += B^T p, the pressure's forces on the displacement DoFs. */
    virtual void
    add_pressure_forces(TrilinosWrappers::MPI::Vector &force) const = 0;

    /**
     * Solve the system above for d (in `direction`, from zero) and q (kept
     * for advance()), with `correction` the constraint's residual at v,
     * by MINRES preconditioned by diag(`amg`, S^{-1}), S the pressure mass
     * scaled by 1/(2 mu) + 1/kappa, to the relative tolerance `tolerance`
     * in at most `max_iterations`. Returns whether it converged and its
     * iterations.
     */
    virtual std::pair<bool, unsigned int>
    solve(const TrilinosWrappers::SparseMatrix    &H,
          const TrilinosWrappers::PreconditionAMG &amg,
          const TrilinosWrappers::MPI::Vector     &v,
          const TrilinosWrappers::MPI::Vector     &f,
          TrilinosWrappers::MPI::Vector           &direction,
          double                                   tolerance,
          unsigned int                             max_iterations) = 0;

    /**
     * The pressure's terms in the line search along d = `direction`, after
     * update_pressure(): the step is one of sequential quadratic
     * programming, in which p is the constraint's multiplier and takes
     * the whole q while v takes alpha d. The merit function is the smooth
     * part above plus rho |h|, h = B v + b_p - C p, an exact penalty
     * (rho = 2 |p + q| exceeds the multiplier), along which d descends. The
     * penalty follows the linear model h(alpha) = (1 - alpha) h of an
     * exact solve: what the inexact solve leaves of the second row, like
     * what it leaves of the first, is the next step's to correct (measured
     * directly, that residual would outweigh a small h and stall the line
     * search). A step that only corrects the multiplier (d ~ 0, at nu =
     * 1/2) leaves the merit flat, and any alpha serves.
     */
    struct LineTerms
    {
      double slope     = 0.; // -p_old.B d: smooth.d holds B^T p_old, not p
      double penalty_0 = 0.; // rho |h| at alpha = 0

      /** rho |h| |1 - a| and its first two derivatives in a. */
      std::array<double, 3>
      penalty(const double a) const
      {
        return {
          {penalty_0 * std::abs(1. - a), a < 1. ? -penalty_0 : penalty_0, 0.}};
      }
    };

    /**
     * p += q, the last solve's q; returns the line terms along
     * `direction`. Collective.
     */
    virtual LineTerms
    update_pressure(const TrilinosWrappers::MPI::Vector &direction) = 0;
  };
} // namespace dualcontact

#endif
