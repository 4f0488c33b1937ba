// Nested meshes, adaptive refinement and nested iteration: the
// error falls over adaptive cycles, hanging nodes on Gamma_C (3D), the
// carried multipliers, nested iteration against a cold start, adaptive
// against global refinement, ranks. Every assertion is on a value that is
// the same on all ranks.

#include <deal.II/base/mpi.h>

#include <dualcontact/contact_problem.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>

#include "scene_run.h"
#include "test_tools.h"

using namespace dualcontact;
using namespace dualcontact_test;

namespace
{
  std::string
  refinement(const std::string &entries)
  {
    return "\nsubsection Refinement\n" + entries + "\nend\n";
  }

  template <int dim>
  void
  require_contact_conditions(const SceneRun<dim> &run)
  {
    const Conditions check = check_conditions(run);
    INFO("smallest l1 " << check.smallest_l1 << ", penetration "
                        << check.penetration << ", complementarity "
                        << check.complementarity);
    CHECK(check.smallest_l1 >= 0.);
    CHECK(check.penetration <= 1e-7);
    CHECK(check.complementarity <= 1e-7);
  }

  // A ball of radius 1 (E = 1000, nu = 0.3) on the rigid plane z = -1,
  // pressed by a uniform pressure on its flat top: Hertz, a = 0.2 for the
  // load P = 4 E* a^3 / (3 R) = 11.7216 on the exact disc of radius 1,
  // p0 = 3 P / (2 pi a^2). The discrete top is a polygon, so the discrete
  // load is a little smaller; the contact force must balance that one.
  const std::string hertz_ball = R"(
subsection Geometry
  set Dimension               = 3
  set Type                    = half disc
  set Center                  = 0, 0, 0
  set Radius                  = 1
  set Pre-refinement steps    = 1
  set Pre-refinement distance = 0.15
end
subsection Material
  set Young's modulus = 1000
  set Poisson's ratio = 0.3
end
subsection Boundary conditions
  set Conditions = 0: contact, 1: traction
  set Tractions  = 1: 0; 0; -3.731104892996815
end
subsection Foundation
  set Point  = 0, 0, -1
  set Normal = 0, 0, 1
end
subsection Refinement
  set Initial global refinement = 2
  set Number of cycles          = 2
  set Strategy                  = contact
  set Refine fraction           = 0.2
end
subsection Exact solution
  set Contact pressure = 139.91643348738054 * sqrt(max(0, 1 - (x^2 + y^2) / 0.04))
  set Peak pressure    = 139.91643348738054
end
)";
} // namespace

TEST_CASE("Adaptive Hertz ('contact' indicator): the pressure error falls "
          "every cycle, the contact conditions hold at every node",
          "[refinement]")
{
  Run         run("hertz_adaptive.prm", refinement("set Number of cycles = 5"));
  const auto &results = run.problem->results();
  REQUIRE(results.size() == 5);
  for (std::size_t k = 1; k < results.size(); ++k)
    {
      INFO("cycle " << k << ": " << results[k].mesh.n_dofs << " DoFs, error "
                    << results[k].zone.pressure_error << " after "
                    << results[k - 1].zone.pressure_error);
      CHECK(results[k].zone.pressure_error <
            results[k - 1].zone.pressure_error);
      // refined where it matters: fewer than twice the DoFs per cycle
      CHECK(results[k].mesh.n_dofs < 2 * results[k - 1].mesh.n_dofs);
      CHECK(results[k].transfer.warm_start);
    }
  std::cout << "adaptive Hertz: pressure error "
            << results[0].zone.pressure_error << " (" << results[0].mesh.n_dofs
            << " DoFs) -> " << results.back().zone.pressure_error << " ("
            << results.back().mesh.n_dofs << " DoFs)" << std::endl;
  CHECK(results.back().zone.pressure_error <=
        results[0].zone.pressure_error / 5.);
  CHECK(std::abs(results.back().zone.contact_force -
                 results.back().solve.normal_load) <=
        1e-8 * results.back().solve.normal_load);
  require_contact_conditions(run);
}

TEST_CASE("3D adaptive Hertz (ball on a plane): hanging nodes on Gamma_C, "
          "the contact conditions at every node, force = load",
          "[refinement][3d]")
{
  SceneRun<3> run("", hertz_ball);
  const auto &results = run.problem->results();
  REQUIRE(results.size() == 2);
  std::cout << "3D Hertz: " << results[1].mesh.n_dofs << " DoFs, "
            << results[1].solve.n_contact_nodes << " contact nodes, "
            << results[1].solve.n_hanging_contact
            << " hanging nodes on Gamma_C, pressure error "
            << results[0].zone.pressure_error << " -> "
            << results[1].zone.pressure_error << std::endl;
  CHECK(results[1].solve.n_hanging_contact > 0);
  CHECK(results[1].zone.pressure_error < results[0].zone.pressure_error);
  CHECK(std::abs(results[1].zone.peak_pressure_error) < 0.05);
  for (const CycleResult &r : results)
    CHECK(std::abs(r.zone.contact_force - r.solve.normal_load) <=
          1e-8 * r.solve.normal_load);
  require_contact_conditions(run);
}

