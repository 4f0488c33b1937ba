// Load paths with friction history (doc/theory.md §11), against what is
// known: a path without history gives the same answer in any number of
// steps (the GRECO plate under proportional loads), the growing stick zone
// of a Hertz contact loaded in more and more steps (the coupled half-plane
// answer, approached as a/R -> 0; doc/theory.md §11), and the order of
// loading of a cylinder pressed and sheared (at once, normal first, in
// proportion). Tagged [path]: ctest runs them apart from the other unit
// tests, on 1 and 2 ranks. Every assertion is on a value reduced over all
// ranks.

#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>

#include <dualcontact/contact_problem.h>

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <functional>
#include <iomanip>
#include <sstream>

#include "cattaneo.h"
#include "scene_run.h"
#include "test_tools.h"

using namespace dualcontact;
using namespace dualcontact_test;

namespace
{
  /**
   * The last step's tractions of two runs on the same mesh, node by node:
   * the largest difference of l1 or l2, and p0, the largest l1 of `b`.
   */
  std::pair<double, double>
  traction_difference(const Run &a, const Run &b)
  {
    const auto ta = tractions(a), tb = tractions(b);
    REQUIRE(ta.size() == tb.size());
    double p0 = 0., difference = 0.;
    for (std::size_t i = 0; i < ta.size(); ++i)
      {
        p0         = std::max(p0, tb[i][1]);
        difference = std::max({difference,
                               std::abs(ta[i][1] - tb[i][1]),
                               std::abs(ta[i][2] - tb[i][2])});
      }
    return {difference, p0};
  }

  /** The record of the last step (or of the last cycle of a static run). */
  const CycleResult &
  last_step(const Run &run)
  {
    return run.problem->steps().empty() ? run.last() :
                                          run.problem->steps().back();
  }

  std::string
  path_of(const unsigned int n_steps)
  {
    return "subsection Load path\n  set Number of steps = " +
           std::to_string(n_steps) + "\nend\n";
  }
} // namespace

TEST_CASE("No spurious history: the GRECO plate under proportional loads "
          "gives the same answer in 1, 5 and 50 steps",
          "[path]")
{
  const Run  one("greco_plate.prm", path_of(1));
  const auto reference = tractions(one);
  double     scale     = 0.;
  for (const auto &node : reference)
    scale = std::max(scale, node[1]);
  // a contact in partial slip: both zones are there
  CHECK(last_step(one).solve.n_stick > 0);
  CHECK(last_step(one).solve.n_slip > 0);
  for (const unsigned int n : {5u, 50u})
    {
      const Run  run("greco_plate.prm", path_of(n));
      const auto other = tractions(run);
      REQUIRE(other.size() == reference.size());
      double difference = 0.;
      for (std::size_t i = 0; i < other.size(); ++i)
        difference = std::max({difference,
                               std::abs(other[i][1] - reference[i][1]),
                               std::abs(other[i][2] - reference[i][2])});
      INFO(n << " steps: largest difference of l1, l2 " << difference / scale
             << " of max l1");
      // the Uzawa tolerance is 1e-8 relative
      CHECK(difference <= 1e-7 * scale);
      CHECK(last_step(run).solve.n_slip == last_step(one).solve.n_slip);
    }
}

namespace
{
  /**
   * prm/hertz_friction.prm (nu = 0.3, F = 0.3) loaded from zero in n equal
   * steps of the pressure on the top, `scale` times the scene's: the stick
   * half-width over the contact half-width after the last step (c/a), the
   * contact element at the zone's edge over a, and a (R = 1, so a = a/R).
   * Each halving of a takes one more pre-refinement step, so that the
   * contact element stays about a/64.
   */
  std::array<double, 3>
  stick_zone_after_gradual_loading(const unsigned int n_steps,
                                   const double       scale,
                                   const unsigned int pre_refinement_steps)
  {
    std::ostringstream overrides;
    overrides.precision(17);
    overrides << "subsection Geometry\n  set Pre-refinement steps = "
              << pre_refinement_steps
              << "\nend\nsubsection Boundary conditions\n  set Tractions = "
                 "1: 0; "
              << -4.315374524161804 * scale << " * t\nend\n"
              << path_of(n_steps);
    const Run                run("hertz_friction.prm", overrides.str());
    const ContactZoneRecord &zone = last_step(run).zone;
    std::vector<double>      x;
    for (const auto &node : tractions(run))
      x.push_back(node[0]);
    double h = 1.;
    for (std::size_t i = 1; i < x.size(); ++i)
      if (std::abs(x[i]) < zone.edge_half_width)
        h = std::min(h, x[i] - x[i - 1]);
    return {{zone.stick_half_width / zone.edge_half_width,
             h / zone.edge_half_width,
             zone.edge_half_width}};
  }
} // namespace

