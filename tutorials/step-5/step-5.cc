/* step-5: nested meshes, and what accuracy costs in time.
 *
 * Step-1 solved frictionless Hertz contact on one mesh and wrote the Uzawa
 * iteration out. This step keeps the library's solver and asks about the
 * meshes: on a sequence of nested meshes, which refinement reaches a given
 * accuracy of the contact pressure with the fewest DoFs and in the least
 * time, and what does it save to start each mesh from the previous mesh's
 * solution (nested iteration) rather than from zero? It also writes a
 * refinement indicator of its own, for the edge of the contact zone, and
 * registers it with the library the way any program can. The theory is
 * doc/theory.md §7; README.md has the introduction and the results.
 */

// @sect3{Include files}
//
// The library's Problem class, its parameters and the registry of
// refinement indicators (refinement_indicator.h), with Kelly's estimator
// (refinement.h) to build on; the shared tools of the tutorials.
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <dualcontact/contact_problem.h>
#include <dualcontact/parameters.h>
#include <dualcontact/refinement.h>
#include <dualcontact/refinement_indicator.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "../common/tutorial_tools.h"

namespace Step5
{
  using namespace dealii;
  using namespace dualcontact;

  using tutorial::format;

  // @sect3{An indicator of one's own: the edge of the contact zone}
  //
  // The pressure p = p0 sqrt(1 - x^2/a^2) has an infinite slope at the
  // edges x = ±a, and the discrete zone ends at a node, not at a: the error
  // of the pressure is made in the elements around the edge. Where is the
  // edge on the mesh? At the solution every contact node satisfies the
  // complementarity l1 (g0 - u_n) = 0: either it presses (l1 > 0, gap 0) or
  // it is open (l1 = 0, gap >= 0). A face of Gamma_C whose nodes disagree,
  // one pressing and one open, contains the edge. So the term
  //   eta_F^2 = |F| / E * mean(l1) * mean(gap)
  // over the vertices of a face F (the gap taken as zero where l1 > 0) is
  // non-zero on exactly the faces that contain an edge of the zone, and
  // grows with the pressure and the gap met there. Dividing by E makes
  // l1 / E a strain and the term a length^dim, the units of Kelly's eta^2,
  // so its weight w has none. It cannot refine alone: the marking refines
  // a fixed fraction of the cells, and all but a few would tie at zero. It
  // is added to Kelly's indicator, as the library's 'contact' adds its
  // traction residual:
  //   eta_K^2 = eta_Kelly^2 + w sum_{F of K on Gamma_C} eta_F^2.
  // Everything it reads comes in IndicatorInput: the solution (ghosted),
  // the contact set with its obstacle and normals, the multiplier field,
  // and the value of its own entry.
  template <int dim>
  Vector<float>
  edge_indicator(const IndicatorInput<dim> &input)
  {
    Vector<float> eta =
      kelly_indicator(input.mapping, input.dof_handler, input.solution);
    if (input.contact_ids.empty())
      return eta;
    const TrilinosWrappers::MPI::Vector l1 = input.multipliers(); // comp. 0
    const double E = input.parameters.material.youngs_modulus;
    const double w =
      numbers_of(input.values, "Refinement/Edge indicator weight").at(0);

    for (const auto &cell : input.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              input.contact_ids.count(cell->face(f)->boundary_id()))
            {
              const auto   face    = cell->face(f);
              double       mean_l1 = 0., mean_gap = 0.;
              const double n_vertices = face->n_vertices();
              for (const unsigned int v : face->vertex_indices())
                {
                  const Point<dim> x        = face->vertex(v);
                  const double     pressure = l1[face->vertex_dof_index(v, 0)];
                  // u_n = u . n with n the body's normal toward the obstacle
                  const Tensor<1, dim> n   = input.contact.basis_at(x).first;
                  double               u_n = 0.;
                  for (unsigned int c = 0; c < dim; ++c)
                    u_n += input.solution[face->vertex_dof_index(v, c)] * n[c];
                  const double gap =
                    pressure > 0. ?
                      0. :
                      std::max(0., input.contact.obstacle->distance(x) - u_n);
                  mean_l1 += pressure / n_vertices;
                  mean_gap += gap / n_vertices;
                }
              const double term = face->measure() / E * mean_l1 * mean_gap;
              if (w * term > 0.) // w = 0: exactly Kelly's indicator
                {
                  float &e = eta[cell->active_cell_index()];
                  e        = std::sqrt(e * e + w * term);
                }
            }
    return eta;
  }

