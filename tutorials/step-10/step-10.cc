/* step-10: the paper's method on its own discretisation.
 *
 * The source paper (Vikhtenko 2012) discretises the contact problem with
 * piecewise-linear elements on triangles, refines by halving (h_i =
 * h_{i-1}/2, nested meshes) and finds the friction threshold g by
 * successive approximations around the Uzawa iteration (the threshold
 * iteration nested). Steps 1-9 ran the method on quadrilaterals. This step
 * runs it the paper's way, on the block of prm/paper_block_p1.prm (P1
 * triangles, <Friction/Threshold iteration> = nested, 3 meshes), and the
 * same block with Q1 quadrilaterals on the same vertices, and asks:
 *   1. what the discretisation changes: the DoFs (none: P1 on two
 *      triangles per square has the nodes of Q1), the iterations and the
 *      time, the contact force, Coulomb's cone, stick and slip along the
 *      wall, and the pressure P1 against Q1 node by node;
 *   2. whether both converge under halving, to the same answer, and at
 *      what rate: the pressure of each mesh against the next one's on the
 *      nodes they share. A singular stress at the top corner of the wall
 *      sets that rate, 1/2 - a with a the exponent of the corner node:
 *      where the corner sticks (Q1) it is clamped, and Williams' exponent
 *      gives 1/2 - a = 0.21; where the corner node slips (P1 on the third
 *      and fourth meshes) it is not clamped, a is smaller and the rate
 *      higher (README.md has the measured figures).
 * The scene is step-10.prm; README.md has the introduction and the results.
 */

// @sect3{Include files}
//
// The library's Problem class (the whole solver, one refinement cycle after
// the other, and the record of each), its parameters, and the tutorials'
// tools (the CSV reader of csv_table.h, the checks, main()).
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/utilities.h>

#include <dualcontact/contact_problem.h>
#include <dualcontact/parameters.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "../common/csv_table.h"
#include "../common/tutorial_tools.h"

namespace Step10
{
  using namespace dealii;
  using namespace dualcontact;

  using tutorial::format;

  constexpr unsigned int dim = 2;

  // The convergence study compares each mesh with the next. The scene's
  // <Refinement/Number of cycles> meshes (3, the paper's sequence of
  // prm/paper_block_p1.prm) give two such pairs and one rate; one mesh
  // more gives a second rate, which shows whether the first was a
  // coincidence. Each mesh's solution depends only on the meshes before
  // it, so the scene's meshes come out the same with or without it.
  constexpr unsigned int extra_meshes = 1;

  // @sect3{The wall, node by node}
  //
  // The library writes, per mesh, one row per contact node into
  // contact_NN.csv (doc/output.md): the position, the weight m_s, the
  // pressure l1, the tangential traction l2 (along t = (-n_y, n_x), here
  // up the wall), the threshold g the solution was computed with, and the
  // node's status. The wall is the line x = 2, so a node is its height y.
  // We read the file the way a user's script would, by column name, and
  // sort the nodes from the foot (y = 0) to the top corner (y = 1).
  struct WallNode
  {
    double      y, l1, l2, g;
    std::string status;
  };

  std::vector<WallNode>
  read_wall(const std::string &filename)
  {
    const tutorial::CsvTable table(filename);
    std::vector<WallNode>    nodes;
    for (unsigned int i = 0; i < table.n_rows(); ++i)
      nodes.push_back({table.number(i, "y"),
                       table.number(i, "l1"),
                       table.number(i, "l2"),
                       table.number(i, "g"),
                       table.text(i, "status")});
    std::sort(nodes.begin(),
              nodes.end(),
              [](const WallNode &a, const WallNode &b) { return a.y < b.y; });
    return nodes;
  }

  unsigned int
  count(const std::vector<WallNode> &nodes, const std::string &status)
  {
    return std::count_if(nodes.begin(), nodes.end(), [&](const WallNode &n) {
      return n.status == status;
    });
  }

