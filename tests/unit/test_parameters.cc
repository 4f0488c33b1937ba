// Parameters: the default file parses back, the material constants, and every
// kind of bad input ends in an InputError with the right exit code and a
// message naming the entry.
#include <deal.II/base/mpi.h>

#include <dualcontact/input_error.h>
#include <dualcontact/parameter_reader.h>
#include <dualcontact/parameters.h>
#include <dualcontact/scene.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "test_tools.h"

using namespace dualcontact;
using dualcontact_test::catch_input_error;
using dualcontact_test::CaughtError;
using dualcontact_test::contains;

namespace
{
  CaughtError
  error_reading(const std::string &text)
  {
    return catch_input_error([&] {
      Parameters parameters;
      parameters.read_string(text);
    });
  }

  CaughtError
  error_building_scene(const std::string &text)
  {
    return catch_input_error([&] {
      Parameters parameters;
      parameters.read_string(text);
      Scene<2> scene(parameters);
    });
  }

} // namespace

TEST_CASE("The default parameter file parses back and gives the defaults",
          "[parameters]")
{
  const std::string text = default_parameter_file();
  REQUIRE(contains(text, "subsection Geometry"));
  REQUIRE(contains(text, "subsection Material"));

  Parameters parameters;
  REQUIRE_NOTHROW(parameters.read_string(text));
  CHECK(parameters.geometry.dimension == 2);
  CHECK(parameters.geometry.type == "rectangle");
  CHECK(parameters.material.youngs_modulus == 1.);
  CHECK(parameters.material.poissons_ratio == 0.3);
  CHECK(parameters.boundary.conditions.empty());
  CHECK(parameters.friction.law == "none");
  CHECK(parameters.refinement.n_cycles == 1);
  CHECK(parameters.output.directory == "output");
  CHECK(parameters.exact.displacement.empty());
}

TEST_CASE("A 3D scene states only what differs: the foundation z = 0 with "
          "normal +z, the unit cube, shapes about the origin; the listing "
          "repeats the run",
          "[parameters][3d]")
{
  // the scene that was the bad input missing_foundation_3d before the 3D
  // defaults: a cube standing on the foundation, pressed by its top
  const std::string scene = "subsection Geometry\n"
                            "  set Dimension = 3\n"
                            "end\n"
                            "subsection Boundary conditions\n"
                            "  set Conditions = 0: normal fixed, 2: normal "
                            "fixed, 4: contact, 5: traction\n"
                            "  set Tractions  = 5: 0; 0; -1\n"
                            "end\n";
  Parameters        parameters;
  REQUIRE_NOTHROW(parameters.read_string(scene));
  const auto point = [](const Parameters &p) {
    return numbers_of(p.obstacle.values, "Foundation/Point");
  };
  const auto normal = [](const Parameters &p) {
    return numbers_of(p.obstacle.values, "Foundation/Normal");
  };
  CHECK(point(parameters) == std::vector<double>{0., 0., 0.});
  CHECK(normal(parameters) == std::vector<double>{0., 0., 1.});
  CHECK(parameters.geometry.lower_left == std::vector<double>{0., 0., 0.});
  CHECK(parameters.geometry.upper_right == std::vector<double>{1., 1., 1.});
  CHECK(parameters.geometry.subdivisions == std::vector<unsigned int>{1, 1, 1});
  CHECK(parameters.geometry.center == std::vector<double>{0., 0., 0.});
  Parameters sphere;
  sphere.read_string(scene + "subsection Obstacle\n  set Type = sphere\nend\n");
  CHECK(numbers_of(sphere.obstacle.values, "Obstacle/Center") ==
        std::vector<double>{0., 0., 0.});
  // the listing holds the 3D values, and reads back to the same scene
  CHECK(contains(parameters.parameter_file, "set Normal = 0, 0, 1"));
  Parameters again;
  REQUIRE_NOTHROW(again.read_string(parameters.parameter_file));
  CHECK(normal(again) == normal(parameters));
  // what a scene gives is kept, in 2D the defaults stay 2D
  Parameters given;
  given.read_string(scene + "subsection Foundation\n  set Point = 0, 0, "
                            "-1\nend\n");
  CHECK(point(given) == std::vector<double>{0., 0., -1.});
  CHECK(normal(given) == std::vector<double>{0., 0., 1.});
  Parameters plane;
  plane.read_string("subsection Geometry\n  set Type = rectangle\nend\n");
  CHECK(normal(plane) == std::vector<double>{0., 1.});
}

