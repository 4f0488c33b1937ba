// The mixed formulation along a load path with Coulomb friction, against
// the closed forms that hold exactly only at nu = 1/2 (Dundurs' beta = 0
// against a rigid plane): Cattaneo-Mindlin's stick zones and tractions and
// Mindlin-Deresiewicz's energy of a cycle (doc/theory.md §11,
// doc/mixed.md). Tagged [mixed][path]: ctest runs them apart, on 2 ranks.

#include <deal.II/base/mpi.h>

#include <dualcontact/contact_problem.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>

#include "cattaneo.h"
#include "scene_run.h"
#include "test_tools.h"

using namespace dualcontact;
using namespace dualcontact_test;

TEST_CASE("Cattaneo-Mindlin and Mindlin-Deresiewicz at nu = 1/2: every "
          "stick zone of the cycle within a node spacing, the tractions "
          "within 3 % of F p0, the cycle's energy within 2 % of W_2D",
          "[mixed][path]")
{
  // pressed (step 1), sheared to Q* in three steps (step 4), back to -Q* in
  // four (step 8) and to Q* again in four (step 12)
  const Run                       run("cattaneo_incompressible.prm", "");
  const std::vector<CycleResult> &steps = run.problem->steps();
  REQUIRE(steps.size() == 12);
  const unsigned int turn = 3, back = 7, end = 11;
  const double       F = 0.3;
  // Q signed by the clamp's reaction at Q*, and the clamp's displacement
  const double sign = steps[turn].reactions.on_id.at(1)[0] > 0. ? 1. : -1.;
  const auto   Q    = [&](const unsigned int n) {
    return sign * steps[n].reactions.on_id.at(1)[0];
  };
  const auto delta = [&](const unsigned int n) {
    return steps[n].step.boundary_displacement.at(1)[0];
  };
  const double P = steps[turn].zone.contact_force;
  const double h = contact_element(run, hertz_half_width(P, run.parameters));
  INFO("node spacing " << h << ", Q*/(F P) = " << Q(turn) / (F * P));
  CHECK(Q(turn) / (F * P) > 0.7);

  for (unsigned int n = 1; n <= end; ++n)
    {
      const CattaneoState state(n <= turn ? CattaneoState::loading :
                                n <= back ? CattaneoState::unloading :
                                            CattaneoState::reloading,
                                steps[n].zone.contact_force,
                                Q(n),
                                n <= back ? Q(turn) : Q(back),
                                F,
                                run.parameters);
      const double measured = steps[n].zone.stick_half_width;
      char         file[32];
      std::snprintf(file, sizeof(file), "/contact_step_%03u.csv", n + 1);
      const auto [rms, measure] =
        traction_rms(run.directory + file, run.comm, state, sign);
      INFO("step " << n + 1
                   << ": Q/(F P) = " << Q(n) / (F * steps[n].zone.contact_force)
                   << ", stick half-width " << measured << " against "
                   << state.c << " (" << (measured - state.c) / h
                   << " node spacings), RMS traction error " << rms << " F p0");
      // a node spacing is half a contact element at degree 2
      CHECK(std::abs(measured - state.c) <= h);
      CHECK(measure > 1.9 * state.a);
      CHECK(rms <= 0.03);
    }

  // The cycle Q* -> -Q* -> Q* (steps 5-12): the energy friction dissipated
  // against W_2D for the P and Q* of the turning point, and against the
  // clamp's work around the loop (Simpson's rule over pairs of steps).
  const double dissipated =
    steps[end].step.dissipation_total - steps[turn].step.dissipation_total;
  double work = 0.;
  for (unsigned int n = turn; n + 2 <= end; n += 2)
    work += (delta(n + 2) - delta(n)) / 6. * (Q(n) + 4. * Q(n + 1) + Q(n + 2));
  work *= sign;
  const CattaneoState at_turn(
    CattaneoState::loading, P, Q(turn), Q(turn), F, run.parameters);
  const double W_2D = cycle_energy_2d(at_turn, run.parameters);
  INFO("dissipated " << dissipated << ", the clamp's work " << work << ", W_2D "
                     << W_2D);
  CHECK(std::abs(dissipated / W_2D - 1.) <= 0.02);
  CHECK(std::abs(work / dissipated - 1.) <= 0.01);
}