  // @sect3{One element on the nested meshes}
  //
  // The scene with the given cell type, solved by ContactProblem::run() on
  // `n_meshes` meshes, each one the one before refined globally (every
  // triangle into 4, every square into 4: h halves, every vertex stays a
  // vertex), into its own folder under output/. From the run we keep
  //   - the record of each mesh (records.h): DoFs, iteration counts, the
  //     contact zone, the wall times of its phases;
  //   - the threshold steps (ContactProblem::iterations(), the rows of
  //     iterations.csv with loop = threshold): for each, the Uzawa steps of
  //     its given-threshold problem, the nodes that slip in its solution,
  //     and d(g) = |g_new - g| / |g_new|;
  //   - the wall of each mesh, read back from its contact_NN.csv.
  // Each mesh starts from the fields of the mesh before (nested iteration,
  // doc/theory.md §7), the first from zero with g = 0.
  struct ThresholdStep
  {
    unsigned int            cycle, uzawa_steps;
    types::global_dof_index n_slip;
    double                  change_g;
  };

  struct Run
  {
    std::string                        name; // P1 or Q1 (Pk, Qk at degree k)
    std::vector<CycleResult>           cycles;
    std::vector<ThresholdStep>         threshold_steps;
    std::vector<std::vector<WallNode>> wall; // one per mesh
  };

  Run
  solve(const Parameters  &scene,
        const CellKind     cells,
        const unsigned int n_meshes)
  {
    const std::string degree = std::to_string(scene.discretization.degree);
    const std::string name = (cells == CellKind::simplex ? "P" : "Q") + degree;
    Parameters        parameters   = scene;
    parameters.geometry.cell_kind  = cells;
    parameters.refinement.n_cycles = n_meshes;
    parameters.output.directory +=
      (cells == CellKind::simplex ? "/p" : "/q") + degree;

    std::ostringstream  silent; // the library's own report: not shown
    ContactProblem<dim> problem(parameters, MPI_COMM_WORLD, silent);
    problem.run();

    Run run;
    run.name   = name;
    run.cycles = problem.results();
    for (const IterationRecord &record : problem.iterations())
      if (record.loop == Loop::threshold)
        run.threshold_steps.push_back(
          {record.cycle, record.uzawa_steps, record.n_slip, record.change_g});
    // Every rank reads the files rank 0 wrote; the barrier makes sure they
    // are complete.
    MPI_Barrier(MPI_COMM_WORLD);
    for (unsigned int cycle = 0; cycle < n_meshes; ++cycle)
      {
        char file[32];
        std::snprintf(file, sizeof(file), "/contact_%02u.csv", cycle);
        run.wall.push_back(read_wall(parameters.output.directory + file));
      }
    return run;
  }

  // @sect3{Two pressures on the nodes they share}
  //
  // The pressure `l1` of one solution against `reference`'s on the nodes
  // of `nodes`, all of which `reference` has too: the nodes of P1 and Q1 on
  // the same mesh are the same, and the nodes of a mesh are nodes of every
  // finer one. The measures, over those nodes:
  //   rms     = sqrt(sum (l1 - l1_ref)^2 / sum l1_ref^2),
  //   the same without the top corner node (y = 1), and
  //   largest = the largest |l1 - l1_ref|, with its node's y and l1_ref.
  // The rms is the unweighted one of tests/unit/test_simplex.cc, which
  // measured 2.2 % for P1 against Q1 on the third mesh; every node counts
  // alike, the two end nodes included (with the weights m_s they would
  // count half).
  struct Difference
  {
    double rms = 0., rms_without_corner = 0.;
    double largest = 0., y = 0., reference_l1 = 0.;
    bool   nodes_shared = true;
  };

