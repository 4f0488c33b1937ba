// A scene from prm/, solved in-process for the tests, and comparisons of
// nodal contact results between runs.
#ifndef dualcontact_scene_run_h
#define dualcontact_scene_run_h

#include <deal.II/base/mpi.h>

#include <dualcontact/contact_problem.h>

#include <algorithm>
#include <cmath>
#include <limits>
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
      // the overrides (and the output entries) are an overlay: they may
      // change what the scene sets
      const std::string output =
        "\nsubsection Output\n  set Directory = " + directory +
        "\n  set Write vtu = false\n  set Print "
        "timing = false\nend\n";
      if (scene.empty())
        parameters.read_string(overrides, output);
      else
        parameters.read_string(read_text(test_file("../prm/" + scene)),
                               overrides + output);
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

  /**
   * The largest spacing of the contact nodes with |s| < within (2D), all
   * ranks': the contact element there.
   */
  inline double
  largest_spacing(const Run &run, const double within)
  {
    const auto nodes   = run.pressures();
    double     element = 0.;
    for (std::size_t i = 1; i < nodes.size(); ++i)
      if (std::abs(nodes[i].first) < within)
        element = std::max(element, nodes[i].first - nodes[i - 1].first);
    return element;
  }

  // prm/patch.prm (E = 1000, nu = 0, the block [0, 2] x [0, 1]) turned into
  // the 2D twin of prm/patch_3d.prm: the uniform stress sigma_yy = -1,
  // sigma_xy = 0.2 (tractions (0.2, -1) on the top, (0, -+0.2) on the
  // sides), Coulomb friction F = 0.4 on the bottom. The plane carries
  // p = 1 and the shear 0.2 < F p at every node, which all stick;
  // u = (4e-4 y, -1e-3 y) is in the space of every degree.
  inline const std::string patch_stick_2d =
    "subsection Boundary conditions\n"
    "  set Conditions = 0: traction, 1: traction, 2: contact, 3: traction\n"
    "  set Tractions  = 0: 0; -0.2, 1: 0; 0.2, 3: 0.2; -1\nend\n"
    "subsection Friction\n  set Law = coulomb\n  set Coefficient = 0.4\nend\n"
    "subsection Exact solution\n  set Displacement = 0.0004 * y; -0.001 * y\n"
    "  set Contact pressure = 1\nend\n"
    "subsection Solver\n  set Uzawa tolerance = 1e-11\nend\n";

  // prm/patch_3d.prm without friction and without shear: the pressure 1 on
  // the top alone; u = (0, 0, -1e-3 z). The planes x = 0 and y = 0 are
  // symmetry planes: without them the lateral motions are free and only
  // the proximal term holds them, to the Uzawa tolerance, not to round-off.
  inline const std::string patch_frictionless_3d =
    "subsection Boundary conditions\n"
    "  set Conditions = 0: normal fixed, 2: normal fixed, 4: contact, 5: "
    "traction\n"
    "  set Tractions  = 5: 0; 0; -1\nend\n"
    "subsection Friction\n  set Law = none\nend\n"
    "subsection Exact solution\n  set Displacement = 0; 0; -0.001 * z\n"
    "  set Contact pressure = 1\nend\n"
    "subsection Solver\n  set Uzawa tolerance = 1e-11\nend\n";

  /** The largest |l1_s - p| and |l2_s - q| over all ranks' contact nodes. */
  template <int dim>
  std::pair<double, double>
  deviation(const SceneRun<dim> &run, const double p, const Tensor<1, dim> &q)
  {
    const ContactSet<dim> &contact = run.problem->contact();
    double                 l1 = 0., l2 = 0.;
    for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
      {
        l1 = std::max(l1, std::abs(contact.l1[s] - p));
        if (contact.friction)
          {
            Tensor<1, dim> traction;
            for (unsigned int k = 0; k + 1 < dim; ++k)
              traction += contact.l2[s][k] * contact.nodes[s].tangents[k];
            l2 = std::max(l2, (traction - q).norm());
          }
      }
    return {Utilities::MPI::max(l1, run.comm),
            Utilities::MPI::max(l2, run.comm)};
  }

  /**
   * 3D: the spacing of the contact nodes on the x axis (y = 0, x >= 0)
   * around x = r, the contact element there (0 if the axis has no node
   * beyond r); the same on every rank.
   */
  inline double
  line_spacing(const SceneRun<3> &run, const double r)
  {
    const ContactSet<3> &contact = run.problem->contact();
    std::vector<double>  local;
    for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
      if (std::abs(contact.nodes[s].position[1]) < 1e-8 &&
          contact.nodes[s].position[0] >= 0.)
        local.push_back(contact.nodes[s].position[0]);
    std::vector<double> x;
    for (const auto &part : Utilities::MPI::all_gather(run.comm, local))
      x.insert(x.end(), part.begin(), part.end());
    std::sort(x.begin(), x.end());
    for (std::size_t i = 1; i < x.size(); ++i)
      if (x[i] >= r)
        return x[i] - x[i - 1];
    return 0.;
  }

  /** Largest |v_i| over all entries; infinity if one is not finite. */
  inline double
  max_entry(const TrilinosWrappers::MPI::Vector &v, const MPI_Comm comm)
  {
    double largest = 0;
    for (const auto i : v.locally_owned_elements())
      largest = std::isfinite(v[i]) ? std::max(largest, std::abs(v[i])) :
                                      std::numeric_limits<double>::infinity();
    return Utilities::MPI::max(largest, comm);
  }

  /**
   * The contact conditions at every contact node of the last cycle: l1 >= 0,
   * the penetration max(v_n - g0) and the complementarity l1 |g0 - v_n|,
   * relative to the largest displacement (and the largest l1).
   */
  struct Conditions
  {
    double smallest_l1     = 0;
    double penetration     = 0;
    double complementarity = 0;
  };

  template <int dim>
  Conditions
  check_conditions(const SceneRun<dim> &run)
  {
    const ContactSet<dim> &c = run.problem->contact();
    const auto            &v = run.problem->displacement();
    Conditions             check;
    double                 l1_max = 0;
    check.smallest_l1             = std::numeric_limits<double>::max();
    for (unsigned int s = 0; s < c.n_local_nodes(); ++s)
      {
        const double gap  = c.nodes[s].gap0 - c.normal_displacement(v, s);
        check.smallest_l1 = std::min(check.smallest_l1, c.l1[s]);
        check.penetration = std::max(check.penetration, -gap);
        check.complementarity =
          std::max(check.complementarity, c.l1[s] * std::abs(gap));
        l1_max = std::max(l1_max, c.l1[s]);
      }
    const double v_max = max_entry(v, run.comm);
    l1_max             = Utilities::MPI::max(l1_max, run.comm);
    check.smallest_l1  = Utilities::MPI::min(check.smallest_l1, run.comm);
    check.penetration =
      Utilities::MPI::max(check.penetration, run.comm) / v_max;
    check.complementarity =
      Utilities::MPI::max(check.complementarity, run.comm) / (l1_max * v_max);
    return check;
  }


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
