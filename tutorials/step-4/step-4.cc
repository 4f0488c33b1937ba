/* step-4: friction in Hertz contact, Dundurs' beta.
 *
 * step-3 showed how Coulomb friction enters the method. This step uses the
 * library's whole solver as a black box and asks a question of mechanics:
 * what does friction do to the contact of an elastic cylinder on a rigid
 * plane? Hertz's theory is frictionless. Under the pressure the elastic
 * surface is drawn toward the centre of the contact, the rigid plane is
 * not, and friction resists that inward slip. How much the normal contact
 * feels of it is measured by Dundurs' beta = (1 - 2 nu) / (2 (1 - nu)) for
 * a rigid foundation (doc/theory.md §9): 0.29 at nu = 0.3, 0.02 at nu =
 * 0.49. The program solves the half disc of step-4.prm four times, without
 * and with friction, at the prm's nu and at nu = 0.49, and compares the
 * contact zones with each other and with Hertz.
 *
 * README.md has the introduction and the results.
 */

// @sect3{Include files}
//
// The library's Problem class (the whole solver and the measurements), its
// parameters, and the tutorials' tools (Hertz's formulas among them).
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <dualcontact/contact_problem.h>
#include <dualcontact/parameters.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "../common/tutorial_tools.h"

namespace Step4
{
  using namespace dealii;
  using namespace dualcontact;

  using tutorial::format;

  constexpr unsigned int dim = 2;

  // The second Poisson's ratio: nearly incompressible, where beta is almost
  // zero and friction should hardly matter. (Exactly 1/2 is not allowed:
  // lambda would be infinite.)
  constexpr double nearly_incompressible = 0.49;

  // @sect3{Dundurs' beta}
  //
  // For two bodies in plane strain with shear moduli mu_1, mu_2 and
  // Poisson's ratios nu_1, nu_2,
  //   beta = [(1 - 2 nu_1)/mu_1 - (1 - 2 nu_2)/mu_2]
  //          / [2 ((1 - nu_1)/mu_1 + (1 - nu_2)/mu_2)].
  // A rigid foundation has mu_2 -> infinity, and what is left depends on
  // the body's nu only (README.md, "Dundurs' beta").
  double
  dundurs_beta(const double nu)
  {
    return (1. - 2. * nu) / (2. * (1. - nu));
  }

  // @sect3{The contact nodes, gathered}
  //
  // All ranks' contact nodes, sorted along the plane (t = e_x): the
  // position x, the pressure l1, the tangential traction l2 (its coordinate
  // along t, l2 = -sigma_t), the threshold theta the solution was computed
  // with (F l1 for the merged threshold iteration) and the status: 0
  // separated, 1 stick (or in contact without friction), 2 slip.
  struct NodeValues
  {
    double       x, l1, l2, theta;
    unsigned int status;