TEST_CASE("An entry set twice is an error naming both lines; an overlay "
          "overrides the scene's value once",
          "[parameters][errors]")
{
  const CaughtError twice =
    error_reading("subsection Output\n set Directory = a\nend\n"
                  "subsection Output\n set Directory = b\nend\n");
  REQUIRE(twice.thrown);
  CHECK(twice.code == exit_unknown_entry);
  CHECK(contains(twice.message,
                 "<Output/Directory> is set twice, at parameters:2 and at "
                 "parameters:5"));

  Parameters parameters;
  parameters.read_string("subsection Output\n set Directory = a\nend\n",
                         "subsection Output\n set Directory = b\nend\n");
  CHECK(parameters.output.directory == "b");
  CHECK(parameters.given.at("Output/Directory") == "overlay:2");

  const CaughtError overlay_twice = catch_input_error([] {
    Parameters p;
    p.read_string("subsection Output\n set Directory = a\nend\n",
                  "subsection Output\n set Directory = b\n"
                  " set Directory = c\nend\n");
  });
  CHECK(overlay_twice.code == exit_unknown_entry);
}

TEST_CASE("A misspelt entry or subsection is named with the closest "
          "declared one",
          "[parameters][errors]")
{
  CaughtError error =
    error_reading("subsection Friction\n  set Coeficient = 0.3\nend\n");
  CHECK(error.code == exit_unknown_entry);
  CHECK(contains(error.message,
                 "<Friction/Coeficient> is not an entry of subsection "
                 "Friction; did you mean <Friction/Coefficient>?"));

  // the right name in the wrong subsection
  error = error_reading("subsection Material\n  set Radius = 2\nend\n");
  CHECK(contains(error.message,
                 "did you mean <Geometry/Radius> or <Obstacle/Radius>?"));

  error = error_reading("subsection Frictoin\nend\n");
  CHECK(error.code == exit_unknown_entry);
  CHECK(contains(error.message,
                 "<Frictoin> is not a subsection; did you mean <Friction>?"));

  // nothing close: no guess
  error = error_reading("subsection Material\n  set Colour = red\nend\n");
  CHECK(contains(error.message, "is not an entry of subsection Material ("));
}

TEST_CASE("The closest match allows about one wrong letter in four",
          "[parameters]")
{
  const std::vector<std::string> names = {"Coefficient", "Threshold", "Law"};
  CHECK(closest_match("Coeficient", names) == "Coefficient");
  CHECK(closest_match("coefficeint", names) == "Coefficient");
  CHECK(closest_match("threshhold", names) == "Threshold");
  CHECK(closest_match("Friction", names).empty());
  CHECK(closest_match("Lae", names) == "Law"); // one edit is always a typo
  CHECK(closest_match("Lbx", names).empty());
}

TEST_CASE("A pattern error says the entry, the value and what is expected "
          "in words",
          "[parameters][errors]")
{
  CaughtError error =
    error_reading("subsection Geometry\n  set Subdivisions = 0, 4\nend\n");
  CHECK(error.code == exit_invalid_value);
  CHECK(contains(error.message,
                 "Invalid value '0, 4' for <Geometry/Subdivisions>: expected "
                 "a comma-separated list of 2 or 3 whole numbers >= 1 "
                 "(parameters:2)"));
  error = error_reading("subsection Friction\n  set Law = tresca\nend\n");
  CHECK(contains(error.message,
                 "Invalid value 'tresca' for <Friction/Law>: expected one "
                 "of: coulomb, given, none"));
}

