// dualcontact: run one scene (.prm file).
//
//   dualcontact scene.prm          run it (mpirun -np N dualcontact scene.prm)
//   dualcontact --help             usage
//   dualcontact --print-parameters every entry with its default and help text

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <dualcontact/contact_problem.h>
#include <dualcontact/input_error.h>
#include <dualcontact/parameters.h>

#include <exception>
#include <iostream>
#include <string>

namespace
{
  /**
   * Run one scene. Any exception from run() is caught while the problem
   * still exists and rethrown after it is gone: the problem's objects then
   * finish normally (every rank throws the same InputError together)
   * instead of during stack unwinding, where deal.II would warn about MPI
   * and TimerOutput would print its notice about an uncaught exception in
   * front of the error message.
   */
  template <int dim>
  void
  run_scene(const dualcontact::Parameters &parameters)
  {
    std::exception_ptr error;
    {
      dualcontact::ContactProblem<dim> problem(parameters);
      try
        {
          problem.run();
        }
      catch (...)
        {
          error = std::current_exception();
        }
    }
    if (error)
      std::rethrow_exception(error);
  }

  const char *const usage =
    "Usage: dualcontact [--help | --print-parameters] [scene.prm]\n"
    "\n"
    "Elastic contact with Coulomb friction by modified duality schemes.\n"
    "Runs the scene described by the parameter file; in parallel with\n"
    "  mpirun -np N dualcontact scene.prm\n"
    "\n"
    "Options:\n"
    "  --help              this text\n"
    "  --print-parameters  print a parameter file with every entry, its\n"
    "                      default value and help text (units in brackets)\n"
    "\n"
    "Exit status: 0 success, 1 solver failure, 2 wrong command line,\n"
    "3 parameter file unreadable, 4 unknown entry, malformed line or entry\n"
    "set twice, 5 invalid value (or an output folder that cannot be made),\n"
    "6 inconsistent scene (or a mesh too large for the machine's memory),\n"
    "7 load the foundation cannot hold.\n";
} // namespace

int
main(int argc, char *argv[])
{
  using namespace dualcontact;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.size() == 1 && (args[0] == "--help" || args[0] == "-h"))
    {
      if (root)
        std::cout << usage;
      return exit_success;
    }
  if (args.size() == 1 && args[0] == "--print-parameters")
    {
      if (root)
        std::cout << default_parameter_file();
      return exit_success;
    }
  if (args.size() != 1 || args[0].empty() || args[0][0] == '-')
    {
      if (root)
        std::cerr << "dualcontact: expected exactly one parameter file.\n\n"
                  << usage;
      return exit_usage;
    }

  try
    {
      Parameters parameters;
      parameters.read_file(args[0]);
      if (root)
        for (const std::string &warning : parameters.ineffective_entries())
          std::cerr << "dualcontact: warning: " << warning << std::endl;
      if (parameters.geometry.dimension == 2)
        run_scene<2>(parameters);
      else
        run_scene<3>(parameters);
    }
  catch (const InputError &error)
    {
      if (root)
        std::cerr << "dualcontact: " << error.what() << std::endl;
      return error.code;
    }
  catch (const dealii::ExceptionBase &exc)
    {
      if (root)
        {
          std::cerr << "dualcontact: error: ";
          exc.print_info(std::cerr);
          std::cerr << std::endl;
        }
      return exit_runtime_failure;
    }
  catch (const std::exception &exc)
    {
      if (root)
        std::cerr << "dualcontact: error: " << exc.what() << std::endl;
      return exit_runtime_failure;
    }
  return exit_success;
}