TEST_CASE("Spence, coupled: a Hertz contact with friction at nu = 0.3 "
          "loaded in 1, 2, 5 and 20 steps, and in 20 steps at a/R = 0.1, "
          "0.05 and 0.025: the stick zone approaches the coupled half-plane "
          "answer",
          "[path]")
{
  // beta = 0.29, F = 0.3 (doc/theory.md §11). The half-plane answers for
  // c/a: one step from the undeformed state, about 0.3 (0.295 on a coupled
  // boundary-element model); loaded gradually, 0.684 after 20 equal steps
  // and 0.694 converged on the coupled model. Spence's closed form
  // beta / F = K(k') / K(k), c/a = 0.744, leaves out the coupling (the
  // shear's change of the normal displacement): it is not the reference.
  const double coupled_20_steps = 0.684;
  const double uncoupled        = 0.744;
  // the finite half disc adds terms of order a/R (its own stress at the
  // contact, the plane's push on the tilted surface); measured: c/a falls
  // by 0.64 to 0.82 per unit a/R between a/R = 0.1, 0.05 and 0.025
  const double per_a_over_R = 1.;

  std::vector<double>   ratio;
  std::array<double, 3> twenty_steps{};
  for (const unsigned int n : {1u, 2u, 5u, 20u})
    {
      twenty_steps = stick_zone_after_gradual_loading(n, 1., 4);
      ratio.push_back(twenty_steps[0]);
    }
  INFO("a/R = 0.1: c/a in 1, 2, 5, 20 steps: "
       << ratio[0] << ", " << ratio[1] << ", " << ratio[2] << ", " << ratio[3]);
  // one step from the undeformed state: about 0.3 a
  CHECK(ratio[0] > 0.25);
  CHECK(ratio[0] < 0.40);
  // more steps, more stick; the changes shrink: it converges
  CHECK(ratio[1] > ratio[0]);
  CHECK(ratio[2] > ratio[1]);
  CHECK(ratio[3] >= ratio[2]);
  CHECK(ratio[3] - ratio[2] < ratio[2] - ratio[1]);

  // 20 steps at a/R = 0.1 (the run above), 0.05 and 0.025 (the load over
  // 4 and 16)
  const std::vector<std::array<double, 3>> series{
    twenty_steps,
    stick_zone_after_gradual_loading(20, 0.25, 5),
    stick_zone_after_gradual_loading(20, 0.0625, 6)};
  for (const auto &zone : series)
    {
      INFO("20 steps, a/R = " << zone[2] << ": c/a = " << zone[0]
                              << ", contact element " << zone[1]
                              << " a; coupled half-plane " << coupled_20_steps);
      // one contact element (the stick zone's ends lie half-way between
      // nodes, a's are extrapolated) plus the finite disc's term
      CHECK(std::abs(zone[0] - coupled_20_steps) <=
            zone[1] + per_a_over_R * zone[2]);
    }
  // c/a falls as a/R falls
  CHECK(series[0][0] > series[1][0]);
  CHECK(series[1][0] > series[2][0]);
  // extrapolated linearly in a/R from the two smallest to a/R = 0: within
  // 1.5 contact elements of the coupled answer (each c/a to half an
  // element, the extrapolation doubles one of them), and nearer to it than
  // to the uncoupled closed form
  const double slope =
    (series[1][0] - series[2][0]) / (series[1][2] - series[2][2]);
  const double extrapolated = series[2][0] - slope * series[2][2];
  INFO("c/a extrapolated to a/R = 0: " << extrapolated << " (slope " << slope
                                       << " per unit a/R)");
  CHECK(std::abs(extrapolated - coupled_20_steps) <= 1.5 * series[2][1]);
  CHECK(std::abs(extrapolated - coupled_20_steps) <
        std::abs(extrapolated - uncoupled));
}