TEST_CASE("Overrides: --set changes an entry after the file, a malformed one "
          "is a usage error, an unknown one is named",
          "[parameters][errors]")
{
  const std::string scene =
    dualcontact_test::test_file("../prm/paper_block.prm");
  Parameters parameters;
  parameters.read_file(scene,
                       {"Friction/Coefficient=0.4",
                        "Material/Poisson's ratio = 0.25"});
  CHECK(parameters.friction.parameter == "0.4");
  CHECK(parameters.material.poissons_ratio == 0.25);
  CHECK(parameters.given.at("Friction/Coefficient") == "--set");
  CHECK(
    contains(parameters.parameter_file, "--set \"Friction/Coefficient=0.4\""));
  CHECK(contains(parameters.parameter_file, "set Coefficient"));

  const auto error_with = [&](const std::string &assignment) {
    return catch_input_error([&] {
      Parameters p;
      p.read_file(scene, {assignment});
    });
  };
  CHECK(error_with("Friction/Coefficient 0.4").code == exit_usage);
  CHECK(error_with("Coefficient=0.4").code == exit_usage);
  CHECK(error_with("Friction/=0.4").code == exit_usage);
  CHECK(error_with("Friction//Law=none").code == exit_usage);
  const CaughtError unknown = error_with("Friction/Coeficient=0.4");
  CHECK(unknown.code == exit_unknown_entry);
  CHECK(contains(unknown.message, "did you mean <Friction/Coefficient>?"));
  CHECK(error_with("Friction/Law=tresca").code == exit_invalid_value);
}

TEST_CASE("The parameters as read, in --print-parameters form, read back to "
          "the same parameters",
          "[parameters]")
{
  Parameters first;
  first.read_file(dualcontact_test::test_file("../prm/hertz_friction.prm"),
                  {"Friction/Coefficient=0.25",
                   "Refinement/Refine fraction=0.5"});
  Parameters second;
  second.read_string(first.parameter_file);
  CHECK(second.friction.parameter == "0.25");
  CHECK(second.geometry.pre_refinement_steps ==
        first.geometry.pre_refinement_steps);
  // the same listing, but for the header line naming the file
  const auto listing = [](const std::string &text) {
    return text.substr(text.find("# Listing of Parameters"));
  };
  CHECK(listing(second.parameter_file) == listing(first.parameter_file));
  // the listing sets every entry, but only those off their default count as
  // given: the same one warning (a refine fraction with global refinement)
  CHECK(first.ineffective_entries().size() == 1);
  CHECK(second.ineffective_entries().size() == 1);
  CHECK(second.given.size() == first.given.size());
}

TEST_CASE("Mixed-up friction entries: the law without its own entry is an "
          "error, an entry of another law a warning",
          "[parameters][errors]")
{
  const std::string contact = "subsection Boundary conditions\n"
                              "  set Conditions = 2: contact, 3: fixed\n"
                              "end\n";
  CaughtError       error =
    error_reading(contact + "subsection Friction\n  set Law = given\n"
                            "  set Coefficient = 0.3\nend\n");
  REQUIRE(error.thrown);
  CHECK(error.code == exit_inconsistent);
  CHECK(contains(
    error.message,
    "The friction law 'given' needs <Friction/Threshold>, which "
    "is not given (0 by default: no friction); "
    "<Friction/Coefficient> (parameters:6) is for the law")); // 'coulomb' (and
                                                              // others a test
                                                              // registers)
  CHECK(contains(error.message, "'coulomb'"));
  error = error_reading(contact + "subsection Friction\n  set Law = coulomb\n"
                                  "  set Threshold = 0.3\nend\n");
  CHECK(error.code == exit_inconsistent);

  Parameters parameters;
  parameters.read_string(contact + "subsection Friction\n  set Law = given\n"
                                   "  set Threshold = 0.1\n"
                                   "  set Coefficient = 0.3\n"
                                   "  set Threshold tolerance = 1e-8\nend\n");
  const std::vector<std::string> warnings = parameters.ineffective_entries();
  REQUIRE(warnings.size() == 2);
  CHECK(contains(warnings[0],
                 "<Friction/Coefficient> has no effect: the law "
                 "'given' takes <Friction/Threshold>"));
  CHECK(contains(warnings[1], "<Friction/Threshold tolerance> has no effect"));
  CHECK(contains(warnings[1], "(parameters:8)"));
}

