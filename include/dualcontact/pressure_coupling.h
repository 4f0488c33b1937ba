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
     * (rho = 2 |p + q| exceeds the multiplier), along which d descends.
     * Along the line h(alpha) = a + alpha b with a = h - C q and b = B d,
     * measured: an exact solve has b = -a, and solve() leaves little
     * enough of the second row's residual a + b for d to descend.
     */
    struct LineTerms
    {
      double slope  = 0.; // -p_old.B d: smooth.d holds B^T p_old, not p
      double weight = 0.; // rho
      double aa = 0., ab = 0., bb = 0.; // a.a, a.b, b.b

      /** rho |a + alpha b| and its first two derivatives in alpha. */
      std::array<double, 3>
      penalty(const double alpha) const
      {
        const double norm =
          std::sqrt(std::max(aa + alpha * (2. * ab + alpha * bb), 0.));
        if (!(norm > 1e-14 * std::sqrt(aa + bb)))
          return {{0., weight * std::sqrt(bb), 0.}}; // from the right
        const double slope = (ab + alpha * bb) / norm;
        return {{weight * norm,
                 weight * slope,
                 weight * std::max(bb - slope * slope, 0.) / norm}};
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
