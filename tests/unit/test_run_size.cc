// The size of a run, estimated before its mesh is built: the estimate
// against the meshes the runs actually make, and the refusal of a scene
// that cannot fit in memory before anything is built or written.
#include <deal.II/base/mpi.h>

#include <dualcontact/contact_problem.h>
#include <dualcontact/run_size.h>

#include <catch2/catch.hpp>

#include <chrono>
#include <cstdlib>
#include <filesystem>

#include "scene_run.h"
#include "test_tools.h"

using namespace dualcontact;
using namespace dualcontact_test;

namespace
{
  /** The estimate from the run's own initial mesh, against its last mesh. */
  template <int dim>
  void
  check_estimate(const SceneRun<dim> &run, const double tolerance)
  {
    const auto   &results = run.problem->results();
    const RunSize size =
      estimate_run_size(run.parameters, results.front().mesh.n_cells, 1);
    INFO("cells " << results.back().mesh.n_cells << " estimated " << size.cells
                  << ", DoFs " << results.back().mesh.n_dofs << " estimated "
                  << size.dofs);
    CHECK(size.cycle == results.back().mesh.cycle);
    CHECK(size.cells == Approx(results.back().mesh.n_cells).epsilon(tolerance));
    CHECK(size.dofs == Approx(results.back().mesh.n_dofs).epsilon(tolerance));
  }
} // namespace

TEST_CASE("The estimate of the finest mesh matches the meshes the runs make",
          "[run size]")
{
  // global refinement: cells x 2^dim per cycle, DoFs from the nodes of a
  // cube of cells
  check_estimate(SceneRun<2>("paper_block.prm", ""), 0.005);
  // (the hanging nodes of the pre-refined band add 2 % to the DoFs)
  check_estimate(SceneRun<2>("hertz.prm", ""), 0.03);
  check_estimate(SceneRun<3>("",
                             "subsection Geometry\n"
                             "  set Dimension = 3\n"
                             "  set Lower left corner = 0, 0, 0\n"
                             "  set Upper right corner = 2, 2, 1\n"
                             "  set Subdivisions = 4, 4, 2\n"
                             "end\n"
                             "subsection Boundary conditions\n"
                             "  set Conditions = 4: fixed, 5: traction\n"
                             "  set Tractions = 5: 0; 0; -1\n"
                             "end\n"
                             "subsection Refinement\n"
                             "  set Number of cycles = 3\n"
                             "end\n"),
                 0.02);
  // adaptive refinement: 1 + 3 x 0.3 per cycle is an upper estimate (the
  // closure of hanging nodes adds some cells, coarsening is not used)
  SceneRun<2>   adaptive("hertz_adaptive.prm",
                       "subsection Refinement\n  set Number of cycles = 3\n"
                         "end\n");
  const auto   &results = adaptive.problem->results();
  const RunSize size =
    estimate_run_size(adaptive.parameters, results.front().mesh.n_cells, 1);
  CHECK(size.cells == Approx(results.back().mesh.n_cells).epsilon(0.25));
}

TEST_CASE("A scene too large for the memory stops before its mesh is built, "
          "naming the entries that make it large; nothing is written",
          "[run size][errors]")
{
  const std::string directory =
    temporary_directory("too_large", MPI_COMM_WORLD);
  Parameters parameters;
  parameters.read_string(
    read_text(test_file("../prm/paper_block.prm")),
    "subsection Refinement\n  set Initial global refinement = 14\nend\n"
    "subsection Output\n  set Directory = " +
      directory + "\nend\n");
  std::ostringstream screen;
  const auto         start = std::chrono::steady_clock::now();
  CaughtError        error;
  {
    ContactProblem<2> problem(parameters, MPI_COMM_WORLD, screen);
    error = catch_input_error([&] { problem.run(); });
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
      .count();
  REQUIRE(error.thrown);
  CHECK(error.code == exit_inconsistent);
  CHECK(error.message.find("The scene is too large for the memory of this "
                           "machine: its finest mesh (cycle 2) would have at "
                           "least 3.44e+12 cells") == 0);
  CHECK(error.message.find("<Refinement/Initial global refinement> (14)") !=
        std::string::npos);
  CHECK(error.message.find("<Refinement/Number of cycles> (3)") !=
        std::string::npos);
  // 800 x 4^14 cells were never made: the 32 s to std::bad_alloc of before
  CHECK(seconds < 5.);
  // rank 0 removes the folder it made: wait for it
  MPI_Barrier(MPI_COMM_WORLD);
  CHECK_FALSE(std::filesystem::exists(directory));
}
