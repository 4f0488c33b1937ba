/* step-11: two elastic bodies, the dual mortar.
 *
 * Steps 1-10 pressed one elastic body against a rigid obstacle. This step
 * presses two elastic bodies against each other: a contact pair (doc/
 * two_bodies.md) names a slave surface, which carries the contact nodes
 * and their multipliers, and a master surface on the other body. With the
 * dual basis for the multipliers, a slave node's constraint gains the
 * master nodes it faces, with the coefficients c_sj = M_sj / sum_j M_sj,
 * M_sj / m_s where the master covers the node's support. A node that the
 * master covers in part (the slave reaching beyond the master's end) has
 * the covered part sum_j M_sj as its weight, so that l1 stays the
 * pressure there (the patch test with the slave beyond the master), and
 * its r and r_t are multiplied by 1 / coverage, a whole node's
 * augmentation (README.md, "The weighted gap"). Nothing else in the
 * method changes. The step asks four questions:
 *   1. what the coupling is: m_s and c_sj of two flat surfaces whose
 *      nodes do not match, computed by mortar::couple without a mesh, and
 *      the forces a uniform pressure puts on the master nodes, with the
 *      dual mortar and with node-to-segment coupling;
 *   2. whether a uniform pressure crosses such an interface uniformly:
 *      the contact patch test of prm/two_blocks_patch.prm, both couplings;
 *   3. whether two curved bodies touch as Hertz says: two cylinders,
 *      identical and dissimilar, against Hertz with E* and R*;
 *   4. whether friction between them follows Cattaneo, Mindlin and
 *      Deresiewicz: the shear cycle of step-11.prm, where two bodies of
 *      one material have Dundurs' beta = 0 at nu = 0.3 and with Q1
 *      elements, which a rigid plane does not allow (step-8).
 * The scene is step-11.prm; README.md has the introduction and the results.
 */

// @sect3{Include files}
//
// The library's Problem class (the whole solver, the load path and its
// records), the mortar coupling of two surfaces (mortar.h: numbers and
// points, no mesh), its parameters, and the tutorials' tools.
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/point.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <dualcontact/contact_problem.h>
#include <dualcontact/mortar.h>
#include <dualcontact/parameters.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "../common/csv_table.h"
#include "../common/tutorial_tools.h"

namespace Step11
{
  using namespace dealii;
  using namespace dualcontact;

  using tutorial::format;

  constexpr unsigned int dim = 2;

  // @sect3{Two flat surfaces, without a mesh}
  //
  // The interface of prm/two_blocks_patch.prm: the line y = 1 from x = 0
  // to 2, cut into 7 equal slave segments (the upper block's bottom, whose
  // outward normal points down) and 10 equal master segments (the lower
  // block's top, normal up). Node k of a surface lies at its k-th point.
  // mortar::couple and mortar::couple_node_to_segment take exactly this:
  // segments with their end points, node numbers and normals.
  struct FlatInterface
  {
    std::vector<mortar::Segment> slave, master;
    std::vector<double>          x_slave, x_master;
  };

  std::vector<mortar::Segment>
  segments(const std::vector<double> &x, const double y, const double n_y)
  {
    std::vector<mortar::Segment> result;
    for (unsigned int k = 0; k + 1 < x.size(); ++k)
      {
        mortar::Segment s;
        s.x         = {{Point<2>(x[k], y), Point<2>(x[k + 1], y)}};
        s.node      = {{k, k + 1}};
        s.normal[1] = n_y;
        result.push_back(s);
      }
    return result;
  }

  FlatInterface
  flat_interface(const unsigned int n_slave,
                 const unsigned int n_master,
                 const double       width,
                 const double       y)
  {
    FlatInterface interface;
    for (unsigned int k = 0; k <= n_slave; ++k)
      interface.x_slave.push_back(width * k / n_slave);
    for (unsigned int k = 0; k <= n_master; ++k)
      interface.x_master.push_back(width * k / n_master);
    interface.slave  = segments(interface.x_slave, y, -1.);
    interface.master = segments(interface.x_master, y, 1.);
    return interface;
  }

  // The force a pressure p, uniform on the slave surface, puts on master
  // node j. The multiplier field lambda_h = sum_s l_s psi_s with l_s = p
  // is p everywhere (the psi_s sum to one), and the work of lambda_h on the
  // master's displacements is sum_s l_s sum_j M_sj v_j: the force on node j
  // is sum_s M_sj p. With the dual mortar that is p int (sum_s psi_s)
  // phi_j = p int phi_j, the consistent load; with node to segment, where
  // M_sj = m_s phi_j(eta_s), it is sum_s m_s p phi_j(eta_s), the slave's
  // nodal forces handed on at the points eta_s below the nodes.
  std::vector<double>
  master_forces(const mortar::Coupling &coupling,
                const unsigned int      n_master_nodes,
                const double            p)
  {
    std::vector<double> f(n_master_nodes, 0.);
    for (const auto &row : coupling.master)
      for (const auto &[j, M] : row)
        f[j] += M * p;
    return f;
  }

  // The consistent load int p phi_j of a uniform p: half of each of its
  // segments.
  std::vector<double>
  consistent_forces(const FlatInterface &interface, const double p)
  {
    std::vector<double> f(interface.x_master.size(), 0.);
    for (const mortar::Segment &m : interface.master)
      for (const unsigned int k : {0u, 1u})
        f[m.node[k]] += 0.5 * p * (m.x[1] - m.x[0]).norm();
    return f;
  }

  // @sect3{Solving a scene}
  //
  // One scene, solved by ContactProblem::run() into its own folder under
  // the scene's output folder; its records (records.h) are what the
  // program reads afterwards: per mesh (results()) and per step of a load
  // path (steps()). The library's own report goes to a string that is not
  // shown. Every rank reads the CSV files rank 0 wrote; the barrier makes
  // sure they are complete.
  struct Solved
  {
    std::vector<CycleResult> cycles, steps;
    std::string              directory;
    double                   time = 0.; // wall time of the run [s]
  };

  Solved
  solve(Parameters parameters, const Parameters &scene, const std::string &name)
  {
    parameters.output.directory = scene.output.directory + "/" + name;
    parameters.output.write_vtu = scene.output.write_vtu;
    Timer               timer;
    std::ostringstream  silent;
    ContactProblem<dim> problem(parameters, MPI_COMM_WORLD, silent);
    problem.run();
    MPI_Barrier(MPI_COMM_WORLD);
    return {problem.results(),
            problem.steps(),
            parameters.output.directory,
            timer.wall_time()};
  }

