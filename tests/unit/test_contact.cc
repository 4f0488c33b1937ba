// Frictionless contact: the patch test, Hertz, semi-coercive
// scenes, independence of r, of the number of ranks and of the units.
// Every assertion is on a value that is the same on all ranks.

#include <deal.II/base/mpi.h>

#include <dualcontact/contact_problem.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>

#include "scene_run.h"
#include "test_tools.h"

using namespace dualcontact;
using namespace dualcontact_test;

namespace
{
  std::string
  solver(const std::string &entries)
  {
    return "\nsubsection Solver\n" + entries + "\nend\n";
  }

  const std::string one_cycle =
    "\nsubsection Refinement\n  set Number of cycles = 1\nend\n";

  // Hertz, prm/hertz.prm: a = 0.1, p0 = 54.945..., P = 8.6307...
  const double hertz_a  = 0.1;
  const double hertz_p0 = 54.94505494505495;
  const double hertz_P  = 2 * 4.315374524161804;
} // namespace

TEST_CASE(
  "Patch test: every nodal contact pressure equals the applied pressure",
  "[contact]")
{
  Run                  run("patch.prm", "");
  const ContactSet<2> &contact   = run.problem->contact();
  double               deviation = 0;
  for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
    deviation = std::max(deviation, std::abs(contact.l1[s] - 1.));
  deviation = Utilities::MPI::max(deviation, run.comm);

  for (const CycleResult &r : run.problem->results())
    {
      CHECK(r.solve.n_active == r.solve.n_contact_nodes);
      CHECK(std::abs(r.zone.contact_force - 2.) <= 1e-10 * 2.);
    }
  CHECK(deviation <= 1e-8);
}

TEST_CASE("Hertz: peak pressure, half-width, pressure error and total force",
          "[contact]")
{
  Run         run("hertz.prm", "");
  const auto &results = run.problem->results();
  REQUIRE(results.size() == 2);

  // the contact-zone element size on the first mesh, from
  // r = r_rel (lambda + 2 mu) / h_C (doc/theory.md §5)
  const MaterialParameters &material = run.parameters.material;
  const double              h        = run.parameters.solver.augmentation *
                   (material.lambda() + 2. * material.mu()) /
                   results[0].solve.r;
  INFO("h_C = " << h << ", peak " << results[0].zone.max_pressure
                << ", half-width " << results[0].zone.half_width << ", errors "
                << results[0].zone.pressure_error << ", "
                << results[1].zone.pressure_error);
  CHECK(h <= hertz_a / 20);
  CHECK(std::abs(results[0].zone.max_pressure - hertz_p0) <= 0.03 * hertz_p0);
  CHECK(std::abs(results[0].zone.half_width - hertz_a) <=
        1.5 * h + 0.01 * hertz_a);
  CHECK(results[0].zone.pressure_error <= 0.05);
  CHECK(results[1].zone.pressure_error < results[0].zone.pressure_error);
  for (const CycleResult &r : results)
    CHECK(std::abs(r.zone.contact_force - hertz_P) <= 1e-6 * hertz_P);
}

TEST_CASE("Semi-coercive half disc and symmetric quarter disc give the same "
          "pressures",
          "[contact]")
{
  // Nothing holds the half disc sideways but the proximal term; the quarter
  // disc has u_x = 0 on the symmetry line. Their meshes coincide on x >= 0.
  Run          half("hertz.prm", one_cycle);
  Run          quarter("hertz.prm",
              one_cycle +
                "\nsubsection Geometry\n  set Type = quarter disc\nend\n"
                         "subsection Boundary conditions\n  set Conditions = 0: "
                         "contact, 1: traction, 2: normal fixed\nend\n");
  unsigned int n_matched = 0;
  const double difference =
    max_pressure_difference(quarter.pressures(), half.pressures(), n_matched);
  INFO("matched " << n_matched << " nodes, max difference " << difference);
  CHECK(n_matched == quarter.last().solve.n_contact_nodes);
  CHECK(difference <= 1e-4 * hertz_p0);
  CHECK(std::abs(2 * quarter.last().zone.contact_force - hertz_P) <=
        1e-6 * hertz_P);
}

