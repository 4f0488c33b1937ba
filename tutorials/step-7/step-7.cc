/* step-7: a ball under normal and tangential load.
 *
 * Steps 1-5 were 2D, where the friction traction is a number between
 * -theta and theta, theta the friction threshold (g in doc/theory.md). In
 * 3D it is a vector in the tangent plane, bounded by a disc of radius
 * theta: the contact can slip in any direction, and where it does the traction
 * points against the slip. This step first shows that disc, the one
 * function the 3D friction law adds (project_onto_disc), then solves the
 * classic 3D partial-slip problem: an elastic ball pressed onto a rough
 * rigid plane and pushed sideways. The zone sticks inside a circle of
 * radius c and slips in the ring around it; Cattaneo (1938) and Mindlin
 * (1949) gave c = a (1 - Q / (F P))^(1/3). The program measures the contact
 * radius a, the stick radius c, the pressure and the friction traction
 * along a line through the centre, and compares each with Hertz and
 * Cattaneo-Mindlin. The scene is step-7.prm; the theory is doc/theory.md
 * §2 (the disc) and §9 (Hertz, Cattaneo-Mindlin, Dundurs' beta); README.md
 * has the introduction and the results.
 */

// @sect3{Include files}
//
// The Problem class of the library, and the pure functions of the contact
// solver (contact_functions.h), among them the projection onto the disc.
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/utilities.h>

#include <dualcontact/contact_functions.h>
#include <dualcontact/contact_problem.h>
#include <dualcontact/parameters.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "../common/csv_table.h"
#include "../common/tutorial_tools.h"

namespace Step7
{
  using namespace dealii;
  using namespace dualcontact;

  using tutorial::format;

  // @sect3{The friction disc}
  //
  // Each Uzawa step updates the friction multiplier of a contact node as
  //   l2 <- proj_theta(l2 + r v_t),
  // the trial traction l2 + r v_t (the old traction plus the augmentation
  // parameter times the tangential displacement) projected onto the disc
  // |l2| <= theta, theta = F l1 the threshold. Inside the disc nothing
  // changes: the node sticks. Outside, the trial traction is scaled back to
  // the circle, keeping its direction: the node slips, with the traction of
  // magnitude theta along the trial one. In 2D the disc is the interval
  // [-theta, theta], and this is a clamp; in 3D it is the only new piece of
  // the friction law. The table shows it on four trial tractions, with
  // theta = 1.
  void
  show_the_disc(ConditionalOStream &pcout)
  {
    pcout << "The friction disc, theta = 1: trial traction -> projection "
             "(|l2|, what the node does)\n";
    const double theta    = 1.;
    const double trials[] = {0.3, 0.4, -0.5, 0.6, 1.2, -0.5, 3., 4.};
    for (unsigned int i = 0; i < 8; i += 2)
      {
        const Tensor<1, 2> y({trials[i], trials[i + 1]});
        const Tensor<1, 2> p = project_onto_disc(y, theta);
        pcout << "  (" << format("%+.2f", y[0]) << ", " << format("%+.2f", y[1])
              << ") -> (" << format("%+.3f", p[0]) << ", "
              << format("%+.3f", p[1])
              << ")  |l2| = " << format("%.3f", p.norm())
              << (y.norm() < theta ? "  sticks" : "  slips") << "\n";
      }
    // the same in 2D: a clamp to [-theta, theta]
    const Tensor<1, 1> y2({-2.5});
    pcout << "  2D: " << format("%+.2f", y2[0]) << " -> "
          << format("%+.3f", project_onto_disc(y2, theta)[0]) << "\n\n";
  }