TEST_CASE("Carried multipliers are admissible on the refined (and coarsened) "
          "mesh: l1 >= 0, |l2| <= g",
          "[refinement][friction]")
{
  Run         run("hertz_friction.prm",
          refinement("set Number of cycles = 3\n"
                             "set Strategy = contact\n"
                             "set Coarsen fraction = 0.05"));
  const auto &results = run.problem->results();
  REQUIRE(results.size() == 3);
  for (std::size_t k = 1; k < results.size(); ++k)
    {
      const CycleResult &r = results[k];
      INFO("cycle " << k << ": smallest carried l1 "
                    << r.transfer.carried_min_l1
                    << ", largest carried |l2| - g "
                    << r.transfer.carried_max_excess);
      CHECK(r.transfer.warm_start);
      CHECK(r.transfer.carried_min_l1 >= -1e-14);
      CHECK(r.transfer.carried_max_excess <= 1e-12);
      // slip nodes were carried with |l2| = g: the bound is attained
      CHECK(r.transfer.carried_max_excess >= -1e-6);
      CHECK(r.solve.n_slip > 0);
    }
}

TEST_CASE("Nested iteration reaches the cold start's solution on the same "
          "mesh in fewer Uzawa and Newton steps",
          "[refinement][friction]")
{
  Run         run("hertz_friction.prm",
          refinement("set Number of cycles = 3\n"
                             "set Strategy = contact\n"
                             "set Compare with cold start = true"));
  const auto &results = run.problem->results();
  REQUIRE(results.size() == 3);
  for (std::size_t k = 1; k < results.size(); ++k)
    {
      const CycleResult &r = results[k];
      std::cout << "cycle " << k << ": Uzawa " << r.solve.uzawa_steps << " vs "
                << r.cold.uzawa_steps << " cold, Newton "
                << r.solve.newton_steps << " vs " << r.cold.newton_steps
                << ", difference " << r.cold.difference_v << " (v), "
                << r.cold.difference_l1 << " (l1)" << std::endl;
      CHECK(r.transfer.warm_start);
      CHECK(r.cold.difference_v <= 1e-6);
      CHECK(r.cold.difference_l1 <= 1e-6);
      CHECK(r.solve.uzawa_steps < r.cold.uzawa_steps);
      CHECK(r.solve.newton_steps < r.cold.newton_steps);
    }
}

TEST_CASE("Adaptive refinement ('contact') reaches the pressure error of the "
          "finest global mesh with fewer DoFs",
          "[refinement]")
{
  Run global("hertz_adaptive.prm",
             refinement("set Number of cycles = 4\nset Strategy = global"));
  Run adaptive("hertz_adaptive.prm", refinement("set Number of cycles = 5"));
  const CycleResult &finest  = global.last();
  const CycleResult *reached = nullptr;
  for (const CycleResult &r : adaptive.problem->results())
    if (r.zone.pressure_error <= finest.zone.pressure_error)
      {
        reached = &r;
        break;
      }
  REQUIRE(reached != nullptr);
  std::cout << "global: " << finest.zone.pressure_error << " with "
            << finest.mesh.n_dofs
            << " DoFs; contact: " << reached->zone.pressure_error << " with "
            << reached->mesh.n_dofs << " DoFs (cycle " << reached->mesh.cycle
            << ")" << std::endl;
  CHECK(reached->mesh.n_dofs < finest.mesh.n_dofs / 2);
}

TEST_CASE("Adaptive refinement: one and several MPI ranks give the same "
          "meshes and pressures, at degree 1, 2 and 3",
          "[refinement][mpi]")
{
  // contact refinement leaves hanging nodes next to Gamma_C, and nested
  // iteration carries v and the multipliers from mesh to mesh
  const unsigned int degree = GENERATE(1u, 2u, 3u);
  INFO("degree " << degree);
  const std::string three =
    refinement("set Number of cycles = 3") +
    "subsection Discretization\n  set Polynomial degree = " +
    std::to_string(degree) + "\nend\n";
  Run world("hertz_adaptive.prm", three);
  Run alone("hertz_adaptive.prm", three, MPI_COMM_SELF);
  CHECK(Utilities::MPI::max(world.last().mesh.n_dofs, MPI_COMM_WORLD) ==
        Utilities::MPI::min(alone.last().mesh.n_dofs, MPI_COMM_WORLD));
  const auto [difference, n_matched] = compare_ranks(world, alone);
  CHECK(n_matched == world.last().solve.n_contact_nodes);
  CHECK(difference <= 1e-6 * 27.47252747252748);
}