    // for Utilities::MPI::all_gather
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &x &l1 &l2 &theta &status;
    }
  };

  std::vector<NodeValues>
  gather_nodes(const ContactSet<dim> &contact)
  {
    std::vector<NodeValues> local;
    for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
      {
        const bool f = contact.friction;
        local.push_back({contact.nodes[s].position * contact.tangent,
                         contact.l1[s],
                         f ? contact.l2[s][0] : 0.,
                         f ? contact.threshold[s] : 0.,
                         contact.status(s)});
      }
    std::vector<NodeValues> all;
    for (const auto &part : Utilities::MPI::all_gather(MPI_COMM_WORLD, local))
      all.insert(all.end(), part.begin(), part.end());
    std::sort(all.begin(), all.end(), [](const auto &a, const auto &b) {
      return a.x < b.x;
    });
    return all;
  }

  // The nodes as CSV for the figures (rank 0 writes).
  void
  write_nodes(const std::vector<NodeValues> &nodes, const std::string &file)
  {
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    std::ofstream out(file);
    out << "x,l1,l2,theta,status\n" << std::setprecision(10);
    for (const NodeValues &n : nodes)
      out << n.x << ',' << n.l1 << ',' << n.l2 << ',' << n.theta << ','
          << n.status << '\n';
  }

  // @sect3{One run}
  //
  // The scene of step-4.prm with the given nu and F, solved by the
  // library's ContactProblem::run(): the threshold iteration in the
  // strategy of step-4.prm around the Uzawa iteration around the Newton
  // iteration (step-1 to step-3). F = 0 makes the scene frictionless: the
  // library then runs the Uzawa iteration on l1 alone. The library's report
  // goes into a string that is thrown away; its files go into the run's own
  // folder under output/ (cycles.csv, contact_00.csv, iterations.csv).
  struct Run
  {
    double                  nu = 0., F = 0.;
    std::string             name;
    CycleResult             result;
    double                  h_contact = 0.;
    std::vector<NodeValues> nodes;
    double                  time = 0.;
    // measured: c, the largest |x| of a sticking node (the stick zone is
    // |x| <= c); the relative changes of a and of the peak by friction
    double c = -1., change_a = 0., change_peak = 0.;
  };

  Run
  solve(const Parameters &scene, const double nu, const double F)
  {
    Run run;
    run.nu = nu;
    run.F  = F;
    run.name =
      format("nu%.2f", nu) + (F > 0. ? format("_F%.3g", F) : "_frictionless");

    Parameters parameters              = scene;
    parameters.material.poissons_ratio = nu;
    parameters.friction.parameter      = format("%.17g", F);
    parameters.output.directory += "/" + run.name;

    std::ostringstream  silent;
    ContactProblem<dim> problem(parameters, MPI_COMM_WORLD, silent);
    Timer               timer(MPI_COMM_WORLD, true);
    problem.run();
    timer.stop();
    run.time      = timer.wall_time();
    run.result    = problem.results().back();
    run.h_contact = problem.contact().min_face_diameter();
    run.nodes     = gather_nodes(problem.contact());
    for (const NodeValues &n : run.nodes)
      if (n.status == 1 && F > 0.)
        run.c = std::max(run.c, std::abs(n.x));
    return run;
  }

  // Coulomb's cone |l2| <= theta at every node, the largest excess relative
  // to the largest theta: zero at slip nodes, negative at stick nodes.
  double
  cone_excess(const std::vector<NodeValues> &nodes)
  {
    double excess = -1e300, largest = 0.;
    for (const NodeValues &n : nodes)
      {
        excess  = std::max(excess, std::abs(n.l2) - n.theta);
        largest = std::max(largest, n.theta);
      }
    return excess / largest;
  }

  // @sect3{The whole step}
  //
  // The program in the shape of deal.II's steps: a class whose run() reads
  // as its stages, one member function each, and members for what a later
  // stage needs of an earlier one (the four runs and the load P).
  class FrictionInHertz
  {
  public:
    explicit FrictionInHertz(const Parameters &scene);

    tutorial::Checks
    run();

  private:
    void
    check_scene();
    void
    solve_four_runs();
    void
    print_scene();
    void
    print_runs() const;
    void
    write_figure_data() const;
    tutorial::Checks
    check_results() const;

    // The scene, the screen (rank 0 prints), whether it shows times, its
    // friction coefficient and Poisson's ratio.
    const Parameters  &scene;
    const bool         root;
    ConditionalOStream pcout;
    const bool         timing;
    double             F = 0., nu = 0.;

    // The four runs and the load P of the first (of all four: the same
    // traction on the same mesh).
    std::vector<Run> runs;
    double           P = 0.;
  };


  FrictionInHertz::FrictionInHertz(const Parameters &scene)
      : scene(scene)
      , root(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      , pcout(std::cout, root)
      , timing(scene.output.print_timing)
  {}


  // The four runs, the scene they share, the table and its figure's data,
  // and the checks.
  tutorial::Checks
  FrictionInHertz::run()
  {
    check_scene();
    solve_four_runs();
    print_scene();
    print_runs();
    write_figure_data();
    return check_results();
  }


  // The formulas of this step hold for the 2D half disc with Coulomb
  // friction; anything else is refused with one message before a solve.
  void
  FrictionInHertz::check_scene()
  {
    AssertThrow(scene.geometry.dimension == dim &&
                  scene.geometry.type == "half disc" &&
                  scene.friction.law == "coulomb",
                ExcMessage("step-4 needs the 2D half disc with Coulomb "
                           "friction."));
    F  = std::stod(scene.friction.parameter);
    nu = scene.material.poissons_ratio;
    if (root)
      std::filesystem::create_directories(scene.output.directory);

    pcout << "step-4: friction in Hertz contact, Dundurs' beta ("
          << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
          << " MPI rank(s))\n\n";
  }


  // Four runs: without and with friction, at the prm's nu and nearly
  // incompressible.
  void
  FrictionInHertz::solve_four_runs()
  {
    for (const double n : {nu, nearly_incompressible})
      for (const double f : {0., F})
        runs.push_back(solve(scene, n, f));
    for (unsigned int i = 1; i < runs.size(); i += 2)
      {
        const auto &with    = runs[i].result.zone;
        const auto &without = runs[i - 1].result.zone;
        runs[i].change_a = with.edge_half_width / without.edge_half_width - 1.;
        runs[i].change_peak = with.max_pressure / without.max_pressure - 1.;
      }
  }


  // @sect4{The table}
  //
  // P from the load vector (the pressure on the flat top, integrated);
  // Hertz's a and p0 from the scene's E, nu and R and that P
  // (tutorial::Hertz). The half-width is measured with the edges
  // extrapolated: near a smooth edge the pressure vanishes like a square
  // root, so l1^2 is linear there (doc/theory.md §9). `change` is
  // relative to the frictionless run at the same nu; c/a the stick zone
  // over the contact zone.
  void
  FrictionInHertz::print_scene()
  {
    const CycleResult &first = runs[0].result;
    P                        = first.solve.normal_load;
    pcout << "The half disc on a rigid plane: R = "
          << format("%g", tutorial::Hertz::radius_of(scene))
          << ", E = " << format("%g", scene.material.youngs_modulus)
          << ", P = " << format("%.6f", P) << ", Coulomb F = " << F << "\n"
          << "  one graded mesh: " << first.mesh.n_cells << " cells, "
          << first.mesh.n_dofs << " DoFs, faces on the contact zone h_C = "
          << format("%.6f", runs[0].h_contact) << "\n\n";
  }


  // One row per run; each run's nodes go to its CSV file for plot.gp.
  void
  FrictionInHertz::print_runs() const
  {
    pcout
      << "The four runs:\n"
      << "    nu  beta      F  Hertz a  Hertz p0  a (edges)    change  peak l1"
         "   change   c/a  stick  slip  Uzawa  Newton    CG\n";
    for (const Run &r : runs)
      {
        Parameters parameters              = scene;
        parameters.material.poissons_ratio = r.nu;
        const tutorial::Hertz hertz(parameters, r.result.solve.normal_load);
        const auto           &z = r.result.zone;
        const auto           &s = r.result.solve;
        pcout << format("%6.2f", r.nu) << format("%6.2f", dundurs_beta(r.nu))
              << format("%7.3f", r.F) << format("%9.4f", hertz.a)
              << format("%10.3f", hertz.p0)
              << format("%11.6f", z.edge_half_width);
        if (r.F > 0.)
          pcout << format("%+8.2f", 100. * r.change_a) << " %"
                << format("%9.3f", z.max_pressure)
                << format("%+7.2f", 100. * r.change_peak) << " %"
                << format("%6.2f", r.c / z.edge_half_width)
                << format("%7.0f", s.n_stick) << format("%6.0f", s.n_slip);
        else
          pcout << "         -" << format("%9.3f", z.max_pressure)
                << "        -     -      -     -";
        pcout << format("%7.0f", s.uzawa_steps)
              << format("%8.0f", s.newton_steps)
              << format("%6.0f", s.cg_iterations)
              << (timing ? format("  (%.2f s)", r.time) : "") << "\n";
        write_nodes(r.nodes, scene.output.directory + "/" + r.name + ".csv");
      }
  }


  // For plot.gp: the file names and Hertz's curve of the first pair.
  void
  FrictionInHertz::write_figure_data() const
  {
    if (root)
      {
        const tutorial::Hertz hertz(scene, P);
        std::ofstream(scene.output.directory + "/runs.gp")
          << "files = '" << runs[0].name << ".csv " << runs[1].name << ".csv "
          << runs[2].name << ".csv " << runs[3].name << ".csv'\n"
          << "a = " << hertz.a << "\np0 = " << hertz.p0 << "\nF = " << F
          << "\nnu = " << nu << "\nnu2 = " << nearly_incompressible << "\n";
      }
  }


  // @sect4{The checks}
  tutorial::Checks
  FrictionInHertz::check_results() const
  {
    pcout << "\nChecks:\n";
    tutorial::Checks checks;
    const double     uzawa_tolerance = scene.solver.uzawa_tolerance;

    // 1. The contact alone holds the disc vertically, so the normal force
    //    sum_s m_s l1_s is P, up to the solver tolerances. Sideways only
    //    friction holds it and there is no sideways load, so the tangential
    //    force |sum_s m_s l2_s| vanishes, relative to what friction could
    //    resist, F P.
    double force_error = 0., tangential = 0., excess = -1.;
    for (const Run &r : runs)
      {
        const auto &z = r.result.zone;
        force_error = std::max(force_error, std::abs(z.contact_force / P - 1.));
        if (r.F > 0.)
          {
            tangential = std::max(tangential, z.tangential_force / (r.F * P));
            excess     = std::max(excess, cone_excess(r.nodes));
          }
      }
    checks(force_error <= uzawa_tolerance,
           "every run: normal force = P (relative " +
             format("%.0e", force_error) + " <= the Uzawa tolerance)");
    checks(tangential <= uzawa_tolerance,
           "with friction: tangential force = 0 (" +
             format("%.0e", tangential) +
             " F P <= the Uzawa tolerance times F P)");
    // 2. Coulomb's cone, for the theta each solution was computed with:
    //    exact up to round-off (the projection is the last operation).
    checks(excess <= 1e-12,
           "with friction: |l2| <= theta at every node (max (|l2| - theta) "
           "/ max theta <= 1e-12)");
    // 3. Without friction the zone is Hertz's, within the model error of a
    //    disc of finite radius, O((a/R)^2) = 1 %, and the mesh error
    //    (step-1 measures both).
    {
      const tutorial::Hertz hertz(scene, P);
      const double error = runs[0].result.zone.edge_half_width / hertz.a - 1.;
      checks(std::abs(error) <= 0.01,
             "nu = " + format("%.2f", nu) +
               ", frictionless: a within 1 % of Hertz's (" +
               format("%+.2f", 100. * error) + " %)");
    }
    // 4. The partial-slip pattern at the prm's nu: a stick zone in the
    //    middle, slip zones toward the edges.
    {
      double nearest_slip = 1e300;
      for (const NodeValues &n : runs[1].nodes)
        if (n.status == 2)
          nearest_slip = std::min(nearest_slip, std::abs(n.x));
      checks(runs[1].c >= 0. && nearest_slip < 1e300 &&
               runs[1].c < nearest_slip,
             "nu = " + format("%.2f", nu) +
               ": stick in the middle, slip toward the edges (every stick "
               "node nearer the centre than every slip node)");
    }
    // 5. The narrowing: resolved at the prm's nu (the edges move inward by
    //    more than one contact face), hardly any at 0.49, and at least 5
    //    times less there than at the prm's nu (README.md, "The checks").
    {
      const double shift = runs[0].result.zone.edge_half_width -
                           runs[1].result.zone.edge_half_width;
      checks(shift > runs[0].h_contact,
             "nu = " + format("%.2f", nu) +
               ": friction narrows the contact zone (a changes by " +
               format("%+.2f", 100. * runs[1].change_a) + " %, " +
               format("%.1f", shift / runs[0].h_contact) +
               " contact faces > 1)");
    }
    checks(std::abs(runs[3].change_a) <= 0.005,
           "nu = " + format("%.2f", nearly_incompressible) +
             ": friction hardly changes the zone (|" +
             format("%+.2f", 100. * runs[3].change_a) + " %| <= 0.5 %)");
    checks(std::abs(runs[1].change_a) >= 5. * std::abs(runs[3].change_a),
           "the narrowing at nu = " + format("%.2f", nu) +
             " is at least 5 times that at nu = " +
             format("%.2f", nearly_incompressible) + " (" +
             format("%.1f", runs[1].change_a / runs[3].change_a) + " times)");
    return checks;
  }


  // The step as run_tutorial() calls it: the program on the scene.
  tutorial::Checks
  run(const Parameters &scene)
  {
    return FrictionInHertz(scene).run();
  }
} // namespace Step4

// @sect3{The main function}
//
// MPI, the parameter file (default step-4.prm) and, after it, overrides as
// the dualcontact program takes them (`--set "Friction/Coefficient=0.175"`),
// for the experiments of README.md; one message and a non-zero exit status
// on any error or failed check.
int
main(int argc, char *argv[])
{
  return dualcontact::tutorial::run_tutorial(
    argc, argv, "step-4", "step-4.prm", Step4::run);
}
