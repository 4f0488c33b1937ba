// Where a later step of a load path starts: from the state the last step
// reached (the warm start), or, where the loads keep their direction, from
// the linear extrapolation of the last two steps (doc/theory.md §11).
#ifndef dualcontact_step_predictor_h
#define dualcontact_step_predictor_h

#include <deal.II/base/tensor.h>

#include <deal.II/lac/trilinos_vector.h>

#include <dualcontact/contact_set.h>

#include <vector>

namespace dualcontact
{
  using namespace dealii;

  /**
   * The predictor of a load path's steps. Along a smooth path the solution
   * changes almost linearly with the loads, so that
   *
   *   x^n ~ x^{n-1} + alpha (x^{n-1} - x^{n-2}),
   *   alpha = (db_n . db_{n-1}) / |db_{n-1}|^2,   db_n = b^n - b^{n-1},
   *
   * for x = v, l1, l2 and g, leaves the Uzawa iteration only the
   * correction. b is the load of a step: the assembled right-hand side
   * (tractions, body force and the lifting of prescribed displacements)
   * and the obstacle's translation, each taken separately. The predictor
   * extrapolates only where every load that changes keeps its direction
   * (each increment within 60 degrees of the one before) at the same
   * ratio alpha; at a turn of the path the extrapolation would overshoot,
   * and the step starts from the last one's state as it is. The
   * extrapolated multipliers are projected onto their admissible sets
   * (l1 >= 0, g >= 0, |l2| <= g), so that the Uzawa iteration starts from
   * a point it could have reached, and converges to the same answer.
   */
  template <int dim>
  class StepPredictor
  {
  public:
    /** Forget the steps so far: a new mesh, or the path's first step. */
    void
    clear();

    /**
     * A converged step: its displacement, the multipliers and threshold
     * of `contact`, its right-hand side and the obstacle's translation.
     */
    void
    add_step(const TrilinosWrappers::MPI::Vector &u,
             const ContactSet<dim>               &contact,
             const TrilinosWrappers::MPI::Vector &rhs,
             const Tensor<1, dim>                &obstacle_displacement);

    /**
     * The start of the next step, with its right-hand side `rhs` and the
     * obstacle at `obstacle_displacement`: if two steps on this mesh came
     * before and the loads keep their direction, v and the multipliers
     * and threshold of `contact` (the last step's state, which they hold)
     * become the extrapolation. Returns alpha, or 0 where the step keeps
     * the warm start. v is left without its constraints distributed.
     * Collective.
     */
    double
    predict(const TrilinosWrappers::MPI::Vector &rhs,
            const Tensor<1, dim>                &obstacle_displacement,
            TrilinosWrappers::MPI::Vector       &v,
            ContactSet<dim>                     &contact) const;

  private:
    /** What the predictor keeps of a step. */
    struct State
    {
      TrilinosWrappers::MPI::Vector   u;
      TrilinosWrappers::MPI::Vector   rhs;
      Tensor<1, dim>                  obstacle_displacement;
      std::vector<double>             l1;
      std::vector<Tensor<1, dim - 1>> l2;
      std::vector<double>             threshold;
    };

    // the last two steps, the older first
    std::vector<State> states;
  };
} // namespace dualcontact

#endif