  Difference
  compare(const std::vector<WallNode> &nodes,
          const std::vector<WallNode> &reference)
  {
    Difference   d;
    double       sums[4] = {0., 0., 0., 0.}; // all nodes; without the corner
    unsigned int j       = 0;
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        // both sorted by y: the same node further on in `reference`
        while (j < reference.size() && reference[j].y < nodes[i].y - 1e-9)
          ++j;
        if (j == reference.size() ||
            std::abs(reference[j].y - nodes[i].y) > 1e-9)
          {
            d.nodes_shared = false;
            continue;
          }
        const double difference = nodes[i].l1 - reference[j].l1;
        const double square     = reference[j].l1 * reference[j].l1;
        sums[0] += difference * difference;
        sums[1] += square;
        if (i + 1 < nodes.size()) // the corner is the highest node
          {
            sums[2] += difference * difference;
            sums[3] += square;
          }
        if (std::abs(difference) > std::abs(d.largest))
          {
            d.largest      = difference;
            d.y            = nodes[i].y;
            d.reference_l1 = reference[j].l1;
          }
      }
    d.rms                = std::sqrt(sums[0] / sums[1]);
    d.rms_without_corner = std::sqrt(sums[2] / sums[3]);
    return d;
  }

  // @sect3{The corner}
  //
  // At the top corner of the wall two sides meet at a right angle: the
  // wall, where the block touches and sticks, so that its displacement is
  // zero there (clamped), and the top, loaded by a given traction (free:
  // a given traction does not change the singularity). Near such a corner
  // the stresses of plane elasticity behave like r^(lambda - 1), r the
  // distance from the corner, and Williams (1952) found lambda as the
  // smallest root in (0, 1) of
  //   (3 - 4 nu) sin^2(lambda alpha) = 4 (1 - nu)^2 - lambda^2 sin^2(alpha)
  // for a wedge of angle alpha, clamped on one side and free on the other.
  // At alpha = pi/2 the left side minus the right is increasing in lambda
  // on (0, 1), negative at 0 and 4 nu (1 - nu) > 0 at 1: one root,
  // found by bisection. For nu = 0.3, lambda = 0.711: the pressure at the
  // corner is infinite, and grows like r^(-0.289) toward it.
  double
  williams_lambda(const double nu)
  {
    const auto f = [nu](const double lambda) {
      const double s = std::sin(lambda * numbers::PI / 2.);
      return (3. - 4. * nu) * s * s + lambda * lambda -
             4. * (1. - nu) * (1. - nu);
    };
    double low = 0., high = 1.;
    for (unsigned int i = 0; i < 60; ++i)
      {
        const double middle           = 0.5 * (low + high);
        (f(middle) < 0. ? low : high) = middle;
      }
    return 0.5 * (low + high);
  }

  // What a mesh sees of that. The nodal pressure at the corner stands for
  // the pressure over the last element, of length h: it grows like h^(-a),
  // a = 1 - lambda, with no limit. Written p_c = p* + C h_c^(-a) on mesh
  // c, the increments grow by 2^a per halving, so that
  //   a = log2((p_{c+2} - p_{c+1}) / (p_{c+1} - p_c))
  // from three consecutive meshes, whatever p* and C are.
  //
  // In the rms difference of two meshes the corner node alone contributes
  // |p_{c+1} - p_c| ~ h^(-a) against the sum over all N ~ 1/h nodes of
  // l1^2 ~ N: a relative rms of order h^(-a) h^(1/2), which falls at the
  // rate 1/2 - a = 0.21 per halving. The nodes next to the corner add
  // terms of the same order, and the smooth part of the wall far less: the
  // corner sets the rate of the whole wall.
  double
  increment_exponent(const double p0, const double p1, const double p2)
  {
    return std::log2((p2 - p1) / (p1 - p0));
  }

  // @sect3{Coulomb's cone}
  //
  // |l2| <= F l1 at every node: the largest excess max_s (|l2_s| - F l1_s)
  // relative to the largest threshold F l1 (step-3). Negative where every
  // node sticks, about zero at a slipping node. The nested threshold
  // iteration stops once d(g) <= tol_g and keeps the g it solved with, so
  // at a slipping node |l2| = g may exceed F l1, the next g, by up to
  // sqrt(N) tol_g max g over N nodes (step-3, cone_bound).
  double
  cone_excess(const std::vector<WallNode> &nodes, const double F)
  {
    double excess = -1e300, largest = 0.;
    for (const WallNode &n : nodes)
      {
        excess  = std::max(excess, std::abs(n.l2) - F * n.l1);
        largest = std::max(largest, F * n.l1);
      }
    return excess / largest;
  }

  // @sect3{The whole step}
  //
  // The program in the shape of deal.II's steps: a class whose run() reads
  // as the stages below, one member function each, and members for what a
  // later stage needs of an earlier one (the two runs, the differences and
  // rates the checks judge).
  class ElementComparison
  {
  public:
    explicit ElementComparison(const Parameters &scene);

    tutorial::Checks
    run();

  private:
    void
    check_scene();
    void
    solve_both_elements();
    void
    print_mesh_table() const;
    void
    print_threshold_iteration() const;
    void
    print_wall() const;
    void
    compare_elements();
    void
    study_convergence();
    void
    study_corner();
    void
    write_figure_data() const;
    tutorial::Checks
    check_results() const;

    // The scene, the screen (rank 0 prints) and whether it shows times; the
    // scene's meshes, those of the convergence study, the scene's last.
    const Parameters  &scene;
    const bool         root;
    ConditionalOStream pcout;
    const bool         timing;
    const unsigned int n_cycles;
    const unsigned int n_meshes;
    const unsigned int last;
    double             F = 0.; // the friction coefficient

    // The two runs, P1 on triangles and Q1 on quadrilaterals, and their
    // names.
    Run                      p1, q1;
    std::vector<const Run *> runs;
    std::string              P, Q;

    // What the checks judge: P1 against Q1 per mesh, each element's mesh
    // against the next and the rates, the corner's exponents and Williams'
    // lambda.
    std::vector<Difference>              p1_q1;
    std::vector<std::vector<Difference>> steps;
    std::vector<double>                  rates;
    std::vector<std::vector<double>>     exponents;
    double                               lambda = 0.;
  };


  ElementComparison::ElementComparison(const Parameters &scene)
      : scene(scene)
      , root(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      , pcout(std::cout, root)
      , timing(scene.output.print_timing)
      , n_cycles(scene.refinement.n_cycles)
      , n_meshes(n_cycles + extra_meshes)
      , last(n_cycles - 1)
  {}


  // Both elements solved; then the meshes, the threshold iteration, the
  // wall, P1 against Q1, the convergence and the corner; the data for
  // plot.gp and the checks.
  tutorial::Checks
  ElementComparison::run()
  {
    check_scene();
    solve_both_elements();
    print_mesh_table();
    print_threshold_iteration();
    print_wall();
    compare_elements();
    study_convergence();
    study_corner();
    write_figure_data();
    return check_results();
  }


  // @sect4{The scene this step needs}
  //
  // The 2D rectangle with Coulomb friction, refined globally at least
  // once; anything else is refused with one message before a solve.
  void
  ElementComparison::check_scene()
  {
    tutorial::require(
      scene.geometry.dimension == dim && scene.geometry.type == "rectangle" &&
        scene.friction.law == "coulomb" &&
        scene.refinement.strategy == "global" && n_cycles >= 2,
      "step-10 compares P1 and Q1 on the block against the wall: it needs "
      "the 2D rectangle, Coulomb friction, <Refinement/Strategy> = global "
      "and two <Refinement/Number of cycles> or more.");
    try
      {
        F = std::stod(scene.friction.parameter);
      }
    catch (const std::exception &)
      {
        tutorial::require(false,
                          "step-10 needs <Friction/Coefficient> as a number.");
      }
    if (root)
      std::filesystem::create_directories(scene.output.directory);

    pcout << "step-10: the paper's method on its own discretisation ("
          << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
          << " MPI rank(s))\n\n";
  }


  // @sect4{P1 and Q1 on the same vertices}
  //
  // The rectangle's 40 x 20 squares, each split into 2 triangles by
  // <Geometry/Cell type> = simplex (FE_SimplexP(1) on a
  // parallel::shared triangulation, doc/simplices.md), or kept as squares
  // (FE_Q(1) on a parallel::distributed one). Both have one node per
  // vertex, so the same DoFs on every mesh; the triangles are twice as
  // many cells. Everything else is the scene: the same loads, r, chi,
  // tolerances, and the threshold iteration it names.
  void
  ElementComparison::solve_both_elements()
  {
    p1   = solve(scene, CellKind::simplex, n_meshes);
    q1   = solve(scene, CellKind::quadrilateral, n_meshes);
    runs = {&p1, &q1};
    P    = p1.name;
    Q    = q1.name;

    pcout << "The block against the wall, Coulomb F = " << F << ", "
          << (scene.friction.strategy == FrictionStrategy::nested ? "nested" :
                                                                    "merged")
          << " threshold iteration; " << n_cycles
          << " meshes, each halving h, and " << extra_meshes
          << " more for the convergence study\n\n";
  }


  // One line per mesh: cells, DoFs, contact nodes, the loops' counts
  // (threshold steps, Uzawa steps, Newton steps, CG iterations), the
  // nodes that stick and slip, the normal contact force sum_s m_s l1_s,
  // and with <Output/Print timing> the wall time of the solve (the three
  // loops); after the table, the counts of all meshes and, with timing,
  // the wall time of all phases of all meshes (refinement, set-up,
  // assembly, solve, measurements, output).
  void
  ElementComparison::print_mesh_table() const
  {
    pcout << P << " on triangles against " << Q
          << " on quadrilaterals, the same vertices:\n"
          << "  element  cycle  cells   DoFs  nodes  threshold  Uzawa  Newton"
             "    CG  stick  slip       force"
          << (timing ? "  solve [s]" : "") << "\n";
    ContactStatistics totals[2];
    double            times[2] = {0., 0.};
    for (unsigned int i = 0; i < runs.size(); ++i)
      for (unsigned int c = 0; c < n_cycles; ++c)
        {
          const CycleResult &r = runs[i]->cycles[c];
          totals[i].add(r.solve);
          times[i] += r.time.cycle;
          pcout << "  " << std::string(7 - runs[i]->name.size(), ' ')
                << runs[i]->name << format("%7.0f", c)
                << format("%7.0f", double(r.mesh.n_cells))
                << format("%7.0f", double(r.mesh.n_dofs))
                << format("%7.0f", double(r.solve.n_contact_nodes))
                << format("%11.0f", r.solve.threshold_steps)
                << format("%7.0f", r.solve.uzawa_steps)
                << format("%8.0f", r.solve.newton_steps)
                << format("%6.0f", r.solve.cg_iterations)
                << format("%7.0f", double(r.solve.n_stick))
                << format("%6.0f", double(r.solve.n_slip))
                << format("%12.7f", r.zone.contact_force)
                << (timing ? format("%11.2f", r.time.solve) : "") << "\n";
        }
    pcout << "\nAll " << n_cycles << " meshes:\n";
    for (unsigned int i = 0; i < runs.size(); ++i)
      pcout << "  " << runs[i]->name << ": " << totals[i].threshold_steps
            << " threshold steps, " << totals[i].uzawa_steps << " Uzawa, "
            << totals[i].newton_steps << " Newton, " << totals[i].cg_iterations
            << " CG" << (timing ? format(" (%.2f s)", times[i]) : "") << "\n";
  }


  // @sect4{The threshold iteration}
  //
  // Each threshold step solves the given-threshold problem for g by the
  // Uzawa iteration, then sets g <- F l1 and measures d(g). g enters the
  // solution only at the nodes that slip (|l2| = g): while every node
  // sticks, the next given-threshold problem has the same solution, its
  // Uzawa iteration stops after one step, and d(g) is at round-off. A
  // slipping node couples g and l1, and the successive approximations
  // contract by a factor per step (doc/theory.md §3.1). The merged
  // strategy has no threshold steps of its own: g <- F l1 in every Uzawa
  // step, and the table counts each Uzawa step as one.
  void
  ElementComparison::print_threshold_iteration() const
  {
    pcout << "\nThe threshold iteration: ";
    if (scene.friction.strategy == FrictionStrategy::merged)
      pcout << "merged, g <- F l1 in every Uzawa step\n";
    else
      pcout << "d(g) after each threshold step, and (its Uzawa steps, "
               "slip nodes):\n";
    for (const Run *r : runs)
      for (unsigned int c = 0;
           c < n_cycles && scene.friction.strategy == FrictionStrategy::nested;
           ++c)
        {
          pcout << "  " << r->name << " cycle " << c << ":";
          for (const ThresholdStep &step : r->threshold_steps)
            if (step.cycle == c)
              pcout << format("  %.2e", step.change_g)
                    << format(" (%.0f,", step.uzawa_steps)
                    << format(" %.0f)", double(step.n_slip));
          pcout << "\n";
        }
  }


  // @sect4{The wall on the last mesh}
  //
  // Stick and slip along the wall, Coulomb's cone at every node, and the
  // four highest nodes, where the two elements differ most.
  void
  ElementComparison::print_wall() const
  {
    const std::vector<WallNode> &wall_p1 = p1.wall[last];
    const std::vector<WallNode> &wall_q1 = q1.wall[last];
    AssertThrow(wall_p1.size() == wall_q1.size(),
                ExcMessage("P and Q elements have different contact nodes."));
    pcout << "\nThe wall on the last mesh (cycle " << last << ", "
          << wall_p1.size() << " nodes from y = " << wall_p1.front().y << " to "
          << wall_p1.back().y << "):\n";
    for (const Run *r : runs)
      {
        const std::vector<WallNode> &wall = r->wall[last];
        pcout << "  " << r->name << ": " << count(wall, "stick") << " stick, "
              << count(wall, "slip") << " slip";
        for (const WallNode &n : wall)
          if (n.status == "slip")
            pcout << " (y = " << format("%.4f", n.y) << ")";
        pcout << ", " << count(wall, "separated")
              << " separated; max (|l2| - F l1) / max F l1 = "
              << format("%.1e", cone_excess(wall, F)) << "\n";
      }
    // The wall's tangential force |sum_s m_s l2_s| is what the slider
    // leaves of the vertical load; friction could hold F N with the normal
    // force N.
    pcout << "  the wall's tangential force: " << P << " "
          << format("%.4f", p1.cycles[last].zone.tangential_force) << ", " << Q
          << " " << format("%.4f", q1.cycles[last].zone.tangential_force)
          << ", against F N = "
          << format("%.4f", F * q1.cycles[last].zone.contact_force) << "\n"
          << "  the top of the wall:\n"
          << "         y     " << P << " l1     " << P << " l2  " << P
          << " state     " << Q << " l1     " << Q << " l2  " << Q
          << " state\n";
    for (unsigned int i =
           wall_p1.size() - std::min<std::size_t>(4, wall_p1.size());
         i < wall_p1.size();
         ++i)
      pcout << format("%10.4f", wall_p1[i].y) << format("%10.4f", wall_p1[i].l1)
            << format("%10.4f", wall_p1[i].l2) << "  " << wall_p1[i].status
            << std::string(std::max<int>(0, 8 - wall_p1[i].status.size()), ' ')
            << format("%10.4f", wall_q1[i].l1)
            << format("%10.4f", wall_q1[i].l2) << "  " << wall_q1[i].status
            << "\n";
  }


  // @sect4{P1 against Q1}
  //
  // On every mesh the two elements have the same contact nodes. Their
  // pressures, node by node, relative to Q1's.
  void
  ElementComparison::compare_elements()
  {
    pcout << "\n"
          << P << " against " << Q
          << ": l1 on the nodes of each mesh, relative to " << Q << "'s:\n"
          << "  cycle  nodes  rms difference  without the corner  largest "
             "difference       at y  "
          << Q << "'s l1 there\n";
    for (unsigned int c = 0; c < n_meshes; ++c)
      {
        p1_q1.push_back(compare(p1.wall[c], q1.wall[c]));
        const Difference &d = p1_q1.back();
        pcout << format("%7.0f", c)
              << format("%7.0f", double(p1.wall[c].size()))
              << format("%14.2f %%", 100. * d.rms)
              << format("%18.2f %%", 100. * d.rms_without_corner)
              << format("%20.4f", d.largest) << format("%11.4f", d.y)
              << format("%15.4f", d.reference_l1) << "\n";
      }
  }


  // @sect4{Convergence under halving}
  //
  // Each mesh against the next, on the nodes of the coarser one, relative
  // to the finer one's pressure; the rate per halving of h between two
  // such differences, log2(d_c / d_{c+1}).
  void
  ElementComparison::study_convergence()
  {
    pcout << "\nConvergence under halving: l1 of mesh c + 1 against mesh c "
             "on the nodes of mesh c:\n"
          << "  element  meshes  rms difference   rate  without the corner   "
             "rate    largest       at y\n";
    steps.resize(runs.size());
    for (unsigned int i = 0; i < runs.size(); ++i)
      for (unsigned int c = 0; c + 1 < n_meshes; ++c)
        {
          steps[i].push_back(compare(runs[i]->wall[c], runs[i]->wall[c + 1]));
          const Difference &d    = steps[i].back();
          std::string       rate = "      -", rate_without = "      -";
          if (c > 0)
            {
              rates.push_back(std::log2(steps[i][c - 1].rms / d.rms));
              rate = format("%7.2f", rates.back());
              rate_without =
                format("%7.2f",
                       std::log2(steps[i][c - 1].rms_without_corner /
                                 d.rms_without_corner));
            }
          pcout << "  " << std::string(7 - runs[i]->name.size(), ' ')
                << runs[i]->name << "    " << c << ", " << c + 1
                << format("%16.3e", d.rms) << rate
                << format("%20.3e", d.rms_without_corner) << rate_without
                << format("%11.4f", d.largest) << format("%11.4f", d.y) << "\n";
        }
  }


  // The corner: its pressure on every mesh, and the exponent a of
  // l1 ~ h^(-a) from each three consecutive meshes, against Williams.
  void
  ElementComparison::study_corner()
  {
    const double nu = scene.material.poissons_ratio;
    lambda          = williams_lambda(nu);
    pcout << "\nThe top corner (y = " << p1.wall[last].back().y
          << "): l1 on each mesh, and a in l1 ~ h^(-a) from the increments "
             "of three meshes:\n";
    exponents.resize(runs.size());
    for (unsigned int i = 0; i < runs.size(); ++i)
      {
        pcout << "  " << runs[i]->name << "  l1:";
        for (unsigned int c = 0; c < n_meshes; ++c)
          pcout << format("%9.4f", runs[i]->wall[c].back().l1);
        pcout << ";  a:";
        for (unsigned int c = 0; c + 2 < n_meshes; ++c)
          {
            exponents[i].push_back(
              increment_exponent(runs[i]->wall[c].back().l1,
                                 runs[i]->wall[c + 1].back().l1,
                                 runs[i]->wall[c + 2].back().l1));
            pcout << format("%6.3f", exponents[i].back());
          }
        pcout << "\n";
      }
    pcout << "  Williams, clamped against free at a right angle, nu = " << nu
          << ": lambda = " << format("%.4f", lambda)
          << ", a = 1 - lambda = " << format("%.3f", 1. - lambda)
          << ", rate of the rms 1/2 - a = " << format("%.3f", lambda - 0.5)
          << "\n";
  }


  // @sect4{The figure's data}
  //
  // The wall on the scene's last mesh, one row per node: plot.gp draws
  // the pressure of P1 and Q1 along it (pressure.svg).
  void
  ElementComparison::write_figure_data() const
  {
    const std::vector<WallNode> &wall_p1 = p1.wall[last];
    const std::vector<WallNode> &wall_q1 = q1.wall[last];
    if (root)
      {
        std::ofstream csv(scene.output.directory + "/wall.csv");
        csv << "y,l1_p1,l1_q1,l2_p1,l2_q1,status_p1,status_q1\n";
        csv.precision(10);
        for (unsigned int i = 0; i < wall_p1.size(); ++i)
          csv << wall_p1[i].y << ',' << wall_p1[i].l1 << ',' << wall_q1[i].l1
              << ',' << wall_p1[i].l2 << ',' << wall_q1[i].l2 << ','
              << wall_p1[i].status << ',' << wall_q1[i].status << '\n';
      }
  }


  // @sect4{The checks}
  //
  // What the README claims, on the step's own numbers; the README's table
  // "The checks" gives each bound's reason.
  tutorial::Checks
  ElementComparison::check_results() const
  {
    pcout << "\nChecks:\n";
    tutorial::Checks checks;
    // 1. The same DoFs and the same contact nodes on every mesh.
    {
      bool        same = true;
      std::string dofs;
      for (unsigned int c = 0; c < n_meshes; ++c)
        {
          same &= p1.cycles[c].mesh.n_dofs == q1.cycles[c].mesh.n_dofs &&
                  p1_q1[c].nodes_shared &&
                  p1.wall[c].size() == q1.wall[c].size();
          dofs +=
            (c == 0 ? "" : ", ") + std::to_string(p1.cycles[c].mesh.n_dofs);
        }
      checks(same,
             P + " and " + Q + " have the same DoFs (" + dofs +
               ") and contact nodes on every mesh");
    }
    // 2. The normal contact force equals the load toward the wall, 30, on
    //    every mesh: only the wall holds the block along x.
    // 3. Coulomb's cone at every node of every mesh, to sqrt(N) tol_g.
    const double tolerance = scene.friction.tolerance;
    for (const Run *r : runs)
      {
        double force_error = 0., excess = -1e300, bound = 0.;
        for (unsigned int c = 0; c < n_meshes; ++c)
          {
            const CycleResult &result = r->cycles[c];
            force_error               = std::max(force_error,
                                   std::abs(result.zone.contact_force /
                                              result.solve.normal_load -
                                            1.));
            excess = std::max(excess, cone_excess(r->wall[c], F));
            bound =
              std::max(bound, std::sqrt(double(r->wall[c].size())) * tolerance);
          }
        checks(force_error <= scene.solver.uzawa_tolerance,
               r->name + ": normal force = load toward the wall (" +
                 format("%.0f", r->cycles[0].solve.normal_load) +
                 ") on every mesh (relative " + format("%.0e", force_error) +
                 " <= Uzawa tolerance)");
        checks(excess <= bound,
               r->name +
                 ": max (|l2| - F l1) / max F l1 = " + format("%.1e", excess) +
                 " <= sqrt(N) tol_g = " + format("%.1e", bound) +
                 " on every mesh");
      }
    // 4. The wall sticks along its whole height, but for the top corner
    //    node, which may slip; nothing separates.
    for (const Run *r : runs)
      {
        bool sticks = true;
        for (const std::vector<WallNode> &wall : r->wall)
          for (unsigned int i = 0; i < wall.size(); ++i)
            sticks &= wall[i].status == "stick" ||
                      (i + 1 == wall.size() && wall[i].status == "slip");
        checks(sticks,
               r->name + ": every node sticks on every mesh, but at most the "
                         "top corner node");
      }
    // 5. P1 against Q1 on the scene's last mesh: 2.2 % rms measured (tests/
    //    unit/test_simplex.cc); the largest difference at the top corner on
    //    every mesh; the rms falls from mesh to mesh.
    {
      const Difference &d = p1_q1[last];
      checks(d.rms <= 0.03,
             P + " against " + Q + " on mesh " + std::to_string(last) +
               ": rms " + format("%.2f", 100. * d.rms) + " % <= 3 %");
      bool        at_corner = true, falls = true;
      std::string rms;
      for (unsigned int c = 0; c < n_meshes; ++c)
        {
          at_corner &= p1_q1[c].y == p1.wall[c].back().y;
          falls &= c == 0 || p1_q1[c].rms < p1_q1[c - 1].rms;
          rms += (c == 0 ? "" : ", ") + format("%.2f", 100. * p1_q1[c].rms);
        }
      checks(at_corner,
             P + " against " + Q +
               ": the largest difference at the top corner on every mesh");
      checks(falls,
             P + " against " + Q + ": the rms falls under halving (" + rms +
               " %)");
    }
    // 6. Each element converges: the difference between consecutive meshes
    //    falls, at a rate per halving between 0.1 and 1/2 (the corner's
    //    1/2 - a = 0.21).
    {
      bool        falls = true;
      std::string list;
      for (unsigned int i = 0; i < runs.size(); ++i)
        for (unsigned int c = 0; c < steps[i].size(); ++c)
          falls &= c == 0 || steps[i][c].rms < steps[i][c - 1].rms;
      bool in_range = true;
      for (unsigned int k = 0; k < rates.size(); ++k)
        {
          in_range &= rates[k] >= 0.1 && rates[k] <= 0.5;
          list += (k == 0 ? "" : ", ") + format("%.2f", rates[k]);
        }
      checks(falls,
             P + " and " + Q +
               ": the rms difference of consecutive meshes falls under "
               "halving");
      checks(in_range,
             "the rates of the rms difference (" + list +
               ") lie in [0.1, 0.5]");
    }
    // 7. The corner: Q1 sticks there on every mesh, so it is clamped, and
    //    its pressure grows with Williams' exponent, within 0.03 (0.278 and
    //    0.286 measured against 0.289). P1's corner node slips from the
    //    third mesh on and is not clamped: its exponent is not checked.
    {
      bool        near = true;
      std::string list;
      for (unsigned int k = 0; k < exponents[1].size(); ++k)
        {
          near &= std::abs(exponents[1][k] - (1. - lambda)) <= 0.03;
          list += (k == 0 ? "" : ", ") + format("%.3f", exponents[1][k]);
        }
      checks(near,
             Q + ": the corner's exponent a (" + list +
               ") within 0.03 of "
               "Williams' 1 - lambda = " +
               format("%.3f", 1. - lambda));
    }
    return checks;
  }


  // The step as run_tutorial() calls it: the program on the scene.
  tutorial::Checks
  run(const Parameters &scene)
  {
    return ElementComparison(scene).run();
  }
} // namespace Step10

// @sect3{The main function}
//
// MPI, the parameter file (default step-10.prm) and, after it, overrides
// as the dualcontact program takes them (`--set "Friction/Threshold
// iteration=merged"`), for the experiments of README.md; one message and a
// non-zero exit status on any error or failed check.
int
main(int argc, char *argv[])
{
  return dualcontact::tutorial::run_tutorial(
    argc, argv, "step-10", "step-10.prm", Step10::run);
}
