/* step-9: higher-order elements.
 *
 * Steps 1-8 used FE_Q(1). The library also offers FE_Q(2) and FE_Q(3),
 * each with a mapping of the same degree, so that the contact boundary
 * follows the disc's circle between the vertices (doc/theory.md §4). This
 * step asks what a higher degree buys for contact, on the frictionless
 * Hertz cylinder of step-1 with a quarter of its load (a/R = 1/20, so that
 * Hertz's half-space formulas are a sharp reference):
 *   1. at nu = 0.3, degrees 1, 2 and 3 on the same globally refined
 *      meshes: the error of the contact pressure against DoFs, and the rate
 *      at which it falls. The pressure has square-root edges, and these,
 *      not the degree, set the rate;
 *   2. at nu = 0.49, degree 1 against degree 2 on about the same number of
 *      DoFs: Q1 elements lock as the material becomes incompressible, and
 *      the peak pressure shows it.
 * The scene is step-9.prm; README.md has the introduction and the results.
 */

// @sect3{Include files}
//
// The library's Problem class (the whole solver, one refinement cycle after
// the other), its parameters, and the tutorials' tools (Hertz's formulas,
// the checks, main()).
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <dualcontact/contact_problem.h>
#include <dualcontact/parameters.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "../common/tutorial_tools.h"

namespace Step9
{
  using namespace dealii;
  using namespace dualcontact;

  using tutorial::format;

  constexpr unsigned int dim = 2;

  // The Poisson's ratio of the locking study: close enough to 1/2 that Q1
  // elements lock visibly, far enough that the CG iteration on Q2 stays
  // affordable (its iterations per Newton step grow as nu -> 1/2).
  constexpr double locking_nu = 0.49;

  // @sect3{One run: a degree on a sequence of meshes}
  //
  // The scene at degree k with `n_cycles` meshes, each refined globally
  // from the one before, solved by ContactProblem::run() into its own
  // folder under output/. The run keeps the record of every mesh
  // (records.h): DoFs, contact nodes, the errors against the scene's
  // <Exact solution>, the iteration counts and the wall times.
  struct Run
  {
    unsigned int             degree = 1;
    double                   nu     = 0.;
    std::vector<CycleResult> cycles;
  };

  Run
  solve(const Parameters  &scene,
        const unsigned int degree,
        const unsigned int n_cycles,
        const std::string &name)
  {
    Parameters parameters            = scene;
    parameters.discretization.degree = degree;
    parameters.refinement.n_cycles   = n_cycles;
    parameters.output.directory += "/" + name;

    std::ostringstream  silent;
    ContactProblem<dim> problem(parameters, MPI_COMM_WORLD, silent);
    problem.run();
    return {degree, parameters.material.poissons_ratio, problem.results()};
  }

  // @sect3{The load}
  //
  // Hertz's a and p0 follow from P, the force per unit thickness that
  // pushes the disc onto the plane. The library computes it from the load
  // vector when it prepares a contact solve (SolveRecord::normal_load):
  // here on the first mesh at degree 1, without solving.
  double
  applied_load(const Parameters &scene)
  {
    Parameters parameters            = scene;
    parameters.discretization.degree = 1;
    std::ostringstream  silent;
    ContactProblem<dim> problem(parameters, MPI_COMM_WORLD, silent);
    problem.make_grid();
    problem.setup_system(0);
    problem.transfer_fields();
    problem.assemble_system();
    return problem.prepare_contact_solve().normal_load;
  }

  // @sect3{Hertz's pressure as the scene's exact solution}
  //
  // The library measures the errors against the entries of <Exact
  // solution>: the pressure p(x) = p0 sqrt(1 - x^2/a^2), the half-width a
  // and the peak p0. They depend on nu through E* = E / (1 - nu^2):
  //   a = sqrt(4 P R / (pi E*)),   p0 = 2 P / (pi a),
  // so a scene at another nu needs them anew.
  void
  set_exact_solution(Parameters &parameters, const tutorial::Hertz &hertz)
  {
    parameters.exact.contact_pressure =
      format("%.17g", hertz.p0) + " * sqrt(max(0, 1 - x^2 / " +
      format("%.17g", hertz.a * hertz.a) + "))";
    parameters.exact.contact_half_width = hertz.a;
    parameters.exact.peak_pressure      = hertz.p0;
  }

