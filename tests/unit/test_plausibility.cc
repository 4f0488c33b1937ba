// No silent wrong physics (doc/theory.md §8): a scene whose equations have a
// solution that is not physical stops or warns, and the shipped scenes do
// neither.

#include <deal.II/base/mpi.h>

#include <dualcontact/contact_problem.h>
#include <dualcontact/input_error.h>

#include <catch2/catch.hpp>

#include <string>

#include "scene_run.h"

using namespace dualcontact;
using namespace dualcontact_test;

namespace
{
  // A 2 x 1 block on 8 x 4 cells (E = 1000) pressed onto y = 0 by its top,
  // with the foundation and the conditions given.
  std::string
  block(const std::string &conditions,
        const std::string &foundation_point,
        const std::string &foundation_normal)
  {
    return "subsection Geometry\n"
           "  set Type = rectangle\n"
           "  set Upper right corner = 2, 1\n"
           "  set Subdivisions = 8, 4\n"
           "end\n"
           "subsection Material\n"
           "  set Young's modulus = 1000\n"
           "end\n"
           "subsection Boundary conditions\n"
           "  set Conditions = " +
           conditions +
           "\n"
           "  set Tractions = 3: 0; -1\n"
           "end\n"
           "subsection Foundation\n"
           "  set Point = " +
           foundation_point + "\n  set Normal = " + foundation_normal +
           "\nend\n"
           "subsection Refinement\n"
           "  set Number of cycles = 1\n"
           "end\n";
  }

  // The exit status of a scene that should fail (0 if it ran).
  int
  exit_status(const std::string &scene)
  {
    try
      {
        const Run run("", scene);
      }
    catch (const InputError &error)
      {
        return error.code;
      }
    return 0;
  }
} // namespace

TEST_CASE("A reversed foundation normal and a body that starts inside the "
          "foundation are input errors",
          "[plausibility]")
{
  CHECK(exit_status(block("2: contact, 3: traction", "0, 0", "0, -1")) ==
        exit_inconsistent);
  CHECK(exit_status(block("2: contact, 3: traction", "0, 0.1", "0, 1")) ==
        exit_inconsistent);
  // on the plane is outside: the reference scene runs
  CHECK(exit_status(block("2: contact, 3: traction", "0, 0", "0, 1")) == 0);
}

TEST_CASE("A boundary without the contact condition that passes through the "
          "foundation stops the run",
          "[plausibility]")
{
  // the contact condition on the sides (ids 0, 1) and the top pushed down:
  // the free bottom (id 2) goes through the foundation y = -1e-3 below it
  const std::string scene =
    block("0: contact, 1: contact, 3: traction", "0, -0.001", "0, 1");
  CHECK(exit_status(scene) == exit_inconsistent);
}

TEST_CASE("At degree 2 and 3 the support points between the vertices are "
          "checked too",
          "[plausibility][degree]")
{
  // One cell, 2 x 1, held at its two bottom corners (the sides have the
  // contact condition, and their lowest points touch y = 0): pressed down
  // by its top it bends, and its free bottom sags through the foundation
  // between the corners, by 4.9e-3 at degree 2 and 4.6e-3 at degree 3. At
  // degree 1 that face is the straight line between the corners and does
  // not cross.
  std::string scene =
    block("0: contact, 1: contact, 3: traction", "0, 0", "0, 1");
  scene.replace(scene.find("Subdivisions = 8, 4"),
                std::string("Subdivisions = 8, 4").size(),
                "Subdivisions = 1, 1");
  CHECK(exit_status(scene) == 0);
  for (const unsigned int k : {2u, 3u})
    CHECK(exit_status(scene +
                      "subsection Discretization\n  set Polynomial degree = " +
                      std::to_string(k) + "\nend\n") == exit_inconsistent);
}

TEST_CASE("A foundation far from the body gives a rigid shift, warned about",
          "[plausibility]")
{
  // only the contact holds the block: it moves 10 down to reach y = -10
  const Run run(
    "", block("0: normal fixed, 2: contact, 3: traction", "0, -10", "0, 1"));
  const PositionRecord &p = run.last().position;
  CHECK(std::abs(p.max_displacement - 10.) <= 0.1);
  CHECK(p.min_initial_gap == Approx(10.));
  REQUIRE(p.warnings.size() == 1);
  CHECK(p.warnings[0].find("500 % of the body's size 2") != std::string::npos);
  CHECK(p.warnings[0].find("starts 10 from the obstacle") != std::string::npos);
}

TEST_CASE("The shipped scenes pass the plausibility checks, at degree 1 "
          "and 2",
          "[plausibility]")
{
  const unsigned int k = GENERATE(1u, 2u);
  for (const std::string scene :
       {"hertz.prm", "paper_block.prm", "patch.prm", "sliding_block.prm"})
    {
      INFO(scene << " at degree " << k);
      const Run             run(scene,
                    "subsection Refinement\n"
                                "  set Number of cycles = 1\n"
                                "end\n"
                                "subsection Discretization\n"
                                "  set Polynomial degree = " +
                      std::to_string(k) + "\nend\n");
      const PositionRecord &p = run.last().position;
      CHECK(p.warnings.empty());
      CHECK(p.penetration <= 1e-10);
      CHECK(p.min_initial_gap >= 0.);
    }
}
