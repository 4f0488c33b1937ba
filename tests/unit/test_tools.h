// Helpers shared by the unit tests.
#ifndef dualcontact_test_tools_h
#define dualcontact_test_tools_h

#include <deal.II/base/mpi.h>

#include <dualcontact/input_error.h>
#include <dualcontact/parameters.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

namespace dualcontact_test
{
  /** What an InputError said: its code and its what() text. */
  struct CaughtError
  {
    bool                  thrown = false;
    dualcontact::ExitCode code   = dualcontact::exit_success;
    std::string           message;
  };

  /** Run `action` and catch the InputError it throws, if any. */
  inline CaughtError
  catch_input_error(const std::function<void()> &action)
  {
    CaughtError caught;
    try
      {
        action();
      }
    catch (const dualcontact::InputError &error)
      {
        caught.thrown  = true;
        caught.code    = error.code;
        caught.message = error.what();
      }
    return caught;
  }

  /** Whether `text` contains `part`. */
  inline bool
  contains(const std::string &text, const std::string &part)
  {
    return text.find(part) != std::string::npos;
  }

  /** The text of a file (the test inputs under tests/). */
  inline std::string
  read_text(const std::string &filename)
  {
    std::ifstream      in(filename);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  /** A file under the source tree's tests/ directory. */
  inline std::string
  test_file(const std::string &relative_path)
  {
    return std::string(DUALCONTACT_TEST_DIR) + "/" + relative_path;
  }

  /**
   * A fresh directory name under the system's temporary directory, the same
   * on every rank of `comm` and different for concurrent runs (it holds the
   * process id of the communicator's rank 0).
   */
  inline std::string
  temporary_directory(const std::string &name, const MPI_Comm comm)
  {
    const int pid = dealii::Utilities::MPI::broadcast(comm, int(getpid()), 0);
    return (std::filesystem::temp_directory_path() /
            ("dualcontact_test_" + name + "_" + std::to_string(pid)))
      .string();
  }

  /** Remove a directory made by a run on `comm` (rank 0 removes it). */
  inline void
  remove_directory(const std::string &directory, const MPI_Comm comm)
  {
    MPI_Barrier(comm);
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      std::filesystem::remove_all(directory);
    MPI_Barrier(comm);
  }
} // namespace dualcontact_test

#endif
