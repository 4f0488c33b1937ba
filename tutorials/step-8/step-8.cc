/* step-8: load paths and friction history.
 *
 * Steps 1-7 solved one static problem each. With friction the answer to a
 * problem of contact depends on how the loads got where they are: Coulomb's
 * law speaks of the slip, and the slip happens along the way. This step
 * follows a load path (doc/theory.md §11): the half disc of step-4 at
 * nu = 0.45, held by a clamp on its flat top, pressed onto a rough rigid
 * plane and then sheared back and forth. It asks three questions of the
 * library's ContactProblem, which solves the path step by step, each step
 * from the state the one before reached:
 *   1. does the order of loading matter? The same final clamp position is
 *      reached at once, pressed first and then sheared, and in proportion;
 *      the stick zones are compared with Cattaneo's;
 *   2. what does a cycle dissipate? The energy friction dissipates in a
 *      closed shear cycle against the area of its force-displacement loop,
 *      and the stick zones and tractions against Mindlin and Deresiewicz;
 *   3. what does a step of a path cost, warm started from the step before,
 *      against one linear solve on the same mesh?
 * The scene is step-8.prm; README.md has the introduction and the results.
 */

// @sect3{Include files}
//
// The library's Problem class (the whole solver, the load path and its
// records), its parameters, and the tutorials' tools (Hertz's formulas).
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
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "../common/tutorial_tools.h"

namespace Step8
{
  using namespace dealii;
  using namespace dualcontact;

  using tutorial::format;

  constexpr unsigned int dim = 2;

  // @sect3{A path, solved}
  //
  // One run of the scene along a path: the clamp's displacement as an
  // expression in t and the times of the steps, solved by
  // ContactProblem::run() into its own folder under output/. What the
  // program reads afterwards is the record of every step (records.h): the
  // forces, the stick zone, the energy dissipated, the iteration counts and
  // times. A path of one step is the static problem; the library then keeps
  // no step records, and the record of its (only) mesh stands in.
  struct Path
  {
    std::string              name;
    std::vector<CycleResult> steps;
    double                   h_contact = 0.; // the contact element
  };

  Path
  solve_path(const Parameters          &scene,
             const types::boundary_id   clamp,
             const std::string         &name,
             const std::string         &clamp_displacement,
             const std::vector<double> &times)
  {
    Parameters parameters                    = scene;
    parameters.boundary.displacements[clamp] = clamp_displacement;
    parameters.load_path.times               = times;
    parameters.output.directory += "/" + name;

    std::ostringstream  silent;
    ContactProblem<dim> problem(parameters, MPI_COMM_WORLD, silent);
    problem.run();
    Path path;
    path.name      = name;
    path.steps     = problem.steps().empty() ?
                       std::vector<CycleResult>{problem.results().back()} :
                       problem.steps();
    path.h_contact = problem.contact().min_face_diameter();
    return path;
  }

  // The forces and the clamp's position of a step. P is what the plane
  // pushes back with, the contact force sum_s m_s l1_s. Q is the clamp's
  // force on the body along the plane (x), signed: the plane takes it, as
  // the friction force. delta is the clamp's displacement along x, the mean
  // over its boundary (the same everywhere on a clamp).
  double
  P_of(const CycleResult &r)
  {
    return r.zone.contact_force;
  }

  double
  Q_of(const CycleResult &r, const types::boundary_id clamp)
  {
    return r.reactions.on_id.at(clamp)[0];
  }

  double
  delta_of(const CycleResult &r, const types::boundary_id clamp)
  {
    return r.step.boundary_displacement.at(clamp)[0];
  }

  // @sect3{Cattaneo, Mindlin and Deresiewicz}
  //
  // For beta = 0 (friction leaves the pressure alone) the tangential
  // traction of a cylinder is a sum of elliptic terms
  //   q_d(x) = F (p0/a) sqrt(d^2 - x^2) on |x| < d,
  // Hertz's a and p0 for the step's P (doc/theory.md §11). Sheared from Q
  // = 0 after the normal load, q = s (q_a - q_c), c/a = sqrt(1 - |Q|/(F
  // P)), s the sign of Q (Cattaneo, Mindlin). When the shear turns at Q_r
  // the traction of that moment stays, and a second such pair of twice the
  // size, of the other sign, grows from the edges:
  //   q = q_r - 2 s_r (q_a - q_c'),  c'/a = sqrt(1 - |Q - Q_r|/(2 F P))
  // (Mindlin and Deresiewicz; Masing's rule: the unloading branch is the
  // loading branch doubled). The stick zone is |x| < c of the newest pair.
  // A turning point is a step at which the clamp's motion along x changes
  // sign. Each prediction holds the terms as pairs (k, d): q(x) = sum k
  // q_d(x).
  struct Prediction
  {
    double                                 a = 0., p0 = 0., c = 0.;
    std::vector<std::pair<double, double>> terms;
  };