TEST_CASE("Entries without effect are listed once each, with the reason; a "
          "scene that uses all it sets has none",
          "[parameters]")
{
  Parameters parameters;
  parameters.read_string("subsection Geometry\n"
                         "  set Radius = 2\n"
                         "  set Pre-refinement distance = 0.1\n"
                         "end\n"
                         "subsection Boundary conditions\n"
                         "  set Conditions = 2: fixed\n"
                         "end\n"
                         "subsection Foundation\n  set Point = 0, -1\nend\n"
                         "subsection Friction\n  set Coefficient = 0.3\nend\n"
                         "subsection Solver\n"
                         "  set Uzawa tolerance = 1e-9\n"
                         "  set Linear solver tolerance = 1e-12\n"
                         "end\n"
                         "subsection Refinement\n"
                         "  set Number of cycles = 2\n"
                         "  set Refine fraction = 0.2\n"
                         "end\n"
                         "subsection Exact solution\n"
                         "  set Peak pressure = 3\n"
                         "end\n");
  const std::vector<std::string> warnings = parameters.ineffective_entries();
  std::string                    all;
  for (const std::string &w : warnings)
    all += w + "\n";
  INFO(all);
  CHECK(warnings.size() == 7);
  for (const std::string entry : {"<Geometry/Radius> has no effect: "
                                  "<Geometry/Type> is 'rectangle'",
                                  "<Geometry/Pre-refinement distance>",
                                  "<Foundation/Point> has no effect: no "
                                  "boundary id has the condition 'contact'",
                                  "<Friction/Coefficient> has no effect: "
                                  "<Friction/Law> is 'none'",
                                  "<Solver/Uzawa tolerance>",
                                  "<Refinement/Refine fraction> has no "
                                  "effect: <Refinement/Strategy> is 'global'",
                                  "<Exact solution/Peak pressure>"})
    CHECK(contains(all, entry));
  CHECK_FALSE(contains(all, "Linear solver tolerance"));

  Parameters used;
  used.read_file(dualcontact_test::test_file("../prm/hertz_friction.prm"));
  CHECK(used.ineffective_entries().empty());
}

TEST_CASE("Degenerate geometry: a disc of radius 0 is an input error naming "
          "<Geometry/Radius>",
          "[parameters][errors]")
{
  for (const std::string radius : {"0", "0.0"})
    {
      const CaughtError error = error_reading(
        "subsection Geometry\n  set Type = half disc\n  set Radius = " +
        radius + "\nend\n");
      REQUIRE(error.thrown);
      CHECK(error.code == exit_invalid_value);
      CHECK(contains(error.message, "<Geometry/Radius> must be positive"));
    }
  // a rectangle does not use the radius
  CHECK_FALSE(
    error_reading("subsection Geometry\n  set Radius = 0\nend\n").thrown);
}

TEST_CASE("Lame constants follow from E and nu (plane strain formulas)",
          "[parameters]")
{
  MaterialParameters material;
  material.youngs_modulus = 1.;
  material.poissons_ratio = 0.25;
  CHECK(material.lambda() == Approx(0.4).epsilon(1e-14));
  CHECK(material.mu() == Approx(0.4).epsilon(1e-14));

  material.youngs_modulus = 210e9;
  material.poissons_ratio = 0.3;
  CHECK(material.lambda() == Approx(210e9 * 0.3 / (1.3 * 0.4)).epsilon(1e-14));
  CHECK(material.mu() == Approx(210e9 / 2.6).epsilon(1e-14));
}