  // A scene derived from another: its parameters as read (the file and the
  // --set overrides, Parameters::parameter_file), with the entries of
  // `overlay`, prm text, put over them. The derived scene passes every
  // check of the input that the original passed.
  Parameters
  derive(const Parameters &scene, const std::string &overlay)
  {
    Parameters parameters;
    parameters.read_string(scene.parameter_file, overlay);
    return parameters;
  }

  // @sect3{The slave surface, node by node}
  //
  // contact_NN.csv (per mesh) and contact_step_NNN.csv (per step of a
  // path) have one row per contact node of the slave surface (doc/
  // output.md): its position, weight m_s, pressure l1, tangential traction
  // l2 (along t_s = (-n_y, n_x)) and status. Sorted along x.
  struct SlaveNode
  {
    double      x, weight, l1, l2;
    std::string status;
  };

  std::vector<SlaveNode>
  read_slave(const std::string &filename)
  {
    const tutorial::CsvTable table(filename);
    std::vector<SlaveNode>   nodes;
    for (unsigned int i = 0; i < table.n_rows(); ++i)
      nodes.push_back({table.number(i, "x"),
                       table.number(i, "weight"),
                       table.number(i, "l1"),
                       table.number(i, "l2"),
                       table.text(i, "status")});
    std::sort(nodes.begin(),
              nodes.end(),
              [](const SlaveNode &a, const SlaveNode &b) { return a.x < b.x; });
    return nodes;
  }

  std::string
  mesh_file(const Solved &run, const unsigned int cycle)
  {
    return run.directory + "/contact_" + format("%02.0f", cycle) + ".csv";
  }

  std::string
  step_file(const Solved &run, const unsigned int step)
  {
    return run.directory + "/contact_step_" + format("%03.0f", step + 1.) +
           ".csv";
  }

  // The contact element h_C: the largest spacing of neighbouring slave
  // nodes in the contact zone |x| <= a, where its edges lie. (The graded
  // mesh coarsens a little beyond the zone.)
  double
  contact_element(const std::vector<SlaveNode> &nodes, const double a)
  {
    double h = 0.;
    for (unsigned int i = 1; i < nodes.size(); ++i)
      if (std::abs(nodes[i].x) <= a && std::abs(nodes[i - 1].x) <= a)
        h = std::max(h, nodes[i].x - nodes[i - 1].x);
    return h;
  }

  // The forces on the two bodies, sum_s m_s (l1_s n_s + T_s l2_s) on the
  // slave body and its shares c_sj on the master nodes: equal and opposite
  // whatever the multipliers are, since the c_sj of a node sum to one.
  // Their sum relative to either.
  double
  imbalance(const CycleResult &r)
  {
    double sum = 0., size = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double s = r.zone.on_slave_body[d] + r.zone.on_master_body[d];
        sum += s * s;
        size += r.zone.on_slave_body[d] * r.zone.on_slave_body[d];
      }
    return std::sqrt(sum / size);
  }

  // @sect3{The patch test}
  //
  // prm/two_blocks_patch.prm: the box [0, 2]^2 cut at y = 1 into two
  // blocks of E = 1000, nu = 0.3, the lower one of 10 x 4 cells, the upper
  // one of 7 x 3: no node of the interface has a partner across it. The
  // lower block is clamped at y = 0; the tractions on its top and sides are
  // those of the uniform stress sigma_yy = -p = -1, sigma_xx = nu/(1 - nu)
  // sigma_yy (no lateral strain, so that the clamp fits it). The exact
  // solution is linear, u = (0, -(1 + nu)(1 - 2 nu)/((1 - nu) E) p y), and
  // the exact pressure is p at every slave node. Two meshes, the second
  // halving the first (14 over 20 cells), and the Uzawa tolerance of the
  // unit test (tests/unit/test_two_bodies.cc), so that round-off, not the
  // iteration, is what remains of a solution that is exact.
  constexpr double patch_pressure = 1.;

  const std::string patch_scene = R"(
subsection Geometry
  set Type               = two blocks
  set Lower left corner  = 0, 0
  set Upper right corner = 2, 2
  set Subdivisions       = 10, 4
  set Upper subdivisions = 7, 3
end
subsection Material
  set Young's modulus = 1000
  set Poisson's ratio = 0.3
end
subsection Boundary conditions
  set Conditions    = 0: traction, 1: traction, 2: fixed, 3: traction
  set Tractions     = 0: 0.3/0.7; 0, 1: -0.3/0.7; 0, 3: 0; -1
  set Contact pairs = 5: 4
end
subsection Exact solution
  set Displacement     = 0; -1.3*0.4/0.7/1000*y
  set Contact pressure = 1
end
subsection Refinement
  set Number of cycles = 2
end
subsection Solver
  set Uzawa tolerance = 1e-11
