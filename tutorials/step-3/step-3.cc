/* step-3: Coulomb friction, the threshold iteration.
 *
 * Step-1 solved frictionless Hertz contact and wrote the Uzawa iteration
 * out by hand. This step adds Coulomb friction. Its threshold g = F l1
 * depends on the unknown contact pressure l1, so the problem is no longer a
 * minimisation but a quasi-variational inequality (doc/theory.md §1). The
 * source paper solves it by successive approximations of the threshold: for
 * a given g the problem is convex and the Uzawa iteration of step-1 solves
 * it; then g = F l1, and again. This is the threshold iteration
 * (doc/theory.md §3.1).
 *
 * Part 1 writes the threshold iteration out in two strategies, on the
 * scene of step-3.prm (the source paper's block against a wall):
 *  - nested, as published: each given-threshold problem is solved to
 *    convergence, then g is updated;
 *  - merged: g is updated after every Uzawa step, and the two loops
 *    become one.
 * It compares their cost and their solutions and shows the stick and slip
 * zones on the wall.
 *
 * Part 2 uses the library's solver as a black box on Hertz contact. It
 * asks what friction does to the contact zone of an elastic cylinder on a
 * rigid plane, at nu = 0.3 and at nu = 0.49 (Dundurs' beta, doc/theory.md
 * §9).
 *
 * README.md has the introduction and the results.
 */