TEST_CASE("Boundary conditions are parsed per id, unlisted ids are free",
          "[parameters]")
{
  Parameters parameters;
  parameters.read_string(
    "subsection Boundary conditions\n"
    "  set Conditions = 0: fixed, 1: normal fixed, 3: traction\n"
    "  set Displacements = 0: 0.1*y; 0\n"
    "  set Tractions = 3: 0; -1\n"
    "end\n");
  const BoundaryParameters &boundary = parameters.boundary;
  CHECK(boundary.condition(0) == BoundaryCondition::fixed);
  CHECK(boundary.condition(1) == BoundaryCondition::normal_fixed);
  CHECK(boundary.condition(2) == BoundaryCondition::free);
  CHECK(boundary.condition(3) == BoundaryCondition::traction);
  CHECK(boundary.displacements.at(0) == "0.1*y; 0");
  CHECK(boundary.tractions.at(3) == "0; -1");
  CHECK(boundary.ids_with(BoundaryCondition::fixed) ==
        std::vector<boundary_id>{0});
}

TEST_CASE("An unknown entry is rejected with exit_unknown_entry naming it",
          "[parameters][errors]")
{
  const CaughtError error =
    error_reading("subsection Material\n  set Shear modulus = 3\nend\n");
  REQUIRE(error.thrown);
  CHECK(error.code == exit_unknown_entry);
  CHECK(contains(error.message, "Shear modulus"));
}

TEST_CASE("A value not matching its pattern is rejected with "
          "exit_invalid_value naming the entry",
          "[parameters][errors]")
{
  const CaughtError error =
    error_reading("subsection Material\n  set Poisson's ratio = abc\nend\n");
  REQUIRE(error.thrown);
  CHECK(error.code == exit_invalid_value);
  CHECK(contains(error.message, "Poisson's ratio"));
}

TEST_CASE("Poisson's ratio 0.5 (incompressible) is rejected with "
          "exit_invalid_value in displacements, naming the mixed "
          "formulation; above 0.5 in either",
          "[parameters][errors]")
{
  const CaughtError error =
    error_reading("subsection Material\n  set Poisson's ratio = 0.5\nend\n");
  REQUIRE(error.thrown);
  CHECK(error.code == exit_invalid_value);
  CHECK(contains(error.message, "Poisson's ratio"));
  CHECK(contains(error.message, "Formulation> = mixed"));
  const CaughtError by_id = error_reading(
    "subsection Material\n  set Materials by id = 1: 100, 0.5\nend\n");
  REQUIRE(by_id.thrown);
  CHECK(by_id.code == exit_invalid_value);
  CHECK(contains(by_id.message, "Formulation> = mixed"));
  for (const std::string formulation : {"displacement", "mixed"})
    {
      const CaughtError above =
        error_reading("subsection Material\n  set Poisson's ratio = 0.5001\n"
                      "  set Formulation = " +
                      formulation + "\nend\n");
      INFO(formulation);
      REQUIRE(above.thrown);
      CHECK(above.code == exit_invalid_value);
      CHECK(contains(above.message, "Poisson's ratio"));
    }
  CHECK_FALSE(error_reading("subsection Material\n  set Poisson's ratio = "
                            "0.5\n  set Formulation = mixed\nend\n"
                            "subsection Discretization\n  set Polynomial "
                            "degree = 2\nend\n")
                .thrown);
}

TEST_CASE("The mixed formulation refuses degree 1 (Q1/Q0, P1/P0 fail the "
          "inf-sup condition), naming the degree that works",
          "[parameters][errors]")
{
  for (const std::string cells : {"quadrilateral", "simplex"})
    {
      const CaughtError error =
        error_reading("subsection Material\n  set Formulation = mixed\nend\n"
                      "subsection Geometry\n  set Cell type = " +
                      cells + "\nend\n");
      INFO(cells);
      REQUIRE(error.thrown);
      CHECK(error.code == exit_inconsistent);
      CHECK(contains(error.message, "inf-sup"));
      CHECK(contains(error.message, "degree> = 2"));
    }
}