end
)";

  // The patch scene with the entries of `overlay` over it (the coupling).
  Parameters
  patch_parameters(const std::string &overlay)
  {
    Parameters parameters;
    parameters.read_string(patch_scene, overlay);
    return parameters;
  }

  // @sect3{Hertz for two cylinders}
  //
  // Two cylinders of radii R1, R2 and materials (E1, nu1), (E2, nu2),
  // pressed together by P per unit length, touch over |x| < a with
  // Hertz's pressure p0 sqrt(1 - x^2/a^2), where the bodies enter only
  // through
  //   1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2,  1/R* = 1/R1 + 1/R2,
  //   a = sqrt(4 P R* / (pi E*)),              p0 = 2 P / (pi a).
  // The upper body (material id 1, the slave) is body 1, the lower (id 0,
  // the master) body 2.
  struct CylinderPair
  {
    std::string name;
    double      E1, nu1, R1, E2, nu2, R2;

    double
    E_star() const
    {
      return 1. / ((1. - nu1 * nu1) / E1 + (1. - nu2 * nu2) / E2);
    }

    double
    R_star() const
    {
      return R1 * R2 / (R1 + R2);
    }

    double
    a(const double P) const
    {
      return std::sqrt(4. * P * R_star() / (numbers::PI * E_star()));
    }

    double
    p0(const double P) const
    {
      return 2. * P / (numbers::PI * a(P));
    }
  };

  // The scene's two cylinders become Hertz's problem: no friction, one
  // load step, the clamp on the upper body's flat top (width 2 R1)
  // replaced by the uniform pressure q = P / (2 R1) with P chosen so that
  // a = R1/10, and two meshes, the scene's first and the one halved. The
  // upper body takes nothing from the clamp, so that only the contact
  // holds it. The materials and radii are the pair's: both written out,
  // the lower body's as the default material, the upper's by its id.
  constexpr double a_over_R1 = 0.1;

  std::string
  hertz_overlay(const CylinderPair &pair)
  {
    const double a = a_over_R1 * pair.R1;
    const double P = numbers::PI * pair.E_star() * a * a / (4. * pair.R_star());
    const double q = P / (2. * pair.R1);
    return "subsection Geometry\n  set Lower radius = " +
           format("%.17g", pair.R2) +
           "\nend\nsubsection Material\n  set Young's modulus = " +
           format("%.17g", pair.E2) +
           "\n  set Poisson's ratio = " + format("%.17g", pair.nu2) +
           "\n  set Materials by id = 1: " + format("%.17g", pair.E1) + ", " +
           format("%.17g", pair.nu1) +
           "\nend\nsubsection Boundary conditions\n"
           "  set Conditions = 1: traction, 3: fixed\n"
           "  set Displacements =\n  set Tractions = 1: 0; " +
           format("%.17g", -q) +
           "\nend\nsubsection Friction\n  set Law = none\nend\n"
           "subsection Refinement\n  set Number of cycles = 2\nend\n"
           "subsection Load path\n  set Times = 1\nend\n"
           "subsection Exact solution\n  set Contact pressure = " +
           format("%.17g", pair.p0(P)) + " * sqrt(max(0, 1 - x^2 / " +
           format("%.17g", a * a) + "))\nend\n";
  }

  // What a mesh gives against Hertz for the P it carries (its contact
  // force): the peak pressure max_s l1_s against p0, the half-width with
  // the edges extrapolated (records.h: edge_half_width) against a, in
  // contact elements too, and the relative L2 error of the pressure on the
  // slave surface (the library's, from <Exact solution/Contact pressure>:
  // the piecewise linear l1_h against p(x), by quadrature on the faces).
  struct HertzMesh
  {
    types::global_dof_index dofs, nodes, uncovered;
    double P, a, p0, h, peak_error, half_width_error, pressure_error;
    double balance;
  };

  HertzMesh
  compare_with_hertz(const CylinderPair &pair,
                     const CycleResult  &r,
                     const std::string  &file)
  {
    const std::vector<SlaveNode> nodes = read_slave(file);
    HertzMesh                    m;
    m.dofs             = r.mesh.n_dofs;
    m.nodes            = r.solve.n_contact_nodes;
    m.uncovered        = r.solve.n_uncovered;
    m.P                = r.zone.contact_force;
    m.a                = pair.a(m.P);
    m.p0               = pair.p0(m.P);
    m.h                = contact_element(nodes, m.a);
    m.peak_error       = r.zone.max_pressure / m.p0 - 1.;
    m.half_width_error = r.zone.edge_half_width / m.a - 1.;
    m.pressure_error   = r.zone.pressure_error;
    m.balance          = imbalance(r);
    return m;
  }

  // @sect3{Cattaneo, Mindlin and Deresiewicz}
  //
  // For beta = 0 the tangential traction of two cylinders is a sum of
  // elliptic terms
  //   q_d(x) = F (p0/a) sqrt(d^2 - x^2) on |x| < d,
  // with Hertz's a and p0 for the pair and the step's P (doc/theory.md
  // §11). Sheared from Q = 0 after the normal load, q = s (q_a - q_c),
  // c/a = sqrt(1 - |Q|/(F P)), s the sign of Q (Cattaneo, Mindlin). When
  // the shear turns at Q_r, the traction of that moment stays and a pair
  // of twice the size and the other sign grows from the edges:
  //   q = q_r - 2 s_r (q_a - q_c'),  c'/a = sqrt(1 - |Q - Q_r|/(2 F P))
  // (Mindlin and Deresiewicz; Masing's rule). The stick zone is |x| < c of
  // the newest pair. A turning point is a step at which the clamp's motion
  // along x changes direction. A prediction holds its terms as pairs
  // (k, d): q(x) = sum k q_d(x).
  //
  // Q is the clamp's force on the upper body along x and delta the clamp's
  // displacement along x, both signed so that the first shear is positive;
  // the traction q of the formulas is then sign * l2 of the CSV files.
  struct Prediction
  {
    double                                 a = 0., p0 = 0., c = 0.;
    std::vector<std::pair<double, double>> terms;
    unsigned int                           turns_before = 0;

    double
    traction(const double x, const double F) const
    {
      double q = 0.;
      for (const auto &[k, d] : terms)
        q += k * F * p0 / a * std::sqrt(std::max(0., d * d - x * x));
      return q;
    }
  };

  struct Cycle
  {
    Solved                    run;
    types::boundary_id        clamp = 0;
    double                    sign  = 1.;
    std::vector<unsigned int> turns; // the turning points, and the last step

    double
    P(const unsigned int n) const
    {
      return run.steps[n].zone.contact_force;
    }

    double
    Q(const unsigned int n) const
    {
      return sign * run.steps[n].reactions.on_id.at(clamp)[0];
    }

    double
    delta(const unsigned int n) const
    {
      return sign * run.steps[n].step.boundary_displacement.at(clamp)[0];
    }
  };

  std::vector<unsigned int>
  turning_points(const Cycle &cycle)
  {
    std::vector<unsigned int> turns;
    double                    direction = 0.;
    for (unsigned int n = 1; n < cycle.run.steps.size(); ++n)
      {
        const double move = cycle.delta(n) - cycle.delta(n - 1);
        if (move != 0. && move * direction < 0.)
          turns.push_back(n - 1);
        if (move != 0.)
          direction = move;
      }
    turns.push_back(cycle.run.steps.size() - 1);
    return turns;
  }

  std::vector<Prediction>
  mindlin_deresiewicz(const Cycle &cycle, const CylinderPair &pair, double F)
  {
    std::vector<Prediction>                predictions;
    std::vector<std::pair<double, double>> at_turn;
    double                                 Q_turn = 0., doubled = 1.;
    unsigned int                           turns_before = 0;
    for (unsigned int n = 0; n < cycle.run.steps.size(); ++n)
      {
        if (n > 0 &&
            std::find(cycle.turns.begin(), cycle.turns.end() - 1, n - 1) !=
              cycle.turns.end() - 1)
          {
            at_turn = predictions[n - 1].terms;
            Q_turn  = cycle.Q(n - 1);
            doubled = 2.;
            ++turns_before;
          }
        const double P = cycle.P(n), Q = cycle.Q(n);
        Prediction   p;
        p.a            = pair.a(P);
        p.p0           = pair.p0(P);
        p.turns_before = turns_before;
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

  // The work the clamp does on the upper body from step i to step j, the
  // integral of Q d delta: Simpson's rule on each two steps of equal
  // length (each branch is smooth between its turning points), the
  // trapezoidal rule on a last single step. Over a closed cycle the
  // elastic energy returns, and this work is the energy dissipated: the
  // area of the loop of Q against delta.
  double
  clamp_work(const Cycle &cycle, const unsigned int i, const unsigned int j)
  {
    double       work = 0.;
    unsigned int n    = i;
    for (; n + 2 <= j; n += 2)
      work += (cycle.delta(n + 2) - cycle.delta(n)) / 6. *
              (cycle.Q(n) + 4. * cycle.Q(n + 1) + cycle.Q(n + 2));
    if (n < j)
      work +=
        0.5 * (cycle.Q(n) + cycle.Q(j)) * (cycle.delta(j) - cycle.delta(n));
    return work;
  }

  // The energy a cycle Q* -> -Q* -> Q* dissipates between two cylinders
  // at beta = 0 (doc/theory.md §11): the slip of the annulus c < |x| < a
  // follows from the surface displacement gradient of a half-plane,
  //   W_2D = 16 F^2 p0^2 / (E* a) int_c^a sqrt(1 - x^2/a^2) S(x) dx,
  //   S(x) = (x sqrt(x^2 - c^2) - c^2 ln((x + sqrt(x^2 - c^2))/c)) / 2,
  // c the stick half-width at Q*; the midpoint rule on 20000 intervals.
  double
  cycle_energy(const double F,
               const double p0,
               const double a,
               const double c,
               const double E_star)
  {
    const unsigned int n        = 20000;
    double             integral = 0.;
    for (unsigned int k = 0; k < n; ++k)
      {
        const double x = c + (a - c) * (k + 0.5) / n;
        const double r = std::sqrt(x * x - c * c);
        const double S = 0.5 * (x * r - c * c * std::log((x + r) / c));
        integral += std::sqrt(1. - x * x / (a * a)) * S * (a - c) / n;
      }
    return 16. * F * F * p0 * p0 / (E_star * a) * integral;
  }

  // @sect3{The whole step}
  //
  // The program in the shape of deal.II's steps: a class whose run() reads
  // as the four questions of the introduction, one member function per
  // stage, and members for what a later stage needs of an earlier one (the
  // runs for the figures' data, the pairs for the cycle, the checks).
  class TwoBodies
  {
  public:
    explicit TwoBodies(const Parameters &scene);

    tutorial::Checks
    run();

  private:
    void
    check_scene();
    void
    couple_flat_surfaces();
    void
    carry_uniform_pressure();
    void
    run_patch_test();
    void
    solve_hertz_pairs();
    void
    compare_pairs_with_hertz();
    void
    solve_shear_cycle();
    void
    compare_shear_with_masing();
    void
    balance_cycle_energy();
    void
    write_figure_data() const;
    tutorial::Checks
    report_checks() const;

    // The scene, the screen (rank 0 prints) and whether it shows times.
    const Parameters  &scene;
    const bool         root;
    ConditionalOStream pcout;
    const bool         timing;
    double             F = 0.; // the friction coefficient

    // The checks, each (holds, what it says): printed at the end.
    std::vector<std::pair<bool, std::string>> checks;

    // The coupling of two flat surfaces, without a mesh.
    FlatInterface    interface;
    unsigned int     n_s = 0, n_m = 0;
    mortar::Coupling mortar_coupling, nts_coupling;

    // The runs of the patch test and of Hertz, for the figures' data.
    std::vector<Solved>                 patch;
    std::vector<CylinderPair>           pairs;
    std::vector<Solved>                 hertz;
    std::vector<std::vector<HertzMesh>> hertz_meshes;

    // The shear cycle, Masing's prediction for each of its steps, and what
    // the pressing left: the contact force, the largest |l2|, the contact
    // element and p0.
    Cycle                   cycle;
    std::vector<Prediction> predicted;
    unsigned int            first_shear = 1;
    double                  P_pressed = 0., most_l2 = 0., h = 0.;
    double                  p0_pressed = 0.;
    // the largest distances of the shear steps from Masing's rule: the
    // stick zone's in contact elements, the traction's RMS over F p0
    double worst_zone = 0., worst_rms = 0.;
  };


  TwoBodies::TwoBodies(const Parameters &scene)
      : scene(scene)
      , root(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      , pcout(std::cout, root)
      , timing(scene.output.print_timing)
  {}


  // The four questions in turn: the coupling without a mesh, the patch
  // test, Hertz, the shear cycle; then the data for plot.gp and the checks.
  tutorial::Checks
  TwoBodies::run()
  {
    check_scene();
    couple_flat_surfaces();
    carry_uniform_pressure();
    run_patch_test();
    solve_hertz_pairs();
    compare_pairs_with_hertz();
    solve_shear_cycle();
    compare_shear_with_masing();
    balance_cycle_energy();
    write_figure_data();
    return report_checks();
  }


  // @sect4{The scene this step needs}
  //
  // The formulas below hold for two half discs in one contact pair with
  // Coulomb friction, sheared by one clamp along a path of three steps or
  // more; anything else is refused with one message before a solve.
  void
  TwoBodies::check_scene()
  {
    tutorial::require(
      scene.geometry.dimension == dim &&
        scene.geometry.type == "two half discs" &&
        scene.boundary.contact_pairs.size() == 1 &&
        scene.friction.law == "coulomb" &&
        scene.boundary.displacements.size() == 1 &&
        scene.load_path.step_times().size() >= 3,
      "step-11 needs the 2D two half discs in one contact pair, Coulomb "
      "friction, one clamp moved by <Boundary conditions/Displacements> and "
      "a load path of three steps or more.");
    try
      {
        F = std::stod(scene.friction.parameter);
      }
    catch (const std::exception &)
      {
        tutorial::require(false,
                          "step-11 needs <Friction/Coefficient> as a number.");
      }
    if (root)
      std::filesystem::create_directories(scene.output.directory);

    pcout << "step-11: two elastic bodies, the dual mortar ("
          << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
          << " MPI rank(s))\n\n";
  }


  // @sect4{The coupling of two flat surfaces}
  //
  // 7 slave segments over 10 master segments on [0, 2]. First the dual
  // basis against the slave's own: the slave surface coupled with a
  // copy of itself, facing it, has M_st = int psi_s phi_t, which must be
  // delta_st m_s. Then the slave against the master: each slave node's
  // m_s and c_sj, and two sums that say what the c_sj do to a field
  // that is linear along the interface, v(x) = alpha + beta x: sum_j
  // c_sj v(x_j) = v(x_s) needs sum_j c_sj = 1 and sum_j c_sj x_j = x_s.
  void
  TwoBodies::couple_flat_surfaces()
  {
    interface              = flat_interface(7, 10, 2., 1.);
    n_s                    = interface.x_slave.size();
    n_m                    = interface.x_master.size();
    double biorthogonality = 0., largest_m = 0.;
    {
      std::vector<mortar::Segment> mirror = interface.slave;
      for (mortar::Segment &s : mirror)
        s.normal = -s.normal;
      const mortar::Coupling self =
        mortar::couple(interface.slave, n_s, mirror);
      for (unsigned int s = 0; s < n_s; ++s)
        {
          largest_m = std::max(largest_m, self.weight[s]);
          for (const auto &[t, M] : self.master[s])
            biorthogonality =
              std::max(biorthogonality,
                       std::abs(M - (s == t ? self.weight[s] : 0.)));
        }
      biorthogonality /= largest_m;
    }
    mortar_coupling = mortar::couple(interface.slave, n_s, interface.master);
    nts_coupling =
      mortar::couple_node_to_segment(interface.slave, n_s, interface.master);

    pcout << "The coupling of 7 slave segments over 10 master segments on "
             "[0, 2] (mortar.h), no mesh:\n"
          << "  the dual basis against the slave's own basis: max_st |int "
             "psi_s phi_t - delta_st m_s| / max m_s = "
          << format("%.1e", biorthogonality) << "\n"
          << "  the dual mortar's coefficients c_sj = M_sj / m_s:\n"
          << "     s     x_s       m_s  c_sj (master node j: c_sj)"
          << std::string(35, ' ') << "sum c_sj  sum c_sj x_j - x_s\n";
    // the same two sums for both couplings, over all slave nodes
    double linear_error[2] = {0., 0.};
    bool   negative        = false;
    for (unsigned int s = 0; s < n_s; ++s)
      {
        std::string entries;
        double      sums[2][2] = {{0., 0.}, {0., 0.}};
        for (unsigned int k = 0; k < 2; ++k)
          {
            const mortar::Coupling &c = k == 0 ? mortar_coupling : nts_coupling;
            for (const auto &[j, M] : c.master[s])
              {
                sums[k][0] += M / c.weight[s];
                sums[k][1] += M / c.weight[s] * interface.x_master[j];
              }
            linear_error[k] =
              std::max({linear_error[k],
                        std::abs(sums[k][0] - 1.),
                        std::abs(sums[k][1] - interface.x_slave[s])});
          }
        for (const auto &[j, M] : mortar_coupling.master[s])
          {
            entries += format("%3.0f: ", j) +
                       format("%7.4f", M / mortar_coupling.weight[s]);
            negative |= M < 0.;
          }
        entries.resize(61, ' ');
        pcout << format("%6.0f", s) << format("%8.4f", interface.x_slave[s])
              << format("%10.6f", mortar_coupling.weight[s]) << "  " << entries
              << format("%9.6f", sums[0][0])
              << format("%20.1e", sums[0][1] - interface.x_slave[s]) << "\n";
      }
    pcout << "  largest |sum c_sj - 1| and |sum c_sj x_j - x_s|: dual mortar "
          << format("%.1e", linear_error[0]) << ", node to segment "
          << format("%.1e", linear_error[1]) << "\n";

    checks.emplace_back(biorthogonality <= 1e-14,
                        "the dual basis is biorthogonal to the slave's own, "
                        "int psi_s phi_t = delta_st m_s (to " +
                          format("%.0e", biorthogonality) + " <= 1e-14)");
    checks.emplace_back(linear_error[0] <= 1e-14 && linear_error[1] <= 1e-14,
                        "both couplings see a linear field exactly: sum_j "
                        "c_sj v(x_j) = v(x_s) (to 1e-14)");
    checks.emplace_back(negative,
                        "some c_sj of the dual mortar are negative (psi_s "
                        "changes sign on its segments)");
  }


  // The forces of the uniform pressure p = 1 on the master nodes, against
  // the consistent load int p phi_j. Both couplings hand on the whole
  // force, p times the width 2; only the dual mortar hands it on as the
  // consistent load.
  void
  TwoBodies::carry_uniform_pressure()
  {
    const std::vector<double> consistent =
      consistent_forces(interface, patch_pressure);
    const std::vector<double> forces[2] = {
      master_forces(mortar_coupling, n_m, patch_pressure),
      master_forces(nts_coupling, n_m, patch_pressure)};
    pcout << "\nThe uniform pressure p = 1 on the slave, carried to the "
             "master nodes (f_j = sum_s M_sj p):\n"
          << "     j     x_j  int p phi_j  dual mortar  node to segment\n";
    double force_error[2] = {0., 0.}, total[3] = {0., 0., 0.};
    for (unsigned int j = 0; j < n_m; ++j)
      {
        pcout << format("%6.0f", j) << format("%8.4f", interface.x_master[j])
              << format("%13.6f", consistent[j])
              << format("%13.6f", forces[0][j])
              << format("%17.6f", forces[1][j]) << "\n";
        for (unsigned int k = 0; k < 2; ++k)
          {
            force_error[k] =
              std::max(force_error[k],
                       std::abs(forces[k][j] - consistent[j]) / consistent[j]);
            total[k + 1] += forces[k][j];
          }
        total[0] += consistent[j];
      }
    pcout << "  sums " << format("%.6f", total[0]) << ", "
          << format("%.6f", total[1]) << ", " << format("%.6f", total[2])
          << "; largest |f_j - int p phi_j| / int p phi_j: dual mortar "
          << format("%.1e", force_error[0]) << ", node to segment "
          << format("%.3f", force_error[1]) << "\n\n";
    if (root)
      {
        std::ofstream csv(scene.output.directory + "/master_forces.csv");
        csv << "x,consistent,mortar,node_to_segment\n";
        csv.precision(10);
        for (unsigned int j = 0; j < n_m; ++j)
          csv << interface.x_master[j] << ',' << consistent[j] << ','
              << forces[0][j] << ',' << forces[1][j] << '\n';
      }
    checks.emplace_back(force_error[0] <= 1e-14 && force_error[1] >= 0.01 &&
                          std::abs(total[1] - total[0]) <= 1e-14 * total[0] &&
                          std::abs(total[2] - total[0]) <= 1e-14 * total[0],
                        "a uniform pressure reaches the master nodes as int "
                        "p phi_j with the dual mortar (to 1e-14), not with "
                        "node to segment (off by " +
                          format("%.0f", 100. * force_error[1]) +
                          " % >= 1 %); both carry the whole force");
  }


  // @sect4{The patch test}
  //
  // The same interface in two blocks, solved with each coupling on two
  // meshes: the largest |l1 - p| over the slave nodes, the relative L2
  // errors of the pressure and of the displacement (against the exact
  // solution of the scene), the contact force, and the forces on the two
  // bodies against each other.
  void
  TwoBodies::run_patch_test()
  {
    patch = {solve(patch_parameters(""), scene, "patch_dual_mortar"),
             solve(patch_parameters("subsection Boundary conditions\n  set "
                                    "Pair coupling = node to segment\nend\n"),
                   scene,
                   "patch_node_to_segment")};
    const std::string coupling_name[2] = {"dual mortar", "node to segment"};
    pcout << "The patch test: two blocks, 7 over 10 cells, then 14 over 20; "
             "p = 1, the exact displacement linear"
          << (timing ? format(" (%.1f s)", patch[0].time + patch[1].time) : "")
          << "\n"
          << "  coupling         cycle  slave nodes  largest |l1 - p|  "
             "p L2 error  u L2 error  contact force  bodies' forces\n";
    double patch_l1[2] = {0., 0.}, patch_u[2] = {0., 0.};
    double patch_u_least = 1., patch_force = 0., patch_balance = 0.;
    for (unsigned int k = 0; k < 2; ++k)
      for (unsigned int c = 0; c < patch[k].cycles.size(); ++c)
        {
          const CycleResult           &r = patch[k].cycles[c];
          const std::vector<SlaveNode> nodes =
            read_slave(mesh_file(patch[k], c));
          double l1 = 0.;
          for (const SlaveNode &n : nodes)
            l1 = std::max(l1, std::abs(n.l1 - patch_pressure));
          const double u = r.errors.error_L2 / r.errors.norm_L2;
          patch_l1[k]    = std::max(patch_l1[k], l1);
          patch_u[k]     = std::max(patch_u[k], u);
          if (k == 1)
            patch_u_least = std::min(patch_u_least, u);
          patch_force =
            std::max(patch_force,
                     std::abs(r.zone.contact_force / (2. * patch_pressure) -
                              1.));
          patch_balance    = std::max(patch_balance, imbalance(r));
          std::string name = "  " + coupling_name[k];
          name.resize(18, ' ');
          pcout << name << format("%5.0f", c)
                << format("%13.0f", double(nodes.size()))
                << format("%18.2e", l1)
                << format("%12.2e", r.zone.pressure_error)
                << format("%12.2e", u) << format("%15.9f", r.zone.contact_force)
                << format("%16.1e", imbalance(r)) << "\n";
        }
    {
      // the pressure node by node on the first mesh
      const std::vector<SlaveNode> dual = read_slave(mesh_file(patch[0], 0));
      const std::vector<SlaveNode> nts  = read_slave(mesh_file(patch[1], 0));
      pcout << "  the pressure at the slave nodes, first mesh:\n"
            << "         x       m_s  dual mortar  node to segment\n";
      for (unsigned int i = 0; i < dual.size() && i < nts.size(); ++i)
        pcout << format("%10.4f", dual[i].x) << format("%10.6f", dual[i].weight)
              << format("%13.6f", dual[i].l1) << format("%17.6f", nts[i].l1)
              << "\n";
      pcout << "\n";
    }
    checks.emplace_back(patch_l1[0] <= 1e-8 && patch_u[0] <= 1e-8,
                        "patch test, dual mortar: l1 = p and the exact "
                        "displacement on both meshes (to 1e-8)");
    checks.emplace_back(patch_l1[1] >= 0.05 && patch_u_least >= 1e-3,
                        "patch test, node to segment: largest |l1 - p| " +
                          format("%.2f", patch_l1[1]) +
                          " >= 0.05, displacement error >= 0.1 % on both "
                          "meshes");
    checks.emplace_back(patch_force <= 1e-10 && patch_balance <= 1e-10,
                        "patch test, both couplings: the contact force is "
                        "the load p times the width 2, the bodies' forces "
                        "equal and opposite (to 1e-10)");
  }


  // @sect4{Hertz: two cylinders}
  //
  // The scene's two cylinders, and the pair with E2 = 3 E1 and R2 = 2 R1
  // (the lower body stiffer and flatter), each pressed so that a = R1/10,
  // on two meshes. This stage solves both pairs and lists their constants.
  void
  TwoBodies::solve_hertz_pairs()
  {
    const MaterialParameters upper = scene.material.of(1);
    const MaterialParameters lower = scene.material.of(0);
    CylinderPair             scene_pair{"identical",
                            upper.youngs_modulus,
                            upper.poissons_ratio,
                            scene.geometry.radius,
                            lower.youngs_modulus,
                            lower.poissons_ratio,
                            scene.geometry.lower_radius};
    if (scene_pair.E1 != scene_pair.E2 || scene_pair.nu1 != scene_pair.nu2 ||
        scene_pair.R1 != scene_pair.R2)
      scene_pair.name = "the scene's pair";
    CylinderPair dissimilar = scene_pair;
    dissimilar.name         = "E2 = 3 E1, R2 = 2 R1";
    dissimilar.E2           = 3. * scene_pair.E1;
    dissimilar.nu2          = scene_pair.nu1;
    dissimilar.R2           = 2. * scene_pair.R1;
    pairs                   = {scene_pair, dissimilar};
    double hertz_time       = 0.;
    for (unsigned int k = 0; k < pairs.size(); ++k)
      {
        hertz.push_back(
          solve(derive(scene, hertz_overlay(pairs[k])),
                scene,
                k == 0 ? "hertz_scene_pair" : "hertz_dissimilar"));
        hertz_time += hertz.back().time;
      }
    pcout << "Hertz: two cylinders, frictionless, pressed by P = pi E* a^2 / "
             "(4 R*) for a = R1/10"
          << (timing ? format(" (%.1f s)", hertz_time) : "") << "\n"
          << "  pair                    E1    nu1   R1       E2    nu2   R2"
             "          E*         R*\n";
    for (const CylinderPair &pair : pairs)
      {
        std::string name = "  " + pair.name;
        name.resize(22, ' ');
        pcout << name << format("%6g", pair.E1) << format("%7g", pair.nu1)
              << format("%5g", pair.R1) << format("%9g", pair.E2)
              << format("%7g", pair.nu2) << format("%5g", pair.R2)
              << format("%12.4f", pair.E_star())
              << format("%11.6f", pair.R_star()) << "\n";
      }
  }


  // Each mesh of each pair against Hertz's a and p0 (compare_with_hertz),
  // one row per mesh; the checks look at the last mesh, at the error's fall
  // under halving, and at the forces.
  void
  TwoBodies::compare_pairs_with_hertz()
  {
    pcout << "  pair                  cycle   DoFs  nodes  facing none        "
             "P       a       p0     h_C    peak   a_m - a  (h_C)   p L2 "
             "error\n";
    hertz_meshes.resize(pairs.size());
    for (unsigned int k = 0; k < pairs.size(); ++k)
      for (unsigned int c = 0; c < hertz[k].cycles.size(); ++c)
        {
          const HertzMesh m = compare_with_hertz(pairs[k],
                                                 hertz[k].cycles[c],
                                                 mesh_file(hertz[k], c));
          hertz_meshes[k].push_back(m);
          std::string name = "  " + pairs[k].name;
          name.resize(22, ' ');
          pcout << name << format("%5.0f", c) << format("%7.0f", m.dofs)
                << format("%7.0f", m.nodes) << format("%13.0f", m.uncovered)
                << format("%9.5f", m.P) << format("%8.5f", m.a)
                << format("%9.4f", m.p0) << format("%8.5f", m.h)
                << format("%+7.2f %%", 100. * m.peak_error)
                << format("%+8.2f %%", 100. * m.half_width_error)
                << format("%+7.2f", m.half_width_error * m.a / m.h)
                << format("%10.2f %%", 100. * m.pressure_error) << "\n";
        }
    pcout << "\n";
    for (unsigned int k = 0; k < pairs.size(); ++k)
      {
        const std::vector<HertzMesh> &m       = hertz_meshes[k];
        const HertzMesh              &last    = m.back();
        double                        balance = 0., P_error = 0.;
        const double                  a = a_over_R1 * pairs[k].R1;
        const double                  P_applied =
          numbers::PI * pairs[k].E_star() * a * a / (4. * pairs[k].R_star());
        for (const HertzMesh &mesh : m)
          {
            balance = std::max(balance, mesh.balance);
            P_error = std::max(P_error, std::abs(mesh.P / P_applied - 1.));
          }
        checks.emplace_back(
          std::abs(last.peak_error) <= 0.01 &&
            std::abs(last.half_width_error) * last.a <= last.h,
          "Hertz, " + pairs[k].name + ", last mesh: peak within " +
            format("%.2f", 100. * std::abs(last.peak_error)) +
            " % <= 1 % of p0, half-width within " +
            format("%.2f", std::abs(last.half_width_error) * last.a / last.h) +
            " <= 1 contact element of a");
        const double ratio = m.size() >= 2 ? m[m.size() - 1].pressure_error /
                                               m[m.size() - 2].pressure_error :
                                             1.;
        checks.emplace_back(ratio < 0.6,
                            "Hertz, " + pairs[k].name +
                              ": the pressure's L2 error falls under halving "
                              "by a factor " +
                              format("%.2f", ratio) + " < 0.6");
        checks.emplace_back(P_error <= 1e-8 && balance <= 1e-10,
                            "Hertz, " + pairs[k].name +
                              ": the contact force is the load P (to 1e-8), "
                              "the bodies' forces equal and opposite (to "
                              "1e-10)");
      }
  }


  // @sect4{Cattaneo, Mindlin and Deresiewicz between the cylinders}
  //
  // The scene as step-11.prm gives it: pressed by the clamp, then sheared
  // back and forth. Its turning points are the steps at +Q* and -Q*; the
  // cycle runs from the first to the third. This stage solves it, predicts
  // each step by Masing's rule for the scene's pair, and reports the state
  // the pressing left.
  void
  TwoBodies::solve_shear_cycle()
  {
    cycle.run   = solve(scene, scene, "cycle");
    cycle.clamp = scene.boundary.displacements.begin()->first;
    cycle.turns = turning_points(cycle);
    tutorial::require(cycle.turns.size() >= 3,
                      "step-11 needs a path that shears the clamp to one "
                      "side, back to the other and to the first again.");
    cycle.sign =
      cycle.run.steps[cycle.turns[0]].reactions.on_id.at(cycle.clamp)[0] >= 0. ?
        1. :
        -1.;
    const CylinderPair &pair = pairs[0];
    predicted                = mindlin_deresiewicz(cycle, pair, F);

    // The first step that shears, and the state the pressing left.
    while (first_shear < cycle.run.steps.size() &&
           cycle.delta(first_shear) == cycle.delta(first_shear - 1))
      ++first_shear;
    P_pressed                            = cycle.P(0);
    const std::vector<SlaveNode> pressed = read_slave(step_file(cycle.run, 0));
    for (const SlaveNode &n : pressed)
      most_l2 = std::max(most_l2, std::abs(n.l2));
    h          = contact_element(pressed, pair.a(P_pressed));
    p0_pressed = pair.p0(P_pressed);
    pcout << "Cattaneo, Mindlin and Deresiewicz between the cylinders: "
             "Coulomb F = "
          << F << ", " << cycle.run.cycles.back().mesh.n_dofs << " DoFs, "
          << cycle.run.steps.size() << " steps"
          << (timing ? format(" (%.1f s)", cycle.run.time) : "") << "\n"
          << "  pressed (step 1): P = " << format("%.5f", P_pressed)
          << ", a = " << format("%.5f", pair.a(P_pressed))
          << ", p0 = " << format("%.4f", p0_pressed)
          << ", contact element h_C = " << format("%.5f", h) << "; "
          << cycle.run.steps[0].solve.n_stick << " stick, "
          << cycle.run.steps[0].solve.n_slip << " slip, max |l2| / (F p0) = "
          << format("%.1e", most_l2 / (F * p0_pressed)) << "\n";
  }


  // One row per step of the shear: the clamp's delta, Q/(F P), the stick
  // and slip nodes, the stick half-width (half the extent of the sticking
  // nodes) against Masing's rule, in contact elements, and the RMS of the
  // traction's difference from the rule's over |x| < a, weighted with the
  // m_s, relative to F p0.
  void
  TwoBodies::compare_shear_with_masing()
  {
    const std::string branch_name[3] = {"loading", "unloading", "reloading"};
    pcout << "  step      t     delta  branch     Q/(F P)  stick  slip  "
             "stick c   formula  (c - c_f)/h_C  RMS(q - q_f)/(F p0)\n";
    for (unsigned int n = first_shear; n < cycle.run.steps.size(); ++n)
      {
        const CycleResult           &r = cycle.run.steps[n];
        const Prediction            &p = predicted[n];
        const std::vector<SlaveNode> nodes =
          read_slave(step_file(cycle.run, n));
        double sum = 0., measure = 0.;
        for (const SlaveNode &node : nodes)
          if (std::abs(node.x) < p.a)
            {
              const double e = cycle.sign * node.l2 - p.traction(node.x, F);
              sum += node.weight * e * e;
              measure += node.weight;
            }
        const double rms = std::sqrt(sum / measure) / (F * p.p0);
        const double off = (r.zone.stick_half_width - p.c) / h;
        worst_zone       = std::max(worst_zone, std::abs(off));
        worst_rms        = std::max(worst_rms, rms);
        std::string branch =
          branch_name[p.turns_before == 0 ? 0 : 2 - p.turns_before % 2];
        branch.resize(9, ' ');
        pcout << format("%6.0f", n + 1.) << format("%7g", r.step.time)
              << format("%10.5f", cycle.delta(n)) << "  " << branch
              << format("%+9.3f", cycle.Q(n) / (F * cycle.P(n)))
              << format("%7.0f", double(r.solve.n_stick))
              << format("%6.0f", double(r.solve.n_slip))
              << format("%9.5f", r.zone.stick_half_width)
              << format("%10.5f", p.c) << format("%+15.2f", off)
              << format("%19.2f %%", 100. * rms) << "\n";
      }
  }


  // The energy of the cycle Q* -> -Q* -> Q*, from the first turning point
  // to the third: as friction dissipated it (the sum of sum_s m_s l2_s .
  // (slip of the step) over its steps, records.h), as the clamp's work
  // (the loop's area), and W_2D for the P and Q* of the first turning
  // point. With it the contact force along the cycle, and the checks of
  // Cattaneo's part.
  void
  TwoBodies::balance_cycle_energy()
  {
    const std::vector<unsigned int> &turns    = cycle.turns;
    const CylinderPair              &pair     = pairs[0];
    double                           P_change = 0.;
    for (unsigned int n = 0; n < cycle.run.steps.size(); ++n)
      P_change = std::max(P_change, std::abs(cycle.P(n) / P_pressed - 1.));

    const unsigned int t0 = turns[0], t2 = turns[2];
    const double       dissipated = cycle.run.steps[t2].step.dissipation_total -
                              cycle.run.steps[t0].step.dissipation_total;
    const double work = clamp_work(cycle, t0, t2);
    const double W_2D = cycle_energy(
      F, predicted[t0].p0, predicted[t0].a, predicted[t0].c, pair.E_star());
    pcout << "  the cycle from step " << t0 + 1
          << " (Q*/(F P) = " << format("%.4f", cycle.Q(t0) / (F * cycle.P(t0)))
          << ") to step " << t2 + 1 << ": dissipated "
          << format("%.4e", dissipated) << ", the clamp's work "
          << format("%.4e", work) << " ("
          << format("%+.2f %%", 100. * (work / dissipated - 1.)) << "), W_2D "
          << format("%.4e", W_2D) << " (dissipated "
          << format("%+.2f %%", 100. * (dissipated / W_2D - 1.)) << ")\n";
    pcout << "  the contact force stays within "
          << (P_change <= 1e-6 ? std::string("1e-6") : format("%.1e", P_change))
          << " of its value after the pressing at every step\n";

    checks.emplace_back(cycle.run.steps[0].solve.n_slip == 0 &&
                          most_l2 <= 0.01 * F * p0_pressed,
                        "Cattaneo: the pressing makes no node slip, and "
                        "leaves |l2| <= 1 % of F p0: beta = 0");
    checks.emplace_back(P_change <= 1e-6,
                        "Cattaneo: the shear leaves the contact force as it "
                        "was (to 1e-6): beta = 0");
    checks.emplace_back(worst_zone <= 1.,
                        "Cattaneo: every shear step's stick zone within " +
                          format("%.2f", worst_zone) +
                          " <= 1 contact element of Masing's rule");
    checks.emplace_back(worst_rms <= 0.07,
                        "Cattaneo: every shear step's traction within " +
                          format("%.1f", 100. * worst_rms) +
                          " % <= 7 % of F p0 of Masing's rule (RMS)");
    checks.emplace_back(std::abs(work / dissipated - 1.) <= 0.02 &&
                          std::abs(dissipated / W_2D - 1.) <= 0.05,
                        "Cattaneo: the cycle dissipates the clamp's work (to "
                        "2 %) and W_2D (to 5 %)");
  }


  // @sect4{The figures' data}
  //
  // plot.gp reads the library's CSV files and output/figures.gp: the
  // files of the runs (patchKC: coupling K, mesh C; the master forces
  // above), Hertz's a and p0 of each pair on its last mesh,
  // and for three states of the cycle (+Q*, the step nearest Q = 0 after
  // it, -Q*) the file, a, p0, Q/(F P) and the predicted traction in units
  // of F p0 along u = x/a, written with qd(u, d/a) of plot.gp.
  void
  TwoBodies::write_figure_data() const
  {
    const std::vector<unsigned int> &turns    = cycle.turns;
    unsigned int                     unloaded = turns[0];
    for (unsigned int n = turns[0]; n <= turns[1]; ++n)
      if (std::abs(cycle.Q(n)) < std::abs(cycle.Q(unloaded)))
        unloaded = n;
    if (root)
      {
        std::ofstream gp(scene.output.directory + "/figures.gp");
        gp << "F = " << F << "\nsign = " << cycle.sign << "\nforces = '"
           << scene.output.directory << "/master_forces.csv'\n";
        for (unsigned int k = 0; k < 2; ++k)
          for (unsigned int c = 0; c < patch[k].cycles.size(); ++c)
            gp << "patch" << k << c << " = '" << mesh_file(patch[k], c)
               << "'\n";
        for (unsigned int k = 0; k < pairs.size(); ++k)
          gp << "hertz" << k << " = '"
             << mesh_file(hertz[k], hertz[k].cycles.size() - 1) << "'\nha" << k
             << " = " << hertz_meshes[k].back().a << "\nhp" << k << " = "
             << hertz_meshes[k].back().p0 << "\nhname" << k << " = '"
             << pairs[k].name << "'\n";
        const unsigned int states[3] = {turns[0], unloaded, turns[1]};
        for (unsigned int i = 0; i < 3; ++i)
          {
            const unsigned int n = states[i];
            const Prediction  &p = predicted[n];
            gp << "file" << i + 1 << " = '" << step_file(cycle.run, n) << "'\nt"
               << i + 1 << " = " << cycle.run.steps[n].step.time << "\nQ"
               << i + 1 << " = " << cycle.Q(n) / (F * cycle.P(n)) << "\na"
               << i + 1 << " = " << p.a << "\np0" << i + 1 << " = " << p.p0
               << "\nmd" << i + 1 << "(u) = 0";
            for (const auto &[k, d] : p.terms)
              gp << " + (" << k << ") * qd(u, " << d / p.a << ")";
            gp << "\n";
          }
      }
  }


  // @sect4{The checks}
  //
  // What the README claims, on the step's own numbers; the README's table
  // "The checks" gives each bound's reason.
  tutorial::Checks
  TwoBodies::report_checks() const
  {
    pcout << "\nChecks:\n";
    tutorial::Checks result;
    for (const auto &[ok, what] : checks)
      result(ok, what);
    return result;
  }


  // The step as run_tutorial() calls it: the program on the scene.
  tutorial::Checks
  run(const Parameters &scene)
  {
    return TwoBodies(scene).run();
  }
} // namespace Step11

// @sect3{The main function}
//
// MPI, the parameter file (default step-11.prm) and, after it, overrides
// as the dualcontact program takes them (`--set "Refinement/Number of
// cycles=2"`), for the experiments of README.md; one message and a
// non-zero exit status on any error or failed check.
int
main(int argc, char *argv[])
{
  return dualcontact::tutorial::run_tutorial(
    argc, argv, "step-11", "step-11.prm", Step11::run);
}