  // @sect3{The exact solutions}
  //
  // Hertz, for a ball of radius R on a rigid plane under the load P
  // (E* = E / (1 - nu^2)):
  //   a = (3 P R / (4 E*))^(1/3),   p0 = 3 P / (2 pi a^2),
  //   p(r) = p0 sqrt(1 - r^2 / a^2).
  // Cattaneo-Mindlin, for the tangential load Q < F P added to it along x:
  // the zone r < c sticks, the ring c < r < a slips, with
  //   c = a (1 - Q / (F P))^(1/3),
  //   q(r) = F p0 sqrt(1 - r^2/a^2)                             c < r < a,
  //   q(r) = F p0 (sqrt(1 - r^2/a^2) - (c/a) sqrt(1 - r^2/c^2))  r < c,
  // the traction along x. Both hold when friction does not change the
  // pressure: on a rigid plane when Dundurs' beta = (1 - 2 nu)/(2 (1 - nu))
  // vanishes, at nu = 1/2. The measured P and Q go in. (The step takes a
  // constant F: <Friction/Coefficient> may be an expression in x, y, z.)
  struct CattaneoMindlin : tutorial::Hertz
  {
    double Q, F, c;

    CattaneoMindlin(const Parameters &parameters,
                    const double      P,
                    const double      Q)
        : tutorial::Hertz(parameters, P)
        , Q(Q)
        , F(std::stod(parameters.friction.parameter))
        , c(a * std::cbrt(1. - Q / (F * P)))
    {}

    double
    traction(const double r) const
    {
      const double inner =
        r < c ? (c / a) * std::sqrt(1. - r * r / (c * c)) : 0.;
      return F * (pressure(r) - p0 * inner);
    }
  };

  // The loads the plane carries: the force of the plane on the ball
  // (r.zone.resultant), reversed, is what the ball pushes the plane with;
  // its z component is -P, its x component Q.
  std::pair<double, double>
  loads(const CycleResult &r)
  {
    return {r.zone.resultant[2], -r.zone.resultant[0]};
  }

  // @sect3{Reading contact_NN.csv}
  //
  // One row per contact node (all ranks' nodes, written by rank 0): its
  // position, weight m_s, the pressure l1, the friction traction l2 as a
  // vector (l2_x, l2_y, l2_z), the threshold theta (the column g, row.g
  // below) and the status (separated, stick, slip). Read by column name,
  // the way a user's script would.
  struct ContactRow
  {
    double      x, y, weight, l1, l2_x, l2_y, g;
    std::string status;
  };

  std::vector<ContactRow>
  read_contact_csv(const std::string &filename)
  {
    const tutorial::CsvTable table(filename);
    std::vector<ContactRow>  rows;
    for (unsigned int i = 0; i < table.n_rows(); ++i)
      rows.push_back({table.number(i, "x"),
                      table.number(i, "y"),
                      table.number(i, "weight"),
                      table.number(i, "l1"),
                      table.number(i, "l2_x"),
                      table.number(i, "l2_y"),
                      table.number(i, "g"),
                      table.text(i, "status")});
    return rows;
  }

  // @sect3{The zone against Hertz and Cattaneo-Mindlin}
  //
  // Over all contact nodes: the friction law (|l2| <= theta everywhere,
  // |l2| = theta where the node slips), and the relative L2 errors, with the
  // weights m_s, of the pressure against p(r) and of the traction along the
  // load against q(r). Along the x axis (y = 0): the nodes, for the profile
  // plot (profile.csv), and the contact element at r = c, the spacing of the
  // nodes there. zones.csv holds every node in contact with its status, for
  // the map of the stick and slip zones.
  struct ZoneFigures
  {
    double excess         = 0.; // max (|l2| - theta), relative to max theta
    double slip_short     = 0.; // max (theta - |l2|) over slipping nodes, same
    double pressure_error = 0., traction_error = 0.;
    double element_at_c  = 0.;
    unsigned int n_stick = 0, n_slip = 0;
  };

