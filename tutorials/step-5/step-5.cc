/* step-5: nested meshes, and what accuracy costs in time.
 *
 * Step-1 solved frictionless Hertz contact and wrote the Uzawa iteration
 * out by hand. This step keeps the library's solver and asks about the
 * meshes instead: on a sequence of nested meshes, which refinement reaches
 * a given accuracy of the contact pressure soonest, and what does it save
 * to start each mesh from the previous mesh's solution (nested iteration)
 * rather than from zero? The program runs one Hertz scene six times, three
 * refinement strategies each with nested iteration and with cold starts,
 * and compares the errors against the degrees of freedom and against the
 * wall time. The theory is doc/theory.md §7; README.md has the
 * introduction and the results.
 */

// @sect3{Include files}
//
// The library's Problem class and its parameters are all this step needs:
// it chooses parameters, calls the phases of a refinement cycle in order,
// and reads the figures each phase returns.
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <dualcontact/contact_problem.h>
#include <dualcontact/parameters.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace Step3
{
  using namespace dealii;
  using namespace dualcontact;

  // @sect3{The six runs}
  //
  // A configuration is a refinement strategy and a way to start each mesh.
  // The strategies (doc/theory.md §7) differ only in the cells that
  // refine_mesh() marks:
  //
  // - global: every cell; h is halved and the number N of DoFs grows about
  //   fourfold per cycle;
  // - kelly: the 30 % of the cells (<Refinement/Refine fraction>) with the
  //   largest Kelly indicator, deal.II's jump of the normal derivative of
  //   u_h across the interior faces F of a cell K,
  //     eta_K^2 = sum_F h_K/24 int_F |[d u_h / d n]|^2;
  // - contact: the same, plus, on the faces F of K on Gamma_C, the residual
  //   of the traction condition sigma(u) n_Omega + l1 n + l2 t = 0 that the
  //   multipliers impose (doc/theory.md §1),
  //     eta_K^2 += w sum_F h_F / E^2 int_F |R|^2,
  //     R = sigma(u_h) n_Omega + l1 n + l2 t,
  //   l1, l2 interpolated from their nodal values, w = <Refinement/Contact
  //   indicator weight> (source/refinement.cc). Dividing by E^2 gives the
  //   term Kelly's units, so w has none.
  //
  // Every new mesh contains the old one: each old cell is a cell or a union
  // of cells of the new mesh, so the Q1 spaces are nested,
  // V_0 ⊂ V_1 ⊂ ... . That makes nested iteration exact for v: the old
  // u_h is a function of the new space.
  //
  // `nested` starts each refined mesh from the previous one's fields
  // (<Refinement/Nested iteration>); otherwise every mesh starts from
  // v = 0, l1 = l2 = 0. `compare` also solves each refined mesh of the
  // nested run again from zero, on the same mesh (<Refinement/Compare with
  // cold start>), and measures how far apart the two solutions are. The
  // separate cold runs give the cost; this comparison shows that nested
  // iteration changes the cost and nothing else.
  struct Configuration
  {
    std::string name;
    std::string strategy; // <Refinement/Strategy>
    bool        nested;
    bool        compare;
  };

  struct Run
  {
    Configuration            configuration;
    std::vector<CycleResult> cycles;
  };

  // @sect3{One run: the refinement cycles}
  //
  // This is ContactProblem::run() written out, so that the place of each
  // phase shows, with one change: a run may stop once its mesh has
  // `dof_budget` DoFs instead of after <Refinement/Number of cycles>. Each
  // run gets its own copy of the scene (the Problem keeps a reference to
  // it) and its own subdirectory of the output directory. There the report
  // writes cycles.csv, every figure of every cycle including the wall times
  // of the phases. The library's screen output goes into a string, and from
  // it into screen.log in the same directory; the screen shows only this
  // program's summary.
  template <int dim>
  std::vector<CycleResult>
  run_configuration(const Parameters             &scene,
                    const Configuration          &configuration,
                    const types::global_dof_index dof_budget)
  {
    Parameters parameters                    = scene;
    parameters.refinement.strategy           = configuration.strategy;
    parameters.refinement.nested_iteration   = configuration.nested;
    parameters.refinement.compare_cold_start = configuration.compare;
    parameters.output.directory =
      scene.output.directory + "/" + configuration.name;

    std::ostringstream  log;
    ContactProblem<dim> problem(parameters, MPI_COMM_WORLD, log);
    Report<dim>        &report = problem.get_report();

    problem.make_grid();
    for (unsigned int cycle = 0;; ++cycle)
      {
        // Marking and refinement. With nested iteration refine_mesh() hands
        // u_h and the nodal fields l1, l2, g to a SolutionTransfer before
        // the cells are split, which interpolates them onto the new mesh.
        if (cycle > 0)
          problem.refine_mesh();

        // The new DoFs, hanging-node and boundary constraints, contact
        // nodes; then the transfer (doc/theory.md §7). v is interpolated
        // (exact under refinement) and the new mesh's constraints are
        // applied to it. l1, l2 and g are interpolated as nodal fields,
        // read at the new contact nodes and projected onto the admissible
        // set,
        //   l1 <- max(l1, 0),  g <- max(g, 0),  l2 <- proj_g(l2).
        // Hat functions are non-negative and sum to one, so under pure
        // refinement the projection only safeguards; the report records in
        // cycles.csv how far the carried fields were from the set.
        CycleResult result;
        result.mesh     = problem.setup_system(cycle);
        result.transfer = problem.transfer_fields();
        report.start_cycle(result.mesh, result.transfer);

        // Assembly and the contact solve: the Uzawa iteration around the
        // Newton iteration (no threshold iteration: there is no friction),
        // from the carried fields or from zero.
        problem.assemble_system();
        result.solve = problem.solve();

        // The contact force and the errors of the pressure against Hertz
        // (doc/theory.md §9); in the comparing run, the cold solve of the
        // same mesh.
        result.zone   = problem.measure_contact_zone();
        result.cold   = problem.compare_with_cold_start();
        result.errors = problem.postprocess();

        // output_results() makes the output directory on the first cycle
        // (and writes .vtu files if <Output/Write vtu> is set); end_cycle()
        // takes the phases' wall times from the timer, adds them to
        // time.total, the wall time of all cycles so far, and writes
        // cycles.csv.
        problem.output_results(cycle);
        report.end_cycle(result);

        if (dof_budget > 0 ? result.mesh.n_dofs >= dof_budget :
                             cycle + 1 == parameters.refinement.n_cycles)
          break;
      }
    report.finish();

    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::ofstream(parameters.output.directory + "/screen.log") << log.str();
    return problem.results();
  }

  // @sect3{Small helpers}
  const Run &
  find_run(const std::vector<Run> &runs, const std::string &name)
  {
    for (const Run &run : runs)
      if (run.configuration.name == name)
        return run;
    AssertThrow(false, ExcMessage("no run named " + name));
    return runs.front();
  }

  std::string
  scientific(const double x, const int digits = 2)
  {
    std::ostringstream s;
    s << std::scientific << std::setprecision(digits) << x;
    return s.str();
  }

  // @sect3{What the screen shows}
  //
  // One table per run: the mesh, the three errors of the contact zone (the
  // relative L2 error of the pressure on Gamma_C; the signed relative
  // errors of the half-width a and of the peak pressure p0), and the work
  // of the solver: Uzawa steps, Newton steps, CG iterations of the cycle.
  // The comparing run adds the steps of the cold solve of the same mesh.
  // Wall times, and the round-off-level differences between the nested and
  // the cold solution, change from one run to the next: they are printed
  // only with <Output/Print timing> = true, so that the screen output is
  // otherwise reproducible. cycles.csv always has them.
  void
  print_run(ConditionalOStream &pcout, const Run &run, const bool timing)
  {
    const Configuration &c = run.configuration;
    pcout << "\n"
          << c.name << ": " << c.strategy << " refinement, "
          << (c.nested ? "nested iteration" : "cold starts") << "\n"
          << "cycle   cells    DoFs  nodes  p error   a error    p0 error  "
             " Uzawa Newton   CG"
          << (c.compare ? " | cold: Uzawa Newton" : "")
          << (c.compare && timing ? "  diff v    diff l1" : "")
          << (timing ? " | solve[s] total[s]" : "") << "\n";
    for (const CycleResult &r : run.cycles)
      {
        std::ostringstream line;
        line << std::setw(5) << r.mesh.cycle << std::setw(8) << r.mesh.n_cells
             << std::setw(8) << r.mesh.n_dofs << std::setw(7)
             << r.solve.n_contact_nodes << std::scientific
             << std::setprecision(2) << "  " << r.zone.pressure_error
             << std::showpos << "  " << r.zone.half_width_error << "  "
             << r.zone.peak_pressure_error << std::noshowpos << std::setw(6)
             << r.solve.uzawa_steps << std::setw(7) << r.solve.newton_steps
             << std::setw(5) << r.solve.cg_iterations;
        if (c.compare && r.mesh.cycle == 0) // the first mesh: no carried start
          line << " |           -      -"
               << (timing ? "         -         -" : "");
        else if (c.compare)
          {
            line << " |       " << std::setw(5) << r.cold.uzawa_steps
                 << std::setw(7) << r.cold.newton_steps;
            if (timing)
              line << "  " << r.cold.difference_v << "  "
                   << r.cold.difference_l1;
          }
        if (timing)
          line << std::fixed << std::setprecision(3) << " | " << std::setw(8)
               << r.time.solve << std::setw(9) << r.time.total;
        pcout << line.str() << "\n";
      }
  }

  // @sect3{What accuracy costs}
  //
  // The cost of an accuracy e is read off a run at the first cycle whose
  // pressure error is at most e: its DoFs, and its cumulative wall time
  // time.total. The cumulative time is the honest price, since an adaptive
  // mesh cannot be had without the coarser meshes whose solutions chose it.
  // With a solver whose cost is about proportional to N, a sequence whose
  // N grows by a factor q per cycle costs about q/(q - 1) times its last
  // mesh: 4/3 for global refinement, about 2 for the adaptive strategies
  // (q ≈ 1.9 at a refine fraction of 0.3).
  const CycleResult *
  first_reaching(const Run &run, const double error)
  {
    for (const CycleResult &r : run.cycles)
      if (r.zone.pressure_error <= error)
        return &r;
    return nullptr;
  }

  void
  print_costs(ConditionalOStream        &pcout,
              const std::vector<Run>    &runs,
              const std::vector<double> &targets,
              const bool                 timing)
  {
    const unsigned int width = timing ? 26 : 17;
    pcout << "\nFirst cycle reaching a pressure error of (cycle: DoFs"
          << (timing ? ", cumulative wall time" : "") << "):\n"
          << "configuration ";
    for (const double e : targets)
      pcout << std::setw(width) << scientific(e);
    pcout << "\n";
    for (const Run &run : runs)
      {
        pcout << std::left << std::setw(14) << run.configuration.name
              << std::right;
        for (const double e : targets)
          {
            std::ostringstream cell;
            if (const CycleResult *r = first_reaching(run, e))
              {
                cell << r->mesh.cycle << ": " << r->mesh.n_dofs;
                if (timing)
                  cell << ", " << std::fixed << std::setprecision(3)
                       << r->time.total << " s";
              }
            else
              cell << "not reached";
            pcout << std::setw(width) << cell.str();
          }
        pcout << "\n";
      }
  }

  // @sect3{Nested iteration against cold starts}
  //
  // The steps of the two runs of each strategy, summed over the refined
  // meshes (cycle 0 is the same cold solve in both). Why the Uzawa steps
  // fall a little and the Newton steps a lot: the Uzawa iteration contracts
  // the error of l1 by a roughly fixed factor rho per step (0.03 to 0.19
  // here, the "Uzawa contraction rate" of screen.log) and stops when the
  // relative change of l1 falls below the tolerance tol = 1e-8. From an
  // initial relative error e0 that takes about log(e0/tol) / log(1/rho)
  // steps: 7 to 10 from l1 = 0 (e0 = 1), 6 to 9 from the carried l1, whose
  // error is only the change of discretisation (the first d(l1) of a nested
  // solve: e0 = 5e-2 to 5e-3). The Newton iteration inside each Uzawa step
  // starts from the previous step's v and active set: from the carried
  // ones the active set is right at once, and one Newton step per Uzawa
  // step nearly always suffices; from zero the first Uzawa step needs 4 to 10
  // Newton steps to find it, the later ones one each.
  struct Totals
  {
    unsigned int uzawa = 0, newton = 0, cg = 0;
    double       time = 0.;
  };

  Totals
  refined_totals(const Run &run)
  {
    Totals t;
    for (unsigned int k = 1; k < run.cycles.size(); ++k)
      {
        t.uzawa += run.cycles[k].solve.uzawa_steps;
        t.newton += run.cycles[k].solve.newton_steps;
        t.cg += run.cycles[k].solve.cg_iterations;
      }
    t.time = run.cycles.back().time.total;
    return t;
  }

  void
  print_savings(ConditionalOStream     &pcout,
                const std::vector<Run> &runs,
                const bool              timing)
  {
    pcout << "\nNested iteration against cold starts (sums over the refined "
             "meshes; nested / cold):\n"
          << "strategy      Uzawa      Newton          CG"
          << (timing ? "   total wall time [s]" : "") << "\n";
    for (const std::string strategy : {"global", "kelly", "contact"})
      {
        const Totals a = refined_totals(find_run(runs, strategy + "-nested"));
        const Totals b = refined_totals(find_run(runs, strategy + "-cold"));
        std::ostringstream line;
        line << std::left << std::setw(8) << strategy << std::right
             << std::setw(6) << a.uzawa << " /" << std::setw(3) << b.uzawa
             << std::setw(6) << a.newton << " /" << std::setw(4) << b.newton
             << std::setw(6) << a.cg << " /" << std::setw(5) << b.cg;
        if (timing)
          line << std::fixed << std::setprecision(3) << std::setw(10) << a.time
               << " /" << std::setw(7) << b.time;
        pcout << line.str() << "\n";
      }
  }

  // @sect3{The checks}
  //
  // What the step claims, checked on its own figures; README.md gives each
  // bound with its reason. All ranks hold the same figures, so all throw
  // together if a check fails, and main() reports it.
  void
  check(ConditionalOStream &pcout, const bool ok, const std::string &what)
  {
    pcout << (ok ? "  passed: " : "  FAILED: ") << what << "\n";
    AssertThrow(ok, ExcMessage("step-5: check failed: " + what));
  }

  void
  check_results(ConditionalOStream     &pcout,
                const std::vector<Run> &runs,
                const Parameters       &scene)
  {
    pcout << "\nChecks:\n";

    // 1. Equilibrium: sum_s m_s l1_s = P, the net load toward the
    // foundation, on every mesh. A rigid translation has no elastic energy,
    // so only the proximal term chi M (v - v^k) (doc/theory.md §3.2), zero
    // at convergence, could make up a difference; it holds to the Uzawa
    // tolerance.
    double worst = 0.;
    for (const Run &run : runs)
      for (const CycleResult &r : run.cycles)
        worst = std::max(worst,
                         std::abs(r.zone.contact_force - r.solve.normal_load) /
                           r.solve.normal_load);
    check(pcout,
          worst <= 1e-6,
          "contact force = applied load to 1e-6 on every mesh of every run");

    // 2. Convergence: the pressure error of every run falls. Under global
    // refinement it falls from each cycle to the next. On adaptive meshes
    // it may stall for a cycle: the error of the square-root pressure sits
    // at the edges x = ±a of the zone and depends on where a falls between
    // two contact nodes, which refinement moves. So adaptive runs are held
    // to a fall over every two cycles, and a stall is named.
    for (const Run &run : runs)
      {
        const bool         global = run.configuration.strategy == "global";
        const unsigned int lag    = global ? 1 : 2;
        bool               falls  = true;
        for (unsigned int k = 1; k < run.cycles.size(); ++k)
          {
            const double e = run.cycles[k].zone.pressure_error;
            if (e >= run.cycles[k - 1].zone.pressure_error)
              pcout << "  note: " << run.configuration.name
                    << ": the pressure error does not fall at cycle " << k
                    << " (" << scientific(e) << " after "
                    << scientific(run.cycles[k - 1].zone.pressure_error)
                    << ")\n";
            if (k >= lag && e >= run.cycles[k - lag].zone.pressure_error)
              falls = false;
          }
        check(pcout,
              falls,
              run.configuration.name + ": the pressure error falls " +
                (global ? "from cycle to cycle" : "over every two cycles"));
      }

    // 3. Adaptivity pays: both adaptive strategies reach the error of the
    // finest global mesh with at most half its DoFs. Global refinement
    // spends most of its DoFs far from Gamma_C, where u is smooth.
    const CycleResult &global = find_run(runs, "global-nested").cycles.back();
    for (const std::string name : {"kelly-nested", "contact-nested"})
      {
        const CycleResult *r =
          first_reaching(find_run(runs, name), global.zone.pressure_error);
        check(pcout,
              r != nullptr && 2 * r->mesh.n_dofs <= global.mesh.n_dofs,
              name + " reaches the finest global error with at most half " +
                "its DoFs (" + (r ? std::to_string(r->mesh.n_dofs) : "none") +
                " vs " + std::to_string(global.mesh.n_dofs) + ")");
      }

    // 4. Nested iteration against cold starts, for each strategy. The cold
    // run must refine to the same meshes, else no step count can be
    // compared; its indicators see the same solution up to the solver's
    // tolerance. Then, summed over the refined meshes, nested iteration
    // needs no more Uzawa steps than the cold starts and at most 3/4 of their
    // Newton steps (mesh by mesh the Uzawa counts differ by a step either
    // way: the contraction rate itself varies from 0.03 to 0.19 between
    // meshes) (for the reasons given above print_savings()); and the
    // pressure errors of the two runs agree to 1e-6.
    for (const std::string strategy : {"global", "kelly", "contact"})
      {
        const Run &nested = find_run(runs, strategy + "-nested");
        const Run &cold   = find_run(runs, strategy + "-cold");
        bool       same   = nested.cycles.size() == cold.cycles.size();
        double     error_difference = 0.;
        for (unsigned int k = 0; same && k < nested.cycles.size(); ++k)
          {
            const CycleResult &a = nested.cycles[k], &b = cold.cycles[k];
            same = a.mesh.n_dofs == b.mesh.n_dofs;
            error_difference =
              std::max(error_difference,
                       std::abs(a.zone.pressure_error / b.zone.pressure_error -
                                1.));
          }
        const Totals a = refined_totals(nested), b = refined_totals(cold);
        check(pcout, same, strategy + ": nested and cold runs, same meshes");
        check(pcout,
              a.uzawa <= b.uzawa,
              strategy + ": nested Uzawa steps <= cold (" +
                std::to_string(a.uzawa) + " vs " + std::to_string(b.uzawa) +
                ")");
        check(pcout,
              4 * a.newton <= 3 * b.newton,
              strategy + ": nested Newton steps <= 3/4 of cold (" +
                std::to_string(a.newton) + " vs " + std::to_string(b.newton) +
                ")");
        check(pcout,
              error_difference <= 1e-6,
              strategy + ": nested and cold pressure errors agree to 1e-6");
      }

    // 5. The same solution. On each refined mesh of the comparing run, the
    // nested and the cold solution differ (v in the energy norm, l1 in the
    // weighted l2 norm, both relative) by at most ten times the Uzawa
    // tolerance: each run stops when the relative change of l1 is below the
    // tolerance, which leaves an error of about rho/(1 - rho) ≈ 0.25 times
    // it (doc/theory.md §6).
    double difference = 0.;
    for (const CycleResult &r : find_run(runs, "contact-nested").cycles)
      difference =
        std::max({difference, r.cold.difference_v, r.cold.difference_l1});
    check(pcout,
          difference <= 10. * scene.solver.uzawa_tolerance,
          "contact: nested and cold solutions of the same mesh differ by at "
          "most 10 x <Uzawa tolerance>");
  }
} // namespace Step3