TEST_CASE("Cattaneo-Mindlin and Mindlin-Deresiewicz: a cylinder pressed, "
          "sheared to Q*, back to -Q* and to Q* again: the stick zone of "
          "every step",
          "[path]")
{
  // a probe on the clamp: it moves as the clamp is told to
  const Run                       run("cattaneo_mindlin.prm",
                "subsection Output\n  set Probe points = 0.25, 0\nend\n");
  const std::vector<CycleResult> &steps = run.problem->steps();
  REQUIRE(steps.size() == 16);
  const double F = 0.3;
  // Q along the first shear, signed by the clamp's reaction
  const auto Q = [&](const unsigned int n) {
    return steps[n].reactions.on_id.at(1)[0] *
           (steps[7].reactions.on_id.at(1)[0] > 0. ? 1. : -1.);
  };
  const double a_first =
    hertz_half_width(steps[3].zone.contact_force, run.parameters);
  const double h     = contact_element(run, a_first);
  double       worst = 0.;
  for (unsigned int n = 4; n < 16; ++n)
    {
      const double P = steps[n].zone.contact_force;
      const double a = hertz_half_width(P, run.parameters);
      double       c = 0.;
      if (n < 8) // loading from 0 to Q*
        c = a * std::sqrt(1. - Q(n) / (F * P));
      else if (n < 12) // unloading from Q* (step 8)
        c = a * std::sqrt(1. - (Q(7) - Q(n)) / (2. * F * P));
      else // reloading from -Q* (step 12)
        c = a * std::sqrt(1. - (Q(n) - Q(11)) / (2. * F * P));
      const double measured = steps[n].zone.stick_half_width;
      INFO("step " << n + 1 << ": Q/(F P) = " << Q(n) / (F * P)
                   << ", stick half-width " << measured << " against " << c
                   << " (" << (measured - c) / h << " contact elements)");
      // nu = 0.45 (beta = 0.09): the normal load leaves an odd shear in
      // the stick zone, which narrows it on one side by up to two contact
      // elements against the formulas for beta = 0
      CHECK(std::abs(measured - c) <= 2.5 * h);
      worst = std::max(worst, std::abs(measured - c) / h);
    }
  INFO("largest difference " << worst << " contact elements (" << h << ")");
  // the cycle reaches a real partial slip: Q*/(F P) about 1/3
  CHECK(Q(7) / (F * steps[7].zone.contact_force) > 0.3);

  // The loop of steps.csv: the clamp's mean displacement is the one
  // prescribed, the force on the obstacle is the clamp's reaction, the
  // probe on the clamp moves with it.
  const auto clamp = [](const double t) {
    return 0.002 * (t <= 1 ? 0. :
                    t <= 2 ? t - 1 :
                    t <= 3 ? 3 - 2 * (t - 1) :
                             2 * (t - 3) - 1);
  };
  const auto &probe = run.problem->get_probes().step_values();
  REQUIRE(probe.size() == steps.size());
  for (unsigned int n = 0; n < 16; ++n)
    {
      const StepRecord &step = steps[n].step;
      INFO("step " << n + 1 << ", t = " << step.time);
      CHECK(probe[n].step == n + 1);
      CHECK(std::abs(step.boundary_displacement.at(1)[0] - clamp(step.time)) <=
            1e-12);
      CHECK(std::abs(step.boundary_displacement.at(1)[1] +
                     0.01 * std::min(step.time, 1.)) <= 1e-12);
      CHECK(std::abs(probe[n].displacement[0] - clamp(step.time)) <= 1e-12);
      CHECK(std::abs(steps[n].reactions.on_id.at(1)[0] +
                     steps[n].zone.resultant[0]) <= 1e-6 * std::abs(Q(7)));
    }
  // The energy friction dissipated over the cycle Q* -> -Q* -> Q* (steps
  // 9-16) is the area of the loop: the trapezoid rule over its 8 segments
  // falls short of the convex loop by less than 3 %.
  double area = 0.;
  for (unsigned int n = 8; n < 16; ++n)
    area += 0.5 *
            (steps[n].reactions.on_id.at(1)[0] +
             steps[n - 1].reactions.on_id.at(1)[0]) *
            (clamp(steps[n].step.time) - clamp(steps[n - 1].step.time));
  const double dissipated =
    steps[15].step.dissipation_total - steps[7].step.dissipation_total;
  INFO("dissipated over the cycle " << dissipated << ", loop area " << area);
  CHECK(dissipated > 0.);
  CHECK(std::abs(std::abs(area) - dissipated) <= 0.03 * dissipated);
}

