// dualcontact: run one scene (.prm file).
//
//   dualcontact scene.prm [--set "Subsection/Entry=value" ...]
//                                    run it (mpirun -np N dualcontact ...)
//   dualcontact --help               usage
//   dualcontact --print-parameters [scene.prm [--set ...]]
//                                    every entry with its default (or the
//                                    scene's value) and help text

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <dualcontact/contact_problem.h>
#include <dualcontact/input_error.h>
#include <dualcontact/parameters.h>

#include <boost/program_options.hpp>
#include <exception>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  namespace po = boost::program_options;

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
  run_scene(const dualcontact::Parameters &parameters, const bool resume)
  {
    std::exception_ptr error;
    {
      dualcontact::ContactProblem<dim> problem(parameters);
      problem.record_parameters(parameters.parameter_file);
      if (resume)
        problem.continue_from_checkpoint();
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

  struct CommandLine
  {
    bool                     help             = false;
    bool                     print_parameters = false;
    std::vector<std::string> scenes;
    std::vector<std::string> overrides;
    std::string              resume; // the folder of the checkpoint
  };

  po::options_description
  options()
  {
    po::options_description options("Options");
    options.add_options()("help,h", "this text")(
      "print-parameters",
      "print a parameter file with every entry, its value (the default, or "
      "the scene's with the overrides applied if a scene is given) and help "
      "text (units in brackets), and stop")(
      "set",
      po::value<std::vector<std::string>>()->composing(),
      "\"Subsection/Entry=value\": override one entry of the scene (after the "
      "file; repeat for several), e.g. --set \"Friction/Coefficient=0.4\"")(
      "resume",
      po::value<std::string>(),
      "folder: go on with the load path from the last checkpoint in this "
      "output folder (<Output/Checkpoint interval>), which becomes "
      "<Output/Directory>; the scene and its --set must be those of the run "
      "that wrote it, on as many MPI ranks");
    return options;
  }

  std::string
  usage()
  {
    std::ostringstream text;
    text
      << "Usage: dualcontact [--set \"Subsection/Entry=value\" ...] scene.prm\n"
         "       dualcontact [--set ...] scene.prm --resume output/\n"
         "       dualcontact --print-parameters [scene.prm [--set ...]]\n"
         "       dualcontact --help\n"
         "\n"
         "Elastic contact with Coulomb friction by modified duality schemes.\n"
         "Runs the scene described by the parameter file; in parallel with\n"
         "  mpirun -np N dualcontact scene.prm\n"
         "\n"
      << options()
      << "\n"
         "Exit status: 0 success, 1 solver failure, 2 wrong command line,\n"
         "3 parameter (or mesh) file unreadable, or a damaged checkpoint,\n"
         "4 unknown entry, malformed line or entry set twice, 5 invalid value\n"
         "(or an output folder that cannot be made), 6 inconsistent scene (or\n"
         "a mesh too large for the machine's memory), 7 load the foundation\n"
         "cannot hold.\n";
    return text.str();
  }

  /** Boost.Program_options; InputError (exit 2) for a wrong command line. */
  CommandLine
  parse_command_line(int argc, char *argv[])
  {
    po::options_description all = options();
    all.add_options()("scene", po::value<std::vector<std::string>>());
    po::positional_options_description positional;
    positional.add("scene", -1);

    po::variables_map values;
    try
      {
        po::store(po::command_line_parser(argc, argv)
                    .options(all)
                    .positional(positional)
                    .run(),
                  values);
        po::notify(values);
      }
    catch (const po::error &error)
      {
        throw dualcontact::InputError(std::string(error.what()) + ".",
                                      dualcontact::exit_usage);
      }

    CommandLine line;
    line.help             = values.count("help") > 0;
    line.print_parameters = values.count("print-parameters") > 0;
    if (values.count("scene"))
      line.scenes = values["scene"].as<std::vector<std::string>>();
    if (values.count("set"))
      line.overrides = values["set"].as<std::vector<std::string>>();
    if (values.count("resume"))
      {
        // an empty name (--resume "$DIR" with DIR unset) would read as no
        // --resume at all: the run would start afresh and remove the
        // checkpoint it was meant to go on from
        line.resume = values["resume"].as<std::string>();
        if (line.resume.empty())
          throw dualcontact::InputError(
            "--resume needs the output folder of the checkpoint, and was "
            "given an empty name; nothing was run or removed.",
            dualcontact::exit_usage);
      }
    const bool needs_scene = !line.help && !line.print_parameters;
    if ((needs_scene && line.scenes.size() != 1) || line.scenes.size() > 1 ||
        (line.scenes.empty() && !line.overrides.empty()))
      throw dualcontact::InputError("expected exactly one parameter file.",
                                    dualcontact::exit_usage);
    return line;
  }
} // namespace

int
main(int argc, char *argv[])
{
  using namespace dualcontact;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  try
    {
      const CommandLine line = parse_command_line(argc, argv);
      if (line.help)
        {
          if (root)
            std::cout << usage();
          return exit_success;
        }
      if (line.print_parameters && line.scenes.empty())
        {
          if (root)
            std::cout << default_parameter_file();
          return exit_success;
        }

      Parameters parameters;
      parameters.read_file(line.scenes[0], line.overrides);
      if (line.print_parameters)
        {
          if (root)
            std::cout << parameters.parameter_file;
          return exit_success;
        }
      if (root)
        for (const std::string &warning : parameters.ineffective_entries())
          std::cerr << "dualcontact: warning: " << printable(warning)
                    << std::endl;

      // a resumed run writes where the checkpoint is
      const bool resume = !line.resume.empty();
      if (resume)
        parameters.output.directory = line.resume;
      if (parameters.geometry.dimension == 2)
        run_scene<2>(parameters, resume);
      else
        run_scene<3>(parameters, resume);
    }
  catch (const InputError &error)
    {
      if (root)
        {
          std::cerr << "dualcontact: " << printable(error.what()) << std::endl;
          if (error.code == exit_usage)
            std::cerr << '\n' << usage();
        }
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
