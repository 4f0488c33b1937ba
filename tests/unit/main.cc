// The unit tests' main: MPI first (every test may use MPI_COMM_WORLD), then
// Catch2. Run on 1 and on 2 ranks by ctest (unit_np1, unit_np2). Each test
// reduces over all ranks what it checks, so every rank takes the same
// branch and a failure cannot hang the run.
#define CATCH_CONFIG_RUNNER
#include <deal.II/base/mpi.h>

#include <catch2/catch.hpp>

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  return Catch::Session().run(argc, argv);
}