TEST_CASE("Cattaneo-Mindlin at nu = 0.49 with elements of degree 3: the "
          "stick zone on loading, unloading, reversal and reloading within "
          "one contact element, the tractions within 5 % of F p0 (RMS)",
          "[path][long]")
{
  // The scene's cylinder with a contact small against it (a/R = 0.008: the
  // half disc's own lateral strain under the clamp stays below the shear of
  // the formulas) at beta = 0.02, on elements of degree 3 (at degree 1 and
  // 2 the shear locks near nu = 1/2); steps at Q*, 0, -Q* and 0 again.
  const Run run(
    "cattaneo_mindlin.prm",
    "subsection Material\n  set Poisson's ratio = 0.49\nend\n"
    "subsection Discretization\n  set Polynomial degree = 3\nend\n"
    "subsection Geometry\n  set Pre-refinement steps = 8\n  set "
    "Pre-refinement distance = 0.00625\nend\n"
    "subsection Refinement\n  set Initial global refinement = 3\n  set Number "
    "of cycles = 1\nend\n"
    "subsection Boundary conditions\n  set Displacements = 1: 3.5e-5 * "
    "if(t <= 1, 0, if(t <= 2, t - 1, if(t <= 3, 3 - 2 * (t - 1), 2 * (t - 3) "
    "- 1))); -0.00016 * min(t, 1)\nend\n"
    "subsection Load path\n  set Times = 1, 2, 2.5, 3, 3.5\nend\n");
  const std::vector<CycleResult> &steps = run.problem->steps();
  REQUIRE(steps.size() == 5);
  const double F = 0.3;
  // Q signed by the clamp's reaction at Q* (step 2)
  const double sign = steps[1].reactions.on_id.at(1)[0] > 0. ? 1. : -1.;
  const auto   Q    = [&](const unsigned int n) {
    return sign * steps[n].reactions.on_id.at(1)[0];
  };
  const double P = steps[0].zone.contact_force;
  const double a = hertz_half_width(P, run.parameters);
  // the smallest spacing of the support points on Gamma_C, 0.28 of a
  // contact element at degree 3 (Gauss-Lobatto points 0, 0.28, 0.72, 1)
  const double h = contact_element(run, a);
  INFO("a = " << a << ", node spacing " << h
              << ", Q*/(F P) = " << Q(1) / (F * P));
  CHECK(Q(1) / (F * P) > 0.4);
  for (unsigned int n = 1; n < 5; ++n)
    {
      // loading to Q* (step 2), unloading to 0 and to -Q*, reloading from
      // -Q* (step 4)
      const CattaneoState state(n == 1 ? CattaneoState::loading :
                                n <= 3 ? CattaneoState::unloading :
                                         CattaneoState::reloading,
                                steps[n].zone.contact_force,
                                Q(n),
                                n <= 3 ? Q(1) : Q(3),
                                F,
                                run.parameters);
      const double measured = steps[n].zone.stick_half_width;
      INFO("step " << n + 1
                   << ": Q/(F P) = " << Q(n) / (F * steps[n].zone.contact_force)
                   << ", stick half-width " << measured << " against "
                   << state.c << " (" << (measured - state.c) / h
                   << " node spacings)");
      // within a node spacing, so within a third of a contact element
      CHECK(std::abs(measured - state.c) <= h);

      // the tractions of contact_step_00<n+1>.csv against the branch's
      // superposition, RMS over |x| < a with the nodal weights (pointwise,
      // the square-root kinks at the zone edges put up to 0.2 F p0 on the
      // node next to each)
      const auto [rms, measure] =
        traction_rms(run.directory + "/contact_step_00" +
                       std::to_string(n + 1) + ".csv",
                     run.comm,
                     state,
                     sign);
      INFO("step " << n + 1 << ": RMS traction error " << rms << " F p0");
      CHECK(measure > 1.9 * state.a);
      CHECK(rms <= 0.05);
    }
}

TEST_CASE("Mindlin-Deresiewicz in 3D: a ball pressed, sheared to Q*, -Q* and "
          "Q* again dissipates the energy of the hysteresis loop",
          "[path][long]")
{
  const SceneRun<3>               run("mindlin_sphere.prm", "");
  const std::vector<CycleResult> &steps = run.problem->steps();
  REQUIRE(steps.size() == 4);
  const double F  = 0.3;
  const double nu = run.parameters.material.poissons_ratio;
  const double E  = run.parameters.material.youngs_modulus;
  const double G  = E / (2. * (1. + nu));
  // P and Q* (the force on the plane) as measured at the end of the cycle,
  // Hertz's a from P
  const double P = steps[3].zone.contact_force;
  const double Q = -steps[3].zone.resultant[0];
  const double a = std::cbrt(3. * P / (4. * E / (1. - nu * nu)));
  const double x = Q / (F * P);
  // Johnson §7.3: the energy of a cycle Q* -> -Q* -> Q*
  const double W = 9. * F * F * P * P * (2. - nu) / (10. * a * G) *
                   (1. - std::pow(1. - x, 5. / 3.) -
                    5. * x / 6. * (1. + std::pow(1. - x, 2. / 3.)));
  const double down = steps[2].step.dissipation; // Q* -> -Q*
  const double up   = steps[3].step.dissipation; // -Q* -> Q*
  INFO("Q*/(F P) = " << x << ", dissipated " << down << " + " << up
                     << " against W = " << W << " (" << (down + up) / W - 1.
                     << ")");
  CHECK(x > 0.5);
  // nu = 0.48 (beta = 0.04): 2.7 % high on 85887 DoFs
  CHECK(std::abs((down + up) / W - 1.) <= 0.05);
  // Masing: both half cycles dissipate the same
  CHECK(std::abs(down - up) <= 0.02 * up);
  // the stick zone at Q* (step 2), within a contact element of Cattaneo's
  const double c = a * std::cbrt(1. + steps[1].zone.resultant[0] / (F * P));
  const double h = line_spacing(run, c);
  INFO("stick radius " << steps[1].zone.stick_half_width << " against " << c
                       << ", contact element " << h);
  CHECK(h > 0.);
  CHECK(std::abs(steps[1].zone.stick_half_width - c) <= h);
}