  std::vector<Prediction>
  mindlin_deresiewicz(const Path              &path,
                      const Parameters        &scene,
                      const types::boundary_id clamp,
                      const double             F)
  {
    std::vector<Prediction>                predictions;
    std::vector<std::pair<double, double>> at_turn; // q_r
    double Q_turn = 0., doubled = 1., direction = 0.;
    for (unsigned int n = 0; n < path.steps.size(); ++n)
      {
        const CycleResult &r = path.steps[n];
        const double       P = P_of(r), Q = Q_of(r, clamp);
        const double       move =
          n > 0 ? delta_of(r, clamp) - delta_of(path.steps[n - 1], clamp) : 0.;
        if (move != 0. && move * direction < 0.)
          {
            at_turn = predictions[n - 1].terms;
            Q_turn  = Q_of(path.steps[n - 1], clamp);
            doubled = 2.;
          }
        if (move != 0.)
          direction = move;

        const tutorial::Hertz hertz(scene, P);
        Prediction            p;
        p.a  = hertz.a;
        p.p0 = hertz.p0;
        p.c =
          p.a * std::sqrt(
                  std::max(0., 1. - std::abs(Q - Q_turn) / (doubled * F * P)));
        const double s = Q >= Q_turn ? 1. : -1.;
        p.terms        = at_turn;
        p.terms.emplace_back(s * doubled, p.a);
        p.terms.emplace_back(-s * doubled, p.c);
        predictions.push_back(p);
      }
    return predictions;
  }

  // The turning points of the clamp's motion along x, and the last step:
  // the steps at which Q is extreme.
  std::vector<unsigned int>
  turning_points(const Path &path, const types::boundary_id clamp)
  {
    std::vector<unsigned int> turns;
    double                    direction = 0.;
    for (unsigned int n = 1; n < path.steps.size(); ++n)
      {
        const double move =
          delta_of(path.steps[n], clamp) - delta_of(path.steps[n - 1], clamp);
        if (move != 0. && move * direction < 0.)
          turns.push_back(n - 1);
        if (move != 0.)
          direction = move;
      }
    turns.push_back(path.steps.size() - 1);
    return turns;
  }

  // @sect3{The loop area}
  //
  // The work the clamp does on the body between steps i and j, the
  // integral of Q d delta by the trapezoidal rule over every `stride`-th
  // step. Over a closed cycle the elastic energy comes back to where it
  // was, so this work is the energy dissipated (doc/theory.md §11): the
  // area of the loop of Q against delta.
  double
  loop_area(const Path              &path,
            const types::boundary_id clamp,
            const unsigned int       i,
            const unsigned int       j,
            const unsigned int       stride)
  {
    double area = 0.;
    for (unsigned int n = i; n < j; n += stride)
      {
        const unsigned int m = std::min(n + stride, j);
        const CycleResult &a = path.steps[n], &b = path.steps[m];
        area += 0.5 * (Q_of(a, clamp) + Q_of(b, clamp)) *
                (delta_of(b, clamp) - delta_of(a, clamp));
      }
    return area;
  }

  // @sect3{The variants' clamp positions}
  //
  // The variants of the path dependence end where the cycle is at the time
  // t_v: the scene's clamp expression with t replaced by that number (a
  // word of its own: "sqrt" keeps its t), one component each.
  std::vector<std::string>
  clamp_at(const std::string &expression, const double t_v)
  {
    const std::string fixed =
      std::regex_replace(expression,
                         std::regex("\\bt\\b"),
                         "(" + format("%.17g", t_v) + ")");
    std::vector<std::string> components;
    std::istringstream       in(fixed);
    for (std::string c; std::getline(in, c, ';');)
      components.push_back("(" + c + ")");
    tutorial::require(components.size() == dim,
                      "step-8 needs two components, separated by ';', in "
                      "the clamp's <Boundary conditions/Displacements>.");
    return components;
  }