  ZoneFigures
  compare_zone(const std::vector<ContactRow> &rows,
               const CattaneoMindlin         &exact,
               const std::string             &directory,
               const bool                     write)
  {
    ZoneFigures f;
    double      g_max = 0.;
    for (const ContactRow &row : rows)
      g_max = std::max(g_max, row.g);
    double              p2[2] = {0., 0.}, q2[2] = {0., 0.};
    std::vector<double> axis;
    std::ofstream       profile, zones;
    if (write)
      {
        profile.open(directory + "/profile.csv");
        profile << "x,l1,l2_x,F_l1,hertz,cattaneo_mindlin\n";
        zones.open(directory + "/zones.csv");
        zones << "x,y,status\n";
      }
    for (const ContactRow &row : rows)
      {
        const double r     = std::hypot(row.x, row.y);
        const double shear = std::hypot(row.l2_x, row.l2_y);
        f.excess           = std::max(f.excess, (shear - row.g) / g_max);
        if (row.status == "slip")
          {
            ++f.n_slip;
            f.slip_short = std::max(f.slip_short, (row.g - shear) / g_max);
          }
        f.n_stick += (row.status == "stick");
        const double p = exact.pressure(r), q = exact.traction(r);
        p2[0] += row.weight * (row.l1 - p) * (row.l1 - p);
        p2[1] += row.weight * p * p;
        q2[0] += row.weight * (row.l2_x - q) * (row.l2_x - q);
        q2[1] += row.weight * q * q;
        if (std::abs(row.y) < 1e-8)
          {
            axis.push_back(row.x);
            if (write)
              profile << row.x << ',' << row.l1 << ',' << row.l2_x << ','
                      << exact.F * row.l1 << ',' << p << ',' << q << '\n';
          }
        if (write && row.status != "separated")
          zones << row.x << ',' << row.y << ','
                << (row.status == "stick" ? 1 : 2) << '\n';
      }
    f.pressure_error = std::sqrt(p2[0] / p2[1]);
    f.traction_error = std::sqrt(q2[0] / q2[1]);
    std::sort(axis.begin(), axis.end());
    for (std::size_t i = 1; i < axis.size(); ++i)
      if (axis[i] >= exact.c)
        {
          f.element_at_c = axis[i] - axis[i - 1];
          break;
        }
    return f;
  }

  // @sect3{The whole step}
  //
  // The program in the shape of deal.II's steps: a class whose run() reads
  // as its stages, one member function each, and members for what a later
  // stage needs of an earlier one (the solved problem, the figures of the
  // last cycle's nodes).
  class HalfBall
  {
  public:
    explicit HalfBall(const Parameters &parameters);

    tutorial::Checks
    run();

  private:
    void
    check_scene() const;
    void
    solve_scene();
    CattaneoMindlin
    exact_for_last_cycle() const;
    void
    compare_zones() const;
    void
    compare_nodes();
    tutorial::Checks
    check_results() const;

    // The scene, the screen (rank 0 prints) and the output folder.
    const Parameters  &parameters;
    const MPI_Comm     comm;
    const bool         root;
    ConditionalOStream pcout;
    const std::string &directory;

    // The library's problem, its screen output (kept for screen.log), and
    // the figures of the last cycle's nodes.
    std::ostringstream                 log;
    std::unique_ptr<ContactProblem<3>> problem;
    ZoneFigures                        zone;
  };


  HalfBall::HalfBall(const Parameters &parameters)
      : parameters(parameters)
      , comm(MPI_COMM_WORLD)
      , root(Utilities::MPI::this_mpi_process(comm) == 0)
      , pcout(std::cout, root)
      , directory(parameters.output.directory)
  {}


  // The disc first; then the scene, solved by the library's
  // ContactProblem::run() (screen output to screen.log in the output
  // folder); then, per cycle, the zone against the formulas for that
  // cycle's loads, and on the last cycle the nodes against the profiles.
  tutorial::Checks
  HalfBall::run()
  {
    check_scene();
    show_the_disc(pcout);
    solve_scene();
    compare_zones();
    compare_nodes();
    return check_results();
  }