  // The indicator owns its entry: declared in subsection Refinement, read
  // into input.values, and named in the help of <Refinement/Strategy>. The
  // registration runs when the program is loaded, before any parameter
  // file is read, so `set Strategy = edge` works in any scene this program
  // reads.
  void
  declare_edge_parameters(EntryDeclarer &declarer)
  {
    declarer.enter_subsection("Refinement");
    declarer.declare_entry(
      "Edge indicator weight",
      "1",
      EntryPattern::number(0.),
      "'edge' (step-5): the weight w of the edge term, |F|/E mean(l1) "
      "mean(gap) on the faces of Gamma_C that contain an edge of the "
      "contact zone, against Kelly's indicator [-]; 0 gives 'kelly'.");
    declarer.leave_subsection();
  }

  const bool edge_registered = register_refinement_indicator(
    "edge",
    {"(step-5) Kelly's indicator plus a term on the faces of Gamma_C that "
     "contain an edge of the contact zone (one node pressing, one open): "
     "|F|/E times the mean pressure and the mean gap of its nodes.",
     declare_edge_parameters,
     {"Refinement/Edge indicator weight"},
     edge_indicator<2>,
     edge_indicator<3>});

  // @sect3{The runs}
  //
  // A configuration is a refinement strategy and a way to start each mesh.
  // Every new mesh contains the old one: each old cell is a cell or a union
  // of cells of the new mesh, so the Q1 spaces are nested, V_0 ⊂ V_1 ⊂ ...,
  // and the old u_h is a function of the new space. `nested` starts each
  // refined mesh from the previous one's fields (<Refinement/Nested
  // iteration>); otherwise every mesh starts from v = 0, l1 = l2 = 0.
  // `compare` also solves each refined mesh of the nested run again from
  // zero, on the same mesh (<Refinement/Compare with cold start>), and
  // measures how far apart the two solutions are.
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

  // @sect3{Hertz for this scene}
  //
  // Hertz's a and p0 depend on E, nu, R and the load P. The first three are
  // the scene's; P is measured: the load vector of the coarse mesh, taken
  // toward the obstacle (SolveRecord::normal_load), which is what the
  // contact force must balance. The closed form then becomes the scene's
  // <Exact solution>, against which the library measures the errors of
  // every cycle.
  double
  measured_load(const Parameters &scene)
  {
    std::ostringstream log;
    ContactProblem<2>  problem(scene, MPI_COMM_WORLD, log);
    problem.make_grid();
    problem.setup_system(0);
    problem.assemble_system();
    return problem.prepare_contact_solve().normal_load;
  }

  void
  set_exact_solution(Parameters &scene, const tutorial::Hertz &hertz)
  {
    std::ostringstream p;
    p << std::setprecision(17) << hertz.p0 << " * sqrt(max(0, 1 - (x - "
      << scene.geometry.center.at(0) << ")^2 / " << hertz.a * hertz.a << "))";
    scene.exact.contact_pressure   = p.str();
    scene.exact.contact_half_width = hertz.a;
    scene.exact.peak_pressure      = hertz.p0;
  }

  // @sect3{One run: the refinement cycles}
  //
  // ContactProblem::run() written out, so that the place of each phase
  // shows, with one change: a run may stop once its mesh has `dof_budget`
  // DoFs instead of after <Refinement/Number of cycles>. Each run has its
  // own copy of the scene and its own folder output/<run>/, with cycles.csv
  // (every figure of every cycle, the wall times of the phases among them)
  // and screen.log (the library's screen output).
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
        // Marking and refinement: the strategy's indicator ranks the cells.
        // With nested iteration refine_mesh() hands u_h and the nodal
        // fields l1, l2 and the friction threshold to a SolutionTransfer
        // before the cells split.
        if (cycle > 0)
          problem.refine_mesh();

        // The new DoFs and constraints; then the transfer (doc/theory.md
        // §7): v interpolated (exact, the spaces are nested), l1, l2, the
        // threshold interpolated as nodal fields, read at the new contact
        // nodes and projected onto the admissible set, l1 <- max(l1, 0),
        // threshold <- max(threshold, 0), l2 <- its projection onto
        // [-threshold, threshold].
        CycleResult result;
        result.mesh     = problem.setup_system(cycle);
        result.transfer = problem.transfer_fields();
        report.start_cycle(result.mesh, result.transfer);

        // The contact solve, from the carried fields or from zero; the
        // contact zone against Hertz; in the comparing run the cold solve
        // of the same mesh.
        problem.assemble_system();
        result.solve  = problem.solve();
        result.zone   = problem.measure_contact_zone();
        result.cold   = problem.compare_with_cold_start();
        result.errors = problem.postprocess();