  // @sect3{The whole step}
  //
  // The program in the shape of deal.II's steps: a class whose run() reads
  // as the stages below, one member function each, and members for what a
  // later stage needs of an earlier one (the cycle and its turning points,
  // the variants, the figures the checks judge).
  class LoadPaths
  {
  public:
    explicit LoadPaths(const Parameters &scene);

    tutorial::Checks
    run();

  private:
    void
    check_scene();
    void
    solve_cycle();
    void
    solve_variants();
    void
    compare_variants();
    double
    print_variant_row(const std::string &label,
                      const Path        &path,
                      const unsigned int last,
                      const bool         in_proportion) const;
    void
    print_proportional_steps() const;
    void
    print_cycle_steps();
    void
    measure_cycle_energy();
    void
    print_step_costs();
    void
    print_later_steps();
    void
    write_figure_data() const;
    tutorial::Checks
    check_results() const;

    // The scene, the screen (rank 0 prints) and whether it shows times.
    const Parameters  &scene;
    const bool         root;
    ConditionalOStream pcout;
    const bool         timing;
    types::boundary_id clamp = 0;
    double             F     = 0.; // the friction coefficient

    // The cycle: its clamp expression, its steps, turning points and
    // Mindlin and Deresiewicz's prediction per step; the step where the
    // variants end (its time t_v), the first step that shears, and the
    // contact element h_C.
    std::string               cycle_expression;
    Path                      cycle;
    std::vector<unsigned int> turns;
    std::vector<Prediction>   predicted;
    unsigned int              variant_step = 0;
    double                    t_v          = 0.;
    unsigned int              first_shear  = 1;
    double                    h            = 0.;

    // The three other paths to the cycle's position at t_v, and what the
    // checks judge: the stick zones' distances from Cattaneo's (a, b, d)
    // and from Mindlin and Deresiewicz's, the last cycle's energy, the CG
    // iterations of one linear solve, the most Newton steps of a later step.
    std::vector<Path>   variants;
    std::vector<double> off_variant;
    double              worst_cycle = 0.;
    double              dissipated = 0., area_1 = 0., area_2 = 0.;
    double              reference_cg = 0.;
    unsigned int        most_newton  = 0;
  };


