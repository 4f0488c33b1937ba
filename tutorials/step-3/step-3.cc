/* step-3: Coulomb friction: the friction functional and the threshold
 * iteration.
 *
 * step-1 solved frictionless contact by the Uzawa iteration on the modified
 * Lagrangian. This step adds Coulomb friction and shows how it enters the
 * method. For a given friction threshold theta_s (Tresca) the problem is a
 * convex minimisation with the non-smooth term sum_s m_s theta_s |v_t(s)|.
 * Splitting w = v_t and minimising over w in closed form turns that term
 * into a Huber function of y = l2 + r v_t, whose gradient is the projection
 * onto the disc of radius theta and whose generalised Hessian is r at a
 * sticking node and r (theta/|y|)(I - y y^T/|y|^2) at a slipping one. The
 * multiplier update becomes l2 <- proj_theta(l2 + r v_t). Coulomb's
 * threshold theta = F l1 depends on the unknown pressure: the threshold
 * iteration finds it by successive approximations (doc/theory.md §1-§3).
 *
 * The program
 *  1. checks the friction term of one node: the closed-form minimum over w
 *     against a search, its gradient and its generalised Hessian against
 *     finite differences, in 2D and in 3D;
 *  2. writes the threshold iteration out in its two strategies, nested (as
 *     published) and merged, on the project's block (prm/paper_block.prm,
 *     with a lighter push: step-3.prm) pressed against a rough wall, and
 *     compares their cost and their solutions and shows the stick and slip
 *     zones on the wall.
 *
 * README.md has the derivation and the results.
 */

// @sect3{Include files}
//
// The library's Problem class for the mesh, the assembly and the
// measurements; its Uzawa and Newton iterations, which the threshold
// iteration below calls; the pure functions of the contact solver
// (projection onto the disc, Huber function); the tutorials' tools.
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <dualcontact/contact_functions.h>
#include <dualcontact/contact_problem.h>
#include <dualcontact/newton_solver.h>
#include <dualcontact/parameters.h>
#include <dualcontact/uzawa_iteration.h>

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

namespace Step3
{
  using namespace dealii;
  using namespace dualcontact;

  using tutorial::format;

  // The block of this step is two-dimensional (plane strain).
  constexpr unsigned int dim = 2;

  // @sect3{The friction term of one node}
  //
  // At a contact node s, with the threshold theta, the multiplier l2 and the
  // augmentation r, the modified Lagrangian holds
  //   min_w [ theta |w| + l2 (v_t - w) + r/2 (v_t - w)^2 ]
  //     = psi_theta(y) / r - l2^2 / (2 r),   y = l2 + r v_t,
  // psi_theta the Huber function: y^2/2 for |y| <= theta, theta |y| -
  // theta^2/2 beyond (README.md, section 3). Its derivative in v_t is
  // proj_theta(y), its second derivative r D(y): r at a sticking node
  // (|y| < theta), 0 at a slipping one in 2D. We evaluate the minimum over
  // w by a search (a convex function of one variable: ternary search) and
  // compare it with the closed form, and compare the derivatives with
  // central differences. The closed forms are the library's huber() and
  // project_onto_disc() (include/dualcontact/contact_functions.h).
  double
  friction_term(const double v_t,
                const double l2,
                const double r,
                const double theta)
  {
    const Tensor<1, 1> y({l2 + r * v_t});
    return huber(y, theta) / r - l2 * l2 / (2. * r);
  }

  double
  friction_term_searched(const double v_t,
                         const double l2,
                         const double r,
                         const double theta)
  {
    const auto f = [&](const double w) {
      return theta * std::abs(w) + l2 * (v_t - w) +
             0.5 * r * (v_t - w) * (v_t - w);
    };
    double low = -100., high = 100.;
    for (unsigned int i = 0; i < 200; ++i)
      {
        const double a = low + (high - low) / 3., b = high - (high - low) / 3.;
        if (f(a) < f(b))
          high = b;
        else
          low = a;
      }
    return f(0.5 * (low + high));
  }

