#include <deal.II/base/mpi.h>

#include <dualcontact/input_error.h>
#include <dualcontact/output_directory.h>

#include <unistd.h>

#include <fstream>
#include <regex>

namespace dualcontact
{
  OutputDirectory::OutputDirectory(const std::string &directory,
                                   const MPI_Comm     comm)
      : comm(comm)
  {
    namespace fs = std::filesystem;
    std::string problem;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::error_code error;
        const fs::path  folder = fs::absolute(directory, error);
        for (fs::path p = folder; !p.empty() && !fs::exists(p, error);
             p          = p.parent_path())
          {
                     made.push_back(p);
                     if (p == p.parent_path())
              break;
          }
        fs::create_directories(folder, error);
        if (error)
          problem = error.message();
        else
          {
            // a folder may exist and still refuse files (permissions, a
            // read-only file system)
            const fs::path probe =
              folder / (".dualcontact_write_test_" + std::to_string(getpid()));
            const bool written = static_cast<bool>(std::ofstream(probe) << "");
            fs::remove(probe, error);
            if (!written)
              problem = "no file can be written in it";
          }
        if (!problem.empty())
          remove_if_unused();
      }
    problem = dealii::Utilities::MPI::broadcast(comm, problem, 0);
    if (!problem.empty())
      throw InputError("Cannot make or write the output folder '" + directory +
                         "' given by <Output/Directory>: " + problem + ".",
                       exit_invalid_value);
  }

  void
  OutputDirectory::remove_if_unused() const
  {
    if (dealii::Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    std::error_code error;
    for (const std::filesystem::path &folder : made)
      if (std::filesystem::is_directory(folder, error) &&
          std::filesystem::is_empty(folder, error))
        std::filesystem::remove(folder, error);
      else
        break;
  }

  unsigned int
  OutputDirectory::remove_earlier_results(const std::string &directory)
  {
    // the names of ContactProblem::output_results(), output_step() and
    // Report
    static const std::regex ours(
      "(solution|contact)(_step)?_[0-9]+(\\.[0-9]+)?\\.(vtu|pvtu)|"
      "contact(_step)?_[0-9]+\\.csv|(solution|contact)(_step)?\\.pvd|"
      "(probes|probes_steps|cycles|steps|iterations)\\.csv|steps\\.gp|"
      "parameters\\.prm");
    std::error_code                    error;
    std::vector<std::filesystem::path> old;
    for (const auto &entry :
         std::filesystem::directory_iterator(directory, error))
      if (entry.is_regular_file(error) &&
          std::regex_match(entry.path().filename().string(), ours))
        old.push_back(entry.path());
    unsigned int removed = 0;
    for (const std::filesystem::path &file : old)
      removed += std::filesystem::remove(file, error) ? 1 : 0;
    // an earlier run's checkpoint (checkpoint.h), and one it did not finish
    for (const char *folder : {"checkpoint", "checkpoint.new"})
      removed +=
        std::filesystem::remove_all(std::filesystem::path(directory) / folder,
                                    error) > 0 ?
          1 :
          0;
    return removed;
  }
} // namespace dualcontact