TEST_CASE("Path dependence: the same final clamp displacement at once, normal "
          "first then shear, and in proportion from a small first step",
          "[path]")
{
  const std::string at_once =
    "subsection Boundary conditions\n  set Displacements = 1: 0.002; "
    "-0.01\nend\nsubsection Load path\n  set Times = 1\nend\n";
  const std::string normal_first =
    "subsection Boundary conditions\n  set Displacements = 1: 0.002 * "
    "max(t - 1, 0); -0.01 * min(t, 1)\nend\nsubsection Load path\n  set "
    "Times = 1, 2\nend\n";
  const std::string proportional =
    "subsection Boundary conditions\n  set Displacements = 1: 0.002 * t; "
    "-0.01 * t\nend\nsubsection Load path\n  set Times = 0.001, 0.1, 0.2, "
    "0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1\nend\n";
  const Run          a("cattaneo_mindlin.prm", at_once);
  const Run          b("cattaneo_mindlin.prm", normal_first);
  const Run          c("cattaneo_mindlin.prm", proportional);
  const CycleResult &ra = last_step(a), &rb = last_step(b);
  const double       F = 0.3;
  const double       h =
    contact_element(b, hertz_half_width(rb.zone.contact_force, b.parameters));
  // (a) and (b): Cattaneo's partial slip, the same stick zone
  for (const CycleResult *r : {&ra, &rb})
    {
      const double P = r->zone.contact_force;
      const double Q = r->zone.tangential_force;
      const double stick =
        hertz_half_width(P, b.parameters) * std::sqrt(1. - Q / (F * P));
      INFO("Q/(F P) = " << Q / (F * P) << ", stick half-width "
                        << r->zone.stick_half_width << " against " << stick);
      // within two contact elements at beta = 0.09, as in the cycle above
      CHECK(std::abs(r->zone.stick_half_width - stick) <= 2. * h);
      CHECK(r->solve.n_slip > 10);
    }
  CHECK(std::abs(ra.zone.stick_half_width - rb.zone.stick_half_width) <= h);
  // (c): in proportion the contact sticks where (a) and (b) slip; at beta =
  // 0.09 the normal load's growth still lets a few nodes at the edges slip
  // (Mindlin's no-slip answer needs beta = 0)
  const CycleResult &rc = last_step(c);
  INFO("slip nodes at the end: at once "
       << ra.solve.n_slip << ", normal first " << rb.solve.n_slip
       << ", in proportion " << rc.solve.n_slip);
  CHECK(rc.solve.n_slip * 5 <= rb.solve.n_slip);
  CHECK(rc.solve.n_stick > rb.solve.n_stick);
}

TEST_CASE("Unloading to zero: the shear taken back leaves locked-in "
          "tractions; the normal load taken back releases the contact",
          "[path]")
{
  // pressed (t = 1), sheared (t = 2), the shear taken back (t = 3), the
  // clamp back where it started (t = 4)
  const Run                       run("cattaneo_mindlin.prm",
                "subsection Boundary conditions\n  set Displacements = 1: "
                                      "0.002 * if(t <= 1, 0, if(t <= 2, t - 1, if(t <= 3, 3 - t, "
                                      "0))); -0.01 * if(t <= 3, min(t, 1), 4 - t)\nend\n"
                                      "subsection Load path\n  set Times = 0.5, 1, 1.5, 2, 2.5, 3, "
                                      "3.5, 4\nend\n");
  const std::vector<CycleResult> &steps = run.problem->steps();
  REQUIRE(steps.size() == 8);
  const double F  = 0.3;
  const double p0 = steps[1].zone.max_pressure;
  // t = 3: no net shear, but tractions locked in by the history; the
  // contact force of the clamp's reaction balances
  const CycleResult &unsheared = steps[5];
  INFO("t = 3: tangential force " << unsheared.zone.tangential_force
                                  << ", contact force "
                                  << unsheared.zone.contact_force);
  CHECK(unsheared.zone.tangential_force <
        1e-2 * F * unsheared.zone.contact_force);
  CHECK(unsheared.solve.n_slip > 0);
  CHECK(unsheared.step.dissipation_total > steps[3].step.dissipation_total);
  // t = 4: nothing is left but round-off
  const auto final_state = tractions(run);
  double     largest     = 0.;
  for (const auto &node : final_state)
    largest = std::max({largest, node[1], std::abs(node[2])});
  INFO("t = 4: largest l1, |l2| " << largest << " (p0 at t = 1: " << p0 << ")");
  CHECK(largest <= 1e-8 * p0);
  CHECK(steps.back().zone.contact_force <= 1e-8 * steps[1].zone.contact_force);
}

