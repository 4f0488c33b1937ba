// A geometry kind added from outside the library, in one file, the way a
// user adds one: a strip [0, L] x [0, 1] (x [0, 1] in 3D) of
// <Geometry/Strip length> with <Geometry/Strip cells> cells along x, its
// boundary ids those of the rectangle, declared, read and checked here and
// nowhere else. The library offers it in <Geometry/Type>, lists its entries
// with the others, warns when they are set for another kind, runs its
// checks (its boundary ids against the conditions), and solves with it:
// the patch test on the strip of length 2 gives the exact uniform pressure
// and the same displacement as the rectangle of the same mesh.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <deal.II/grid/grid_generator.h>

#include <dualcontact/geometry.h>
#include <dualcontact/input_error.h>

#include <catch2/catch.hpp>

#include <cmath>

#include "scene_run.h"
#include "test_tools.h"

using namespace dualcontact;
using namespace dualcontact_test;

namespace
{
  // ---- the kind, as a user writes it
  double       strip_length = 1.;
  unsigned int strip_cells  = 1;

  template <int dim>
  class Strip : public Geometry<dim>
  {
  public:
    CellKind
    cell_kind() const override
    {
      return CellKind::quadrilateral;
    }

    double
    n_coarse_cells() const override
    {
      return strip_cells * std::pow(strip_cells / strip_length, dim - 1);
    }

    void
    create_coarse_mesh(Triangulation<dim> &triangulation) const override
    {
      std::vector<unsigned int> cells(dim, 1);
      cells[0] = strip_cells;
      for (unsigned int d = 1; d < dim; ++d)
        cells[d] =
          static_cast<unsigned int>(std::lround(strip_cells / strip_length));
      Point<dim> upper;
      for (unsigned int d = 0; d < dim; ++d)
        upper[d] = d == 0 ? strip_length : 1.;
      GridGenerator::subdivided_hyper_rectangle(
        triangulation, cells, Point<dim>(), upper, /*colorize=*/true);
    }

    Point<dim>
    center() const override
    {
      Point<dim> middle;
      for (unsigned int d = 0; d < dim; ++d)
        middle[d] = d == 0 ? 0.5 * strip_length : 0.5;
      return middle;
    }

    double
    characteristic_length() const override
    {
      return std::max(strip_length, 1.);
    }
  };

  void
  declare(EntryDeclarer &declarer)
  {
    declarer.declare_entry("Strip length",
                           "1",
                           EntryPattern::number(0.),
                           "Strip: its length L along x [length].");
    declarer.declare_entry("Strip cells",
                           "1",
                           EntryPattern::whole_number(1),
                           "Strip: its number of cells along x [-].");
  }

  void
  parse(ParameterHandler &prm, GeometryParameters &)
  {
    strip_length = prm.get_double("Strip length");
    strip_cells  = prm.get_integer("Strip cells");
  }

  void
  check(const Parameters &parameters)
  {
    if (parameters.geometry.cell_kind == CellKind::simplex)
      throw InputError("The entry <Geometry/Type> 'strip' is made of "
                       "quadrilaterals.",
                       exit_inconsistent);
  }

  template <int dim>
  std::unique_ptr<Geometry<dim>>
  make(const Parameters &, const std::function<void(double)> &)
  {
    return std::make_unique<Strip<dim>>();
  }

  const bool registered = register_geometry(
    "strip",
    {10,
     "'strip': [0, L] x [0, 1] with the rectangle's boundary ids.",
     declare,
     parse,
     {"Strip length", "Strip cells"},
     {{{"Strip length", "Strip cells"}, "'strip'"}},
     {},
     nullptr,
     nullptr,
     nullptr,
     check,
     [](const unsigned int dim) { return 2 * dim; },
     nullptr,
     make<2>,
     make<3>});

  const std::string strip_scene = "subsection Geometry\n"
                                  "  set Type = strip\n"
                                  "  set Strip length = 2\n"
                                  "  set Strip cells = 4\n"
                                  "end\n";
} // namespace

TEST_CASE("A geometry kind registered from outside the library is offered, "
          "listed, checked and warned about like the library's own",
          "[geometry][plugin]")
{
  const std::string listing = default_parameter_file();
  CHECK(contains(listing, "'strip': [0, L] x [0, 1]"));
  CHECK(contains(listing, "set Strip length"));

  // its entry set for another kind has no effect, and says for which
  Parameters rectangle;
  rectangle.read_string(read_text(test_file("../prm/patch.prm")),
                        "subsection Geometry\n  set Strip cells = 3\nend\n");
  const std::vector<std::string> warnings = rectangle.ineffective_entries();
  REQUIRE(warnings.size() == 1);
  CHECK(contains(warnings[0],
                 "<Geometry/Strip cells> has no effect: <Geometry/Type> is "
                 "'rectangle' (it is for 'strip')"));

  // the rectangle's entries have no effect on the strip
  Parameters strip;
  strip.read_string(read_text(test_file("../prm/patch.prm")), strip_scene);
  const std::vector<std::string> on_strip = strip.ineffective_entries();
  REQUIRE(!on_strip.empty());
  for (const std::string &warning : on_strip)
    CHECK(contains(warning,
                   "has no effect: <Geometry/Type> is 'strip' (it is for the "
                   "rectangle)"));

  // its check and its boundary ids run where the parameters are read
  for (const auto &[overrides, message] :
       std::vector<std::pair<std::string, std::string>>{
         {"subsection Geometry\n  set Cell type = simplex\nend\n",
          "'strip' is made of quadrilaterals"},
         {"subsection Boundary conditions\n  set Conditions = 0: normal "
          "fixed, 2: contact, 4: traction\n  set Tractions = 4: 0; -1\nend\n",
          "boundary id 4"}})
    {
      Parameters refused;
      try
        {
          refused.read_string(read_text(test_file("../prm/patch.prm")),
                              strip_scene + overrides);
          FAIL("accepted: " << overrides);
        }
      catch (const InputError &error)
        {
          CHECK(error.code == exit_inconsistent);
          CHECK(contains(error.what(), message));
        }
    }
}

TEST_CASE("The patch test on a user's strip: the exact pressure 1 at every "
          "node, and the displacement of the rectangle of the same mesh",
          "[geometry][plugin]")
{
  Run        on_strip("patch.prm", strip_scene);
  Run        on_rectangle("patch.prm", "");
  const auto strip_pressures     = on_strip.pressures();
  const auto rectangle_pressures = on_rectangle.pressures();
  REQUIRE(strip_pressures.size() == rectangle_pressures.size());
  REQUIRE(!strip_pressures.empty());
  for (std::size_t i = 0; i < strip_pressures.size(); ++i)
    {
      CHECK(std::abs(strip_pressures[i].second - 1.) < 1e-6);
      CHECK(std::abs(strip_pressures[i].second -
                     rectangle_pressures[i].second) < 1e-12);
    }
  const auto &u_strip     = on_strip.problem->displacement();
  const auto &u_rectangle = on_rectangle.problem->displacement();
  double      difference  = 0.;
  for (const auto i : u_rectangle.locally_owned_elements())
    difference = std::max(difference, std::abs(u_strip[i] - u_rectangle[i]));
  difference         = Utilities::MPI::max(difference, on_rectangle.comm);
  const double u_max = max_entry(u_rectangle, on_rectangle.comm);
  INFO("largest |u| " << u_max << ", largest difference " << difference);
  CHECK(u_max > 5e-4);
  CHECK(difference < 1e-12 * u_max);
}