  // The slip Hessian in 3D, written from the formula: for |y| >= theta,
  // D(y) = (theta/|y|) (I - yhat yhat^T), yhat = y/|y|, in the tangent
  // plane. Compared with central differences of the library's projection.
  double
  slip_hessian_difference(const Tensor<1, 2> &y, const double theta)
  {
    const double       norm    = y.norm();
    const Tensor<1, 2> y_hat   = y / norm;
    const double       h       = 1e-6;
    double             largest = 0.;
    for (unsigned int b = 0; b < 2; ++b)
      {
        Tensor<1, 2> e;
        e[b]                    = 1.;
        const Tensor<1, 2> diff = (project_onto_disc(y + h * e, theta) -
                                   project_onto_disc(y - h * e, theta)) /
                                  (2. * h);
        for (unsigned int a = 0; a < 2; ++a)
          {
            const double D_ab =
              theta / norm * ((a == b ? 1. : 0.) - y_hat[a] * y_hat[b]);
            largest = std::max(largest, std::abs(D_ab - diff[a]));
          }
      }
    return largest;
  }

  // The table, and the largest deviation of all comparisons (returned for
  // the checks).
  double
  show_one_node(ConditionalOStream &pcout)
  {
    const double theta = 1., r = 2., l2 = 0.2, h = 1e-6;
    pcout << "The friction term of one node, theta = 1, r = 2, l2 = 0.2:\n"
          << "     v_t       y  node   Phi (Huber)  (search)   Phi' = proj"
             "  (difference)   Phi'' = r D  (difference)\n";
    double largest = 0.;
    for (const double v_t : {0.1, 0.5, -1.})
      {
        const double y        = l2 + r * v_t;
        const double phi      = friction_term(v_t, l2, r, theta);
        const double searched = friction_term_searched(v_t, l2, r, theta);
        const double gradient = project_onto_disc(Tensor<1, 1>({y}), theta)[0];
        const double gradient_difference =
          (friction_term(v_t + h, l2, r, theta) -
           friction_term(v_t - h, l2, r, theta)) /
          (2. * h);
        const double hessian = std::abs(y) < theta ? r : 0.; // r D(y), 2D
        const double hessian_difference =
          (project_onto_disc(Tensor<1, 1>({y + r * h}), theta)[0] -
           project_onto_disc(Tensor<1, 1>({y - r * h}), theta)[0]) /
          (2. * h);
        largest = std::max({largest,
                            std::abs(phi - searched),
                            std::abs(gradient - gradient_difference),
                            std::abs(hessian - hessian_difference)});
        pcout << format("%8.2f", v_t) << format("%8.2f", y)
              << (std::abs(y) < theta ? "  stick" : "  slip ")
              << format("%13.6f", phi) << format("%10.6f", searched)
              << format("%14.6f", gradient)
              << format("%14.6f", gradient_difference)
              << format("%14.6f", hessian)
              << format("%14.6f", hessian_difference) << "\n";
      }
    const Tensor<1, 2> y({1.5, 2.});
    const double       d3 = slip_hessian_difference(y, theta);
    largest               = std::max(largest, d3);
    pcout << "  3D, y = (1.5, 2), |y| = 2.5: D(y) = (theta/|y|) (I - yhat "
             "yhat^T) against differences of proj: "
          << format("%.1e", d3) << "\n\n";
    return largest;
  }

  // @sect3{The contact nodes, gathered}
  //
  // Each rank owns some of the contact nodes s (doc/theory.md §4). For the
  // tables, the checks and the figures we gather all of them on every rank,
  // sorted by their position along the tangent t of the wall (t = e_y, up
  // the wall). At each node we keep
  //   l1       the contact pressure,
  //   l2       the tangential traction, its coordinate along t,
  //   theta    the threshold the solution was computed with,
  //   F l1     the threshold of the final pressure (the friction law's
  //            threshold_from_pressure; F l1 for Coulomb),
  //   status   0 separated (l1 = 0), 1 stick (|l2| < theta), 2 slip.
  // The merged strategy ends with theta = F l1 exactly. The nested one ends
  // with the theta of the previous pressure, within the threshold tolerance
  // of F l1, so that |l2| <= theta holds exactly for the theta it solved
  // with.
  struct NodeValues
  {
    double       position, l1, l2, theta, F_l1;
    unsigned int status;

