// Rigid obstacles beyond the plane, against closed-form answers: a cylinder
// pressed into a block by force and by depth (Hertz, plane strain), with
// Coulomb friction, a flat punch given by its signed distance (Sadowsky),
// and a sphere in 3D (Hertz). Every assertion is on a value that is the same
// on all ranks, so the test runs on 1 and 2 ranks alike.

#include <deal.II/base/mpi.h>

#include <dualcontact/contact_problem.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "scene_run.h"
#include "test_tools.h"

using namespace dualcontact;
using namespace dualcontact_test;

namespace
{
  const double E_star = 1000. / (1. - 0.3 * 0.3);

  /** Hertz, plane strain: the half-width and peak pressure for a force P. */
  std::pair<double, double>
  hertz_2d(const double P, const double R)
  {
    const double a = std::sqrt(4. * P * R / (numbers::PI * E_star));
    return {a, 2. * P / (numbers::PI * a)};
  }

  /** The force on the obstacle (the negative of the zone's resultant). */
  template <int dim>
  Tensor<1, dim>
  obstacle_force(const SceneRun<dim> &run)
  {
    Tensor<1, dim> f;
    for (unsigned int c = 0; c < dim; ++c)
      f[c] = -run.last().zone.resultant[c];
    return f;
  }
} // namespace

TEST_CASE("A rigid cylinder pressed into a block by force: Hertz's a and p0 "
          "within 1 %, the force on the obstacle equal to the load",
          "[obstacle][hertz]")
{
  Run          run("indenter_cylinder.prm", "");
  const auto  &zone = run.last().zone;
  const double P    = 8. * 0.5394218155202255; // the half model's load
  // the half model's zone [0, a] is measured as mirrored across x = 0
  const double a                 = zone.edge_half_width;
  const auto [a_exact, p0_exact] = hertz_2d(2. * P, 1.);
  INFO("a " << a << " (Hertz " << a_exact << "), p0 " << zone.max_pressure
            << " (Hertz " << p0_exact << ")");
  CHECK(std::abs(a / a_exact - 1.) < 0.01);
  CHECK(std::abs(zone.max_pressure / p0_exact - 1.) < 0.01);
  CHECK(zone.pressure_error < 0.015); // L2 on Gamma_C: 1.2 % measured
  CHECK(obstacle_force(run)[1] == Approx(P).epsilon(1e-9));
  CHECK(run.last().reactions.imbalance < 1e-8);
  // the contact conditions hold at every node
  const Conditions c = check_conditions(run);
  CHECK(c.smallest_l1 >= 0.);
  CHECK(c.penetration < 1e-7);
}

TEST_CASE("A rigid cylinder pressed in by a prescribed depth: the force on "
          "the obstacle balances the reaction, and a and p0 are Hertz's for "
          "that force within 1 %",
          "[obstacle][hertz]")
{
  Run          run("indenter_cylinder_depth.prm", "");
  const auto  &zone = run.last().zone;
  const double P    = 2. * obstacle_force(run)[1];
  REQUIRE(P > 0.);
  const auto &bottom = run.last().reactions.on_id.at(2);
  INFO("P " << P << ", bottom reaction " << bottom[1]);
  CHECK(bottom[1] == Approx(P / 2.).epsilon(1e-8)); // pushes the body up
  CHECK(run.last().reactions.imbalance < 1e-8);
  const auto [a_exact, p0_exact] = hertz_2d(P, 1.);
  const double a                 = zone.edge_half_width; // mirrored
  INFO("a " << a << " (Hertz " << a_exact << "), p0 " << zone.max_pressure
            << " (Hertz " << p0_exact << ")");
  CHECK(std::abs(a / a_exact - 1.) < 0.01);
  CHECK(std::abs(zone.max_pressure / p0_exact - 1.) < 0.01);
  // deeper, harder: twice the depth needs more than the force, less than
  // twice... the force grows with the depth
  Run deeper("indenter_cylinder_depth.prm",
             "subsection Obstacle\n  set Displacement = 0, -0.04\nend\n"
             "subsection Refinement\n  set Number of cycles = 1\nend\n");
  CHECK(2. * obstacle_force(deeper)[1] > 1.5 * P);
}