TEST_CASE("Young's modulus 0 is rejected with exit_invalid_value",
          "[parameters][errors]")
{
  const CaughtError error =
    error_reading("subsection Material\n  set Young's modulus = 0\nend\n");
  REQUIRE(error.thrown);
  CHECK(error.code == exit_invalid_value);
  CHECK(contains(error.message, "Young's modulus"));
}

TEST_CASE("A boundary id listed twice in Conditions is rejected with "
          "exit_inconsistent",
          "[parameters][errors]")
{
  const CaughtError error =
    error_reading("subsection Boundary conditions\n"
                  "  set Conditions = 0: fixed, 2: fixed, 2: free\n"
                  "end\n");
  REQUIRE(error.thrown);
  CHECK(error.code == exit_inconsistent);
  CHECK(contains(error.message, "Conditions"));
  CHECK(contains(error.message, "2"));
}

TEST_CASE("A 'traction' id without a traction is rejected with "
          "exit_inconsistent naming the Tractions entry",
          "[parameters][errors]")
{
  const CaughtError error = error_reading("subsection Boundary conditions\n"
                                          "  set Conditions = 3: traction\n"
                                          "end\n");
  REQUIRE(error.thrown);
  CHECK(error.code == exit_inconsistent);
  CHECK(contains(error.message, "Tractions"));
}

TEST_CASE("A boundary id the geometry does not have is rejected with "
          "exit_inconsistent",
          "[parameters][errors]")
{
  // a 2D rectangle has ids 0..3, a half disc 0 and 1
  CaughtError error = error_reading("subsection Boundary conditions\n"
                                    "  set Conditions = 4: fixed\n"
                                    "end\n");
  REQUIRE(error.thrown);
  CHECK(error.code == exit_inconsistent);
  CHECK(contains(error.message, "Conditions"));

  error = error_reading("subsection Geometry\n  set Type = half disc\nend\n"
                        "subsection Boundary conditions\n"
                        "  set Conditions = 2: fixed\n"
                        "end\n");
  REQUIRE(error.thrown);
  CHECK(error.code == exit_inconsistent);
  CHECK(contains(error.message, "Conditions"));
}

TEST_CASE("A body force with the wrong number of components is rejected "
          "when the scene is built, with exit_invalid_value",
          "[parameters][errors][scene]")
{
  const std::string text =
    "subsection Loads\n  set Body force = 0; -1; 0\nend\n";
  // the parameter file alone is fine: the count is checked by the scene
  REQUIRE_FALSE(error_reading(text).thrown);

  const CaughtError error = error_building_scene(text);
  REQUIRE(error.thrown);
  CHECK(error.code == exit_invalid_value);
  CHECK(contains(error.message, "Body force"));

  // a zero body force with the wrong count is wrong as well
  const CaughtError zero =
    error_building_scene("subsection Loads\n  set Body force = 0\nend\n");
  REQUIRE(zero.thrown);
  CHECK(zero.code == exit_invalid_value);
}