    // for Utilities::MPI::all_gather
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &position &l1 &l2 &theta &F_l1 &status;
    }
  };

  std::vector<NodeValues>
  gather_nodes(const ContactSet<dim> &contact)
  {
    std::vector<NodeValues> local;
    for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
      local.push_back({contact.nodes[s].position * contact.tangent,
                       contact.l1[s],
                       contact.l2[s][0],
                       contact.threshold[s],
                       contact.threshold_from_pressure(s),
                       contact.status(s)});
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
    out << "position,l1,l2,abs_l2,theta,F_l1,status_code,status\n"
        << std::setprecision(10);
    for (const NodeValues &n : nodes)
      out << n.position << ',' << n.l1 << ',' << n.l2 << ',' << std::abs(n.l2)
          << ',' << n.theta << ',' << n.F_l1 << ',' << n.status << ','
          << name[n.status] << '\n';
  }

  // @sect3{Watching the Uzawa steps}
  //
  // The Uzawa and Newton iterations tell an IterationObserver of every step
  // (include/dualcontact/contact_system.h). This one numbers the Uzawa
  // steps of a solve consecutively and records d(theta) = |theta_new -
  // theta| / |theta_new| whenever theta changes: after every Uzawa step in
  // the merged strategy (the record carries it as change_g), after every
  // given-threshold problem in the nested one (the nested loop below adds
  // it). The figure threshold_history.svg plots it: how fast theta
  // converges against the Uzawa steps it costs.
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
    add(const double change)
    {
      rows.emplace_back(uzawa_steps, change);
    }

    unsigned int                                 uzawa_steps = 0;
    std::vector<std::pair<unsigned int, double>> rows;
  };

  // @sect3{The threshold iteration, written out}
  //
  // For a given threshold theta the problem is convex, and the Uzawa
  // iteration of step-1, with both multipliers, solves it. Each of its
  // steps is a proximal step by the Newton iteration and the multiplier
  // update (README.md, section 4; doc/theory.md §3.2):
  //   l1 <- (l1 - r g(v))^+,   l2 <- proj_theta(l2 + r v_t),
  // proj_theta the clamp to [-theta, theta] in 2D. UzawaIteration::solve()
  // runs it until the relative changes of l1, l2, v and the penetration are
  // below <Solver/Uzawa tolerance> (doc/theory.md §6).
  //
  // Coulomb's law asks for theta = F l1 with the l1 of the solution itself:
  // a fixed point of the map theta -> F l1(theta). For small F the map is a
  // contraction (Lipschitz constant proportional to F), and successive
  // approximations converge.
  //
  // The first threshold theta^(0) = F l1^(0). On a cold start l1^(0) = 0,
  // so theta^(0) = 0 (<Friction/Initial threshold> = zero): the first
  // given-threshold problem is the frictionless one, and every node in
  // contact "slips" with |l2| = theta = 0. With `frictionless`, l1^(0) is
  // the pressure of a frictionless solve run first. On a refined mesh
  // (nested iteration, doc/theory.md §7) the previous mesh's theta, carried
  // by transfer_fields(), is kept.
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

  // The nested strategy, as published. Threshold step j:
  //   1. solve the given-threshold problem for theta^(j) by the Uzawa
  //      iteration, to convergence;
  //   2. theta^(j+1) = F l1(theta^(j)), and its relative change
  //        d(theta) = |theta^(j+1) - theta^(j)| / |theta^(j+1)|
  //      (Euclidean norms over the nodes);
  //   3. stop if d(theta) <= tol_theta (<Friction/Threshold tolerance>),
  //      keeping theta^(j), with which |l2| <= theta holds exactly;
  //      otherwise repeat.
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

        double sums[2] = {0., 0.}; // |theta_new - theta|^2, |theta_new|^2
        for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
          {
            const double theta_new = contact.threshold_from_pressure(s);
            sums[0] += std::pow(theta_new - contact.threshold[s], 2);
            sums[1] += theta_new * theta_new;
          }
        Utilities::MPI::sum(ArrayView<const double>(sums, 2),
                            MPI_COMM_WORLD,
                            ArrayView<double>(sums, 2));
        const double change =
          relative_change(std::sqrt(sums[0]), std::sqrt(sums[1]));
        history.add(change);
        total.threshold_steps = step;
        total.change_g        = change;

        pcout << "   threshold step " << std::setw(3) << step << ": "
              << std::setw(2) << part.uzawa_steps << " Uzawa steps, "
              << std::setw(2) << part.newton_steps << " Newton, "
              << std::setw(3) << part.cg_iterations << " CG, stick/slip "
              << part.n_stick << '/' << part.n_slip << ", d(theta) "
              << format("%.2e", change) << '\n';

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
  // theta = F l1, then l2 = proj_theta(l2 + r v_t) (doc/theory.md §3.2,
  // step 3), so |l2| <= F l1 holds after every step. It stops when the
  // Uzawa tests and d(theta) <= tol_theta hold together.
  // UzawaIteration::solve() does exactly this when told to update the
  // threshold. The convergence theorem of the Uzawa iteration is for a
  // fixed theta and does not cover this loop; that is why the program
  // compares its solution with the nested one's.
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
    total.threshold_steps   = total.uzawa_steps; // theta moved in every step
    return total;
  }

  // @sect3{The block against the wall}
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

    // (a blank line before each strategy, and before each refined mesh of
    // the nested one: paragraphs that README.md can quote one by one)
    pcout << (strategy == FrictionStrategy::merged ? "\n" : "") << "  "
          << run.name << " threshold iteration\n";
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
        pcout << (cycle > 0 && strategy == FrictionStrategy::nested ? "\n" : "")
              << "  cycle " << cycle << ": " << mesh.n_cells << " cells, "
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
        excess  = std::max(excess, std::abs(n.l2) - n.F_l1);
        largest = std::max(largest, n.F_l1);
      }
    return excess / largest;
  }

  // How far the cone may be exceeded. The merged strategy projects l2 onto
  // [-F l1, F l1] right after setting theta = F l1: exact up to round-off.
  // The nested one stops when |theta^(j+1) - theta^(j)| <= tol_theta
  // |theta^(j+1)| and keeps theta^(j), so at a slip node |l2| = theta^(j)
  // may exceed F l1 = theta^(j+1); over N nodes the Euclidean bound gives
  // at most sqrt(N) tol_theta max theta at any one node.
  double
  cone_bound(const FrictionStrategy strategy,
             const double           tolerance,
             const unsigned int     n_nodes)
  {
    return strategy == FrictionStrategy::merged ?
             1e-12 :
             std::sqrt(1. * n_nodes) * tolerance;
  }

  // The zones: the smallest and the largest position of a node with status
  // `status` (1e300 and -1 if there is none).
  std::pair<double, double>
  zone_extent(const std::vector<NodeValues> &nodes, const unsigned int status)
  {
    double lowest = 1e300, highest = -1.;
    for (const NodeValues &n : nodes)
      if (n.status == status)
        {
          lowest  = std::min(lowest, n.position);
          highest = std::max(highest, n.position);
        }
    return {lowest, highest};
  }

  // @sect3{The whole step}
  //
  // The program in the shape of deal.II's steps: a class whose run() reads
  // as its stages, one member function each, and members for what a later
  // stage needs of an earlier one (the two runs and the figures the checks
  // judge).
  class ThresholdStrategies
  {
  public:
    explicit ThresholdStrategies(const Parameters &parameters);

    tutorial::Checks
    run();

  private:
    void
    check_scene();
    void
    solve_both_strategies();
    void
    print_costs();
    void
    compare_on_finest_mesh();
    void
    write_figure_data() const;
    tutorial::Checks
    check_results() const;

    // The scene, the screen (rank 0 prints), whether it shows times, and
    // the friction coefficient.
    const Parameters  &parameters;
    const bool         root;
    ConditionalOStream pcout;
    const bool         timing;
    double             F = 0.;

    // The largest error of the one-node test, the two runs and their
    // totals; on the finest mesh: the nodes, the largest differences of l1
    // and l2 between the runs, the stick and slip zones, and the nodes per
    // status (separated, stick, slip).
    double                    one_node = 0.;
    BlockRun                  nested, merged;
    ContactStatistics         totals[2];
    unsigned int              n_nodes = 0;
    double                    d_l1 = 0., d_l2 = 0.;
    std::pair<double, double> stick, slip;
    unsigned int              counts[3] = {0, 0, 0};
  };


  ThresholdStrategies::ThresholdStrategies(const Parameters &parameters)
      : parameters(parameters)
      , root(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      , pcout(std::cout, root)
      , timing(parameters.output.print_timing)
  {}


  // The friction term on one node (section 3 of the README), then both
  // strategies on the block, their cost, their solutions compared, the
  // data for plot.gp and the checks.
  tutorial::Checks
  ThresholdStrategies::run()
  {
    check_scene();
    one_node = show_one_node(pcout);
    solve_both_strategies();
    print_costs();
    compare_on_finest_mesh();
    write_figure_data();
    return check_results();
  }


  // A 2D scene whose friction threshold depends on the pressure through
  // a coefficient F (Coulomb, or a law of that kind that you add).
  void
  ThresholdStrategies::check_scene()
  {
    const auto law = create_friction_law(parameters.friction.law);
    AssertThrow(parameters.geometry.dimension == dim &&
                  law->depends_on_pressure() &&
                  law->parameter_entry() == "Coefficient",
                ExcMessage("step-3 needs a 2D scene with Coulomb friction "
                           "(or another law theta(F, l1))."));
    F = std::stod(parameters.friction.parameter);
    if (root)
      std::filesystem::create_directories(parameters.output.directory);

    pcout << "step-3: Coulomb friction, the friction functional and the "
             "threshold iteration ("
          << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
          << " MPI rank(s))\n\n";
  }


  // @sect4{Nested against merged}
  //
  // Both strategies, from the same start on the same meshes. The first
  // mesh starts cold (v = 0, l1 = l2 = 0, theta^(0) = 0); every refined
  // mesh starts from the previous mesh's v, l1, l2 and theta (nested
  // iteration, doc/theory.md §7), so that the cost of the later meshes
  // shows what each strategy does from a good first guess.
  void
  ThresholdStrategies::solve_both_strategies()
  {
    pcout << "The block against the wall, Coulomb F = " << F << '\n';
    nested = solve_block(parameters, FrictionStrategy::nested, pcout);
    merged = solve_block(parameters, FrictionStrategy::merged, pcout);
  }


  // The cost, per mesh and in total. For the nested strategy `threshold`
  // counts the given-threshold problems solved and `Uzawa` all the Uzawa
  // steps spent on them; for the merged one the two are the same, since
  // theta moves in every Uzawa step. Each Uzawa step is one proximal
  // step, a few Newton steps, each one CG solve: the Newton and CG
  // columns are what the time goes into.
  void
  ThresholdStrategies::print_costs()
  {
    pcout << "\nThe cost of the two strategies, per mesh and in total:\n"
          << "  strategy  cycle    DoFs  threshold  Uzawa  Newton     CG  stick"
             "  slip\n";
    for (const unsigned int i : {0, 1})
      {
        const BlockRun &run = i == 0 ? nested : merged;
        for (unsigned int c = 0; c < run.cycles.size(); ++c)
          {
            const ContactStatistics &s = run.cycles[c].statistics;
            totals[i].add(s);
            pcout << std::setw(10) << run.name << std::setw(7) << c
                  << std::setw(8) << run.cycles[c].n_dofs << std::setw(11)
                  << s.threshold_steps << std::setw(7) << s.uzawa_steps
                  << std::setw(8) << s.newton_steps << std::setw(7)
                  << s.cg_iterations << std::setw(7) << s.n_stick
                  << std::setw(6) << s.n_slip << '\n';
          }
        pcout << std::setw(10) << run.name << "    all" << std::setw(19)
              << totals[i].threshold_steps << std::setw(7)
              << totals[i].uzawa_steps << std::setw(8) << totals[i].newton_steps
              << std::setw(7) << totals[i].cg_iterations
              << (timing ? format("  (%.2f s)", run.time) : "") << '\n';
      }
  }


  // How far apart are the two solutions? The merged one is a fixed point
  // of theta = F l1 to the Uzawa tolerance (its test on d(l1) = d(theta));
  // the nested one lags by its last threshold step, d(theta) <= tol_theta
  // in the Euclidean norm, which can concentrate at one node up to
  // sqrt(N) tol_theta. The two solutions on the finest mesh, node by
  // node: the same nodes in the same order, since both runs made the same
  // meshes.
  void
  ThresholdStrategies::compare_on_finest_mesh()
  {
    AssertThrow(nested.nodes.size() == merged.nodes.size(), ExcInternalError());
    n_nodes       = merged.nodes.size();
    double l1_max = 0., theta_max = 0.;
    for (unsigned int i = 0; i < n_nodes; ++i)
      {
        d_l1 =
          std::max(d_l1, std::abs(nested.nodes[i].l1 - merged.nodes[i].l1));
        d_l2 =
          std::max(d_l2, std::abs(nested.nodes[i].l2 - merged.nodes[i].l2));
        l1_max    = std::max(l1_max, merged.nodes[i].l1);
        theta_max = std::max(theta_max, merged.nodes[i].F_l1);
      }
    d_l1 /= l1_max;
    d_l2 /= theta_max;

    // The zones along the wall, measured from its foot y = 0: a node
    // sticks where |l2| < F l1 and slips where |l2| = F l1.
    stick = zone_extent(merged.nodes, 1);
    slip  = zone_extent(merged.nodes, 2);
    for (const NodeValues &n : merged.nodes)
      ++counts[n.status];
    const ContactZoneRecord &zone = merged.zone;
    pcout << "\nThe finest mesh: normal force "
          << format("%.6f", zone.contact_force) << " (net normal load "
          << format("%.6f", merged.normal_load) << "), tangential force "
          << format("%.5f", zone.tangential_force)
          << " (F N = " << format("%.5f", F * zone.contact_force) << ")\n"
          << "  wall: " << counts[1] << " stick, " << counts[2] << " slip, "
          << counts[0] << " separated nodes";
    if (counts[1] > 0)
      pcout << "; stick for y <= " << format("%.4f", stick.second);
    if (counts[2] > 0)
      pcout << "; slip for y >= " << format("%.4f", slip.first);
    pcout << "\n  nested against merged: max |l1 difference| / max l1 = "
          << format("%.2e", d_l1) << ",\n"
          << "                         max |l2 difference| / max F l1 = "
          << format("%.2e", d_l2) << '\n';
  }


  // The finest mesh's nodes and each strategy's d(theta) per threshold
  // step of the first mesh, for plot.gp.
  void
  ThresholdStrategies::write_figure_data() const
  {
    write_nodes(merged.nodes, parameters.output.directory + "/contact.csv");
    if (root)
      {
        std::ofstream out(parameters.output.directory +
                          "/threshold_history.csv");
        out << "strategy,uzawa_steps,change_theta\n";
        for (const BlockRun *r : {&nested, &merged})
          for (const auto &[k, change] : r->history)
            out << r->name << ',' << k << ',' << change << '\n';
      }
  }


  // @sect4{The checks}
  //
  // 1. The friction term of one node: the closed forms against the search
  //    and the central differences. The search resolves the minimum to
  //    round-off; the differences with h = 1e-6 are exact for the
  //    piecewise quadratic Phi away from a kink up to round-off of order
  //    1e-16/h = 1e-10.
  // 2. Only the wall holds the block along x, so the normal contact force
  //    sum_s m_s l1_s equals the net load toward the wall, up to the
  //    solver tolerances (doc/theory.md §6: the Newton target, the
  //    Uzawa tolerance on the change of v). The slider shares the vertical
  //    load with the wall, so the wall's tangential force is not fixed by
  //    statics and is not checked.
  // 3. Coulomb's cone, to the bound of cone_bound() above.
  // 4. Nested and merged agree to that bound plus the solutions' own
  //    tolerance.
  // 5. The wall has the zones step-3.prm promises.
  // 6. The merged strategy is the cheaper one.
  tutorial::Checks
  ThresholdStrategies::check_results() const
  {
    pcout << "\nChecks:\n";
    tutorial::Checks checks;
    checks(one_node <= 1e-8,
           "one node: closed form = search, derivatives = differences (" +
             format("%.0e", one_node) + " <= 1e-8)");
    const double uzawa_tolerance = parameters.solver.uzawa_tolerance;
    const double tolerance       = parameters.friction.tolerance;
    for (const BlockRun *r : {&nested, &merged})
      {
        const FrictionStrategy strategy =
          r == &nested ? FrictionStrategy::nested : FrictionStrategy::merged;
        const double error =
          std::abs(r->zone.contact_force / r->normal_load - 1.);
        checks(error <= uzawa_tolerance,
               r->name + ": normal force = net load (relative " +
                 format("%.0e", error) + " <= Uzawa tolerance)");
        const double excess = cone_excess(r->nodes);
        const double bound  = cone_bound(strategy, tolerance, n_nodes);
        checks(excess <= bound,
               r->name + ": max (|l2| - F l1) / max F l1 = " +
                 format("%.1e", excess) + " <= " + format("%.1e", bound));
      }
    const double same =
      cone_bound(FrictionStrategy::nested, tolerance, n_nodes) +
      10. * uzawa_tolerance;
    checks(std::max(d_l1, d_l2) <= same,
           "nested = merged: " + format("%.1e", std::max(d_l1, d_l2)) +
             " <= sqrt(N) tol_theta + 10 tol_Uzawa = " + format("%.1e", same));
    checks(counts[1] > 0 && counts[2] > 0 && stick.second < slip.first,
           "the wall sticks at its foot, slips at its top");
    checks(totals[1].uzawa_steps < totals[0].uzawa_steps &&
             totals[1].newton_steps < totals[0].newton_steps,
           "merged cheaper: Uzawa " + std::to_string(totals[1].uzawa_steps) +
             " < " + std::to_string(totals[0].uzawa_steps) + ", Newton " +
             std::to_string(totals[1].newton_steps) + " < " +
             std::to_string(totals[0].newton_steps));
    return checks;
  }


  // The step as run_tutorial() calls it: the program on the scene.
  tutorial::Checks
  run(const Parameters &parameters)
  {
    return ThresholdStrategies(parameters).run();
  }
} // namespace Step3

// @sect3{The main function}
//
// MPI, the parameter file (default step-3.prm) and, after it, overrides as
// the dualcontact program takes them (`--set "Friction/Coefficient=0.2"`),
// for the experiments of README.md; one message and a non-zero exit status
// on any error or failed check.
int
main(int argc, char *argv[])
{
  return dualcontact::tutorial::run_tutorial(
    argc, argv, "step-3", "step-3.prm", Step3::run);
}