TEST_CASE("A rigid cylinder with Coulomb friction: the friction law at every "
          "node, the load balanced, and friction raising p0 and narrowing "
          "the zone as the coupling at nu = 0.3 makes it",
          "[obstacle][friction]")
{
  Run                  run("indenter_cylinder.prm",
          "subsection Friction\n  set Law = coulomb\n  set Coefficient = "
                           "0.3\nend\n");
  const ContactSet<2> &c      = run.problem->contact();
  double               excess = 0., g_max = 0.;
  unsigned int         slip = 0;
  for (unsigned int s = 0; s < c.n_local_nodes(); ++s)
    {
      excess = std::max(excess, c.l2[s].norm() - 0.3 * c.l1[s]);
      g_max  = std::max(g_max, c.threshold[s]);
      slip += c.status(s) == 2;
    }
  excess = Utilities::MPI::max(excess, MPI_COMM_WORLD);
  g_max  = Utilities::MPI::max(g_max, MPI_COMM_WORLD);
  CHECK(excess <= 1e-6 * g_max);
  CHECK(Utilities::MPI::sum(slip, MPI_COMM_WORLD) > 0);
  const double P = 8. * 0.5394218155202255;
  CHECK(obstacle_force(run)[1] == Approx(P).epsilon(1e-9));
  CHECK(run.last().reactions.imbalance < 1e-8);
  // At nu = 0.3 friction couples the normal and tangential problems
  // (Dundurs' beta = (1 - 2 nu) / (2 (1 - nu)) = 0.29): the stuck centre
  // stops the surface from sliding inward, the zone narrows and the peak
  // rises, so Hertz is not the answer here. The ratios to the frictionless
  // run depend on beta and F only (Spence 1975): 2.5 % and 7 % for the
  // elastic cylinder on a rigid plane of prm/hertz_friction.prm, the same
  // beta (doc/theory.md §9, §10).
  Run          frictionless("indenter_cylinder.prm", "");
  const double a_ratio =
    run.last().zone.edge_half_width / frictionless.last().zone.edge_half_width;
  const double p0_ratio =
    run.last().zone.max_pressure / frictionless.last().zone.max_pressure;
  INFO("a / a_frictionless " << a_ratio << ", p0 / p0_frictionless "
                             << p0_ratio);
  CHECK(a_ratio > 0.965);
  CHECK(a_ratio < 0.99);
  CHECK(p0_ratio > 1.05);
  CHECK(p0_ratio < 1.10);
}

TEST_CASE("A rigid flat punch given by its signed distance: the pressure "
          "P / (pi sqrt(b^2 - x^2)) away from the edges, the total force "
          "exact",
          "[obstacle][punch]")
{
  Run          run("flat_punch.prm", "");
  const double P = 1., b = 0.251;
  CHECK(obstacle_force(run)[1] == Approx(P / 2.).epsilon(1e-9));
  CHECK(std::abs(obstacle_force(run)[0]) < 1e-9);
  double       worst = 0.;
  unsigned int n     = 0;
  // the position along the tangent, which may point either way
  for (const auto &[x, l1] : run.pressures())
    if (std::abs(x) < 0.8 * b)
      {
        const double exact = P / (numbers::PI * std::sqrt(b * b - x * x));
        worst              = std::max(worst, std::abs(l1 / exact - 1.));
        ++n;
      }
  INFO(n << " nodes with |x| < 0.8 b, largest relative error " << worst);
  CHECK(n > 50);
  CHECK(worst < 0.02);
}