  LoadPaths::LoadPaths(const Parameters &scene)
      : scene(scene)
      , root(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      , pcout(std::cout, root)
      , timing(scene.output.print_timing)
  {}


  // The cycle first; then the other paths to one of its states and the
  // table that compares them; the cycle step by step, its energy and its
  // cost; the data for plot.gp and the checks.
  tutorial::Checks
  LoadPaths::run()
  {
    check_scene();
    solve_cycle();
    solve_variants();
    compare_variants();
    print_cycle_steps();
    measure_cycle_energy();
    print_step_costs();
    print_later_steps();
    write_figure_data();
    return check_results();
  }


  // @sect4{The scene this step needs}
  //
  // The 2D half disc with Coulomb friction and one clamped boundary part,
  // whose displacement makes the path; anything else is refused with one
  // message before a solve.
  void
  LoadPaths::check_scene()
  {
    const std::vector<types::boundary_id> clamps =
      scene.boundary.ids_with(BoundaryCondition::fixed);
    tutorial::require(scene.geometry.dimension == dim &&
                        scene.geometry.type == "half disc" &&
                        scene.friction.law == "coulomb" && clamps.size() == 1,
                      "step-8 needs the 2D half disc with Coulomb friction "
                      "and one clamped boundary part (<Boundary "
                      "conditions/Conditions>).");
    clamp = clamps[0];
    F     = std::stod(scene.friction.parameter);
    if (root)
      std::filesystem::create_directories(scene.output.directory);

    pcout << "step-8: load paths and friction history ("
          << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
          << " MPI rank(s))\n\n";
  }


  // @sect4{The cycle}
  //
  // The scene as step-8.prm gives it: pressed, then sheared back and
  // forth between +Q* and -Q*. Its turning points are the steps at +Q*
  // and -Q*; a cycle runs from one turning point to the one two later.
  void
  LoadPaths::solve_cycle()
  {
    cycle_expression = scene.boundary.displacements.at(clamp);
    cycle            = solve_path(
      scene, clamp, "cycle", cycle_expression, scene.load_path.step_times());
    turns = turning_points(cycle, clamp);
    tutorial::require(turns.size() >= 3,
                      "step-8 needs a path that shears the clamp to one "
                      "side, back to the other and to the first again "
                      "(<Boundary conditions/Displacements>, <Load "
                      "path/Times>).");
    predicted = mindlin_deresiewicz(cycle, scene, clamp, F);

    // The variants end where the cycle's first shear has |Q|/(F P) nearest
    // 1/2: at that step's time t_v (|Q|: the shear may go toward -x).
    for (unsigned int n = 0; n <= turns[0]; ++n)
      {
        const CycleResult &r = cycle.steps[n];
        const CycleResult &v = cycle.steps[variant_step];
        if (std::abs(std::abs(Q_of(r, clamp)) / (F * P_of(r)) - 0.5) <
            std::abs(std::abs(Q_of(v, clamp)) / (F * P_of(v)) - 0.5))
          variant_step = n;
      }
    t_v = cycle.steps[variant_step].step.time;
    // the first step that shears
    while (first_shear < cycle.steps.size() &&
           delta_of(cycle.steps[first_shear], clamp) ==
             delta_of(cycle.steps[first_shear - 1], clamp))
      ++first_shear;
  }


  // @sect4{Path dependence}
  //
  // Three more paths to the cycle's clamp position at t_v, (X, Y):
  //   (a) at once: one step, the static problem;
  //   (b) normal first: pressed by Y at t = 1 (no shear), then sheared by
  //       X in one step at t = 2;
  //   (c) in proportion: (X, Y) t at t = 0.001, 0.1, 0.2, ..., 1.
  // The cycle itself is a fourth: pressed first, then sheared gradually.
  void
  LoadPaths::solve_variants()
  {
    const std::vector<std::string> XY = clamp_at(cycle_expression, t_v);
    const std::string             &X = XY[0], &Y = XY[1];
    std::vector<double>            proportional_times = {0.001};
    for (unsigned int i = 1; i <= 10; ++i)
      proportional_times.push_back(0.1 * i);
    // (only the cycle's cost is compared with a linear solve)
    Parameters variant_scene                  = scene;
    variant_scene.solver.time_reference_solve = false;
    variants.push_back(
      solve_path(variant_scene, clamp, "at_once", X + "; " + Y, {1.}));
    variants.push_back(solve_path(variant_scene,
                                  clamp,
                                  "normal_first",
                                  X + " * max(t - 1, 0); " + Y + " * min(t, 1)",
                                  {1., 2.}));
    variants.push_back(solve_path(variant_scene,
                                  clamp,
                                  "proportional",
                                  X + " * t; " + Y + " * t",
                                  proportional_times));
    h = cycle.h_contact;
  }


  // The table: per path its final P and Q/(F P), the nodes in stick and
  // slip, the contact zone's half-width (edges extrapolated) and the stick
  // zone's (half the extent of the sticking nodes) over Hertz's a for the
  // measured P, the predicted c/a and the difference in contact elements
  // h_C, the energy dissipated along the path, and the most nodes that
  // slipped in a step after the first. The prediction for beta = 0 is
  // Cattaneo's after the normal load or at once, and no slip (c = a) in
  // proportion. A row returns its stick zone's difference in h_C.
  double
  LoadPaths::print_variant_row(const std::string &label,
                               const Path        &path,
                               const unsigned int last,
                               const bool         in_proportion) const
  {
    const CycleResult    &r = path.steps[last];
    const double          P = P_of(r), Q = Q_of(r, clamp);
    const tutorial::Hertz hertz(scene, P);
    const double          c_predicted =
      in_proportion ?
                 hertz.a :
                 hertz.a * std::sqrt(std::max(0., 1. - std::abs(Q) / (F * P)));
    unsigned int later_slip = 0;
    for (unsigned int n = 1; n <= last; ++n)
      later_slip =
        std::max<unsigned int>(later_slip, path.steps[n].solve.n_slip);
    pcout << label << format("%6.0f", last + 1.) << format("%9.5f", P)
          << format("%9.3f", Q / (F * P))
          << format("%7.0f", double(r.solve.n_stick))
          << format("%6.0f", double(r.solve.n_slip))
          << format("%7.3f", r.zone.edge_half_width / hertz.a)
          << format("%7.3f", r.zone.stick_half_width / hertz.a)
          << format("%8.3f", c_predicted / hertz.a)
          << format("%+11.2f", (r.zone.stick_half_width - c_predicted) / h)
          << format("%12.3e", r.step.dissipation_total)
          << (last > 0 ? format("%8.0f", double(later_slip)) :
                         std::string("       -"))
          << "\n";
    return (r.zone.stick_half_width - c_predicted) / h;
  }


  // The four paths side by side, (d) being the cycle up to t_v.
  void
  LoadPaths::compare_variants()
  {
    const CycleResult &at_v = cycle.steps[variant_step];
    pcout << "Path dependence: four paths to the clamp position ("
          << format("%.6g", delta_of(at_v, clamp)) << ", "
          << format("%.6g", at_v.step.boundary_displacement.at(clamp)[1])
          << "), where the cycle is at t = " << format("%g", t_v) << "\n"
          << "  path                          steps        P  Q/(F P)  stick  "
             "slip  a_m/a    c/a  predicted  (c - c_p)/h_C  dissipated  later "
             "slip\n";
    off_variant.push_back(print_variant_row(
      "  (a) at once                 ", variants[0], 0, false));
    // (b)'s last step (its second, or the last sub-step of a shear that
    // adaptive step control cut)
    off_variant.push_back(print_variant_row("  (b) normal first, then shear",
                                            variants[1],
                                            variants[1].steps.size() - 1,
                                            false));
    print_variant_row("  (c) in proportion           ",
                      variants[2],
                      variants[2].steps.size() - 1,
                      true);
    std::string shear_in_steps =
      "  (d) as (b), shear in " +
      std::to_string(variant_step - first_shear + 1) + " steps";
    shear_in_steps.resize(30, ' ');
    off_variant.push_back(
      print_variant_row(shear_in_steps, cycle, variant_step, false));
    print_proportional_steps();
  }


  // (c) step by step: the slip nodes, Q/(F P) and the ratio of the
  // increments (the clamp prescribes displacements, not forces, and
  // Q/P is not quite fixed), and for comparison the slip nodes of the
  // cycle's steps that only press
  void
  LoadPaths::print_proportional_steps() const
  {
    const Path &c = variants[2];
    pcout << "  (c) step by step:       t";
    // (a space before each: the sub-steps of adaptive step control have
    // times of more digits)
    for (const CycleResult &r : c.steps)
      pcout << format(" %6.4g", r.step.time);
    pcout << "\n                 slip nodes";
    for (const CycleResult &r : c.steps)
      pcout << format("%7.0f", double(r.solve.n_slip));
    pcout << "\n                    Q/(F P)";
    for (const CycleResult &r : c.steps)
      pcout << format("%7.3f", Q_of(r, clamp) / (F * P_of(r)));
    pcout << "\n                dQ/(F dP)      -";
    for (unsigned int n = 1; n < c.steps.size(); ++n)
      pcout << format("%7.3f",
                      (Q_of(c.steps[n], clamp) - Q_of(c.steps[n - 1], clamp)) /
                        (F * (P_of(c.steps[n]) - P_of(c.steps[n - 1]))));
    pcout << "\n  the cycle's steps that only press: slip nodes";
    for (unsigned int n = 0; n < first_shear; ++n)
      pcout << " " << cycle.steps[n].solve.n_slip;
    pcout << "; contact element h_C = " << format("%.6f", h) << "\n\n";
  }


  // @sect4{The cycle, step by step}
  //
  // Every other step of the shear up to the third turning point, counted
  // from the first so that the turning points are among them, and the
  // later turning points: Q/(F P), the nodes in stick and slip, the stick
  // half-width against Mindlin and Deresiewicz, the energy dissipated in
  // the step.
  void
  LoadPaths::print_cycle_steps()
  {
    const CycleResult &peak = cycle.steps[turns[0]];
    pcout << "The cycle: pressed to P = " << format("%.5f", P_of(peak))
          << ", sheared to Q*/(F P) = "
          << format("%.3f", Q_of(peak, clamp) / (F * P_of(peak)))
          << "; turning points at t =";
    for (const unsigned int n : turns)
      pcout << " " << format("%g", cycle.steps[n].step.time);
    pcout << "\n"
          << "       t      delta  Q/(F P)  stick  slip    c/a  Mindlin-D.  "
             "(c - c_MD)/h_C  dissipated\n";
    for (unsigned int n = first_shear; n < cycle.steps.size(); ++n)
      {
        const CycleResult &r   = cycle.steps[n];
        const Prediction  &p   = predicted[n];
        const double       off = (r.zone.stick_half_width - p.c) / h;
        worst_cycle            = std::max(worst_cycle, std::abs(off));
        const bool turning =
          std::find(turns.begin(), turns.end(), n) != turns.end();
        if (!turning && (n > turns[2] || (n + turns[0]) % 2 != 0))
          continue;
        pcout << format("%8.3f", r.step.time)
              << format("%11.6f", delta_of(r, clamp))
              << format("%9.3f", Q_of(r, clamp) / (F * P_of(r)))
              << format("%7.0f", double(r.solve.n_stick))
              << format("%6.0f", double(r.solve.n_slip))
              << format("%7.3f", r.zone.stick_half_width / p.a)
              << format("%12.3f", p.c / p.a) << format("%+16.2f", off)
              << format("%12.3e", r.step.dissipation) << "\n";
      }
  }


  // The energy of each cycle, from a turning point to the one two
  // later (+Q* to -Q* and back): as friction dissipated it, and as the
  // clamp's work, the loop's area by the trapezoidal rule over every step
  // and over every other step. Q/(F P) at both ends says whether the
  // state came back to where it was.
  void
  LoadPaths::measure_cycle_energy()
  {
    pcout << "\nThe energy of each shear cycle, from +Q* to -Q* and back:\n"
          << "  from t  to t  Q/(F P) at both ends   dissipated   loop area, "
             "every step   every other step\n";
    for (unsigned int k = 0; k + 2 < turns.size(); k += 2)
      {
        const CycleResult &begin = cycle.steps[turns[k]];
        const CycleResult &end   = cycle.steps[turns[k + 2]];
        dissipated = end.step.dissipation_total - begin.step.dissipation_total;
        area_1     = loop_area(cycle, clamp, turns[k], turns[k + 2], 1);
        area_2     = loop_area(cycle, clamp, turns[k], turns[k + 2], 2);
        pcout << format("%8g", begin.step.time) << format("%6g", end.step.time)
              << format("%10.5f", Q_of(begin, clamp) / (F * P_of(begin)))
              << format("%10.5f", Q_of(end, clamp) / (F * P_of(end)))
              << format("%14.4e", dissipated) << format("%22.4e", area_1)
              << format("%19.4e", area_2) << "\n";
      }
    const CycleResult &peak = cycle.steps[turns[0]];
    const double       rectangle =
      4. * std::abs(Q_of(peak, clamp) * delta_of(peak, clamp));
    pcout << "  the last loop fills "
          << format("%.2f", 100. * area_1 / rectangle)
          << " % of the rectangle 2 Q* by 2 delta*\n\n";
  }


  // @sect4{The cost of a step}
  //
  // The cycle's steps in parts: the first (a cold start from the
  // undeformed body), the rest of the pressing, the first shear from
  // rest, the first step after each turning point (where the slip
  // reverses), and the other steps of the later legs. Each part's mean
  // per step; "linear solves" is the CG iterations over those of one
  // linear solve with the step's final Newton matrix, from zero to the
  // linear tolerance (<Solver/Time a reference linear solve>), whose time
  // is in the last row.
  void
  LoadPaths::print_step_costs()
  {
    struct Part
    {
      std::string               label;
      std::vector<unsigned int> steps;
    };
    std::vector<Part> parts = {{"pressing, cold start", {0}},
                               {"pressing", {}},
                               {"shear from rest", {}},
                               {"first step after a turn", {}},
                               {"shear after a turn", {}}};
    for (unsigned int n = 1; n < cycle.steps.size(); ++n)
      {
        unsigned int kind = 4;
        if (n < first_shear)
          kind = 1;
        else if (n <= turns[0])
          kind = 2;
        else if (std::find(turns.begin(), turns.end(), n - 1) != turns.end())
          kind = 3;
        parts[kind].steps.push_back(n);
      }
    double reference_time = 0.;
    for (const CycleResult &r : cycle.steps)
      {
        reference_cg +=
          r.solve.reference_iterations / double(cycle.steps.size());
        reference_time += r.solve.time_reference / cycle.steps.size();
      }
    pcout << "The cost of the cycle's steps (mean per step of each part):\n"
          << "  part                       steps  Uzawa  Newton     CG   AMG"
             "  linear solves"
          << (timing ? "  solve [s]" : "") << "\n";
    const auto cost_row = [&](std::string                      label,
                              const std::vector<unsigned int> &steps) {
      double uzawa = 0., newton = 0., cg = 0., amg = 0., time = 0.;
      for (const unsigned int n : steps)
        {
          const auto &s = cycle.steps[n].solve;
          uzawa += s.uzawa_steps;
          newton += s.newton_steps;
          cg += s.cg_iterations;
          amg += s.amg_setups;
          time += cycle.steps[n].time.solve;
        }
      const double m = steps.size();
      label.resize(25, ' ');
      pcout << "  " << label << format("%7.0f", m) << format("%7.1f", uzawa / m)
            << format("%8.1f", newton / m) << format("%7.0f", cg / m)
            << format("%6.1f", amg / m)
            << format("%15.2f", cg / m / reference_cg)
            << (timing ? format("%11.3f", time / m) : "") << "\n";
    };
    for (const Part &part : parts)
      if (!part.steps.empty())
        cost_row(part.label, part.steps);
    pcout << "  one linear solve               1      -       -"
          << format("%7.0f", reference_cg) << "   1.0" << format("%15.2f", 1.)
          << (timing ? format("%11.3f", reference_time) : "") << "\n";
  }


  // The later steps together, against the cold first step and against
  // the cold solve of variant (a), the final load in one step.
  void
  LoadPaths::print_later_steps()
  {
    double             later_newton = 0., later_cg = 0., later_time = 0.;
    const unsigned int n_later = cycle.steps.size() - 1;
    for (unsigned int n = 1; n < cycle.steps.size(); ++n)
      {
        const auto &s = cycle.steps[n].solve;
        later_newton += s.newton_steps / double(n_later);
        later_cg += s.cg_iterations / double(n_later);
        later_time += cycle.steps[n].time.solve / n_later;
        most_newton = std::max(most_newton, s.newton_steps);
      }
    const auto &cold = cycle.steps[0].solve;
    const auto &once = variants[0].steps[0].solve;
    pcout << "\nThe later steps 2-" << cycle.steps.size() << ": "
          << format("%.1f", later_newton) << " Newton steps, "
          << format("%.0f", later_cg)
          << " CG iterations = " << format("%.2f", later_cg / reference_cg)
          << " linear solves (mean), at most " << most_newton << " Newton steps"
          << (timing ? format(" (%.3f s)", later_time) : "") << "\n"
          << "  cold starts: the cycle's step 1, " << cold.newton_steps
          << " Newton steps, " << cold.cg_iterations
          << " CG; (a), the final load at once, " << once.newton_steps
          << " Newton steps, " << once.cg_iterations << " CG\n";
  }


  // @sect4{The figures' data}
  //
  // plot.gp draws the loop from the cycle's steps.csv, and the traction
  // l2/(F p0) along x/a at +Q*, at the step nearest Q = 0 after it, and
  // at -Q* from their contact_step_NNN.csv, with the predicted traction
  // of each: output/figures.gp has the file names, a, p0 and the terms.
  void
  LoadPaths::write_figure_data() const
  {
    const CycleResult &peak     = cycle.steps[turns[0]];
    unsigned int       unloaded = turns[0];
    for (unsigned int n = turns[0]; n <= turns[1]; ++n)
      if (std::abs(Q_of(cycle.steps[n], clamp)) <
          std::abs(Q_of(cycle.steps[unloaded], clamp)))
        unloaded = n;
    if (root)
      {
        std::ofstream      gp(scene.output.directory + "/figures.gp");
        const CycleResult &first = cycle.steps[first_shear];
        gp << "F = " << F << "\nFP = " << F * P_of(peak)
           << "\nk0 = " << Q_of(first, clamp) / delta_of(first, clamp)
           << "\nclamp = " << clamp << "\nsteps = '" << scene.output.directory
           << "/cycle/steps.csv'\n";
        // and the tractions after the pressing, before any shear
        gp << "file0 = '" << scene.output.directory << "/cycle/contact_step_"
           << format("%03.0f", double(first_shear))
           << ".csv'\nt0 = " << cycle.steps[first_shear - 1].step.time << "\n";
        const unsigned int states[3] = {turns[0], unloaded, turns[1]};
        for (unsigned int i = 0; i < 3; ++i)
          {
            const unsigned int n = states[i];
            const Prediction  &p = predicted[n];
            gp << "file" << i + 1 << " = '" << scene.output.directory
               << "/cycle/contact_step_" << format("%03.0f", n + 1.)
               << ".csv'\nt" << i + 1 << " = " << cycle.steps[n].step.time
               << "\nQ" << i + 1 << " = "
               << Q_of(cycle.steps[n], clamp) / (F * P_of(cycle.steps[n]))
               << "\na" << i + 1 << " = " << p.a << "\np0" << i + 1 << " = "
               << p.p0 << "\nmd" << i + 1 << "(u) = 0";
            for (const auto &[k, d] : p.terms)
              gp << " + (" << k << ") * qd(u, " << d / p.a << ")";
            gp << "\n";
          }
      }
  }


  // @sect4{The checks}
  tutorial::Checks
  LoadPaths::check_results() const
  {
    pcout << "\nChecks:\n";
    tutorial::Checks checks;
    // 1. Cattaneo, whichever way the shear came after (or with) the normal
    //    load: partial slip, and the stick zone within 2.5 contact elements
    //    of the formula for beta = 0 (README.md, "The checks", says why).
    {
      double worst = 0.;
      for (const double off : off_variant)
        worst = std::max(worst, std::abs(off));
      checks(variants[0].steps.back().solve.n_slip > 0 &&
               variants[1].steps.back().solve.n_slip > 0 && worst <= 2.5,
             "(a), (b), (d): partial slip, the stick zone within " +
               format("%.2f", worst) +
               " contact elements of Cattaneo's (<= 2.5)");
    }
    // 2. In proportion friction does far less: the energy it dissipates
    //    along the path, and the nodes that slip at the end.
    {
      const CycleResult &c = variants[2].steps.back();
      const double       least =
        std::min(variants[0].steps.back().step.dissipation_total,
                 variants[1].steps.back().step.dissipation_total);
      const unsigned int fewest =
        std::min(variants[0].steps.back().solve.n_slip,
                 variants[1].steps.back().solve.n_slip);
      checks(10. * c.step.dissipation_total <= least,
             "(c) dissipates " +
               format("%.0f", least / c.step.dissipation_total) +
               " times less than (a) and (b) (>= 10 times)");
      checks(5 * c.solve.n_slip <= fewest,
             "(c) ends with " + std::to_string(c.solve.n_slip) +
               " slip nodes, at most a fifth of (a)'s and (b)'s " +
               std::to_string(fewest));
    }
    // 3. The cycle's stick zones against Mindlin and Deresiewicz.
    checks(worst_cycle <= 4.,
           "the cycle: every shear step's stick zone within " +
             format("%.2f", worst_cycle) +
             " contact elements of Mindlin-Deresiewicz (<= 4)");
    // 4. The energy of the last cycle: the dissipation and the loop's area
    //    agree within the trapezoidal rule's error, estimated by the
    //    difference of the rule over every step and over every other step.
    checks(std::abs(dissipated - area_1) <= std::abs(area_1 - area_2),
           "the last cycle: dissipated energy = loop area, |difference| " +
             format("%.2e", std::abs(dissipated - area_1)) +
             " <= the trapezoidal rule's change " +
             format("%.2e", std::abs(area_1 - area_2)));
    // 5. The warm start: a later step takes fewer Newton steps than the
    //    cold first step.
    checks(most_newton < cycle.steps[0].solve.newton_steps,
           "every later step of the cycle takes fewer Newton steps (at most " +
             std::to_string(most_newton) + ") than its cold first step (" +
             std::to_string(cycle.steps[0].solve.newton_steps) + ")");
    return checks;
  }


  // The step as run_tutorial() calls it: the program on the scene.
  tutorial::Checks
  run(const Parameters &scene)
  {
    return LoadPaths(scene).run();
  }
} // namespace Step8

// @sect3{The main function}
//
// MPI, the parameter file (default step-8.prm) and, after it, overrides as
// the dualcontact program takes them (`--set "Friction/Coefficient=0.4"`),
// for the experiments of README.md; one message and a non-zero exit status
// on any error or failed check.
int
main(int argc, char *argv[])
{
  return dualcontact::tutorial::run_tutorial(
    argc, argv, "step-8", "step-8.prm", Step8::run);
}