TEST_CASE("Adapt at every step: the same meshes and the same stick zones on "
          "all ranks and on one",
          "[path]")
{
  const std::string adapt =
    "subsection Boundary conditions\n  set Tractions = 1: 0; "
    "-4.315374524161804 * t\nend\nsubsection Refinement\n  set Strategy = "
    "contact\n  set Coarsen fraction = 0.1\n  set Number of cycles = 1\nend\n"
    "subsection Load path\n  set Number of steps = 3\n  set Adapt at every "
    "step = true\nend\n";
  const Run   world("hertz_friction.prm", adapt);
  const Run   alone("hertz_friction.prm", adapt, MPI_COMM_SELF);
  const auto &a = world.problem->steps(), &b = alone.problem->steps();
  REQUIRE(a.size() == 3);
  REQUIRE(b.size() == 3);
  for (unsigned int n = 0; n < 3; ++n)
    {
      INFO("step " << n + 1 << ": " << a[n].mesh.n_dofs << " DoFs");
      CHECK(a[n].mesh.n_dofs == b[n].mesh.n_dofs);
      CHECK(a[n].solve.n_stick == b[n].solve.n_stick);
      CHECK(std::abs(a[n].zone.contact_force - b[n].zone.contact_force) <=
            1e-8 * a[n].zone.contact_force);
      CHECK(a[n].zone.stick_half_width == Approx(b[n].zone.stick_half_width));
    }
  // the mesh follows the growing zone
  CHECK(a[2].mesh.n_dofs > a[0].mesh.n_dofs);
}

namespace
{
  // A 1 x 1 block, its top clamped, on a foundation that starts 0.001 below
  // it, rises by 0.002 at t = 1 (contact) and then falls away: every step
  // after t = 1.5 carries no load at all.
  const std::string lift_off =
    "subsection Geometry\n  set Type = rectangle\n"
    "  set Lower left corner = 0, 0\n  set Upper right corner = 1, 1\n"
    "  set Subdivisions = 2, 2\nend\n"
    "subsection Material\n  set Young's modulus = 1000\n"
    "  set Poisson's ratio = 0.3\nend\n"
    "subsection Boundary conditions\n  set Conditions = 2: contact, 3: "
    "fixed\nend\n"
    "subsection Foundation\n  set Point = 0, -0.001\n  set Normal = 0, 1\n"
    "end\n"
    "subsection Obstacle\n  set Displacement = 0; 0.002 * if(t <= 1, t, 2 - "
    "t)\nend\n"
    "subsection Load path\n  set Times = 1, 1.8, 2, 2.2, 2.4, 2.6\nend\n"
    "subsection Output\n  set Write vtu = false\nend\n";

  // A 0.75 x 0.43 block on the plane, Coulomb F = 0.92, its top clamped and
  // pushed down by d at t = 1, back to its start at t = 2: the last step is
  // the undeformed state, the bottom touching the plane with no force.
  std::string
  back_to_start(const double d, const std::string &iteration)
  {
    std::ostringstream depth;
    depth << std::setprecision(10) << d;
    return "subsection Geometry\n  set Type = rectangle\n"
           "  set Lower left corner = 0, 0\n"
           "  set Upper right corner = 0.750309, 0.427227\n"
           "  set Subdivisions = 7, 4\nend\n"
           "subsection Material\n  set Young's modulus = 8.37268\n"
           "  set Poisson's ratio = 0.494342\nend\n"
           "subsection Boundary conditions\n  set Conditions = 2: contact, "
           "3: fixed\n  set Displacements = 3: 0; -" +
           depth.str() +
           " * if(t <= 1, t, 2 - t)\nend\n"
           "subsection Friction\n  set Law = coulomb\n"
           "  set Coefficient = 0.920748\n  set Threshold iteration = " +
           iteration +
           "\n  set Threshold tolerance = 8.37282e-07\nend\n"
           "subsection Load path\n  set Times = 1, 2\nend\n"
           "subsection Output\n  set Write vtu = false\nend\n";
  }
} // namespace