TEST_CASE("A flat punch at degrees 1, 2 and 3: the nodes beside its corners "
          "take the body's normal, so the force on it is vertical and equal "
          "to the load on every mesh",
          "[obstacle][punch][degree]")
{
  // The nodes of the free surface beside the punch have the punch's corner
  // as their nearest obstacle point. With the direction from the corner as
  // their normal they would meet the punch's side: the surface beside a
  // pressed punch moves inward by (1 - 2 nu)(1 + nu) P / (2 E) = 2.6e-4, and
  // at degree 3 a Gauss-Lobatto node lies closer than that to the corner.
  for (const unsigned int degree : {1u, 2u, 3u})
    {
      Run run("flat_punch.prm",
              "subsection Discretization\n  set Polynomial degree = " +
                std::to_string(degree) + "\nend\n");
      REQUIRE(run.problem->results().size() == 2);
      for (const CycleResult &cycle : run.problem->results())
        {
          INFO("degree " << degree << ", cycle " << cycle.mesh.cycle << ", "
                         << cycle.mesh.n_dofs << " DoFs: contact force "
                         << cycle.zone.contact_force << ", resultant ("
                         << cycle.zone.resultant[0] << ", "
                         << cycle.zone.resultant[1] << ")");
          CHECK(cycle.zone.contact_force == Approx(0.5).epsilon(1e-9));
          CHECK(-cycle.zone.resultant[1] == Approx(0.5).epsilon(1e-9));
          CHECK(std::abs(cycle.zone.resultant[0]) < 1e-9);
        }
      CHECK(run.problem->contact().n_corner_nodes() > 0);
    }
}

TEST_CASE("A rigid sphere pressed into a block (3D): Hertz's p0 within 1 % "
          "on the finest mesh, a within one contact cell, the force exact",
          "[obstacle][hertz][3d]")
{
  SceneRun<3>  run("indenter_sphere_3d.prm", "");
  const double P  = 4. * 4. * 0.09157509157509158; // the whole sphere
  const double a  = std::cbrt(3. * P * 1. / (4. * E_star));
  const double p0 = 3. * P / (2. * numbers::PI * a * a);
  CHECK(obstacle_force(run)[2] == Approx(P / 4.).epsilon(1e-9));
  INFO("p0 " << run.last().zone.max_pressure << " (Hertz " << p0 << ")");
  CHECK(std::abs(run.last().zone.max_pressure / p0 - 1.) < 0.01);
  CHECK(run.last().zone.pressure_error < 0.025); // L2 on Gamma_C: 1.8 %
  // the contact zone's radius, along the symmetry lines y = 0 and x = 0
  // (where the nodes lie on a line, one cell apart): between the farthest
  // node in contact and the nearest one out of it
  const ContactSet<3> &c       = run.problem->contact();
  double               inside  = 0.;
  double               outside = std::numeric_limits<double>::max();
  for (unsigned int s = 0; s < c.n_local_nodes(); ++s)
    {
      const Point<3> &x = c.nodes[s].position;
      if (std::min(std::abs(x[0]), std::abs(x[1])) > 1e-12)
        continue;
      const double r = std::hypot(x[0], x[1]);
      if (c.l1[s] > 0.)
        inside = std::max(inside, r);
      else
        outside = std::min(outside, r);
    }
  inside  = Utilities::MPI::max(inside, MPI_COMM_WORLD);
  outside = Utilities::MPI::min(outside, MPI_COMM_WORLD);
  INFO("a " << a << ", in contact up to r = " << inside
            << ", first free node at r = " << outside);
  CHECK(inside <= a + 1e-12 + (outside - inside));
  CHECK(outside >= a - (outside - inside));
  // the radius the code reports: the quarter's lines mirrored across both
  // symmetry planes (-0.51 % measured)
  INFO("reported radius " << run.last().zone.edge_half_width);
  CHECK(run.last().zone.mirrored == 2);
  CHECK(std::abs(run.last().zone.edge_half_width - a) <= outside - inside);
}
