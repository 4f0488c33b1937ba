// When a loop does not converge, its message names the loop, its last
// changes, and the likely causes, most likely first.

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <dualcontact/contact_problem.h>

#include <catch2/catch.hpp>

#include <sstream>
#include <string>

#include "scene_run.h"

using namespace dualcontact;
using namespace dualcontact_test;

namespace
{
  // The message of the solver failure a scene ends with ("" if none).
  std::string
  failure(const std::string &scene, const std::string &overrides)
  {
    try
      {
        const Run run(scene, overrides);
      }
    catch (const ExceptionBase &exc)
      {
        std::ostringstream text;
        exc.print_info(text);
        return text.str();
      }
    return "";
  }

  // Where `part` starts in `text` (npos if absent).
  std::size_t
  at(const std::string &text, const std::string &part)
  {
    return text.find(part);
  }
} // namespace

TEST_CASE("A slowly converging Uzawa iteration names its last changes and "
          "says how many more steps it needs",
          "[robustness][messages]")
{
  // r_rel = 0.01: about 260 Uzawa steps on paper_block (doc/theory.md §5)
  const std::string message = failure("paper_block.prm",
                                      "subsection Solver\n"
                                      "  set Augmentation parameter = 0.01\n"
                                      "  set Maximum Uzawa steps = 20\n"
                                      "end\n"
                                      "subsection Refinement\n"
                                      "  set Number of cycles = 1\n"
                                      "end\n");
  INFO(message);
  CHECK(at(message,
           "The Uzawa iteration (loop 2) did not converge in 20 "
           "steps (<Solver/Maximum Uzawa steps>)") != std::string::npos);
  CHECK(at(message, "d(l1) ") != std::string::npos);
  CHECK(at(message, "d(l2) ") != std::string::npos);
  CHECK(at(message, "contraction rate ") != std::string::npos);
  // the first cause: slow but steady, with an estimate of the steps left
  CHECK(at(message, "(1) slow but steady convergence, about ") !=
        std::string::npos);
  CHECK(at(message,
           "<Solver/Augmentation parameter> (a larger r contracts "
           "faster)") != std::string::npos);
  // the violation falls steadily: not "the contact condition cannot be met"
  CHECK(at(message, "cannot be met") == std::string::npos);
}

TEST_CASE("CG failing on a nearly incompressible material names the material "
          "first",
          "[robustness][messages]")
{
  const std::string message = failure("hertz.prm",
                                      "subsection Material\n"
                                      "  set Poisson's ratio = 0.4999999\n"
                                      "end\n"
                                      "subsection Solver\n"
                                      "  set Maximum linear iterations = 30\n"
                                      "end\n"
                                      "subsection Refinement\n"
                                      "  set Number of cycles = 1\n"
                                      "end\n");
  INFO(message);
  CHECK(at(message, "CG did not converge in 30 iterations") !=
        std::string::npos);
  CHECK(at(message,
           "(1) a nearly incompressible material (<Material/"
           "Poisson's ratio> = 0.4999999") != std::string::npos);
  CHECK(at(message, "(3) too few iterations allowed") != std::string::npos);

  // at nu = 0.3 the material is not suspected
  const std::string ordinary = failure("hertz.prm",
                                       "subsection Solver\n"
                                       "  set Maximum linear iterations = 2\n"
                                       "end\n"
                                       "subsection Refinement\n"
                                       "  set Number of cycles = 1\n"
                                       "end\n");
  INFO(ordinary);
  CHECK(at(ordinary, "CG did not converge in 2 iterations") !=
        std::string::npos);
  CHECK(at(ordinary, "incompressible") == std::string::npos);
}

TEST_CASE("A threshold iteration that runs out of steps names loop 1, its "
          "last change of g, and entries that exist",
          "[robustness][messages]")
{
  const std::string message = failure("hertz_friction.prm",
                                      "subsection Friction\n"
                                      "  set Threshold iteration = nested\n"
                                      "  set Maximum threshold steps = 1\n"
                                      "end\n"
                                      "subsection Refinement\n"
                                      "  set Number of cycles = 1\n"
                                      "end\n");
  INFO(message);
  CHECK(at(message,
           "The threshold iteration (loop 1) did not converge in 1 "
           "steps (<Friction/Maximum threshold steps>)") != std::string::npos);
  CHECK(at(message, "last relative change of g was ") != std::string::npos);
  // the other strategy by the name of its entry
  CHECK(at(message, "<Friction/Threshold iteration> = merged") !=
        std::string::npos);
  CHECK(at(message, "<Friction/Strategy>") == std::string::npos);
}