// @sect3{Include files}
//
// The library's Problem class for the mesh, the assembly and the
// measurements; its Uzawa and Newton iterations, which the threshold
// iteration of Part 1 calls; the parameters.
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <dualcontact/contact_functions.h>
#include <dualcontact/contact_problem.h>
#include <dualcontact/input_error.h>
#include <dualcontact/newton_solver.h>
#include <dualcontact/parameters.h>
#include <dualcontact/uzawa_iteration.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace Step2
{
  using namespace dealii;
  using namespace dualcontact;

  // Both scenes of this step are two-dimensional (plane strain).
  constexpr unsigned int dim = 2;

  // @sect3{The contact nodes, gathered}
  //
  // Each rank owns some of the contact nodes s (doc/theory.md §4). For the
  // tables, the checks and the figures we gather all of them on every rank,
  // sorted by their position along the tangent t of the foundation: up the
  // wall (t = e_y) in Part 1, along the plane (t = e_x) in Part 2. At each
  // node we keep
  //   l1   the contact pressure,
  //   l2   the tangential traction, its coordinate along t (l2 = -sigma_t),
  //   g    the threshold the solution was computed with,
  //   F l1 the threshold of the final pressure (the friction law's,
  //        g_of_l1; F l1 for Coulomb),
  //   the status: 0 separated (l1 = 0), 1 stick (|l2| < g), 2 slip.
  // The merged strategy ends with g = F l1 exactly. The nested one ends
  // with the g of the previous pressure, within the threshold tolerance of
  // F l1, so that |l2| <= g holds exactly for the g it solved with.
  struct NodeValues
  {
    double       position, l1, l2, g, g_of_l1;
    unsigned int status;

    // for Utilities::MPI::all_gather
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &position &l1 &l2 &g &g_of_l1 &status;
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
                         f ? contact.threshold_from_pressure(s) : 0.,
                         contact.status(s)});
      }
    std::vector<NodeValues> all;
    for (const auto &part : Utilities::MPI::all_gather(MPI_COMM_WORLD, local))
      all.insert(all.end(), part.begin(), part.end());
    std::sort(all.begin(), all.end(), [](const auto &a, const auto &b) {
      return a.position < b.position;
    });
    return all;
  }

  // The nodes as CSV, one line each, for the figures (rank 0 writes).
  void
  write_nodes(const std::vector<NodeValues> &nodes, const std::string &file)
  {
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    const char   *name[] = {"separated", "stick", "slip"};
    std::ofstream out(file);
    out << "position,l1,l2,abs_l2,g,F_l1,status_code,status\n"
        << std::setprecision(10);
    for (const NodeValues &n : nodes)
      out << n.position << ',' << n.l1 << ',' << n.l2 << ',' << std::abs(n.l2)
          << ',' << n.g << ',' << n.g_of_l1 << ',' << n.status << ','
          << name[n.status] << '\n';
  }

  // @sect3{Watching the Uzawa steps}
  //
  // The Uzawa and Newton iterations tell an IterationObserver of every step
  // (include/dualcontact/contact_system.h). This one numbers the Uzawa
  // steps of a solve consecutively and records d(g) = |g_new - g| / |g_new|
  // whenever g changes: after every Uzawa step in the merged strategy (the
  // record carries it), after every given-threshold problem in the nested
  // one (the nested loop below adds it). The README plots this history:
  // how fast g converges against the Uzawa steps it costs.
  class History : public IterationObserver
  {
  public:
    void
    uzawa_step(const IterationRecord &record,
               const bool,
               const bool merged) override
    {
      ++uzawa_steps;
      if (merged)
        add(record.change_g);
    }

    void
    add(const double change_g)
    {
      rows.emplace_back(uzawa_steps, change_g);
    }

    unsigned int                                 uzawa_steps = 0;
    std::vector<std::pair<unsigned int, double>> rows;
  };

  // @sect3{The threshold iteration, written out}
  //
  // The problem for a given threshold g (Tresca friction) is convex:
  // minimise 1/2 a(v, v) - L(v) + int_{Gamma_C} g |v_t| over v_n <= g0
  // (doc/theory.md §1). The Uzawa iteration of step-1, now with both
  // multipliers, solves it. Each of its steps is a proximal step by the
  // Newton iteration and the multiplier update (doc/theory.md §3.2):
  //   l1 <- (l1 + r (v_n - g0))^+,   l2 <- proj_g(l2 + r v_t),
  // proj_g the clamp to [-g, g]. UzawaIteration::solve() runs it until the
  // relative changes of l1, l2, v and the penetration are below
  // <Solver/Uzawa tolerance> (doc/theory.md §6).
  //
  // Coulomb's law asks for g = F l1 with the l1 of the solution itself:
  // the threshold is a fixed point of the map g -> F l1(g), l1(g) the
  // pressure of the given-threshold solution. For small F the map is a
  // contraction (Lipschitz constant proportional to F), and successive
  // approximations converge.
  //
  // The first threshold g^0 = F l1^0. On a cold start l1^0 = 0, so g^0 = 0
  // (<Friction/Initial threshold> = zero): the first given-threshold
  // problem is the frictionless one, and every node in contact "slips"
  // with |l2| = g = 0. With `frictionless`, l1^0 is the
  // pressure of a frictionless solve run first. On a refined mesh with
  // nested iteration (doc/theory.md §7) the previous mesh's g, carried by
  // transfer_fields(), is kept.
  ContactStatistics
  initial_threshold(const FrictionParameters      &friction,
                    UzawaIteration<dim>           &uzawa,
                    const ContactSystem           &system,
                    ContactSet<dim>               &contact,
                    TrilinosWrappers::MPI::Vector &v,
                    const bool                     carried,
                    History                       &history)
  {
    ContactStatistics statistics;
    if (carried)
      return statistics;
    if (friction.initial_threshold == InitialThreshold::frictionless)
      {
        contact.friction = false; // no tangential terms at all
        statistics       = uzawa.solve(system, contact, v, &history);
        contact.friction = true;
      }
    for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
      contact.threshold[s] = contact.threshold_from_pressure(s);
    return statistics;
  }

  // The nested strategy, as published. Threshold step s:
  //   1. solve the given-threshold problem for g^s by the Uzawa iteration,
  //      to convergence;
  //   2. g^{s+1} = F l1(g^s), and its relative change
  //        d(g) = |g^{s+1} - g^s| / |g^{s+1}|   (Euclidean over the nodes);
  //   3. stop if d(g) <= tol_g (<Friction/Threshold tolerance>), keeping
  //      g^s, with which |l2| <= g holds exactly; otherwise repeat.
  // The Uzawa iteration starts each threshold step from the previous v, l1
  // and l2: the next given-threshold problem differs only a little.
  ContactStatistics
  nested_threshold_iteration(const FrictionParameters      &friction,
                             UzawaIteration<dim>           &uzawa,
                             const ContactSystem           &system,
                             ContactSet<dim>               &contact,
                             TrilinosWrappers::MPI::Vector &v,
                             History                       &history,
                             ConditionalOStream            &pcout)
  {
    ContactStatistics total;
    for (unsigned int step = 1; step <= friction.max_steps; ++step)
      {
        const ContactStatistics part =
          uzawa.solve(system, contact, v, &history);
        total.add(part);

        double sums[2] = {0., 0.}; // |g_new - g|^2, |g_new|^2
        for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
          {
            const double g_new = contact.threshold_from_pressure(s);
            sums[0] += std::pow(g_new - contact.threshold[s], 2);
            sums[1] += g_new * g_new;
          }
        Utilities::MPI::sum(ArrayView<const double>(sums, 2),
                            MPI_COMM_WORLD,
                            ArrayView<double>(sums, 2));
        const double change =
          relative_change(std::sqrt(sums[0]), std::sqrt(sums[1]));
        history.add(change);
        total.threshold_steps = step;
        total.change_g        = change;

        // one line per threshold step, as the library's report prints it
        pcout << "   threshold step " << std::setw(3) << step << ": "
              << std::setw(2) << part.uzawa_steps << " Uzawa steps, "
              << std::setw(2) << part.newton_steps << " Newton, "
              << std::setw(3) << part.cg_iterations << " CG, stick/slip "
              << part.n_stick << '/' << part.n_slip << ", d(g) "
              << format_number(change) << '\n';

        if (change <= friction.tolerance)
          return total;
        for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
          contact.threshold[s] = contact.threshold_from_pressure(s);
      }
    AssertThrow(false,
                ExcMessage("The nested threshold iteration did not converge "
                           "in <Friction/Maximum threshold steps>."));
    return total;
  }

  // The merged strategy: one loop. After every Uzawa step, update l1, then
  // g = F l1, then l2 = proj_g(l2 + r v_t) (doc/theory.md §3.2, step 3),
  // so |l2| <= F l1 holds after every step. It stops when the Uzawa tests
  // and d(g) <= tol_g hold together. UzawaIteration::solve() does exactly
  // this when told to update the threshold. The convergence theorem of the
  // Uzawa iteration is for a fixed g and does not cover this loop; that is
  // why Part 1 compares its solution with the nested one's.
  ContactStatistics
  merged_threshold_iteration(const FrictionParameters      &friction,
                             UzawaIteration<dim>           &uzawa,
                             const ContactSystem           &system,
                             ContactSet<dim>               &contact,
                             TrilinosWrappers::MPI::Vector &v,
                             History                       &history)
  {
    ContactStatistics total = uzawa.solve(system,
                                          contact,
                                          v,
                                          &history,
                                          /*update_threshold=*/true,
                                          friction.tolerance);
    total.threshold_steps   = total.uzawa_steps; // g moved in every step
    return total;
  }

  // @sect3{Part 1: the block against the wall}
  //
  // One strategy on the scene of step-3.prm, on every mesh of its
  // refinement cycles. We call the phases of ContactProblem in the order
  // its run() does (source/contact_problem.cc), but put our own threshold
  // iteration where run() would call solve(): prepare_contact_solve()
  // finds the contact nodes, their weights and r; contact_system() hands
  // out K = A + chi M, M, b, r and chi; initial_displacement() gives the
  // first v (the previous mesh's, interpolated, or zero);
  // set_displacement() stores the result for the measurements and the
  // output. The NewtonSolver shares the problem's linear solver, whose
  // algebraic multigrid knows the rigid-body modes of this mesh.
  struct CycleRow
  {
    types::global_dof_index n_dofs;
    ContactStatistics       statistics;
  };

  struct BlockRun
  {
    std::string                                  name;
    std::vector<CycleRow>                        cycles;
    ContactZoneRecord                            zone;
    double                                       normal_load = 0.;
    double                                       time        = 0.;
    std::vector<NodeValues>                      nodes;
    std::vector<std::pair<unsigned int, double>> history; // cycle 0
  };

  BlockRun
  solve_block(const Parameters      &prm_parameters,
              const FrictionStrategy strategy,
              ConditionalOStream    &pcout)
  {
    BlockRun run;
    run.name = strategy == FrictionStrategy::nested ? "nested" : "merged";

    Parameters parameters        = prm_parameters; // this run's variant
    parameters.friction.strategy = strategy;
    parameters.output.directory += "/block_" + run.name;
    std::ostringstream  silent; // the library's own report: not shown
    ContactProblem<dim> problem(parameters, MPI_COMM_WORLD, silent);
    NewtonSolver<dim>   newton(parameters.solver, problem.linear_solver());
    UzawaIteration<dim> uzawa(parameters.solver, newton);

    pcout << "  " << run.name << " threshold iteration\n";
    problem.make_grid();
    for (unsigned int cycle = 0; cycle < parameters.refinement.n_cycles;
         ++cycle)
      {
        if (cycle > 0)
          problem.refine_mesh();
        const MeshRecord     mesh     = problem.setup_system(cycle);
        const TransferRecord transfer = problem.transfer_fields();
        problem.assemble_system();
        const SolveRecord prepared = problem.prepare_contact_solve();
        pcout << "  cycle " << cycle << ": " << mesh.n_cells << " cells, "
              << mesh.n_dofs << " DoFs, " << prepared.n_contact_nodes
              << " contact nodes\n";

        Timer             timer(MPI_COMM_WORLD, true);
        const auto        system  = problem.contact_system();
        auto              v       = problem.initial_displacement();
        auto             &contact = problem.contact();
        History           history;
        ContactStatistics statistics = initial_threshold(parameters.friction,
                                                         uzawa,
                                                         system,
                                                         contact,
                                                         v,
                                                         transfer.warm_start,
                                                         history);
        statistics.add(
          strategy == FrictionStrategy::nested ?
            nested_threshold_iteration(
              parameters.friction, uzawa, system, contact, v, history, pcout) :
            merged_threshold_iteration(
              parameters.friction, uzawa, system, contact, v, history));
        timer.stop();
        run.time += timer.wall_time();
        // The solution goes back to the problem: measure_contact_zone()
        // reads the multipliers in `contact`, output_results() and the
        // refinement the displacement.
        problem.set_displacement(v);

        run.cycles.push_back({mesh.n_dofs, statistics});
        if (cycle == 0)
          run.history = history.rows;
        run.zone        = problem.measure_contact_zone();
        run.normal_load = prepared.normal_load;
        problem.output_results(cycle); // vtu files, if asked for
      }
    run.nodes = gather_nodes(problem.contact());
    return run;
  }

  // @sect3{Part 2: Hertz contact with and without friction}
  //
  // The half disc of prm/hertz_friction.prm: radius R = 1, E = 1000, a
  // pressure on its flat top that adds up to P = 8.6307 per unit thickness,
  // pressed onto the rigid plane y = -1. Without friction Hertz's theory
  // gives the contact half-width a = sqrt(4 P R / (pi E*)), E* = E / (1 -
  // nu^2): a = 0.1 at nu = 0.3 (doc/theory.md §9). With friction the zone
  // narrows by about 2.5 % at nu = 0.3 (doc/friction.md). To see a change
  // of 0.0025 the faces on Gamma_C must be much smaller than that: the mesh
  // is refined 5 times globally and then 5 times more toward the
  // foundation, in bands that shrink by 0.8 from a distance 0.03 (the
  // smallest band still holds the whole contact zone: the gap at |x| = 0.1
  // is 0.005). That gives faces of 0.00077 on the contact zone in one
  // mesh, one cycle. The scene is written here; <Friction>, <Solver> and
  // <Output> come from step-3.prm.
  const char *const hertz_scene = R"(