  // The formulas of this step hold for the 3D half ball with Coulomb
  // friction; anything else is refused with one message before a solve.
  void
  HalfBall::check_scene() const
  {
    AssertThrow(parameters.geometry.dimension == 3 &&
                  parameters.geometry.type == "half disc" &&
                  parameters.friction.law == "coulomb",
                ExcMessage("step-7 needs the 3D half ball with Coulomb "
                           "friction"));
  }


  // The scene as the library solves it, every cycle; its screen output
  // goes to screen.log.
  void
  HalfBall::solve_scene()
  {
    problem = std::make_unique<ContactProblem<3>>(parameters, comm, log);
    // parameters.prm in the output folder: the entries this run used
    problem->record_parameters(parameters.parameter_file);
    problem->run();
    if (root)
      std::ofstream(directory + "/screen.log") << log.str();
  }


  // Hertz and Cattaneo-Mindlin for the loads of the last cycle.
  CattaneoMindlin
  HalfBall::exact_for_last_cycle() const
  {
    const auto [P, Q] = loads(problem->results().back());
    return CattaneoMindlin(parameters, P, Q);
  }


  // The contact radius a is measured on two lines of nodes through the
  // centre of the zone, its edges extrapolated from l1^2; the stick
  // radius c on the same lines, each end half-way between the last
  // sticking and the first slipping node (doc/theory.md §9).
  void
  HalfBall::compare_zones() const
  {
    pcout << "The zone on each mesh against Hertz and Cattaneo-Mindlin for "
             "its loads P, Q (relative errors):\n"
          << "cycle   DoFs  stick  slip         P         Q  Q/(F P)"
             "         a    error         c    error\n";
    for (const CycleResult &r : problem->results())
      {
        const auto [P, Q] = loads(r);
        const CattaneoMindlin exact(parameters, P, Q);
        pcout << std::setw(5) << r.mesh.cycle << std::setw(7) << r.mesh.n_dofs
              << std::setw(7) << r.solve.n_stick << std::setw(6)
              << r.solve.n_slip << format("%10.5f", P) << format("%10.5f", Q)
              << format("%9.3f", Q / (exact.F * P))
              << format("%10.5f", r.zone.edge_half_width)
              << format("%+9.1e", r.zone.edge_half_width / exact.a - 1.)
              << format("%10.5f", r.zone.stick_half_width)
              << format("%+9.1e", r.zone.stick_half_width / exact.c - 1.)
              << "\n";
      }
    const CattaneoMindlin exact = exact_for_last_cycle();
    pcout << "Hertz and Cattaneo-Mindlin for the last cycle: a = "
          << format("%.5f", exact.a) << ", p0 = " << format("%.3f", exact.p0)
          << ", c = " << format("%.5f", exact.c) << "\n";
    if (root) // for plot.gp
      std::ofstream(directory + "/exact.gp")
        << "a = " << exact.a << "\np0 = " << exact.p0 << "\nc = " << exact.c
        << "\nF = " << exact.F << "\n";
  }


  // Every rank reads the file rank 0 wrote; the barrier makes sure it is
  // complete.
  void
  HalfBall::compare_nodes()
  {
    const CycleResult    &last  = problem->results().back();
    const CattaneoMindlin exact = exact_for_last_cycle();
    MPI_Barrier(comm);
    char name[32];
    std::snprintf(name, sizeof(name), "/contact_%02u.csv", last.mesh.cycle);
    zone =
      compare_zone(read_contact_csv(directory + name), exact, directory, root);
    pcout << "\nThe nodes of the last cycle (contact" << (name + 8)
          << "): " << zone.n_stick << " stick, " << zone.n_slip << " slip\n"
          << "  friction law: max (|l2| - theta) = "
          << format("%.1e", zone.excess)
          << " theta_max, slipping nodes max (theta - |l2|) = "
          << format("%.1e", zone.slip_short) << " theta_max\n"
          << "  relative L2 errors: pressure against Hertz "
          << format("%.2e", zone.pressure_error)
          << ", traction along x against Cattaneo-Mindlin "
          << format("%.2e", zone.traction_error) << "\n"
          << "  peak pressure " << format("%.3f", last.zone.max_pressure)
          << " (Hertz " << format("%.3f", exact.p0) << ", "
          << format("%+.1e", last.zone.max_pressure / exact.p0 - 1.)
          << "); the contact element at r = c: "
          << format("%.5f", zone.element_at_c) << "\n";
  }


