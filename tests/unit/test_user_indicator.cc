// A refinement indicator added from outside the library, in one file, the
// way a user adds one: 'height' ranks the cells by the height of their
// centre, and 'depth' by its opposite. On the patch test (8 x 4 cells after
// one global refinement) with a refine fraction of 1/4, the indicator alone
// decides which row of 8 cells is refined: the top row leaves the 9 contact
// nodes on the base as they were, the bottom row doubles them to 17. Both
// keep the patch test exact (the pressure 1 at every contact node, hanging
// nodes included).

#include <deal.II/base/mpi.h>

#include <dualcontact/refinement_indicator.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <regex>

#include "scene_run.h"
#include "test_tools.h"

using namespace dualcontact;
using namespace dualcontact_test;

namespace
{
  template <int dim, int sign>
  Vector<float>
  height(const IndicatorInput<dim> &input)
  {
    const auto   &triangulation = input.dof_handler.get_triangulation();
    Vector<float> eta(triangulation.n_active_cells());
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        eta[cell->active_cell_index()] =
          sign > 0 ? cell->center()[dim - 1] : 2. - cell->center()[dim - 1];
    return eta;
  }

  const bool registered_height =
    register_refinement_indicator("height",
                                  {"the height of the cell's centre.",
                                   nullptr,
                                   {},
                                   height<2, 1>,
                                   height<3, 1>});
  const bool registered_depth =
    register_refinement_indicator("depth",
                                  {"the depth of the cell's centre.",
                                   nullptr,
                                   {},
                                   height<2, -1>,
                                   height<3, -1>});

  const std::string refined = "subsection Refinement\n"
                              "  set Refine fraction = 0.25\n"
                              "  set Strategy = ";
} // namespace

TEST_CASE("A refinement indicator registered from outside the library "
          "decides which cells are refined",
          "[refinement][plugin]")
{
  // the help of <Refinement/Strategy> as one line: the file wraps it into
  // comment lines wherever the other indicators' help texts put the breaks
  const std::string file = std::regex_replace(default_parameter_file(),
                                              std::regex("\\s*\\n\\s*#\\s*"),
                                              " ");
  CHECK(file.find("'height' the height of the cell's centre.") !=
        std::string::npos);
  for (const auto &[name, contact_nodes] :
       std::vector<std::pair<std::string, std::size_t>>{{"height", 9},
                                                        {"depth", 17}})
    {
      Run run("patch.prm", refined + name + "\nend\n");
      INFO("indicator " << name);
      CHECK(run.last().mesh.n_cells == 32 - 8 + 4 * 8);
      const auto pressures = run.pressures();
      CHECK(pressures.size() == contact_nodes);
      for (const auto &[x, l1] : pressures)
        CHECK(std::abs(l1 - 1.) < 1e-6);
    }
}