  // @sect3{The rate per DoF}
  //
  // If e ~ C N^(-s) the rate per DoF is s = ln(e_1/e_2) / ln(N_2/N_1)
  // between two meshes; in 2D N ~ h^-2, so e ~ h^q means s = q/2. Over
  // several meshes: the least-squares slope of ln e against ln N.
  double
  rate(const CycleResult &coarse, const CycleResult &fine)
  {
    return std::log(coarse.zone.pressure_error / fine.zone.pressure_error) /
           std::log(double(fine.mesh.n_dofs) / coarse.mesh.n_dofs);
  }

  double
  fitted_rate(const std::vector<CycleResult> &cycles)
  {
    double       sx = 0., sy = 0., sxx = 0., sxy = 0.;
    const double n = cycles.size();
    for (const CycleResult &r : cycles)
      {
        const double x = std::log(double(r.mesh.n_dofs));
        const double y = std::log(r.zone.pressure_error);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
      }
    return -(n * sxy - sx * sy) / (n * sxx - sx * sx);
  }

  // @sect3{The table of a run}
  //
  // One line per mesh: degree, mesh, DoFs, contact nodes, the relative L2
  // error of the pressure on Gamma_C (the computed l1 interpolated by the
  // element's own shape functions on each face, against Hertz's p, by a
  // Gauss rule of k + 3 points), the relative errors of the peak pressure
  // max_s l1_s and of the half-width (edges extrapolated), the CG
  // iterations per Newton step, and with <Output/Print timing> the wall
  // time of the mesh's phases (the solve, and everything around it).
  std::string
  header(const bool timing)
  {
    return std::string("  k  cycle  cells   DoFs  nodes  pressure err  peak "
                       "err  half-width err  CG/Newton") +
           (timing ? "  time [s]" : "");
  }

  std::string
  row(const Run &run, const unsigned int cycle, const bool timing)
  {
    const CycleResult &r = run.cycles[cycle];
    return format("%3.0f", run.degree) + format("%7.0f", cycle) +
           format("%7.0f", double(r.mesh.n_cells)) +
           format("%7.0f", double(r.mesh.n_dofs)) +
           format("%7.0f", double(r.solve.n_contact_nodes)) +
           format("%14.3e", r.zone.pressure_error) +
           format("%+10.2e", r.zone.peak_pressure_error) +
           format("%+16.2e", r.zone.half_width_error) +
           format("%11.1f",
                  double(r.solve.cg_iterations) /
                    std::max(1u, r.solve.newton_steps)) +
           (timing ? format("%10.2f", r.time.cycle) : "");
  }

  // @sect3{The whole step}
  //
  // The program in the shape of deal.II's steps: a class whose run() reads
  // as its stages, one member function each, and members for what a later
  // stage needs of an earlier one (the load, the runs and their rates).
  class DegreeStudy
  {
  public:
    explicit DegreeStudy(const Parameters &scene);

    tutorial::Checks
    run();

  private:
    void
    check_scene();
    void
    study_three_degrees();
    void
    print_rates();
    void
    study_locking();
    void
    write_figure_data() const;
    tutorial::Checks
    check_results() const;

    // The scene, the screen (rank 0 prints), whether it shows times, and
    // its number of meshes.
    const Parameters  &scene;
    const bool         root;
    ConditionalOStream pcout;
    const bool         timing;
    const unsigned int n_cycles;

    // The load P, the runs of the three degrees with their rates per DoF
    // (the last two meshes', the fitted), and the two runs at nu = 0.49.
    double              P = 0.;
    std::vector<Run>    runs;
    std::vector<double> last_rates, fitted_rates;
    std::vector<Run>    locking;
  };


