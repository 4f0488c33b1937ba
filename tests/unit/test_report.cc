// The screen log at each <Output/Verbosity>, on a 2D friction scene
// (prm/paper_block.prm, two cycles) and a 3D one
// (tests/prm/hertz_ball_friction.prm): no line longer than 120 characters,
// quiet one table row per cycle, normal the Uzawa rows, detailed the Newton
// rows as well; warnings shown at every level. The runs print wall times
// (Print timing = true), whose columns make the widest lines. Every assertion
// is on a value broadcast from rank 0, which alone prints.

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <dualcontact/contact_problem.h>
#include <dualcontact/report.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <regex>
#include <sstream>

#include "test_tools.h"

using namespace dualcontact;
using namespace dualcontact_test;

namespace
{
  constexpr std::size_t line_width = 120;

  const std::string paper_block =
    read_text(test_file("../prm/paper_block.prm"));
  // an overlay: its entries override the scene's
  const std::string two_cycles =
    "\nsubsection Refinement\n  set Number of cycles = 2\nend\n";

  std::string
  output(const std::string &directory, const std::string &verbosity)
  {
    return "\nsubsection Output\n  set Directory = " + directory +
           "\n  set Write vtu = false\n  set Print timing = true\n"
           "  set Verbosity = " +
           verbosity + "\nend\n";
  }

  std::vector<std::string>
  lines_of(const std::string &text)
  {
    std::vector<std::string> lines;
    std::istringstream       in(text);
    for (std::string line; std::getline(in, line);)
      lines.push_back(line);
    return lines;
  }

  /** Characters, not bytes (the log has a "§"). */
  std::size_t
  length(const std::string &line)
  {
    return std::count_if(line.begin(), line.end(), [](const char c) {
      return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    });
  }

  /** The screen lines (rank 0's, the same on every rank) of a run. */
  template <int dim>
  std::vector<std::string>
  screen_of(const std::string &scene,
            const std::string &verbosity,
            const std::string &overlay)
  {
    const std::string directory =
      temporary_directory("log_" + verbosity, MPI_COMM_WORLD);
    Parameters parameters;
    parameters.read_string(scene, overlay + output(directory, verbosity));
    std::ostringstream screen;
    {
      ContactProblem<dim> problem(parameters, MPI_COMM_WORLD, screen);
      problem.run();
    }
    remove_directory(directory, MPI_COMM_WORLD);
    return lines_of(Utilities::MPI::broadcast(MPI_COMM_WORLD, screen.str(), 0));
  }

  std::size_t
  count_matching(const std::vector<std::string> &lines, const std::regex &re)
  {
    return std::count_if(lines.begin(), lines.end(), [&](const auto &l) {
      return std::regex_search(l, re);
    });
  }

  void
  check_widths(const std::vector<std::string> &lines)
  {
    for (const std::string &line : lines)
      {
        INFO(line);
        CHECK(length(line) <= line_width);
      }
  }

  /**
   * quiet: the scene and effects (a few lines), the header of the cycle
   * table, then exactly one row per cycle, as wide as the header and
   * starting with its cycle number, then the summary.
   */
  void
  check_quiet(const std::vector<std::string> &lines,
              const unsigned int              n_cycles)
  {
    const auto header =
      std::find_if(lines.begin(), lines.end(), [](const std::string &l) {
        return l.rfind(" cycle ", 0) == 0;
      });
    REQUIRE(header != lines.end());
    CHECK(header - lines.begin() <= 10);
    const auto summary =
      std::find_if(header, lines.end(), [](const std::string &l) {
        return l.rfind("Summary (", 0) == 0;
      });
    REQUIRE(summary != lines.end());
    std::vector<std::string> rows;
    std::copy_if(header + 1, summary, std::back_inserter(rows), [](auto &l) {
      return !l.empty();
    });
    REQUIRE(rows.size() == n_cycles);
    for (unsigned int cycle = 0; cycle < n_cycles; ++cycle)
      {
        INFO(rows[cycle]);
        CHECK(rows[cycle].size() == header->size());
        CHECK(std::stoul(rows[cycle]) == cycle);
      }
    // nothing of the loops
    CHECK(count_matching(lines,
                         std::regex("Uzawa +[0-9]+ |Newton +[0-9]+:|"
                                    "^Cycle |^Legend")) == 0);
  }