TEST_CASE("A traction, a displacement or a body force with the wrong number "
          "of components is rejected whatever its values; a 3D scene's "
          "default body force has three",
          "[parameters][errors][scene][3d]")
{
  const auto error_3d = [](const std::string &text) {
    return catch_input_error([&] {
      Parameters parameters;
      parameters.read_string(text);
      Scene<3> scene(parameters);
    });
  };
  const std::string box_3d =
    "subsection Geometry\n  set Dimension = 3\nend\n"
    "subsection Boundary conditions\n  set Conditions = 4: contact, 5: "
    "traction, 1: fixed\n";
  for (const std::string tractions : {"5: 0; 0", "5: 0", "5: 0; -1"})
    {
      const CaughtError error =
        error_3d(box_3d + "  set Tractions = " + tractions + "\nend\n");
      INFO("3D, Tractions = " << tractions);
      REQUIRE(error.thrown);
      CHECK(error.code == exit_invalid_value);
      CHECK(contains(error.message, "Tractions"));
      CHECK(contains(error.message, "needs 3"));
    }
  const CaughtError displacement =
    error_3d(box_3d + "  set Tractions = 5: 0; 0; -1\n  set Displacements = "
                      "1: 0; 0\nend\n");
  REQUIRE(displacement.thrown);
  CHECK(displacement.code == exit_invalid_value);
  CHECK(contains(displacement.message, "Displacements"));
  // the same scene with three components each builds, with the default
  // body force (three zeros in 3D) and no body force assembled
  {
    Parameters parameters;
    parameters.read_string(box_3d + "  set Tractions = 5: 0; 0; 0\n  set "
                                    "Displacements = 1: 0; 0; 0\nend\n");
    Scene<3> scene(parameters);
    CHECK_FALSE(scene.effects().body_force);
    CHECK_FALSE(scene.effects().tractions);
  }
  // a 2D traction of one zero, and a 3D body force written with two zeros
  const CaughtError one_zero = error_building_scene(
    "subsection Boundary conditions\n  set Conditions = 2: contact, 3: "
    "traction\n  set Tractions = 3: 0\nend\n");
  REQUIRE(one_zero.thrown);
  CHECK(one_zero.code == exit_invalid_value);
  const CaughtError body_force = error_3d(
    box_3d + "  set Tractions = 5: 0; 0; -1\nend\nsubsection Loads\n  set "
             "Body force = 0; 0\nend\n");
  REQUIRE(body_force.thrown);
  CHECK(contains(body_force.message, "Body force"));
}

TEST_CASE("The uniform times of a load path stay finite up to the largest "
          "End time",
          "[parameters][load_path]")
{
  Parameters parameters;
  parameters.read_string("subsection Load path\n  set Number of steps = 4\n"
                         "  set End time = 1e308\nend\n");
  const std::vector<double> times = parameters.load_path.step_times();
  REQUIRE(times.size() == 4);
  for (unsigned int n = 0; n < 4; ++n)
    {
      INFO("step " << n);
      CHECK(std::isfinite(times[n]));
      CHECK(times[n] == Approx(0.25e308 * (n + 1)).epsilon(1e-15));
    }
  CHECK(times.back() == 1e308);
  Parameters largest;
  largest.read_string("subsection Load path\n  set Number of steps = 3\n"
                      "  set End time = 1.7976931348623157e308\nend\n");
  CHECK(std::isfinite(largest.load_path.step_times()[1]));
  CHECK(largest.load_path.step_times().back() ==
        std::numeric_limits<double>::max());
}

TEST_CASE("An expression that does not parse is rejected when the scene is "
          "built, with exit_invalid_value naming the entry",
          "[parameters][errors][scene]")
{
  CaughtError error = error_building_scene(
    "subsection Loads\n  set Body force = 0; -9.81*/rho\nend\n");
  REQUIRE(error.thrown);
  CHECK(error.code == exit_invalid_value);
  CHECK(contains(error.message, "Body force"));

  error = error_building_scene("subsection Boundary conditions\n"
                               "  set Conditions = 2: fixed, 3: traction\n"
                               "  set Tractions = 3: 0; -unknown_constant\n"
                               "end\n");
  REQUIRE(error.thrown);
  CHECK(error.code == exit_invalid_value);
  CHECK(contains(error.message, "Tractions"));
}

TEST_CASE("A parameter file that does not exist is rejected with "
          "exit_cannot_read_file naming it",
          "[parameters][errors]")
{
  const std::string filename = "/nonexistent/dualcontact/no_such_scene.prm";
  const CaughtError error    = catch_input_error([&] {
    Parameters parameters;
    parameters.read_file(filename);
  });
  REQUIRE(error.thrown);
  CHECK(error.code == exit_cannot_read_file);
  CHECK(contains(error.message, filename));
}

TEST_CASE("The test scene tests/prm/mms.prm reads without error",
          "[parameters]")
{
  Parameters parameters;
  REQUIRE_NOTHROW(
    parameters.read_file(dualcontact_test::test_file("prm/mms.prm")));
  CHECK(parameters.boundary.condition(3) == BoundaryCondition::traction);
  CHECK(parameters.refinement.n_cycles == 4);
}