        // end_cycle() takes the phases' wall times from the timer, adds
        // them to time.total (all cycles so far) and writes cycles.csv.
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

  const Run &
  find_run(const std::vector<Run> &runs, const std::string &name)
  {
    for (const Run &run : runs)
      if (run.configuration.name == name)
        return run;
    AssertThrow(false, ExcMessage("no run named " + name));
    return runs.front();
  }

  // @sect3{What the screen shows}
  //
  // One table per run: the mesh, the errors of the contact zone (the
  // relative L2 error of the pressure on Gamma_C; the signed relative
  // errors of the half-width a and of the peak pressure p0), and the work
  // of the solver: Uzawa steps, Newton steps, CG iterations. The comparing
  // run adds the steps of the cold solve of the same mesh. With
  // <Output/Print timing> = true a last column gives the cumulative wall
  // time; the test runs without it, so that its output is reproducible.
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
          << (timing ? "   total [s]" : "") << "\n";
    for (const CycleResult &r : run.cycles)
      {
        std::ostringstream line;
        line << std::setw(5) << r.mesh.cycle << std::setw(8) << r.mesh.n_cells
             << std::setw(8) << r.mesh.n_dofs << std::setw(7)
             << r.solve.n_contact_nodes
             << format("%10.2e", r.zone.pressure_error)
             << format("%+11.2e", r.zone.half_width_error)
             << format("%+11.2e", r.zone.peak_pressure_error) << std::setw(6)
             << r.solve.uzawa_steps << std::setw(7) << r.solve.newton_steps
             << std::setw(5) << r.solve.cg_iterations;
        if (c.compare && r.mesh.cycle == 0) // the first mesh starts cold
          line << " |           -      -";
        else if (c.compare)
          line << " |       " << std::setw(5) << r.cold.uzawa_steps
               << std::setw(7) << r.cold.newton_steps;
        if (timing)
          line << format("%12.3f", r.time.total);
        pcout << line.str() << "\n";
      }
  }

  // The adaptive indicators side by side, cycle by cycle: the marking
  // refines the same fraction of the cells, so equal cycles have nearly
  // equal DoFs, and the pressure errors compare at equal cost.
  void
  print_side_by_side(ConditionalOStream             &pcout,
                     const std::vector<Run>         &runs,
                     const std::vector<std::string> &strategies)
  {
    pcout << "\nThe adaptive indicators at equal cycles (nested runs):\n"
          << "cycle";
    for (const std::string &strategy : strategies)
      pcout << std::setw(15) << strategy + " DoFs"
            << "   p error";
    pcout << "\n";
    const std::size_t n_cycles =
      find_run(runs, strategies[0] + "-nested").cycles.size();
    for (std::size_t k = 0; k < n_cycles; ++k)
      {
        pcout << std::setw(5) << k;
        for (const std::string &strategy : strategies)
          {
            const CycleResult &r =
              find_run(runs, strategy + "-nested").cycles.at(k);
            pcout << std::setw(15) << r.mesh.n_dofs
                  << format("%10.2e", r.zone.pressure_error);
          }
        pcout << "\n";
      }
  }

  // @sect3{What accuracy costs}
  //
  // The cost of an accuracy e is read off a run at the first cycle whose
  // pressure error is at most e: its DoFs, and its cumulative wall time
  // time.total. The cumulative time is the honest price: an adaptive mesh
  // cannot be had without the coarser meshes whose solutions chose it.
  // With a solver whose cost is about proportional to N, a sequence whose
  // N grows by a factor q per cycle costs about q/(q - 1) times its last
  // mesh: 4/3 for global refinement, about 2 for the adaptive strategies
  // (q = 1 + 3 theta = 1.9 at a refine fraction theta = 0.3).
  const CycleResult *
  first_reaching(const Run &run, const double error)
  {
    for (const CycleResult &r : run.cycles)
      if (r.zone.pressure_error <= error)
        return &r;
    return nullptr;
  }

  void
  print_cost(ConditionalOStream     &pcout,
             const std::vector<Run> &runs,
             const double            target,
             const std::string      &why,
             const bool              timing)
  {
    pcout << "\nReaching a pressure error of " << format("%.2e", target) << " ("
          << why << "), the first such cycle of each run:\n"
          << "configuration   cycle     DoFs   p error"
          << (timing ? "   total [s]" : "") << "\n";
    for (const Run &run : runs)
      {
        pcout << std::left << std::setw(14) << run.configuration.name
              << std::right;
        if (const CycleResult *r = first_reaching(run, target))
          pcout << std::setw(7) << r->mesh.cycle << std::setw(9)
                << r->mesh.n_dofs << format("%10.2e", r->zone.pressure_error)
                << (timing ? format("%12.3f", r->time.total) : "") << "\n";
        else
          pcout << "    not reached" << (timing ? "           -" : "") << "\n";
      }
  }

  // @sect3{Nested iteration against cold starts}
  //
  // The steps of the two runs of each strategy, summed over the refined
  // meshes (cycle 0 is the same cold solve in both). The Uzawa iteration
  // contracts the error of l1 by a roughly fixed factor rho per step and
  // stops when the relative change of l1 falls below the tolerance tol; from
  // an initial relative error e0 that takes about log(e0/tol) / log(1/rho)
  // steps. The carried l1 is off only by the change of discretisation, so
  // the Uzawa steps fall a little. The Newton iteration inside each Uzawa
  // step starts from the previous v and active set: from the carried ones
  // the active set is right at once, and one Newton step per Uzawa step
  // nearly always suffices; from zero the first Uzawa step needs several to
  // find it. So the Newton steps fall a lot.
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

  const std::vector<std::string> compared_strategies = {"global",
                                                        "kelly",
                                                        "contact"};

  void
  print_savings(ConditionalOStream     &pcout,
                const std::vector<Run> &runs,
                const bool              timing)
  {
    pcout << "\nNested iteration against cold starts (sums over the refined "
             "meshes; nested / cold):\n"
          << "strategy      Uzawa      Newton          CG"
          << (timing ? "    time [s]" : "") << "\n";
    for (const std::string &strategy : compared_strategies)
      {
        const Totals a = refined_totals(find_run(runs, strategy + "-nested"));
        const Totals b = refined_totals(find_run(runs, strategy + "-cold"));
        std::ostringstream line;
        line << std::left << std::setw(8) << strategy << std::right
             << std::setw(6) << a.uzawa << " /" << std::setw(3) << b.uzawa
             << std::setw(6) << a.newton << " /" << std::setw(4) << b.newton
             << std::setw(6) << a.cg << " /" << std::setw(5) << b.cg;
        if (timing)
          line << "  " << format("%.2f", a.time) << "/"
               << format("%.2f", b.time);
        pcout << line.str() << "\n";
      }
  }

  // @sect3{The checks}
  //
  // What the step claims, checked on its own figures; README.md gives each
  // bound with its reason.
  tutorial::Checks
  check_results(ConditionalOStream     &pcout,
                const std::vector<Run> &runs,
                const Parameters       &scene)
  {
    pcout << "\nChecks:\n";
    tutorial::Checks checks;

    // 1. Equilibrium: sum_s m_s l1_s = P on every mesh. A rigid translation
    // has no elastic energy, so only the proximal term (doc/theory.md §3.2),
    // zero at convergence, could make up a difference.
    double worst = 0.;
    for (const Run &run : runs)
      for (const CycleResult &r : run.cycles)
        worst = std::max(worst,
                         std::abs(r.zone.contact_force - r.solve.normal_load) /
                           r.solve.normal_load);
    checks(worst <= 1e-6,
           "contact force = applied load to 1e-6 on every mesh of every run");

    // 2. Convergence. Under global refinement the pressure error falls from
    // each cycle to the next. On adaptive meshes it may stall for a cycle:
    // the error of the square-root pressure sits at the edges x = ±a and
    // depends on where a falls between two contact nodes, which refinement
    // moves. So adaptive runs are held to a fall over every two cycles, and
    // a stall is named.
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
                    << " (" << format("%.2e", e) << " after "
                    << format("%.2e", run.cycles[k - 1].zone.pressure_error)
                    << ")\n";
            if (k >= lag && e >= run.cycles[k - lag].zone.pressure_error)
              falls = false;
          }
        checks(falls,
               run.configuration.name + ": the pressure error falls " +
                 (global ? "from cycle to cycle" : "over every two cycles"));
      }

    // 3. Adaptivity pays: every adaptive strategy reaches the error of the
    // finest global mesh with at most half its DoFs. Global refinement
    // spends most of its DoFs far from Gamma_C, where u is smooth.
    const CycleResult &global = find_run(runs, "global-nested").cycles.back();
    for (const std::string name :
         {"kelly-nested", "contact-nested", "edge-nested"})
      {
        const CycleResult *r =
          first_reaching(find_run(runs, name), global.zone.pressure_error);
        checks(r != nullptr && 2 * r->mesh.n_dofs <= global.mesh.n_dofs,
               name + " reaches the finest global error with at most half " +
                 "its DoFs (" + (r ? std::to_string(r->mesh.n_dofs) : "none") +
                 " vs " + std::to_string(global.mesh.n_dofs) + ")");
      }

    // 4. Nested iteration against cold starts, per strategy. The cold run
    // must refine to the same meshes, else no count can be compared; its
    // indicators see the same solution up to the solver's tolerance. Then,
    // summed over the refined meshes, nested iteration needs no more Uzawa
    // steps and at most 3/4 of the Newton steps (the reasons above
    // print_savings(); mesh by mesh the Uzawa counts may differ by a step
    // either way, since rho varies between meshes), and the pressure
    // errors of the two runs agree to 1e-6.
    for (const std::string &strategy : compared_strategies)
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
        checks(same, strategy + ": nested and cold runs, same meshes");
        checks(a.uzawa <= b.uzawa,
               strategy + ": nested Uzawa steps <= cold (" +
                 std::to_string(a.uzawa) + " vs " + std::to_string(b.uzawa) +
                 ")");
        checks(4 * a.newton <= 3 * b.newton,
               strategy + ": nested Newton steps <= 3/4 of cold (" +
                 std::to_string(a.newton) + " vs " + std::to_string(b.newton) +
                 ")");
        checks(error_difference <= 1e-6,
               strategy + ": nested and cold pressure errors agree to 1e-6");
      }

    // 5. The same solution. On each refined mesh of the comparing run the
    // nested and the cold solution differ (v in the energy norm, l1 in the
    // weighted l2 norm, both relative) by at most ten times the Uzawa
    // tolerance: each run stops when the relative change of l1 is below the
    // tolerance, which leaves an error of about rho/(1 - rho) times it
    // (doc/theory.md §6).
    double difference = 0.;
    for (const CycleResult &r : find_run(runs, "contact-nested").cycles)
      difference =
        std::max({difference, r.cold.difference_v, r.cold.difference_l1});
    checks(difference <= 10. * scene.solver.uzawa_tolerance,
           "contact: nested and cold solutions of the same mesh differ by at "
           "most 10 x <Uzawa tolerance>");
    return checks;
  }

  // @sect3{The whole step}
  //
  // Hertz for the scene; then the seven runs. The adaptive ones run first,
  // so that global refinement can be given the size of their finest mesh
  // as its budget: it refines until it has at least as many DoFs, which
  // compares the strategies over the same range of DoFs with any advantage
  // to global refinement. Then the tables and the checks.
  tutorial::Checks
  run(Parameters &scene)
  {
    ConditionalOStream pcout(std::cout,
                             Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) ==
                               0);
    AssertThrow(scene.geometry.dimension == 2 &&
                  scene.geometry.type == "half disc",
                ExcMessage("step-5 compares with plane-strain Hertz: it "
                           "needs the 2D half disc (<Geometry/Type>)"));
    const tutorial::Hertz hertz(scene, measured_load(scene));
    set_exact_solution(scene, hertz);
    const bool timing = scene.output.print_timing;
    pcout << "step-5: Hertz contact, P = " << format("%.6f", hertz.P)
          << ", a = " << format("%.6f", hertz.a)
          << ", p0 = " << format("%.4f", hertz.p0) << "; "
          << scene.refinement.n_cycles
          << " adaptive cycles, global refinement up to as many DoFs\n";

    const std::vector<Configuration> configurations = {
      {"contact-nested", "contact", true, true},
      {"contact-cold", "contact", false, false},
      {"kelly-nested", "kelly", true, false},
      {"kelly-cold", "kelly", false, false},
      {"edge-nested", "edge", true, false},
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

    print_side_by_side(pcout, runs, {"kelly", "contact", "edge"});
    print_cost(pcout, runs, 1e-2, "1 %", timing);
    print_cost(
      pcout,
      runs,
      find_run(runs, "global-nested").cycles.back().zone.pressure_error,
      "the finest global mesh",
      timing);
    print_savings(pcout, runs, timing);
    return check_results(pcout, runs, scene);
  }
} // namespace Step5

// @sect3{The main function}
//
// MPI, the parameter file (default step-5.prm) and, after it, overrides as
// the dualcontact program takes them, `--set "Refinement/Refine
// fraction=0.5"`; one message and a non-zero exit status on any error.
int
main(int argc, char *argv[])
{
  return dualcontact::tutorial::run_tutorial(
    argc, argv, "step-5", "step-5.prm", Step5::run);
}