TEST_CASE("Steps without load, however many in a row, and a Coulomb path "
          "back to the start are solved to u = 0 with no contact force",
          "[path]")
{
  {
    // five steps in a row without load after the lift-off: the relative
    // tests keep the scale of the last loaded step
    const Run                       run("", lift_off);
    const std::vector<CycleResult> &steps = run.problem->steps();
    REQUIRE(steps.size() == 6);
    CHECK(steps[0].zone.contact_force > 1.);
    for (unsigned int n = 1; n < 6; ++n)
      {
        INFO("step " << n + 1 << ": contact force "
                     << steps[n].zone.contact_force << ", ||u|| "
                     << steps[n].errors.norm_L2 << ", imbalance "
                     << steps[n].reactions.imbalance);
        // u = 0 to the Uzawa tolerance (1e-8) of the loaded step's size
        CHECK(steps[n].zone.contact_force == 0.);
        CHECK(steps[n].errors.norm_L2 <= 1e-8 * steps[0].errors.norm_L2);
      }
  }
  // the depths at which the threshold test had no scale left at the last
  // step (|g| round-off), and others; nested and merged
  for (const std::string iteration : {"nested", "merged"})
    for (const double d : {1.0e-4, 1.02e-4, 1.04e-4, 1.05e-4, 1.11e-4})
      {
        INFO(iteration << " threshold iteration, depth " << d);
        const Run                       run("", back_to_start(d, iteration));
        const std::vector<CycleResult> &steps = run.problem->steps();
        REQUIRE(steps.size() == 2);
        CHECK(steps[0].zone.contact_force > 1e-3);
        INFO("last step: contact force " << steps[1].zone.contact_force
                                         << ", ||u|| "
                                         << steps[1].errors.norm_L2);
        CHECK(std::abs(steps[1].zone.contact_force) <=
              1e-8 * steps[0].zone.contact_force);
        CHECK(steps[1].errors.norm_L2 <= 1e-8 * steps[0].errors.norm_L2);
      }
}

TEST_CASE("The predictor changes the cost of the steps, not their answer: "
          "the Cattaneo-Mindlin cycle with and without it",
          "[path]")
{
  const std::string coarse =
    "subsection Refinement\n  set Number of cycles = 1\nend\n";
  const Run                       predicted("cattaneo_mindlin.prm", coarse);
  const Run                       warm("cattaneo_mindlin.prm",
                 coarse +
                   "subsection Load path\n  set Predictor = false\nend\n");
  const std::vector<CycleResult> &a = predicted.problem->steps(),
                                 &b = warm.problem->steps();
  REQUIRE(a.size() == 16);
  REQUIRE(b.size() == 16);
  // pressed to t = 1 in four steps, sheared to t = 2, back to t = 3,
  // forward to t = 4: the second step has one state before it, and the
  // steps at t = 1.25, 2.25, 3.25 turn the path (the extrapolation would
  // overshoot); every other later step is extrapolated, at alpha = 1
  unsigned int uzawa_a = 0, uzawa_b = 0;
  for (unsigned int n = 0; n < 16; ++n)
    {
      INFO("step " << n + 1);
      const bool turn = n < 2 || n == 4 || n == 8 || n == 12;
      CHECK(b[n].solve.predictor == 0.);
      if (turn)
        CHECK(a[n].solve.predictor == 0.);
      else
        CHECK(std::abs(a[n].solve.predictor - 1.) <= 1e-10);
      // the same stick and slip zones, the same forces
      CHECK(a[n].solve.n_stick == b[n].solve.n_stick);
      CHECK(a[n].solve.n_slip == b[n].solve.n_slip);
      CHECK(std::abs(a[n].zone.contact_force - b[n].zone.contact_force) <=
            1e-7 * b[n].zone.contact_force);
      CHECK(std::abs(a[n].zone.tangential_force - b[n].zone.tangential_force) <=
            1e-7 * b[n].zone.contact_force);
      uzawa_a += a[n].solve.uzawa_steps;
      uzawa_b += b[n].solve.uzawa_steps;
    }
  // the tractions of the last step, node by node, to 1e-6 F p0
  const auto [difference, p0] = traction_difference(predicted, warm);
  const double F              = 0.3;
  INFO("largest traction difference "
       << difference << ", F p0 " << F * p0 << "; Uzawa steps " << uzawa_a
       << " with the predictor, " << uzawa_b << " without");
  CHECK(difference <= 1e-6 * F * p0);
  // it saves Uzawa steps (one in seven on the extrapolated shear steps)
  CHECK(uzawa_a < uzawa_b);
}

