// The times of a load path's later steps (step_control.h): fixed control
// takes the listed times one by one; adaptive control halves a step that
// failed, doubles it after two steps that converged, never spans more than
// a listed interval, reaches every listed time exactly and stops cutting at
// the minimum step.

#include <dualcontact/step_control.h>

#include <catch2/catch.hpp>

#include <vector>

using namespace dualcontact;

namespace
{
  LoadPathParameters
  path(const bool adaptive, const double minimum_step = 0.)
  {
    LoadPathParameters parameters;
    parameters.adaptive_steps = adaptive;
    parameters.minimum_step   = minimum_step;
    return parameters;
  }
} // namespace

TEST_CASE("Fixed step control takes the listed times one by one and cuts "
          "nothing",
          "[functions][step control]")
{
  StepControl control({0.25, 1., 3.}, path(false));
  REQUIRE(!control.finished());
  CHECK(control.next_time() == 1.);
  CHECK(control.next_listed() == 2);
  CHECK(control.next_step_size() == 0.75);
  CHECK(!control.cut());
  CHECK(control.next_time() == 1.);
  control.accept();
  CHECK(control.next_time() == 3.);
  CHECK(control.next_listed() == 3);
  control.accept();
  CHECK(control.finished());
}

TEST_CASE("Adaptive step control halves a failed step, grows after two "
          "converged ones, and reaches the listed times exactly",
          "[functions][step control]")
{
  StepControl control({0.5, 1.5, 2.5}, path(true));
  CHECK(control.minimum_step() == 1. / 1024.);
  // the step to 1.5 fails twice: 1.0 -> 0.5 -> 0.25
  REQUIRE(control.cut());
  CHECK(control.next_time() == 1.);
  CHECK(control.next_listed() == 0);
  REQUIRE(control.cut());
  CHECK(control.next_time() == 0.75);
  CHECK(control.cuts() == 2);
  std::vector<double> reached;
  std::vector<bool>   listed;
  while (!control.finished())
    {
      reached.push_back(control.next_time());
      listed.push_back(control.next_listed() > 0);
      control.accept();
      CHECK(control.cuts() == 0);
    }
  // 0.75, 1 (two converged: 0.5), 1.5 (listed), then 2 and 2.5 at 0.5
  // (two more converged: the whole listed step again, for the next path)
  const std::vector<double> expected = {0.75, 1., 1.5, 2., 2.5};
  CHECK(reached == expected);
  CHECK(listed == std::vector<bool>{false, false, true, false, true});
}

TEST_CASE("Adaptive step control never passes a listed time and halves the "
          "rest of an interval that failed",
          "[functions][step control]")
{
  StepControl control({0., 1., 2.}, path(true));
  for (unsigned int i = 0; i < 3; ++i)
    REQUIRE(control.cut()); // 0.125
  control.accept();         // t = 0.125
  control.accept();         // t = 0.25, two converged: 0.25
  control.accept();         // t = 0.5
  control.accept();         // t = 0.75, two converged: 0.5
  // 0.75 + 0.5 would pass 1: the step ends at 1
  CHECK(control.next_time() == 1.);
  CHECK(control.next_listed() == 2);
  CHECK(control.next_step_size() == 0.25);
  // that rest fails: the retry is half of it, not the 0.25 again
  REQUIRE(control.cut());
  CHECK(control.next_step_size() == 0.125);
  CHECK(control.next_time() == 0.875);
}

TEST_CASE("Adaptive step control stops cutting at the minimum step",
          "[functions][step control]")
{
  StepControl control({0., 1.}, path(true, 0.2));
  CHECK(control.minimum_step() == 0.2);
  REQUIRE(control.cut()); // 0.5
  REQUIRE(control.cut()); // 0.25
  CHECK(!control.cut());  // 0.125 < 0.2
  CHECK(control.next_step_size() == 0.25);
}