  /** The lines of the legend, from its title to the first cycle. */
  std::size_t
  legend_size(const std::vector<std::string> &lines)
  {
    const auto first = std::find_if(lines.begin(), lines.end(), [](auto &l) {
      return l.rfind("Legend", 0) == 0;
    });
    return std::find_if(first,
                        lines.end(),
                        [](auto &l) { return l.rfind("Cycle 0:", 0) == 0; }) -
           first;
  }

  /**
   * normal: a legend, the Uzawa rows, no Newton rows; detailed: the same
   * lines, one row per Newton step and the legend's lines for them.
   */
  void
  check_normal_and_detailed(const std::vector<std::string> &normal,
                            const std::vector<std::string> &detailed)
  {
    const std::regex uzawa_row("^   Uzawa +[0-9]+ ");
    const std::regex newton_row("^      Newton +[0-9]+: gradient ");
    for (const auto *lines : {&normal, &detailed})
      {
        CHECK(count_matching(*lines, std::regex("^Legend")) == 1);
        CHECK(count_matching(*lines, std::regex("^  d\\(x\\) +relative")) == 1);
      }
    CHECK(count_matching(normal, uzawa_row) > 0);
    CHECK(count_matching(normal, uzawa_row) ==
          count_matching(detailed, uzawa_row));
    CHECK(count_matching(normal, newton_row) == 0);
    const std::size_t newton_rows = count_matching(detailed, newton_row);
    // at least one per Uzawa step: the last is the test that ends it
    CHECK(newton_rows >= count_matching(detailed, uzawa_row));
    const std::size_t newton_legend =
      legend_size(detailed) - legend_size(normal);
    CHECK(newton_legend >= 1);
    CHECK(detailed.size() == normal.size() + newton_rows + newton_legend);
  }

  template <int dim>
  void
  check_levels(const std::string &scene,
               const unsigned int n_cycles,
               const std::string &overlay = "")
  {
    const auto quiet    = screen_of<dim>(scene, "quiet", overlay);
    const auto normal   = screen_of<dim>(scene, "normal", overlay);
    const auto detailed = screen_of<dim>(scene, "detailed", overlay);
    check_widths(quiet);
    check_widths(normal);
    check_widths(detailed);
    check_quiet(quiet, n_cycles);
    check_normal_and_detailed(normal, detailed);
  }
} // namespace

TEST_CASE("Screen log at each verbosity: 2D Coulomb friction (paper block)",
          "[report]")
{
  check_levels<2>(paper_block, 2, two_cycles);
}

TEST_CASE("Screen log at each verbosity: 3D Coulomb friction, nested "
          "threshold iteration, hanging nodes (Hertz ball)",
          "[report]")
{
  check_levels<3>(read_text(test_file("prm/hertz_ball_friction.prm")), 2);
}

TEST_CASE("quiet shows warnings, not notes; long ones are wrapped", "[report]")
{
  Parameters parameters;
  parameters.read_string(paper_block, two_cycles + output("unused", "quiet"));
  const Scene<2>     scene(parameters);
  std::ostringstream discarded, screen;
  const TimerOutput  timer(MPI_COMM_WORLD,
                          discarded,
                          TimerOutput::never,
                          TimerOutput::wall_times);
  Report<2>          report(parameters, scene, timer, MPI_COMM_WORLD, screen);
  report.note("threshold iteration: a note");
  std::string long_warning = "the displacements exceed 10 % of the body size";
  for (unsigned int i = 0; i < 6; ++i)
    long_warning += "; a small-strain model does not hold there";
  report.warning(long_warning);
  const auto lines =
    lines_of(Utilities::MPI::broadcast(MPI_COMM_WORLD, screen.str(), 0));
  REQUIRE(lines.size() >= 2);
  CHECK(lines[0].rfind("Warning: the displacements exceed", 0) == 0);
  check_widths(lines);
  CHECK(count_matching(lines, std::regex("a note")) == 0);
}
