// The output folder of a run, made and tested before the mesh is built.
#ifndef dualcontact_output_directory_h
#define dualcontact_output_directory_h

#include <deal.II/base/mpi.h>

#include <filesystem>
#include <string>
#include <vector>

namespace dualcontact
{
  /**
   * Makes the folder <Output/Directory> (and its missing parents) on rank 0
   * and tests that a file can be written in it, before anything is
   * computed: a folder that cannot be made is bad input found at once, not
   * after the first solve. A run that fails before it wrote anything calls
   * remove_if_unused(), so that bad input leaves no folder behind.
   */
  class OutputDirectory
  {
  public:
    /** Throws InputError (exit_invalid_value) on every rank on failure. */
    OutputDirectory(const std::string &directory, const MPI_Comm comm);

    /** Remove the folders made here that are still empty (rank 0). */
    void
    remove_if_unused() const;

    /**
     * Remove from `directory` the files that a run of dualcontact writes
     * (solution_NN.*, contact_NN.*, solution.pvd, contact.pvd, probes.csv,
     * cycles.csv, iterations.csv, parameters.prm, the folder checkpoint/),
     * so that the files of an earlier, longer run do not stand next to the
     * new ones. Other files and folders are kept. Call on one rank; returns how
     * many were removed.
     */
    static unsigned int
    remove_earlier_results(const std::string &directory);

  private:
    const MPI_Comm comm;
    // the folders that did not exist before, the deepest first
    std::vector<std::filesystem::path> made;
  };
} // namespace dualcontact

#endif