  DegreeStudy::DegreeStudy(const Parameters &scene)
      : scene(scene)
      , root(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      , pcout(std::cout, root)
      , timing(scene.output.print_timing)
      , n_cycles(scene.refinement.n_cycles)
  {}


  // The three degrees and their rates, the locking test, the data for
  // plot.gp and the checks.
  tutorial::Checks
  DegreeStudy::run()
  {
    check_scene();
    study_three_degrees();
    print_rates();
    study_locking();
    write_figure_data();
    return check_results();
  }


  // The rates of this step are those of frictionless plane-strain Hertz on
  // globally refined meshes; anything else is refused with one message
  // before a solve.
  void
  DegreeStudy::check_scene()
  {
    tutorial::require(
      scene.geometry.dimension == dim && scene.geometry.type == "half disc" &&
        scene.friction.law == "none" && scene.refinement.strategy == "global" &&
        n_cycles >= 2,
      "step-9 compares the rates of frictionless plane-strain "
      "Hertz on globally refined meshes: it needs the 2D half "
      "disc without friction, <Refinement/Strategy> = global and "
      "two <Refinement/Number of cycles> or more.");
    if (root)
      std::filesystem::create_directories(scene.output.directory);

    pcout << "step-9: higher-order elements ("
          << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
          << " MPI rank(s))\n\n";
  }


  // @sect4{Three degrees on the same meshes}
  //
  // FE_Q(k) for k = 1, 2, 3 on the scene's meshes: on one mesh FE_Q(2)
  // has about 4 and FE_Q(3) about 9 times the DoFs of FE_Q(1), and as
  // many more contact nodes per contact face (k per face in 2D). Each
  // run's errors are measured against Hertz for the scene's own nu and
  // load, so that `--set "Material/Poisson's ratio=..."` needs no other
  // change; the scene's <Exact solution> entries serve a plain run of
  // the dualcontact program.
  void
  DegreeStudy::study_three_degrees()
  {
    P = applied_load(scene);
    const tutorial::Hertz hertz(scene, P);
    Parameters            study = scene;
    set_exact_solution(study, hertz);
    for (const unsigned int k : {1u, 2u, 3u})
      runs.push_back(solve(study, k, n_cycles, "study_k" + std::to_string(k)));

    pcout << "Hertz (plane strain), nu = " << scene.material.poissons_ratio
          << ": P = " << format("%.6f", P)
          << ", a = " << format("%.6f", hertz.a)
          << ", p0 = " << format("%.5f", hertz.p0) << "\n\n"
          << "Degrees at nu = " << scene.material.poissons_ratio
          << ", global refinement:\n"
          << header(timing) << "\n";
    for (const Run &r : runs)
      for (unsigned int c = 0; c < r.cycles.size(); ++c)
        pcout << row(r, c, timing) << "\n";
  }


  // The rates per DoF: between the last two meshes, and the least-squares
  // slope over all of them. The README explains why they are about 1/2
  // whatever the degree: the element that holds the edge of the zone has
  // an error of order h there.
  void
  DegreeStudy::print_rates()
  {
    pcout << "\nRates per DoF of the pressure error, s in e ~ N^(-s):\n"
          << "  k  last two meshes  all meshes (least squares)  smooth p: "
             "(k+1)/2\n";
    for (const Run &r : runs)
      {
        last_rates.push_back(
          rate(r.cycles[n_cycles - 2], r.cycles[n_cycles - 1]));
        fitted_rates.push_back(fitted_rate(r.cycles));
        pcout << format("%3.0f", r.degree)
              << format("%17.2f", last_rates.back())
              << format("%28.2f", fitted_rates.back())
              << format("%21.1f", (r.degree + 1.) / 2.) << "\n";
      }
  }


  // @sect4{Locking at nu = 0.49}
  //
  // The same scene at nu = 0.49, with Hertz's a and p0 for that nu (the
  // load stays). Degree 1 on the finest mesh of the study against degree
  // 2 on the mesh one refinement coarser: about the same DoFs. As nu ->
  // 1/2 the bulk modulus lambda + 2 mu/3 grows without bound against mu,
  // and a displacement field has to be nearly divergence-free to keep its
  // energy finite. Few bilinear fields on a mesh are nearly divergence-
  // free, many more biquadratic ones: the Q1 body is too stiff (it locks),
  // and in contact too stiff means a narrower zone and a higher peak,
  // since a ~ E*^(-1/2) and p0 ~ E*^(1/2).
  void
  DegreeStudy::study_locking()
  {
    Parameters nearly_incompressible              = scene;
    nearly_incompressible.material.poissons_ratio = locking_nu;
    const tutorial::Hertz hertz_049(nearly_incompressible, P);
    set_exact_solution(nearly_incompressible, hertz_049);
    locking.push_back(solve(nearly_incompressible, 1, n_cycles, "locking_k1"));
    locking.push_back(
      solve(nearly_incompressible, 2, n_cycles - 1, "locking_k2"));

    pcout << "\nLocking at nu = " << locking_nu << ": P = " << format("%.6f", P)
          << ", a = " << format("%.6f", hertz_049.a)
          << ", p0 = " << format("%.5f", hertz_049.p0)
          << "; each degree's last mesh\n"
          << header(timing) << "\n";
    for (const Run &r : locking)
      pcout << row(r, r.cycles.size() - 1, timing) << "\n";
  }


  // @sect4{The figure's data}
  //
  // One row per mesh of every run: plot.gp draws the pressure error
  // against the DoFs (pressure_error.svg).
  void
  DegreeStudy::write_figure_data() const
  {
    if (root)
      {
        std::ofstream csv(scene.output.directory + "/degrees.csv");
        csv << "nu,degree,cycle,cells,dofs,contact_nodes,pressure_error,"
               "peak_error,half_width_error,cg_per_newton\n";
        csv.precision(10);
        for (const std::vector<Run> *set : {&runs, &locking})
          for (const Run &run : *set)
            for (unsigned int c = 0; c < run.cycles.size(); ++c)
              {
                const CycleResult &r = run.cycles[c];
                csv << run.nu << ',' << run.degree << ',' << c << ','
                    << r.mesh.n_cells << ',' << r.mesh.n_dofs << ','
                    << r.solve.n_contact_nodes << ',' << r.zone.pressure_error
                    << ',' << r.zone.peak_pressure_error << ','
                    << r.zone.half_width_error << ','
                    << double(r.solve.cg_iterations) /
                         std::max(1u, r.solve.newton_steps)
                    << '\n';
              }
      }
  }


  // @sect4{The checks}
  //
  // What the README claims, on the step's own numbers; the README's table
  // "The checks" gives each bound's reason.
  tutorial::Checks
  DegreeStudy::check_results() const
  {
    pcout << "\nChecks:\n";
    tutorial::Checks checks;
    // 1. Every degree converges: its pressure error falls from each mesh to
    //    the next.
    for (const Run &r : runs)
      {
        bool        falls = true;
        std::string errors;
        for (unsigned int c = 0; c < r.cycles.size(); ++c)
          {
            falls &= c == 0 || r.cycles[c].zone.pressure_error <
                                 r.cycles[c - 1].zone.pressure_error;
            errors += (c == 0 ? "" : ", ") +
                      format("%.2e", r.cycles[c].zone.pressure_error);
          }
        checks(falls,
               "degree " + std::to_string(r.degree) +
                 ": the pressure error falls under refinement (" + errors +
                 ")");
      }
    // 2. The edge sets the rate: for every degree the fitted rate per DoF
    //    lies between 1/4 and 3/4, about the 1/2 of an error of order h,
    //    and far from the (k+1)/2 a smooth pressure would allow at k >= 2.
    {
      bool        near_half = true;
      std::string rates;
      for (unsigned int i = 0; i < runs.size(); ++i)
        {
          near_half &= fitted_rates[i] >= 0.25 && fitted_rates[i] <= 0.75;
          rates += (i == 0 ? "" : ", ") + format("%.2f", fitted_rates[i]);
        }
      checks(near_half,
             "the fitted rates per DoF (" + rates +
               ") lie in [0.25, 0.75] for every degree");
    }
    // 3. Locking: at nu = 0.49 degree 2 gives the peak within 1 % of p0,
    //    and degree 1 on about as many DoFs is not better.
    {
      const double peak_1 = locking[0].cycles.back().zone.peak_pressure_error;
      const double peak_2 = locking[1].cycles.back().zone.peak_pressure_error;
      checks(std::abs(peak_2) <= 0.01,
             "nu = 0.49, degree 2: the peak pressure within 1 % of p0 (" +
               format("%+.2f", 100. * peak_2) + " %)");
      checks(std::abs(peak_1) >= std::abs(peak_2),
             "nu = 0.49: degree 1's peak error (" +
               format("%+.2f", 100. * peak_1) +
               " %) is not smaller than degree 2's on about as many DoFs");
    }
    return checks;
  }


  // The step as run_tutorial() calls it: the program on the scene.
  tutorial::Checks
  run(const Parameters &scene)
  {
    return DegreeStudy(scene).run();
  }
} // namespace Step9

// @sect3{The main function}
//
// MPI, the parameter file (default step-9.prm) and, after it, overrides as
// the dualcontact program takes them (`--set "Refinement/Number of
// cycles=4"`), for the experiments of README.md; one message and a
// non-zero exit status on any error or failed check.
int
main(int argc, char *argv[])
{
  return dualcontact::tutorial::run_tutorial(
    argc, argv, "step-9", "step-9.prm", Step9::run);
}
