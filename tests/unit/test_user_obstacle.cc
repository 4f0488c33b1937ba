// An obstacle kind added from outside the library, in one file, the way a
// user adds one: a floor y = h (2D) or z = h (3D) with its own entry
// <Obstacle/Floor height>, declared, read and checked here and nowhere
// else. The library offers it in <Obstacle/Type>, lists its entry with
// the others, warns when the entry is set for another kind, runs its
// check, and solves with it: the patch test on a floor 0.01 below the
// block gives the exact uniform pressure and the displacement of the same
// patch on the plane obstacle moved down by 0.01.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <dualcontact/input_error.h>
#include <dualcontact/obstacle.h>

#include <catch2/catch.hpp>

#include <cmath>

#include "scene_run.h"
#include "test_tools.h"

using namespace dualcontact;
using namespace dualcontact_test;

namespace
{

  // ---- the kind, as a user writes it
  template <int dim>
  class Floor : public Obstacle<dim>
  {
  public:
    explicit Floor(const double height)
        : height(height)
    {}

    std::string
    name() const override
    {
      return "floor";
    }

    std::string
    description() const override
    {
      return "floor at height " + std::to_string(height);
    }

    double
    distance(const Point<dim> &x) const override
    {
      return x[dim - 1] - height;
    }

    Tensor<1, dim>
    normal(const Point<dim> &) const override
    {
      Tensor<1, dim> m;
      m[dim - 1] = 1.;
      return m;
    }

    bool
    is_plane() const override
    {
      return true;
    }

  private:
    double height;
  };

  void
  declare(EntryDeclarer &declarer)
  {
    declarer.enter_subsection("Obstacle");
    declarer.declare_entry("Floor height",
                           "0",
                           EntryPattern::number(),
                           "Floor: the height h of the floor y = h (2D), z = h "
                           "(3D) [length]; at most 0.");
    declarer.leave_subsection();
  }

  std::vector<std::string>
  entries(const unsigned int)
  {
    return {"Obstacle/Floor height"};
  }

  void
  check(const EntryValues &values, const unsigned int)
  {
    if (numbers_of(values, "Obstacle/Floor height").at(0) > 0.)
      throw InputError("The entry <Obstacle/Floor height> must be at most 0.",
                       exit_invalid_value);
  }

  template <int dim>
  std::unique_ptr<Obstacle<dim>>
  make(const EntryValues &values, const MaterialParameters &, const double)
  {
    return std::make_unique<Floor<dim>>(
      numbers_of(values, "Obstacle/Floor height").at(0));
  }

  const bool registered = register_obstacle(
    "floor",
    {"a floor y = h (2D), z = h (3D) at <Obstacle/Floor height>.",
     declare,
     entries,
     {},
     check,
     make<2>,
     make<3>});

  // ---- the patch test of prm/patch.prm on it
  const std::string floor_scene = "subsection Obstacle\n"
                                  "  set Type = floor\n"
                                  "  set Floor height = -0.01\n"
                                  "end\n";
} // namespace

TEST_CASE("An obstacle kind registered from outside the library is offered, "
          "listed, checked and warned about like the library's own",
          "[obstacle][plugin]")
{
  const std::string listing = default_parameter_file();
  CHECK(contains(listing, "'floor': a floor y = h (2D)"));
  CHECK(contains(listing, "set Floor height"));

  // its entry set for another kind has no effect, and says for which
  Parameters plane;
  plane.read_string(read_text(test_file("../prm/patch.prm")),
                    "subsection Obstacle\n  set Floor height = -1\nend\n");
  const std::vector<std::string> warnings = plane.ineffective_entries();
  REQUIRE(warnings.size() == 1);
  CHECK(contains(warnings[0],
                 "<Obstacle/Floor height> has no effect: <Obstacle/Type> is "
                 "'plane' (it is for 'floor')"));

  // its check runs where the parameters are read
  Parameters above;
  try
    {
      above.read_string(read_text(test_file("../prm/patch.prm")),
                        "subsection Obstacle\n  set Type = floor\n  set "
                        "Floor height = 0.5\nend\n");
      FAIL("a floor above the block was accepted");
    }
  catch (const InputError &error)
    {
      CHECK(error.code == exit_invalid_value);
      CHECK(contains(error.what(), "<Obstacle/Floor height> must be at most"));
    }
}

TEST_CASE("The patch test on a user's floor: the exact pressure 1 at every "
          "node, and the displacement of the plane obstacle moved the same",
          "[obstacle][plugin]")
{
  Run        on_floor("patch.prm", floor_scene);
  Run        on_plane("patch.prm",
               "subsection Foundation\n  set Point = 0, -0.01\nend\n");
  const auto floor_pressures = on_floor.pressures();
  const auto plane_pressures = on_plane.pressures();
  REQUIRE(floor_pressures.size() == plane_pressures.size());
  REQUIRE(!floor_pressures.empty());
  for (std::size_t i = 0; i < floor_pressures.size(); ++i)
    {
      CHECK(std::abs(floor_pressures[i].second - 1.) < 1e-6);
      CHECK(std::abs(floor_pressures[i].second - plane_pressures[i].second) <
            1e-12);
    }
  const auto &u_floor    = on_floor.problem->displacement();
  const auto &u_plane    = on_plane.problem->displacement();
  double      difference = 0.;
  for (const auto i : u_plane.locally_owned_elements())
    difference = std::max(difference, std::abs(u_floor[i] - u_plane[i]));
  difference         = Utilities::MPI::max(difference, on_plane.comm);
  const double u_max = max_entry(u_plane, on_plane.comm);
  INFO("largest |u| " << u_max << ", largest difference " << difference);
  CHECK(u_max > 0.01);
  CHECK(difference < 1e-12 * u_max);
}