// @sect3{The main function}
//
// Read the scene and run the six configurations. The adaptive ones run
// first, so that global refinement can be given the size of their finest
// mesh as its budget: it refines until it has at least as many DoFs. That
// compares the strategies over the same range of DoFs, with any advantage
// to global refinement. Then the tables and the checks.
int
main(int argc, char *argv[])
{
  using namespace Step3;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ConditionalOStream               pcout(std::cout,
                           Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) ==
                             0);
  try
    {
      Parameters scene;
      scene.read_file(argc > 1 ? argv[1] : "step-5.prm");
      AssertThrow(scene.geometry.dimension == 2 &&
                    scene.exact.contact_half_width > 0. &&
                    !scene.exact.contact_pressure.empty(),
                  ExcMessage("step-5 needs a 2D scene with an exact contact "
                             "pressure and half-width (Hertz)"));
      const bool timing = scene.output.print_timing;
      pcout << "step-5: Hertz contact, a = " << scene.exact.contact_half_width
            << ", p0 = " << scene.exact.peak_pressure << "; "
            << scene.refinement.n_cycles
            << " adaptive cycles, global refinement up to as many DoFs\n";

      const std::vector<Configuration> configurations = {
        {"contact-nested", "contact", true, true},
        {"contact-cold", "contact", false, false},
        {"kelly-nested", "kelly", true, false},
        {"kelly-cold", "kelly", false, false},
        {"global-nested", "global", true, false},
        {"global-cold", "global", false, false}};
      std::vector<Run>        runs;
      types::global_dof_index budget = 0;
      for (const Configuration &c : configurations)
        {
          const bool global = c.strategy == "global";
          runs.push_back(
            {c, run_configuration<2>(scene, c, global ? budget : 0)});
          if (!global)
            budget = std::max(budget, runs.back().cycles.back().mesh.n_dofs);
          print_run(pcout, runs.back(), timing);
        }

      // Three accuracies to compare at: 3 % and 1 %, and the error of the
      // finest global mesh.
      print_costs(
        pcout,
        runs,
        {3e-2,
         1e-2,
         find_run(runs, "global-nested").cycles.back().zone.pressure_error},
        timing);
      print_savings(pcout, runs, timing);
      check_results(pcout, runs, scene);
    }
  catch (const std::exception &exc)
    {
      // as source/main.cc: the message on rank 0, exit status 1
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::cerr << "step-5: error: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}