  // @sect4{The checks}
  tutorial::Checks
  HalfBall::check_results() const
  {
    const CycleResult &last     = problem->results().back();
    const auto [P, Q]           = loads(last);
    const CattaneoMindlin exact = exact_for_last_cycle();
    pcout << "\nChecks:\n";
    tutorial::Checks checks;

    // 1. The disc: no node outside it, every slipping node on its circle.
    checks(zone.excess <= 1e-9 && zone.slip_short <= 1e-9 && zone.n_slip > 0 &&
             zone.n_stick > 0,
           "the friction disc: |l2| <= theta at every node, |l2| = theta "
           "where it slips (to 1e-9 theta_max)");

    // 2. Equilibrium: the plane's force on the ball balances the clamp's
    // reaction, or the loads where a traction replaces the clamp
    // (README.md, "Loads instead of a clamp").
    const auto   clamp = last.reactions.on_id.find(1);
    Tensor<1, 3> balance;
    for (unsigned int d = 0; d < 3; ++d)
      balance[d] =
        (clamp != last.reactions.on_id.end() ? clamp->second[d] :
                                               last.reactions.applied_load[d]) +
        last.zone.resultant[d];
    checks(balance.norm() <= 1e-8 * P,
           "the force on the plane equals the clamp's reaction or the "
           "loads (1e-8 P)");

    // 3. Hertz: the contact radius within one contact element.
    checks(std::abs(last.zone.edge_half_width - exact.a) <= zone.element_at_c,
           "a within one contact element of Hertz's");

    // 4. Cattaneo-Mindlin: the stick radius within 5 % or one contact
    // element.
    checks(std::abs(last.zone.stick_half_width / exact.c - 1.) <= 0.05 ||
             std::abs(last.zone.stick_half_width - exact.c) <=
               zone.element_at_c,
           "c within 5 % of Cattaneo-Mindlin's (or one contact element)");

    // 5. The profiles, on this second mesh (README.md, "How close the
    // profiles are"): the pressure within 10 % of Hertz's (7.5 % measured:
    // Q1 elements at nu = 0.45 are too stiff, +5.5 % at the peak without
    // friction as well, and the last node before the edge), the traction
    // within 20 % of Cattaneo-Mindlin's (15.7 %: the same edge, and r = c,
    // where q has an infinite slope).
    checks(zone.pressure_error < 0.10,
           "the pressure within 10 % of Hertz's (relative L2)");
    checks(zone.traction_error < 0.20,
           "the traction along x within 20 % of Cattaneo-Mindlin's (relative "
           "L2)");
    return checks;
  }


  // The step as run_tutorial() calls it: the program on the scene.
  tutorial::Checks
  run(const Parameters &parameters)
  {
    return HalfBall(parameters).run();
  }
} // namespace Step7

// @sect3{The main function}
//
// MPI, the parameter file (default step-7.prm) and, after it, overrides as
// the dualcontact program takes them, `--set "Material/Poisson's ratio=0.3"`,
// for the experiments of README.md; one message and a non-zero exit status
// on any error.
int
main(int argc, char *argv[])
{
  return dualcontact::tutorial::run_tutorial(
    argc, argv, "step-7", "step-7.prm", Step7::run);
}
