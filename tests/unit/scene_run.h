// A scene from prm/, solved in-process for the tests, and comparisons of
// nodal contact results between runs.
#ifndef dualcontact_scene_run_h
#define dualcontact_scene_run_h

#include <deal.II/base/mpi.h>

#include <dualcontact/contact_problem.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

#include "test_tools.h"

namespace dualcontact_test
{
  using namespace dualcontact;

  /**
   * A scene from prm/ (or, with an empty name, the overrides alone), with
   * overrides, solved on `comm`.
   */
  template <int dim>
  struct SceneRun
  {
    Parameters                           parameters;
    std::ostringstream                   screen;
    std::unique_ptr<ContactProblem<dim>> problem;
    std::string                          directory;
    MPI_Comm                             comm;

    SceneRun(const std::string &scene,
             const std::string &overrides,
             const MPI_Comm     comm = MPI_COMM_WORLD)
        : comm(comm)
    {
      static unsigned int counter = 0;
      directory = temporary_directory("contact" + std::to_string(dim) + "d" +
                                        std::to_string(counter++),
                                      comm);
      parameters.read_string(
        (scene.empty() ? std::string() :
                         read_text(test_file("../prm/" + scene))) +
        overrides + "\nsubsection Output\n  set Directory = " + directory +
        "\n  set Write vtu = false\n  set Print timing = "
        "false\nend\n");
      problem = std::make_unique<ContactProblem<dim>>(parameters, comm, screen);
      problem->run();
    }

    ~SceneRun()
    {
      remove_directory(directory, comm);
    }

    const CycleResult &
    last() const
    {
      return problem->results().back();
    }

    /** (position along t, l1) of every contact node on every rank, sorted. */
    std::vector<std::pair<double, double>>
    pressures() const
    {
      const ContactSet<dim>                 &contact = problem->contact();
      std::vector<std::pair<double, double>> local;
      for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
        local.emplace_back(contact.nodes[s].position * contact.tangent,
                           contact.l1[s]);
      std::vector<std::pair<double, double>> all;
      for (const auto &part : Utilities::MPI::all_gather(comm, local))
        all.insert(all.end(), part.begin(), part.end());
      std::sort(all.begin(), all.end());
      return all;
    }
  };

  using Run = SceneRun<2>;

  /** Largest |l1_a - l1_b| over nodes at the same x (matched within 1e-9). */
  inline double
  max_pressure_difference(const std::vector<std::pair<double, double>> &a,
                          const std::vector<std::pair<double, double>> &b,
                          unsigned int &n_matched)
  {
    double difference = 0;
    n_matched         = 0;
    for (const auto &[x, l1] : a)
      {
        const auto it = std::lower_bound(b.begin(),
                                         b.end(),
                                         std::make_pair(x - 1e-9, -1e300));
        if (it != b.end() && std::abs(it->first - x) < 1e-9)
          {
            difference = std::max(difference, std::abs(it->second - l1));
            ++n_matched;
          }
      }
    return difference;
  }

  /**
   * The same scene solved on all ranks and on each rank alone: the largest
   * pressure difference at matching nodes and the number of nodes matched,
   * both reduced over MPI_COMM_WORLD (so every rank asserts the same).
   */
  inline std::pair<double, unsigned int>
  compare_ranks(const Run &world, const Run &alone)
  {
    unsigned int n_matched = 0;
    const double difference =
      max_pressure_difference(world.pressures(), alone.pressures(), n_matched);
    return {Utilities::MPI::max(difference, MPI_COMM_WORLD),
            Utilities::MPI::min(n_matched, MPI_COMM_WORLD)};
  }

} // namespace dualcontact_test

#endif
