// The size of a run, estimated before its mesh is built: the estimate
// against the meshes the runs actually make, the refusal of a scene that
// cannot fit in memory before anything is built or written (a coarse box
// or mesh file too, before it is built), and the memory under an
// address-space limit.
#include <deal.II/base/mpi.h>

#include <deal.II/distributed/tria.h>

#include <dualcontact/contact_problem.h>
#include <dualcontact/run_size.h>
#include <dualcontact/scene.h>

#include <catch2/catch.hpp>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <sys/resource.h>

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

TEST_CASE("The coarse mesh of a box or a mesh file is checked before it is "
          "built",
          "[run size]")
{
  // a box: the product of the subdivisions, times 2^dim per initial global
  // refinement, before subdivided_hyper_rectangle runs
  {
    Parameters parameters;
    parameters.read_string("subsection Geometry\n"
                           "  set Subdivisions = 60000, 60000\n"
                           "end\n"
                           "subsection Refinement\n"
                           "  set Initial global refinement = 2\n"
                           "end\n");
    const Scene<2>                          scene(parameters);
    parallel::distributed::Triangulation<2> mesh(MPI_COMM_WORLD);
    double                                  first = 0.;
    const auto                              stop  = [&first](const double n) {
      first = n;
      throw std::runtime_error("stopped");
    };
    CHECK_THROWS_AS(scene.create_mesh(mesh, stop), std::runtime_error);
    CHECK(first == 3.6e9 * 16.);
    CHECK(mesh.n_levels() == 0); // nothing built
  }
  // a mesh file: the quadrilaterals the scan counts (the half disc's 6),
  // before deal.II's reader builds them
  {
    Parameters parameters;
    parameters.read_string(
      "subsection Geometry\n"
      "  set Type = mesh file\n"
      "  set Mesh file = " +
      std::filesystem::absolute(test_file("../prm/meshes/half_disc.msh"))
        .lexically_normal()
        .string() +
      "\n"
      "end\n"
      "subsection Refinement\n"
      "  set Initial global refinement = 3\n"
      "end\n");
    double     cells = 0.;
    const auto stop  = [&cells](const double n) {
      cells = n;
      throw std::runtime_error("stopped");
    };
    CHECK_THROWS_AS(Scene<2>(parameters, stop), std::runtime_error);
    CHECK(cells == 6. * 64.);
  }
}

TEST_CASE("A box of 60000 x 60000 coarse cells is refused at once, before "
          "anything is built",
          "[run size][errors]")
{
  const std::string directory =
    temporary_directory("box_too_large", MPI_COMM_WORLD);
  Parameters parameters;
  parameters.read_string("subsection Geometry\n"
                         "  set Subdivisions = 60000, 60000\n"
                         "end\n"
                         "subsection Boundary conditions\n"
                         "  set Conditions = 2: fixed, 3: traction\n"
                         "  set Tractions = 3: 0; -1\n"
                         "end\n"
                         "subsection Output\n"
                         "  set Directory = " +
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
  CHECK(error.message.find("its finest mesh (cycle 0) would have at least "
                           "3.60e+09 cells") != std::string::npos);
  CHECK(error.message.find("<Geometry/Subdivisions> (60000, 60000)") !=
        std::string::npos);
  // 3.6e9 cells were never made (building them ends in std::bad_alloc)
  CHECK(seconds < 5.);
  MPI_Barrier(MPI_COMM_WORLD);
  CHECK_FALSE(std::filesystem::exists(directory));
}

TEST_CASE("The memory a run may use respects the address-space limit of its "
          "ranks",
          "[run size]")
{
  if (std::getenv("DUALCONTACT_MEMORY_GB") != nullptr)
    {
      WARN("DUALCONTACT_MEMORY_GB is set: it replaces the limits");
      return;
    }
  const MemoryLimit machine = memory_limit(MPI_COMM_WORLD);
  REQUIRE(machine.bytes > 0.);
  rlimit saved{};
  REQUIRE(getrlimit(RLIMIT_AS, &saved) == 0);
  if (saved.rlim_cur != RLIM_INFINITY)
    {
      WARN("the tests run under an address-space limit already");
      return;
    }
  // each rank's limit: what it has mapped now and 1 GB more, well below
  // the machine's memory of the ranks on this node
  std::ifstream status("/proc/self/status");
  std::string   line;
  double        mapped = 0.;
  while (std::getline(status, line))
    if (line.rfind("VmSize:", 0) == 0)
      mapped = std::stod(line.substr(7)) * 1024.;
  REQUIRE(mapped > 0.);
  const double gigabyte = 1024. * 1024. * 1024.;
  const double own      = mapped + gigabyte;
  rlimit       lowered  = saved;
  lowered.rlim_cur      = static_cast<rlim_t>(own);
  REQUIRE(setrlimit(RLIMIT_AS, &lowered) == 0);
  MemoryLimit limited;
  std::string message;
  {
    limited = memory_limit(MPI_COMM_WORLD);
    // a scene of 1e8 cells: some 340 GB, more than either limit
    Parameters parameters;
    parameters.read_string("subsection Geometry\n"
                           "  set Subdivisions = 1000, 1000\n"
                           "end\n"
                           "subsection Boundary conditions\n"
                           "  set Conditions = 2: fixed, 3: traction\n"
                           "  set Tractions = 3: 0; -1\n"
                           "end\n");
    const RunSizeCheck size(parameters, MPI_COMM_WORLD);
    message = catch_input_error([&] { size.check(1e8, false); }).message;
  }
  REQUIRE(setrlimit(RLIMIT_AS, &saved) == 0);
  const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  INFO("machine " << machine.bytes / gigabyte << " GB, limited "
                  << limited.bytes / gigabyte << " GB; " << message);
  CHECK(limited.source == MemoryLimit::Source::address_space);
  CHECK(limited.address_space_per_rank ==
        Approx(Utilities::MPI::min(own, MPI_COMM_WORLD)).epsilon(1e-6));
  // the limit less what a rank has mapped but does not use: the 1 GB above
  // its mapped space and its resident memory
  CHECK(limited.bytes >= 0.99 * n_ranks * gigabyte);
  CHECK(limited.bytes <=
        n_ranks * Utilities::MPI::max(own, MPI_COMM_WORLD) * 1.0001);
  CHECK(message.find("that the address-space limit (ulimit -v) of ") !=
        std::string::npos);
  CHECK(memory_limit(MPI_COMM_WORLD).source == MemoryLimit::Source::machine);
}