TEST_CASE(
  "The augmentation parameter over four decades gives the same solution",
  "[contact]")
{
  Run                reference("hertz.prm", one_cycle);
  const auto         p_reference = reference.pressures();
  std::ostringstream table;
  table << "r_rel  Uzawa  Newton  CG\n";
  for (const double r_rel : {0.1, 1., 10., 100., 1000.})
    {
      Run          run("hertz.prm",
              one_cycle + solver("  set Augmentation parameter = " +
                                 std::to_string(r_rel) +
                                 "\n  set Maximum Uzawa steps = 2000"));
      unsigned int n_matched = 0;
      const double difference =
        max_pressure_difference(run.pressures(), p_reference, n_matched);
      table << r_rel << "  " << run.last().solve.uzawa_steps << "  "
            << run.last().solve.newton_steps << "  "
            << run.last().solve.cg_iterations
            << "  (max |dl1|/p0 = " << difference / hertz_p0 << ")\n";
      INFO("r_rel = " << r_rel << ": max |l1 - l1_ref| / p0 = "
                      << difference / hertz_p0);
      CHECK(n_matched == reference.last().solve.n_contact_nodes);
      CHECK(difference <= 1e-5 * hertz_p0);
    }
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::cout << "Hertz, iteration counts over r:\n" << table.str();
}

TEST_CASE("One and several MPI ranks give the same pressures", "[contact][mpi]")
{
  Run world("hertz.prm", one_cycle);
  Run alone("hertz.prm", one_cycle, MPI_COMM_SELF);
  const auto [difference, n_matched] = compare_ranks(world, alone);
  CHECK(n_matched == world.last().solve.n_contact_nodes);
  CHECK(difference <= 1e-6 * hertz_p0);
  CHECK(Utilities::MPI::max(std::abs(world.last().zone.contact_force -
                                     alone.last().zone.contact_force),
                            MPI_COMM_WORLD) <= 1e-9 * hertz_P);
}

TEST_CASE("The same scene in N-mm-MPa and in N-m-Pa: same iterations, same "
          "dimensionless results",
          "[contact]")
{
  // prm/hertz.prm read as N-mm-MPa (R = 1 mm, E = 1000 MPa), and the same
  // scene in N-m-Pa: lengths times 1e-3, stresses times 1e6.
  Run                mm("hertz.prm", one_cycle);
  Run                m("hertz.prm",
        one_cycle +
          "\nsubsection Geometry\n  set Radius = 1e-3\n"
                         "  set Pre-refinement distance = 5e-5\nend\n"
                         "subsection Material\n  set Young's modulus = 1e9\nend\n"
                         "subsection Boundary conditions\n"
                         "  set Tractions = 1: 0; -4.315374524161804e6\nend\n"
                         "subsection Foundation\n  set Point = 0, -1e-3\nend\n"
                         "subsection Exact solution\n  set Contact pressure = "
                         "54.94505494505495e6 * sqrt(max(0, 1 - x^2 / 1e-8))\nend\n");
  const CycleResult &a = mm.last(), &b = m.last();
  CHECK(a.mesh.n_dofs == b.mesh.n_dofs);
  CHECK(a.solve.uzawa_steps == b.solve.uzawa_steps);
  CHECK(a.solve.newton_steps == b.solve.newton_steps);
  CHECK(a.solve.cg_iterations == b.solve.cg_iterations);
  CHECK(a.solve.n_active == b.solve.n_active);
  CHECK(std::abs(a.zone.max_pressure / 1e3 - b.zone.max_pressure / 1e9) <=
        1e-8 * a.zone.max_pressure / 1e3);
  CHECK(std::abs(a.zone.half_width / 1. - b.zone.half_width / 1e-3) <=
        1e-8 * a.zone.half_width);
  CHECK(std::abs(a.zone.pressure_error - b.zone.pressure_error) <= 1e-8);
  CHECK(std::abs(a.zone.contact_force / 1. - b.zone.contact_force / 1e3) <=
        1e-8 * a.zone.contact_force);
}