TEST_CASE("Adaptive step control: a step that fails at full size is cut "
          "until it converges, and the path ends where the same steps, "
          "fixed, end",
          "[path]")
{
  // the cylinder pressed to a quarter of its load, then pressed fully and
  // sheared in one step, with a Newton limit (4) that the large step
  // exceeds in its first Uzawa step and the smaller ones do not
  const std::string scene =
    "subsection Refinement\n  set Number of cycles = 1\nend\n"
    "subsection Solver\n  set Maximum Newton steps = 4\nend\n"
    "subsection Load path\n  set Times = 0.25, 2\n";
  CHECK_THROWS_AS(Run("cattaneo_mindlin.prm", scene + "end\n"),
                  dealii::ExceptionBase);

  const Run                       adaptive("cattaneo_mindlin.prm",
                     scene + "  set Step control = adaptive\nend\n");
  const std::vector<CycleResult> &a = adaptive.problem->steps();
  REQUIRE(a.size() > 2);
  // the step to t = 2 was cut, the sub-steps reach t = 2 exactly, and
  // each follows the one before
  unsigned int cuts = 0;
  for (std::size_t n = 1; n < a.size(); ++n)
    {
      INFO("step " << n + 1 << " at t = " << a[n].step.time);
      cuts += a[n].step.cuts;
      CHECK(std::abs(a[n].step.time - a[n - 1].step.time -
                     a[n].step.step_size) <= 1e-14);
      CHECK(a[n].step.listed == (n + 1 == a.size() ? 2u : 0u));
      CHECK(a[n].step.step_size <= 1.75 / 2.);
    }
  CHECK(cuts >= 1);
  CHECK(a[1].step.cuts >= 1);
  CHECK(a.back().step.time == 2.);

  // the same times as fixed steps: the same final state, to the Uzawa
  // tolerance (tractions to 1e-6 F p0, the same stick and slip nodes)
  std::ostringstream list;
  list << std::setprecision(17);
  for (const CycleResult &r : a)
    list << (&r == &a.front() ? "" : ", ") << r.step.time;
  const std::string               times = list.str();
  const Run                       fixed("cattaneo_mindlin.prm",
                  "subsection Refinement\n  set Number of cycles = 1\nend\n"
                                        "subsection Solver\n  set Maximum Newton steps = 4\nend\n"
                                        "subsection Load path\n  set Times = " +
                    times + "\nend\n");
  const std::vector<CycleResult> &b = fixed.problem->steps();
  REQUIRE(b.size() == a.size());
  CHECK(a.back().solve.n_stick == b.back().solve.n_stick);
  CHECK(a.back().solve.n_slip == b.back().solve.n_slip);
  CHECK(a.back().step.dissipation_total ==
        Approx(b.back().step.dissipation_total).epsilon(1e-6));
  const auto [difference, p0] = traction_difference(adaptive, fixed);
  INFO("times " << times << "; largest traction difference " << difference
                << ", F p0 " << 0.3 * p0);
  CHECK(difference <= 1e-6 * 0.3 * p0);
}

TEST_CASE("Nodes that touch during a step count their slip from where their "
          "gap closes: a proportional path from a small first step slips at "
          "a few nodes, and dissipates a thousandth of the static problem",
          "[path]")
{
  // the cylinder pressed and sheared in proportion (Q/P below F), from
  // t = 0.001 in steps of 0.1; Mindlin: for beta = 0 nothing slips. The
  // static problem at the same clamp position slips like Cattaneo's.
  const std::string scene =
    "subsection Refinement\n  set Number of cycles = 1\nend\n"
    "subsection Boundary conditions\n  set Displacements = 1: 0.0033 * t; "
    "-0.01 * t\nend\n";
  const Run                       proportional("cattaneo_mindlin.prm",
                         scene +
                           "subsection Load path\n  set Times = 0.001, 0.1, "
                                                 "0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1\nend\n");
  const Run                       at_once("cattaneo_mindlin.prm",
                    scene + "subsection Load path\n  set Times = 1\nend\n");
  const std::vector<CycleResult> &steps = proportional.problem->steps();
  REQUIRE(steps.size() == 11);
  unsigned int most_slip = 0;
  for (std::size_t n = 1; n < steps.size(); ++n)
    most_slip = std::max(most_slip, steps[n].solve.n_slip);
  const double static_slip       = last_step(at_once).solve.n_slip;
  const double dissipated        = steps.back().step.dissipation_total;
  const double static_dissipated = last_step(at_once).step.dissipation_total;
  INFO("most slip nodes in a later step "
       << most_slip << " (static " << static_slip << "); dissipated "
       << dissipated << " against " << static_dissipated);
  // with the slip counted from the step before's positions, 3-11 nodes
  // slip per step and the path dissipates 1/36 of the static problem
  CHECK(most_slip <= 3);
  CHECK(static_slip >= 10);
  CHECK(dissipated <= 1e-3 * static_dissipated);
}