subsection Geometry
  set Type                    = half disc
  set Center                  = 0, 0
  set Radius                  = 1
  set Pre-refinement steps    = 5
  set Pre-refinement distance = 0.03
  set Pre-refinement grading  = 0.8
end
subsection Material
  set Young's modulus = 1000
  set Poisson's ratio = 0.3
end
subsection Boundary conditions
  set Conditions = 0: contact, 1: traction
  set Tractions  = 1: 0; -4.315374524161804
end
subsection Foundation
  set Point  = 0, -1
  set Normal = 0, 1
end
subsection Refinement
  set Initial global refinement = 5
  set Number of cycles          = 1
end
subsection Friction
  set Law = coulomb
end
)";
  constexpr double  hertz_load  = 8.630749048323608; // P = q * 2R

  struct HertzRun
  {
    double                  nu, F;
    CycleResult             result;
    double                  h_contact = 0.;
    std::vector<NodeValues> nodes;
    double                  time = 0.;
  };

  // One run: the library's ContactProblem::run(), the whole algorithm (the
  // threshold iteration in the strategy of step-3.prm around the Uzawa
  // iteration around the Newton iteration). F = 0 makes the scene
  // frictionless: the library then runs the Uzawa iteration on l1 alone.
  HertzRun
  solve_hertz(const Parameters &prm_parameters, const double nu, const double F)
  {
    HertzRun run;
    run.nu = nu;
    run.F  = F;

    Parameters parameters;
    parameters.read_string(hertz_scene);
    parameters.material.poissons_ratio = nu;
    parameters.friction                = prm_parameters.friction;
    parameters.friction.parameter      = std::to_string(F);
    parameters.solver                  = prm_parameters.solver;
    parameters.output                  = prm_parameters.output;
    std::ostringstream name;
    name << "/hertz_nu" << nu << "_F" << F;
    parameters.output.directory += name.str();

    // The library's report (scene, every Uzawa step, the cycle table) goes
    // into a string that is thrown away: the table below says what matters
    // here. Its files go into the run's own folder under output/:
    // cycles.csv, iterations.csv and, with <Output/Write vtu>, the fields
    // contact_pressure, tangential_traction, contact_status, ... for
    // ParaView.
    std::ostringstream  silent;
    ContactProblem<dim> problem(parameters, MPI_COMM_WORLD, silent);
    Timer               timer(MPI_COMM_WORLD, true);
    problem.run();
    timer.stop();
    run.time      = timer.wall_time();
    run.result    = problem.results().back();
    run.h_contact = problem.contact().min_face_diameter();
    run.nodes     = gather_nodes(problem.contact());
    return run;
  }

  // @sect3{Measuring a solution}
  //
  // Coulomb's cone |l2| <= F l1 at every node: the largest excess
  // max_s (|l2_s| - F l1_s), relative to the largest threshold F l1. Zero
  // at slip nodes, negative at stick nodes.
  double
  cone_excess(const std::vector<NodeValues> &nodes)
  {
    double excess = -1e300, largest = 0.;
    for (const NodeValues &n : nodes)
      {
        excess  = std::max(excess, std::abs(n.l2) - n.g_of_l1);
        largest = std::max(largest, n.g_of_l1);
      }
    return excess / largest;
  }

  // How far the cone may be exceeded. The merged strategy projects l2 onto
  // [-F l1, F l1] right after setting g = F l1: exact up to round-off. The
  // nested one stops when |g^{s+1} - g^s| <= tol_g |g^{s+1}| and keeps
  // g^s, so at a slip node |l2| = g^s may exceed F l1 = g^{s+1}; over N
  // nodes a Euclidean bound gives at most sqrt(N) tol_g max g at any one
  // node.
  double
  cone_bound(const FrictionParameters &friction, const unsigned int n_nodes)
  {
    return friction.strategy == FrictionStrategy::merged ?
             1e-12 :
             std::sqrt(1. * n_nodes) * friction.tolerance;
  }

  // The zones: the largest distance from `centre` of a node with status
  // `status`, and the smallest (-1 and 1e300 if there is none).
  std::pair<double, double>
  zone_extent(const std::vector<NodeValues> &nodes,
              const unsigned int             status,
              const double                   centre)
  {
    double nearest = 1e300, farthest = -1.;
    for (const NodeValues &n : nodes)
      if (n.status == status)
        {
          nearest  = std::min(nearest, std::abs(n.position - centre));
          farthest = std::max(farthest, std::abs(n.position - centre));
        }
    return {nearest, farthest};
  }

  // @sect3{The program}
  void
  run(const std::string &prm_file)
  {
    ConditionalOStream pcout(std::cout,
                             Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) ==
                               0);
    Parameters         parameters;
    parameters.read_file(prm_file);
    // A 2D scene whose friction threshold depends on the pressure through
    // a coefficient F (Coulomb, or a law of that kind that you add).
    const auto law = create_friction_law(parameters.friction.law);
    AssertThrow(parameters.geometry.dimension == dim &&
                  law->depends_on_pressure() &&
                  law->parameter_entry() == "Coefficient",
                ExcMessage("step-3 needs a 2D scene with Coulomb friction "
                           "(or another law g(F, l1))."));
    const bool   timing = parameters.output.print_timing;
    const double F      = std::stod(parameters.friction.parameter);
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::filesystem::create_directories(parameters.output.directory);

    // Every claim is checked at the end, on every rank (all figures are
    // gathered or reduced, so all ranks agree). A failing check throws
    // with the claim and the measured value, and main() returns 1.
    std::ostringstream checks;
    const auto         check = [&checks](const bool         ok,
                                 const std::string &claim,
                                 const double       measured,
                                 const std::string &bound) {
      AssertThrow(ok,
                  ExcMessage("check failed: " + claim + ": measured " +
                             format_number(measured) + ", bound " + bound));
      checks << "  passed: " << claim << ": " << format_number(measured) << " ("
             << bound << ")\n";
    };

    // @sect4{Part 1: nested against merged}
    //
    // Both strategies, from the same start on the same meshes. The first
    // mesh starts cold (v = 0, l1 = l2 = 0, g^0 = 0); every refined mesh
    // starts from the previous mesh's v, l1, l2 and g (nested iteration,
    // doc/theory.md §7), so that the cost of the later meshes shows what
    // each strategy does from a good first guess.
    pcout << "step-3: Coulomb friction, the threshold iteration ("
          << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
          << " MPI rank(s))\n\n"
          << "Part 1: the block against the wall, Coulomb F = " << F << '\n';
    const BlockRun nested =
      solve_block(parameters, FrictionStrategy::nested, pcout);
    const BlockRun merged =
      solve_block(parameters, FrictionStrategy::merged, pcout);

    // The cost, per mesh and in total. For the nested strategy `threshold`
    // counts the given-threshold problems solved and `Uzawa` all the Uzawa
    // steps spent on them; for the merged one the two are the same, since g
    // moves in every Uzawa step. Each Uzawa step is one proximal step, a
    // few Newton steps, each one CG solve: the Newton and CG columns are
    // what the time goes into.
    pcout << "\n  strategy  cycle    DoFs  threshold  Uzawa  Newton     CG"
             "  stick  slip\n";
    ContactStatistics totals[2];
    for (const unsigned int i : {0, 1})
      {
        const BlockRun &run = i == 0 ? nested : merged;
        for (unsigned int c = 0; c < run.cycles.size(); ++c)
          {
            const ContactStatistics &s = run.cycles[c].statistics;
            totals[i].add(s);
            pcout << "  " << std::setw(8) << run.name << std::setw(7) << c
                  << std::setw(8) << run.cycles[c].n_dofs << std::setw(11)
                  << s.threshold_steps << std::setw(7) << s.uzawa_steps
                  << std::setw(8) << s.newton_steps << std::setw(7)
                  << s.cg_iterations << std::setw(7) << s.n_stick
                  << std::setw(6) << s.n_slip << '\n';
          }
        pcout << "  " << std::setw(8) << run.name << "    all" << std::setw(19)
              << totals[i].threshold_steps << std::setw(7)
              << totals[i].uzawa_steps << std::setw(8) << totals[i].newton_steps
              << std::setw(7) << totals[i].cg_iterations << '\n';
      }
    if (timing)
      pcout << "  wall time of the contact solves: nested " << std::fixed
            << std::setprecision(2) << nested.time << " s, merged "
            << merged.time << " s\n"
            << std::defaultfloat;

    // How far apart are the two solutions? The merged one is a fixed point
    // of g = F l1 to the Uzawa tolerance (its test on d(l1) = d(g)); the
    // nested one lags by its last threshold step, d(g) <= tol_g in the
    // Euclidean norm, which can concentrate at one node up to sqrt(N)
    // tol_g. So the difference should be of the order of tol_g, and shrink
    // with it: README.md has the measurements.
    //
    // The two solutions on the finest mesh, node by node: the same nodes in
    // the same order, since both runs made the same meshes.
    AssertThrow(nested.nodes.size() == merged.nodes.size(), ExcInternalError());
    const unsigned int n_nodes = merged.nodes.size();
    double             d_l1 = 0., d_l2 = 0., l1_max = 0., g_max = 0.;
    for (unsigned int i = 0; i < n_nodes; ++i)
      {
        d_l1 =
          std::max(d_l1, std::abs(nested.nodes[i].l1 - merged.nodes[i].l1));
        d_l2 =
          std::max(d_l2, std::abs(nested.nodes[i].l2 - merged.nodes[i].l2));
        l1_max = std::max(l1_max, merged.nodes[i].l1);
        g_max  = std::max(g_max, merged.nodes[i].g_of_l1);
      }
    d_l1 /= l1_max;
    d_l2 /= g_max;

    // The zones along the wall, measured from its foot y = 0: a node
    // sticks where |l2| < F l1 and slips where |l2| = F l1. At the foot the
    // slider holds v_y = 0, so the body's side has no tangential motion to
    // resist there: l2 grows from 0 at y = 0 with the height.
    const auto   stick     = zone_extent(merged.nodes, 1, 0.);
    const auto   slip      = zone_extent(merged.nodes, 2, 0.);
    unsigned int counts[3] = {0, 0, 0};
    for (const NodeValues &n : merged.nodes)
      ++counts[n.status];
    const ContactZoneRecord &zone = merged.zone;
    pcout << std::setprecision(7) << "\n  finest mesh: normal force "
          << zone.contact_force << " (net normal load " << merged.normal_load
          << "), tangential force " << zone.tangential_force
          << " (F N = " << F * zone.contact_force << ")\n"
          << "  wall: " << counts[1] << " stick, " << counts[2] << " slip, "
          << counts[0] << " separated nodes";
    if (counts[1] > 0)
      pcout << "; stick for y <= " << stick.second;
    if (counts[2] > 0)
      pcout << "; slip for y >= " << slip.first;
    pcout << "\n  nested against merged: max |l1 difference| / max l1 = "
          << format_number(d_l1) << ",\n"
          << "                         max |l2 difference| / max F l1 = "
          << format_number(d_l2) << '\n';

    write_nodes(merged.nodes, parameters.output.directory + "/contact.csv");
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        std::ofstream out(parameters.output.directory +
                          "/threshold_history.csv");
        out << "strategy,uzawa_steps,change_g\n";
        for (const BlockRun *r : {&nested, &merged})
          for (const auto &[k, change] : r->history)
            out << r->name << ',' << k << ',' << change << '\n';
      }

    // The checks of Part 1. Only the wall holds the block along x, so the
    // normal contact force sum_s m_s l1_s must equal the net load toward
    // the wall; it does up to the solver tolerances (the Newton gradient
    // 1e-10 |b|, the change of v 1e-8). The slider shares the vertical load
    // with the wall, so the wall's tangential force is not fixed by statics
    // and is not checked here (Part 2 checks it where it is).
    FrictionParameters nested_friction = parameters.friction;
    FrictionParameters merged_friction = parameters.friction;
    nested_friction.strategy           = FrictionStrategy::nested;
    merged_friction.strategy           = FrictionStrategy::merged;
    const double uzawa_tolerance       = parameters.solver.uzawa_tolerance;
    for (const BlockRun *r : {&nested, &merged})
      {
        const double error =
          std::abs(r->zone.contact_force / r->normal_load - 1.);
        check(error <= uzawa_tolerance,
              "Part 1, " + r->name + ": normal force = net normal load",
              error,
              "relative, <= the Uzawa tolerance");
        const FrictionParameters &f =
          r == &nested ? nested_friction : merged_friction;
        const double excess = cone_excess(r->nodes);
        check(excess <= cone_bound(f, n_nodes),
              "Part 1, " + r->name + ": |l2| <= F l1 at every node",
              excess,
              "max (|l2| - F l1) / max F l1 <= " +
                format_number(cone_bound(f, n_nodes)));
      }
    // Nested and merged agree to the bound derived above, plus the
    // solution's own tolerance; the wall has the zones the prm promises;
    // and the merged strategy is the cheaper one.
    const double same =
      cone_bound(nested_friction, n_nodes) + 10. * uzawa_tolerance;
    check(std::max(d_l1, d_l2) <= same,
          "Part 1: nested and merged give the same l1 and l2",
          std::max(d_l1, d_l2),
          "<= sqrt(N) tol_g + 10 tol_Uzawa = " + format_number(same));
    check(counts[1] > 0 && counts[2] > 0 && stick.second < slip.first,
          "Part 1: the wall sticks at its foot and slips at its top",
          slip.first,
          "the lowest slip node; every slip node above every stick node");
    check(totals[1].uzawa_steps < totals[0].uzawa_steps &&
            totals[1].newton_steps < totals[0].newton_steps,
          "Part 1: merged needs fewer Uzawa and Newton steps than nested",
          1. * totals[1].uzawa_steps / totals[0].uzawa_steps,
          "ratio of the Uzawa steps < 1");

    // @sect4{Part 2: what friction does to Hertz contact}
    //
    // Frictionless and with the coefficient F of step-3.prm, at nu = 0.3
    // (beta = 0.29) and at nu = 0.49 (beta = 0.02).
    //
    // Why nu matters. Under the pressure the elastic surface of the disc
    // is drawn toward the centre of the contact, by an amount proportional
    // to Dundurs' beta = (1 - 2 nu) / (2 (1 - nu)) for a rigid foundation
    // (doc/theory.md §9); the rigid plane does not move. Friction resists
    // that inward slip: an outward shear on the body, odd in x, sticking in
    // the middle, slipping toward the edges. Through the same beta that
    // shear feeds back into the normal displacement, and the pressure
    // concentrates: the zone narrows and the peak rises. An incompressible
    // body (nu = 1/2, beta = 0) has no inward slip and friction changes
    // nothing. The table also prints Hertz's a; at nu = 0.49 the measured
    // frictionless a falls short of it because Q1 elements lock as nu ->
    // 1/2 (too stiff in the bulk), a mesh effect that is the same with and
    // without friction and drops out of the relative change.
    pcout << "\nPart 2: Hertz contact on a rigid plane, frictionless and "
             "with Coulomb F = "
          << F << '\n';
    //
    // The table: Hertz's a, the half-width measured with the edges
    // extrapolated from the square-root pressure (l1^2 is linear near an
    // edge; doc/theory.md §9), its relative change by friction, the peak
    // pressure, c/a (c the largest |x| of a stick node: the stick zone is
    // |x| < c), the counts of nodes in contact, sticking and slipping,
    // and the cost.
    std::vector<HertzRun> hertz;
    for (const double nu : {0.3, 0.49})
      for (const double f : {0., F})
        hertz.push_back(solve_hertz(parameters, nu, f));
    pcout << "  one graded mesh: " << hertz[0].result.mesh.n_cells << " cells, "
          << hertz[0].result.mesh.n_dofs
          << " DoFs, faces on the contact zone h_C = " << std::setprecision(3)
          << hertz[0].h_contact << '\n'
          << "    nu  beta    F  Hertz a  a (edges)   change  peak l1  "
             "c/a  active  stick  slip  Uzawa  Newton    CG\n";
    std::vector<double> change(hertz.size(), 0.);
    for (unsigned int i = 0; i < hertz.size(); ++i)
      {
        const HertzRun &h = hertz[i];
        const auto     &z = h.result.zone;
        const auto     &s = h.result.solve;
        // Hertz's half-width on a rigid plane, E* = E / (1 - nu^2)
        const double E_star  = 1000. / (1. - h.nu * h.nu);
        const double a_hertz = std::sqrt(4. * hertz_load / (M_PI * E_star));
        const double beta    = (1. - 2. * h.nu) / (2. * (1. - h.nu));
        pcout << std::fixed << "  " << std::setprecision(2) << std::setw(4)
              << h.nu << std::setw(6) << beta << std::setprecision(1)
              << std::setw(5) << h.F << std::setprecision(4) << std::setw(9)
              << a_hertz << std::setprecision(6) << std::setw(11)
              << z.edge_half_width;
        if (h.F > 0.)
          {
            change[i] =
              z.edge_half_width / hertz[i - 1].result.zone.edge_half_width - 1.;
            pcout << std::setprecision(2) << std::setw(7) << 100. * change[i]
                  << " %" << std::setprecision(3) << std::setw(9)
                  << z.max_pressure << std::setprecision(2) << std::setw(5)
                  << zone_extent(h.nodes, 1, 0.).second / z.edge_half_width
                  << std::setw(8) << s.n_active << std::setw(7) << s.n_stick
                  << std::setw(6) << s.n_slip;
          }
        else
          pcout << "        -" << std::setprecision(3) << std::setw(9)
                << z.max_pressure << "    -" << std::setw(8) << s.n_active
                << "      -     -";
        pcout << std::setw(7) << s.uzawa_steps << std::setw(8) << s.newton_steps
              << std::setw(6) << s.cg_iterations << '\n'
              << std::defaultfloat;
      }
    if (timing)
      {
        pcout << "  wall times:";
        for (const HertzRun &h : hertz)
          pcout << ' ' << std::fixed << std::setprecision(2) << h.time << " s"
                << std::defaultfloat;
        pcout << '\n';
      }
    for (const HertzRun &h : hertz)
      {
        std::ostringstream file;
        file << parameters.output.directory << "/hertz_nu" << h.nu << "_F"
             << h.F << ".csv";
        write_nodes(h.nodes, file.str());
      }

    // The checks of Part 2. The contact alone holds the disc, so the normal
    // force is P. Sideways only friction holds it and there is no
    // sideways load, so the tangential force sum_s m_s l2_s must vanish, to
    // the solver tolerances, relative to what friction could resist, F P.
    for (const HertzRun &h : hertz)
      {
        std::ostringstream run;
        run << "Part 2, nu = " << h.nu << ", F = " << h.F;
        const auto  &z     = h.result.zone;
        const double error = std::abs(z.contact_force / hertz_load - 1.);
        check(error <= uzawa_tolerance,
              run.str() + ": normal force = P",
              error,
              "relative, <= the Uzawa tolerance");
        if (h.F == 0.)
          continue;
        check(z.tangential_force <= uzawa_tolerance * h.F * hertz_load,
              run.str() + ": tangential force = 0",
              z.tangential_force,
              "<= the Uzawa tolerance times F P");
        const double excess = cone_excess(h.nodes);
        const double bound  = cone_bound(parameters.friction, h.nodes.size());
        check(excess <= bound,
              run.str() + ": |l2| <= F l1 at every node",
              excess,
              "max (|l2| - F l1) / max F l1 <= " + format_number(bound));
      }
    // The stick zone |x| < c in the middle, slip zones c < |x| < a beside
    // it (at nu = 0.3, where there is slip).
    const auto centre_stick = zone_extent(hertz[1].nodes, 1, 0.);
    const auto centre_slip  = zone_extent(hertz[1].nodes, 2, 0.);
    check(centre_stick.second >= 0. && centre_slip.first < 1e300 &&
            centre_stick.second < centre_slip.first,
          "Part 2, nu = 0.3: stick in the middle, slip toward the edges",
          centre_stick.second / hertz[1].result.zone.edge_half_width,
          "c/a, every stick node nearer the centre than every slip node");
    // The narrowing: Spence's partial-slip solution makes it depend on
    // beta/F only; measured 2.4-2.5 % at nu = 0.3 on every mesh and at
    // a/R = 0.05, 0.12 % at nu = 0.49 (doc/friction.md).
    check(change[1] <= -0.015,
          "Part 2, nu = 0.3: friction narrows the contact zone",
          change[1],
          "relative change of a <= -1.5 %");
    check(std::abs(change[3]) <= 0.005,
          "Part 2, nu = 0.49: friction hardly changes the zone",
          change[3],
          "|relative change of a| <= 0.5 %");
    check(std::abs(change[1]) >= 5. * std::abs(change[3]),
          "Part 2: the narrowing at nu = 0.3 is much larger than at 0.49",
          change[1] / change[3],
          "ratio >= 5");

    pcout << "\nChecks:\n" << checks.str() << "All checks passed.\n";
  }
} // namespace Step2

// @sect3{The main function}
//
// As in the library's source/main.cc: one parameter file, and a message
// and a non-zero exit status if anything fails (a failed check included).
int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  try
    {
      Step2::run(argc > 1 ? argv[1] : "step-3.prm");
    }
  catch (const dualcontact::InputError &error)
    {
      if (root)
        std::cerr << "step-3: " << error.what() << std::endl;
      return error.code;
    }
  catch (const dealii::ExceptionBase &exc)
    {
      if (root)
        {
          std::cerr << "step-3: error: ";
          exc.print_info(std::cerr);
          std::cerr << std::endl;
        }
      return 1;
    }
  catch (const std::exception &exc)
    {
      if (root)
        std::cerr << "step-3: error: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}
