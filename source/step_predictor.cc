#include <deal.II/base/mpi.h>

#include <dualcontact/step_predictor.h>

#include <algorithm>
#include <cmath>

namespace dualcontact
{
  namespace
  {
    /**
     * The ratio alpha = (d_new . d_old) / |d_old|^2 of a load's two last
     * increments, if they point within 60 degrees of each other; 0 if
     * they do not, or if one of them vanishes and the other does not;
     * -1 if the load does not change at all (it has no say).
     */
    double
    increment_ratio(const double dot,
                    const double new_square,
                    const double old_square)
    {
      const double scale = std::max(new_square, old_square);
      if (scale == 0. ||
          (new_square <= 1e-24 * scale && old_square <= 1e-24 * scale))
        return -1.;
      if (new_square <= 1e-24 * scale || old_square <= 1e-24 * scale)
        return 0.;
      if (dot < 0.5 * std::sqrt(new_square * old_square))
        return 0.;
      return dot / old_square;
    }
  } // namespace

  template <int dim>
  void
  StepPredictor<dim>::clear()
  {
    states.clear();
  }

  template <int dim>
  void
  StepPredictor<dim>::add_step(const TrilinosWrappers::MPI::Vector &u,
                               const ContactSet<dim>               &contact,
                               const TrilinosWrappers::MPI::Vector &rhs,
                               const Tensor<1, dim> &obstacle_displacement)
  {
    if (states.size() == 2)
      states.erase(states.begin());
    State state;
    state.u.reinit(rhs.locally_owned_elements(), rhs.get_mpi_communicator());
    state.u                     = u;
    state.rhs                   = rhs;
    state.obstacle_displacement = obstacle_displacement;
    state.l1                    = contact.l1;
    state.l2                    = contact.l2;
    state.threshold             = contact.threshold;
    states.push_back(std::move(state));
  }

  template <int dim>
  double
  StepPredictor<dim>::predict(const TrilinosWrappers::MPI::Vector &rhs,
                              const Tensor<1, dim> &obstacle_displacement,
                              TrilinosWrappers::MPI::Vector &v,
                              ContactSet<dim>               &contact) const
  {
    if (states.size() < 2)
      return 0.;
    const State   &older = states[0], &newer = states[1];
    const MPI_Comm comm = rhs.get_mpi_communicator();
    // the same contact nodes on every rank (a contact pair may pair anew)
    const unsigned int same_nodes =
      Utilities::MPI::min(contact.l1.size() == newer.l1.size() &&
                              newer.l1.size() == older.l1.size() ?
                            1u :
                            0u,
                          comm);
    if (same_nodes == 0)
      return 0.;

    // each load's increment ratio: the right-hand side's, the obstacle's
    TrilinosWrappers::MPI::Vector d_new(rhs), d_old(newer.rhs);
    d_new -= newer.rhs;
    d_old -= older.rhs;
    const Tensor<1, dim> U_new =
                           obstacle_displacement - newer.obstacle_displacement,
                         U_old = newer.obstacle_displacement -
                                 older.obstacle_displacement;
    const double ratios[2] = {
      increment_ratio(d_new * d_old, d_new.norm_sqr(), d_old.norm_sqr()),
      increment_ratio(U_new * U_old, U_new.norm_square(), U_old.norm_square())};
    double alpha = -1.;
    for (const double ratio : ratios)
      {
        if (ratio < 0.)
          continue; // this load does not change
        if (ratio == 0. ||
            (alpha > 0. && std::abs(ratio - alpha) > 1e-3 * alpha))
          return 0.;
        alpha = ratio;
      }
    if (alpha <= 0.)
      return 0.; // nothing changes: the last state is the answer

    // x^{n-1} + alpha (x^{n-1} - x^{n-2}), the multipliers projected
    TrilinosWrappers::MPI::Vector step(newer.u);
    step -= older.u;
    v = newer.u;
    v.add(alpha, step);
    const auto extrapolate = [alpha](const auto &now, const auto &before) {
      return now + alpha * (now - before);
    };
    for (unsigned int s = 0; s < contact.l1.size(); ++s)
      {
        contact.l1[s] = std::max(0., extrapolate(newer.l1[s], older.l1[s]));
        if (!contact.friction)
          continue;
        if (contact.law->depends_on_pressure())
          contact.threshold[s] =
            std::max(0., extrapolate(newer.threshold[s], older.threshold[s]));
        Tensor<1, dim - 1> l2 = extrapolate(newer.l2[s], older.l2[s]);
        const double       g  = contact.threshold[s];
        if (l2.norm() > g)
          l2 *= g / l2.norm();
        contact.l2[s] = l2;
      }
    return alpha;
  }

  template class StepPredictor<2>;
  template class StepPredictor<3>;
} // namespace dualcontact
