// The closed forms of Cattaneo-Mindlin and Mindlin-Deresiewicz for a
// cylinder on a rough rigid plane (doc/theory.md §11), and what the tests
// read of a 2D run to compare with them: the contact nodes' tractions, the
// node spacing across the zone, the RMS of the tangential traction against
// a branch of the cycle, the energy a cycle dissipates.
#ifndef dualcontact_cattaneo_h
#define dualcontact_cattaneo_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "scene_run.h"
#include "test_tools.h"

namespace dualcontact_test
{
  /** (x, l1, l2) of every contact node after the last step, sorted by x. */
  inline std::vector<std::array<double, 3>>
  tractions(const Run &run)
  {
    const ContactSet<2> &c = run.problem->contact();
    std::vector<double>  local;
    for (unsigned int s = 0; s < c.n_local_nodes(); ++s)
      local.insert(local.end(), {c.nodes[s].position[0], c.l1[s], c.l2[s][0]});
    std::vector<std::array<double, 3>> all;
    for (const auto &part : Utilities::MPI::all_gather(run.comm, local))
      for (std::size_t i = 0; i + 2 < part.size(); i += 3)
        all.push_back({{part[i], part[i + 1], part[i + 2]}});
    std::sort(all.begin(), all.end());
    return all;
  }

  /**
   * The smallest spacing of contact nodes with |x| < a: the contact element
   * at degree 1, its shortest Gauss-Lobatto interval at degree k.
   */
  inline double
  contact_element(const Run &run, const double a)
  {
    std::vector<double> x;
    for (const auto &node : tractions(run))
      x.push_back(node[0]);
    double h = a;
    for (std::size_t i = 1; i < x.size(); ++i)
      if (std::abs(x[i]) < a)
        h = std::min(h, x[i] - x[i - 1]);
    return h;
  }

  /** Hertz's half-width of a cylinder R = 1 pressed by P (plane strain). */
  inline double
  hertz_half_width(const double P, const Parameters &parameters)
  {
    const double nu     = parameters.material.poissons_ratio;
    const double E_star = parameters.material.youngs_modulus / (1. - nu * nu);
    return std::sqrt(4. * P / (numbers::PI * E_star));
  }

  /**
   * One state of the cycle at beta = 0 for a cylinder R = 1: P and Q of the
   * step, the Q of the last turning point, and which branch. Gives the stick
   * half-width and the tangential traction of the superposition of
   * q_d(x) = F (p0/a) sqrt(d^2 - x^2):
   * - loading from 0: c/a = sqrt(1 - Q/(F P)), q = q_a - q_c;
   * - unloading from Q* > 0: c/a = sqrt(1 - (Q* - Q)/(2 F P)),
   *   q = -q_a + 2 q_c - q_c*;
   * - reloading from -Q*: c/a = sqrt(1 - (Q + Q*)/(2 F P)),
   *   q = q_a - 2 q_c + q_c*,
   * with c* the stick half-width at the turning point.
   */
  struct CattaneoState
  {
    enum Branch
    {
      loading,
      unloading,
      reloading
    };

    double a, p0, F, c, c_turn;
    Branch branch;

    CattaneoState(const Branch      branch,
                  const double      P,
                  const double      Q,
                  const double      Q_turn,
                  const double      F,
                  const Parameters &parameters)
        : a(hertz_half_width(P, parameters))
        , p0(2. * P / (numbers::PI * a))
        , F(F)
        , branch(branch)
    {
      const auto half_width = [&](const double ratio) {
        return a * std::sqrt(std::max(1. - ratio, 0.));
      };
      c_turn = half_width(std::abs(Q_turn) / (F * P));
      if (branch == loading)
        c = half_width(Q / (F * P));
      else if (branch == unloading)
        c = half_width((Q_turn - Q) / (2. * F * P));
      else
        c = half_width((Q - Q_turn) / (2. * F * P));
    }

    double
    q_d(const double x, const double d) const
    {
      return F * p0 / a * std::sqrt(std::max(d * d - x * x, 0.));
    }

    /** The tangential traction at x. */
    double
    traction(const double x) const
    {
      if (branch == loading)
        return q_d(x, a) - q_d(x, c);
      if (branch == unloading)
        return -q_d(x, a) + 2. * q_d(x, c) - q_d(x, c_turn);
      return q_d(x, a) - 2. * q_d(x, c) + q_d(x, c_turn);
    }
  };

  /**
   * The RMS over |x| < a of sign l2 - q(x), with the nodal weights, from a
   * step's contact_step_NNN.csv, in units of F p0; and the measure it
   * covered (about 2 a when the zone is resolved).
   */
  inline std::pair<double, double>
  traction_rms(const std::string   &file,
               const MPI_Comm       comm,
               const CattaneoState &state,
               const double         sign)
  {
    const CsvFile table(file, comm);
    double        sum = 0., measure = 0.;
    for (unsigned int i = 0; i < table.rows(); ++i)
      {
        const double x = table.value(i, "x");
        if (std::abs(x) >= state.a)
          continue;
        const double w = table.value(i, "weight");
        const double e = sign * table.value(i, "l2") - state.traction(x);
        sum += w * e * e;
        measure += w;
      }
    return {std::sqrt(sum / measure) / (state.F * state.p0), measure};
  }

  /**
   * The energy a cycle Q* -> -Q* -> Q* dissipates (doc/theory.md §11):
   *   W_2D = 16 F^2 p0^2 / (E* a) int_c^a sqrt(1 - x^2/a^2) S(x) dx,
   *   S(x) = (x sqrt(x^2 - c^2) - c^2 ln((x + sqrt(x^2 - c^2))/c)) / 2,
   * c the stick half-width at Q*; the midpoint rule on 20000 intervals.
   */
  inline double
  cycle_energy_2d(const CattaneoState &turn, const Parameters &parameters)
  {
    const double nu     = parameters.material.poissons_ratio;
    const double E_star = parameters.material.youngs_modulus / (1. - nu * nu);
    const double a = turn.a, c = turn.c;
    const unsigned int n        = 20000;
    double             integral = 0.;
    for (unsigned int k = 0; k < n; ++k)
      {
        const double x = c + (a - c) * (k + 0.5) / n;
        const double r = std::sqrt(x * x - c * c);
        const double S = 0.5 * (x * r - c * c * std::log((x + r) / c));
        integral += std::sqrt(1. - x * x / (a * a)) * S * (a - c) / n;
      }
    return 16. * turn.F * turn.F * turn.p0 * turn.p0 / (E_star * a) * integral;
  }
} // namespace dualcontact_test

#endif
