// Parameters: the default file parses back, the material constants, and every
// kind of bad input ends in an InputError with the right exit code and a
// message naming the entry.
#include <deal.II/base/mpi.h>

#include <dualcontact/input_error.h>
#include <dualcontact/parameters.h>
#include <dualcontact/scene.h>

#include <catch2/catch.hpp>

#include "test_tools.h"

using namespace dualcontact;
using dualcontact_test::catch_input_error;
using dualcontact_test::CaughtError;

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

  bool
  contains(const std::string &text, const std::string &part)
  {
    return text.find(part) != std::string::npos;
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
  CHECK(parameters.geometry.type == GeometryType::rectangle);
  CHECK(parameters.material.youngs_modulus == 1.);
  CHECK(parameters.material.poissons_ratio == 0.3);
  CHECK(parameters.boundary.conditions.empty());
  CHECK(parameters.friction.law == "none");
  CHECK(parameters.refinement.n_cycles == 1);
  CHECK(parameters.output.directory == "output");
  CHECK(parameters.exact.displacement.empty());
}

TEST_CASE("Later 'set' lines override earlier ones", "[parameters]")
{
  Parameters parameters;
  parameters.read_string("subsection Output\n set Directory = a\nend\n"
                         "subsection Output\n set Directory = b\nend\n");
  REQUIRE(parameters.output.directory == "b");
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
          "exit_invalid_value",
          "[parameters][errors]")
{
  const CaughtError error =
    error_reading("subsection Material\n  set Poisson's ratio = 0.5\nend\n");
  REQUIRE(error.thrown);
  CHECK(error.code == exit_invalid_value);
  CHECK(contains(error.message, "Poisson's ratio"));
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
