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
#include <limits>
#include <sstream>
#include <string>
#include <vector>

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

  /**
   * A CSV file of numbers with a header line (the program's contact and
   * step tables), read by rank 0 of `comm` and known on every rank.
   */
  class CsvFile
  {
  public:
    CsvFile(const std::string &filename, const MPI_Comm comm)
    {
      std::string text;
      if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
        text = read_text(filename);
      text = dealii::Utilities::MPI::broadcast(comm, text, 0);
      std::istringstream lines(text);
      std::string        line;
      std::getline(lines, line);
      std::istringstream header(line);
      for (std::string column; std::getline(header, column, ',');)
        columns.push_back(column);
      while (std::getline(lines, line))
        {
          std::istringstream       fields(line);
          std::vector<std::string> row;
          for (std::string field; std::getline(fields, field, ',');)
            row.push_back(field);
          if (row.size() == columns.size())
            values.push_back(row);
        }
    }

    unsigned int
    rows() const
    {
      return values.size();
    }

    /** The entry of `column` in row i as a number (NaN if not one). */
    double
    value(const unsigned int i, const std::string &column) const
    {
      for (unsigned int c = 0; c < columns.size(); ++c)
        if (columns[c] == column)
          try
            {
              return std::stod(values[i][c]);
            }
          catch (const std::exception &)
            {
              break;
            }
      return std::numeric_limits<double>::quiet_NaN();
    }

  private:
    std::vector<std::string>              columns;
    std::vector<std::vector<std::string>> values;
  };

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
