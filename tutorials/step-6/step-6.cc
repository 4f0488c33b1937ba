/* step-6: your own geometry.
 *
 * Steps 1-4 ran on the library's built-in shapes against a rigid plane. A
 * problem of your own has its own body, drawn in a mesh generator, and its
 * own obstacle. This step reads a body drawn in Gmsh (half_space.geo), with
 * its boundary parts named by physical groups, keeps its curved boundary
 * curved under refinement, presses a rigid cylinder into it by a prescribed
 * depth, and then reads back what a user plots: the force on the obstacle,
 * the contact pressure along Gamma_C from contact_NN.csv, and the stresses at
 * probe points beneath the contact. Each is compared with its exact value,
 * Hertz's pressure and McEwen's subsurface stresses. Everything about the
 * problem is in step-6.prm; the program around the library only looks at
 * the mesh before the solve and at the results after it. The theory is
 * doc/theory.md §9-10, the mesh files doc/meshes.md; README.md has the
 * introduction and the results.
 */

// @sect3{Include files}
//
// Besides the Problem class, the functions that read a Gmsh file and attach
// manifolds to its curved boundary parts (mesh_file.h): the library calls
// them in make_grid(); this step calls them itself to look at the mesh.
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <deal.II/grid/tria.h>

#include <dualcontact/contact_problem.h>
#include <dualcontact/mesh_file.h>
#include <dualcontact/parameters.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "../common/csv_table.h"
#include "../common/tutorial_tools.h"

namespace Step6
{
  using namespace dealii;
  using namespace dualcontact;

  using tutorial::format;
  using tutorial::Hertz;

  // @sect3{The mesh, before anything is solved}
  //
  // A physical group of curves in the .geo file becomes a boundary id: the
  // number in `Physical Curve(n)` is the id that <Boundary conditions/
  // Conditions> uses. The first thing to check in a mesh of your own is that
  // the ids are the parts you meant, so the step lists them with the number
  // of faces and the length of each.
  std::map<types::boundary_id, std::pair<unsigned int, double>>
  boundary_parts(const Triangulation<2> &mesh)
  {
    std::map<types::boundary_id, std::pair<unsigned int, double>> parts;
    for (const auto &cell : mesh.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            ++parts[face->boundary_id()].first;
            parts[face->boundary_id()].second += face->measure();
          }
    return parts;
  }

  // Without a manifold, refinement puts the new vertex of a boundary face
  // at the middle of the straight face: a read-in arc stays the polygon of
  // the coarse mesh, however fine the mesh gets. <Geometry/Manifolds> puts
  // the faces of an id on a circle (deal.II's SphericalManifold), and the
  // cells beside it on a transfinite interpolation of their boundary, so
  // that new vertices land on the arc. The step refines two copies of the
  // coarse mesh, one with the manifolds of the scene and one without, and
  // compares the length of each curved part with the arc's: each coarse
  // face of chord c on a circle of radius R spans the arc 2 R asin(c/2R).
  struct ArcLengths
  {
    double       exact            = 0.;
    double       without_manifold = 0., with_manifold = 0.;
    unsigned int faces = 0;
  };

  std::vector<ArcLengths>
  describe_mesh(ConditionalOStream &pcout,
                const Parameters   &parameters,
                const unsigned int  n_refinements)
  {
    const GeometryParameters &geometry = parameters.geometry;
    Triangulation<2>          flat, curved;
    read_mesh_file(geometry, flat);
    read_mesh_file(geometry, curved);
    attach_manifolds(geometry, curved);

    pcout << "The mesh "
          << std::filesystem::path(geometry.mesh_file).filename().string()
          << ": " << flat.n_active_cells() << " cells, " << flat.n_vertices()
          << " vertices; its boundary parts (physical curves):\n";
    for (const auto &[id, part] : boundary_parts(flat))
      pcout << "  id " << static_cast<unsigned int>(id) << ": " << std::setw(2)
            << part.first << " faces, length " << format("%.5f", part.second)
            << "\n";

    // (a scene without a circle in <Geometry/Manifolds>: no arc to follow)
    if (geometry.manifolds.empty() ||
        geometry.manifolds[0].kind != BoundaryManifold::Kind::circle)
      return {};
    const BoundaryManifold &circle = geometry.manifolds[0];
    double                  exact  = 0.;
    for (const auto &cell : flat.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && face->boundary_id() == circle.id)
          exact += 2. * circle.radius *
                   std::asin(face->measure() / (2. * circle.radius));

    pcout << "\nThe length of id " << static_cast<unsigned int>(circle.id)
          << " under global refinement (the arc: " << format("%.5f", exact)
          << "):\n"
          << "refinements  faces  without manifold    error  with manifold"
             "      error\n";
    std::vector<ArcLengths> lengths;
    for (unsigned int k = 0; k <= n_refinements; ++k)
      {
        if (k > 0)
          {
            flat.refine_global(1);
            curved.refine_global(1);
          }
        ArcLengths l;
        l.exact            = exact;
        l.faces            = boundary_parts(flat)[circle.id].first;
        l.without_manifold = boundary_parts(flat)[circle.id].second;
        l.with_manifold    = boundary_parts(curved)[circle.id].second;
        lengths.push_back(l);
        pcout << std::setw(11) << k << std::setw(7) << l.faces
              << format("%18.5f", l.without_manifold)
              << format("%10.1e", l.without_manifold / exact - 1.)
              << format("%15.5f", l.with_manifold)
              << format("%11.1e", l.with_manifold / exact - 1.) << "\n";
      }
    return lengths;
  }

  // @sect3{The exact solutions}
  //
  // A rigid cylinder of radius R pressed into an elastic half-plane by a
  // force P per unit thickness (plane strain, E* = E / (1 - nu^2)) touches
  // it on |x| < a (Hertz; doc/theory.md §9):
  //   a = sqrt(4 P R / (pi E*)),   p0 = 2 P / (pi a),
  //   p(x) = p0 sqrt(1 - x^2 / a^2).
  // Pressed by a depth instead, the force it takes depends on the size and
  // the support of the body (there is no half-plane value in 2D), so the step
  // measures P, the force on the obstacle, and asks whether the contact zone
  // and the pressure are Hertz's for that P.
  //
  // Beneath the centre of the contact, at depth z, the stresses of the Hertz
  // pressure in the half-plane are McEwen's (1949):
  //   sigma_yy = -p0 a / sqrt(a^2 + z^2),
  //   sigma_xx = -p0 ((a^2 + 2 z^2) / (a sqrt(a^2 + z^2)) - 2 z / a),
  //   sigma_zz = nu (sigma_xx + sigma_yy)   (plane strain),
  // and the largest shear stress in the plane, tau = (sigma_xx - sigma_yy)/2,
  // peaks at 0.300 p0 at z = 0.786 a, below the surface: where yielding
  // starts in a ductile material, and what a probe is for.
  // tutorial::Hertz (tutorials/common/tutorial_tools.h) has these formulas,
  // with R the obstacle's radius and the material of the scene.

  // The force on the obstacle: the contact force on the body, reversed
  // (cycles.csv: obstacle_force_x, obstacle_force_y). Its y component is P.
  double
  obstacle_force_y(const CycleResult &r)
  {
    return -r.zone.resultant[1];
  }

  // @sect3{Reading contact_NN.csv}
  //
  // The library writes, per cycle, one row per contact node, ordered along
  // Gamma_C: s (the position along the boundary: s = x . t with the mean
  // tangent t, which here points to -x), x, y, the weight m_s,
  // the pressure l1, the gap after the solve, the obstacle's normal, the
  // status. That file is what a user plots (contrib/plot_pressure.sh); the
  // step reads it the way a user's script would, by column name.
  struct ContactRow
  {
    double      s, x, weight, l1;
    std::string status;
  };

  std::vector<ContactRow>
  read_contact_csv(const std::string &filename)
  {
    const tutorial::CsvTable table(filename);
    std::vector<ContactRow>  rows;
    for (unsigned int i = 0; i < table.n_rows(); ++i)
      rows.push_back({table.number(i, "s"),
                      table.number(i, "x"),
                      table.number(i, "weight"),
                      table.number(i, "l1"),
                      table.text(i, "status")});
    return rows;
  }

  // @sect3{The pressure along Gamma_C against Hertz}
  //
  // Two measures of the computed pressure l1 against Hertz's p(x) for the
  // measured force: the largest nodal difference, relative to p0, and the
  // relative L2 error on Gamma_C with the nodal weights m_s (the same
  // quadrature as the contact force sum_s m_s l1_s). The rows, with p(x),
  // go to pressure.csv for plot.gp.
  struct PressureFigures
  {
    double       max_difference = 0., l2_error = 0.;
    unsigned int n_rows = 0, n_in_contact = 0;
    bool         ordered = true;
  };

  PressureFigures
  compare_pressure(const std::vector<ContactRow> &rows,
                   const Hertz                   &hertz,
                   const std::string             &output_file,
                   const bool                     write)
  {
    PressureFigures f;
    double          difference2 = 0., exact2 = 0.;
    std::ofstream   out;
    if (write)
      {
        out.open(output_file);
        out << "x,l1,hertz\n";
      }
    for (unsigned int i = 0; i < rows.size(); ++i)
      {
        const ContactRow &r     = rows[i];
        const double      exact = hertz.pressure(r.x);
        f.max_difference =
          std::max(f.max_difference, std::abs(r.l1 - exact) / hertz.p0);
        difference2 += r.weight * (r.l1 - exact) * (r.l1 - exact);
        exact2 += r.weight * exact * exact;
        f.n_in_contact += (r.status != "separated");
        if (i > 0 && r.s < rows[i - 1].s)
          f.ordered = false;
        if (write)
          out << r.x << ',' << r.l1 << ',' << exact << '\n';
      }
    f.n_rows   = rows.size();
    f.l2_error = std::sqrt(difference2 / exact2);
    return f;
  }

  // @sect3{The probes beneath the contact against McEwen}
  //
  // <Output/Probe points> lists points of the body; the library finds the
  // cell of each (on whichever rank owns it) and writes the displacement and
  // the stress there, every cycle, to probes.csv. The same values are in
  // memory as Probes::values(), on every rank. The step takes the last
  // cycle's, on the axis x = 0, and compares each stress with McEwen's for
  // the measured force, in units of p0; the rows go to axis.csv.
  struct ProbeFigures
  {
    double worst    = 0.; // max |sigma - sigma_McEwen| / p0
    double tau_max  = 0.; // the largest tau of the probes / p0
    double tau_peak = 0.; // McEwen's largest tau at the same depths / p0
  };

  ProbeFigures
  compare_probes(ConditionalOStream &pcout,
                 const Probes<2>    &probes,
                 const unsigned int  cycle,
                 const Hertz        &hertz,
                 const double        nu,
                 const std::string  &output_file,
                 const bool          write)
  {
    ProbeFigures  f;
    std::ofstream out;
    if (write)
      {
        out.open(output_file);
        out << "z,z_over_a,sigma_xx,sigma_yy,sigma_zz,tau,"
               "mcewen_xx,mcewen_yy,mcewen_zz,mcewen_tau\n";
      }
    pcout << "\nStresses on the axis beneath the contact, in units of p0 "
             "(probes; McEwen in brackets):\n"
          << "    z/a       sigma_xx            sigma_yy            sigma_zz"
             "             tau\n";
    for (const Probes<2>::Value &v : probes.values())
      {
        if (v.cycle != cycle)
          continue;
        AssertThrow(std::abs(v.point[0]) < 1e-12,
                    ExcMessage("step-6 expects its probes on the axis x = 0"));
        const double z         = -v.point[1];
        const double p0        = hertz.p0;
        const double exact[4]  = {hertz.sigma_xx(z),
                                  hertz.sigma_yy(z),
                                  nu * (hertz.sigma_xx(z) + hertz.sigma_yy(z)),
                                  (hertz.sigma_xx(z) - hertz.sigma_yy(z)) / 2};
        const double probed[4] = {v.stress[0][0],
                                  v.stress[1][1],
                                  v.stress_zz,
                                  (v.stress[0][0] - v.stress[1][1]) / 2};
        std::string  line      = format("%7.2f", z / hertz.a);
        for (unsigned int i = 0; i < 4; ++i)
          {
            line += format("   %+.4f", probed[i] / p0) +
                    format(" (%+.4f)", exact[i] / p0);
            f.worst = std::max(f.worst, std::abs(probed[i] - exact[i]) / p0);
          }
        pcout << line << "\n";
        f.tau_max  = std::max(f.tau_max, probed[3] / p0);
        f.tau_peak = std::max(f.tau_peak, exact[3] / p0);
        if (write)
          {
            out << z << ',' << z / hertz.a;
            for (const double s : probed)
              out << ',' << s;
            for (const double s : exact)
              out << ',' << s;
            out << '\n';
          }
      }
    return f;
  }

  // @sect3{The whole step}
  //
  // The program in the shape of deal.II's steps: a class whose run() reads
  // as its stages, one member function each, and members for what a later
  // stage needs of an earlier one (the arc's lengths, the solved problem,
  // the figures the checks judge).
  class CylinderObstacle
  {
  public:
    explicit CylinderObstacle(const Parameters &parameters);

    tutorial::Checks
    run();

  private:
    void
    check_scene() const;
    void
    solve_scene();
    Hertz
    hertz_for_last_cycle() const;
    void
    compare_zones() const;
    void
    compare_along_contact_boundary();
    void
    compare_beneath_contact();
    tutorial::Checks
    check_results() const;

    // The scene, the screen (rank 0 prints) and the output folder.
    const Parameters  &parameters;
    const MPI_Comm     comm;
    const bool         root;
    ConditionalOStream pcout;
    const std::string &directory;

    // The arc's lengths per refinement, the library's problem and its
    // screen output (kept for screen.log), and the figures of the pressure
    // along Gamma_C and of the probes.
    std::vector<ArcLengths>            arc;
    std::ostringstream                 log;
    std::unique_ptr<ContactProblem<2>> problem;
    PressureFigures                    pressure;
    ProbeFigures                       probes;
  };


  CylinderObstacle::CylinderObstacle(const Parameters &parameters)
      : parameters(parameters)
      , comm(MPI_COMM_WORLD)
      , root(Utilities::MPI::this_mpi_process(comm) == 0)
      , pcout(std::cout, root)
      , directory(parameters.output.directory)
  {}


  // The mesh first; then the scene, solved by the library's
  // ContactProblem::run(): cycles of setup, assembly, contact solve,
  // postprocessing and output, as in steps 1-5. Its screen output goes to
  // screen.log in the output folder; the screen shows this program's
  // tables. Then the comparisons, and the checks.
  tutorial::Checks
  CylinderObstacle::run()
  {
    check_scene();
    arc = describe_mesh(pcout, parameters, 4);
    solve_scene();
    compare_zones();
    compare_along_contact_boundary();
    compare_beneath_contact();
    return check_results();
  }


  // The comparisons of this step need a 2D mesh file pressed by a
  // cylinder without friction; anything else is refused with one message
  // before a solve.
  void
  CylinderObstacle::check_scene() const
  {
    AssertThrow(parameters.geometry.dimension == 2 &&
                  parameters.geometry.type == "mesh file" &&
                  parameters.obstacle.type == "cylinder" &&
                  parameters.friction.law == "none",
                ExcMessage("step-6 needs a 2D scene on a mesh file with a "
                           "cylinder obstacle and no friction"));
  }


  // The scene as the library solves it, every cycle; its screen output
  // goes to screen.log.
  void
  CylinderObstacle::solve_scene()
  {
    problem = std::make_unique<ContactProblem<2>>(parameters, comm, log);
    // parameters.prm in the output folder: the entries this run used
    problem->record_parameters(parameters.parameter_file);
    problem->run();
    if (root)
      std::ofstream(directory + "/screen.log") << log.str();
  }


  // Hertz for the force the last cycle measured.
  Hertz
  CylinderObstacle::hertz_for_last_cycle() const
  {
    return Hertz(parameters, obstacle_force_y(problem->results().back()));
  }


  // The contact zone of every cycle against Hertz for its force. a is
  // the half-width of the nodes in contact, their edges extrapolated to
  // where the pressure would reach zero (doc/theory.md §9).
  void
  CylinderObstacle::compare_zones() const
  {
    pcout << "\nThe contact zone against Hertz for the measured force P "
             "(relative errors):\n"
          << "cycle   DoFs  nodes          P          a    error"
             "          p0    error\n";
    for (const CycleResult &r : problem->results())
      {
        const Hertz hertz(parameters, obstacle_force_y(r));
        pcout << std::setw(5) << r.mesh.cycle << std::setw(7) << r.mesh.n_dofs
              << std::setw(7) << r.solve.n_contact_nodes
              << format("%11.5f", hertz.P)
              << format("%11.6f", r.zone.edge_half_width)
              << format("%+9.1e", r.zone.edge_half_width / hertz.a - 1.)
              << format("%12.4f", r.zone.max_pressure)
              << format("%+9.1e", r.zone.max_pressure / hertz.p0 - 1.) << "\n";
      }
    const Hertz hertz = hertz_for_last_cycle();
    pcout << "Hertz for the last cycle's P = " << format("%.5f", hertz.P)
          << ": a = " << format("%.6f", hertz.a)
          << ", p0 = " << format("%.4f", hertz.p0) << "\n";
    if (root) // for plot.gp: the exact curves
      std::ofstream(directory + "/hertz.gp")
        << "a = " << hertz.a << "\np0 = " << hertz.p0
        << "\nnu = " << parameters.material.poissons_ratio << "\n";
  }


  // The pressure at the nodes of the last cycle against Hertz's. Every
  // rank reads the file rank 0 wrote; the barrier makes sure it is
  // complete.
  void
  CylinderObstacle::compare_along_contact_boundary()
  {
    const CycleResult &last  = problem->results().back();
    const Hertz        hertz = hertz_for_last_cycle();
    MPI_Barrier(comm);
    char name[32];
    std::snprintf(name, sizeof(name), "/contact_%02u.csv", last.mesh.cycle);
    pressure = compare_pressure(read_contact_csv(directory + name),
                                hertz,
                                directory + "/pressure.csv",
                                root);
    pcout << "\nThe pressure along Gamma_C (contact" << (name + 8) << ": "
          << pressure.n_rows << " nodes, " << pressure.n_in_contact
          << " in contact):\n"
          << "  largest nodal difference from Hertz "
          << format("%.2e", pressure.max_difference)
          << " p0, relative L2 error " << format("%.2e", pressure.l2_error)
          << "\n";
  }


  // The stresses at the probes beneath the contact against McEwen's.
  void
  CylinderObstacle::compare_beneath_contact()
  {
    const CycleResult &last  = problem->results().back();
    const Hertz        hertz = hertz_for_last_cycle();
    probes                   = compare_probes(pcout,
                            problem->get_probes(),
                            last.mesh.cycle,
                            hertz,
                            parameters.material.poissons_ratio,
                            directory + "/axis.csv",
                            root);
    pcout << "  largest difference " << format("%.4f", probes.worst)
          << " p0; largest tau of the probes " << format("%.4f", probes.tau_max)
          << " p0 (McEwen at the same depths "
          << format("%.4f", probes.tau_peak) << " p0)\n";
  }


  // @sect4{The checks}
  tutorial::Checks
  CylinderObstacle::check_results() const
  {
    const CycleResult &last  = problem->results().back();
    const Hertz        hertz = hertz_for_last_cycle();
    pcout << "\nChecks:\n";
    tutorial::Checks checks;

    // 1. The manifold: with it the curved part's length converges to the
    // arc's (the error of a polygon of n chords falls as 1/n^2, by about 4
    // per refinement); without it the polygon of the coarse mesh stays.
    if (arc.empty())
      pcout << "  skipped: the arc (no circle in <Geometry/Manifolds>)\n";
    else
      checks(
        std::abs(arc.back().with_manifold / arc.back().exact - 1.) < 1e-4 &&
          std::abs(arc.back().without_manifold - arc.front().without_manifold) <
            1e-12 * arc.back().exact,
        "the arc: within 1e-4 of its length with the manifold, the "
        "coarse polygon without");

    // 2. Equilibrium: the force on the obstacle is the reaction of the
    // fixed arc (id 3), the only other support: nothing else loads the body.
    const double arc_reaction = last.reactions.on_id.at(3)[1];
    checks(std::abs(arc_reaction - hertz.P) <= 1e-8 * hertz.P &&
             std::abs(obstacle_force_y(last)) > 0.,
           "the force on the obstacle equals the reaction of the fixed arc to "
           "1e-8");

    // 3. Hertz: on the last mesh a and p0 within 1 % of Hertz's for the
    // measured force, and the pressure profile within 1 % (relative L2).
    checks(std::abs(last.zone.edge_half_width / hertz.a - 1.) < 0.01,
           "a within 1 % of Hertz's for the measured force");
    checks(std::abs(last.zone.max_pressure / hertz.p0 - 1.) < 0.01,
           "p0 within 1 % of Hertz's for the measured force");
    checks(pressure.l2_error < 0.01 && pressure.ordered,
           "contact_NN.csv: ordered along Gamma_C, and its pressure within "
           "1 % of Hertz's (relative L2)");

    // 4. The probes: every stress within 3 % of p0 of McEwen's, and the
    // largest shear of the probes within 2 % of McEwen's at the same
    // depths.
    checks(probes.worst < 0.03 &&
             std::abs(probes.tau_max / probes.tau_peak - 1.) < 0.02,
           "the probes: McEwen's stresses within 0.03 p0, the largest shear "
           "within 2 %");
    return checks;
  }


  // The step as run_tutorial() calls it: the program on the scene.
  tutorial::Checks
  run(const Parameters &parameters)
  {
    return CylinderObstacle(parameters).run();
  }
} // namespace Step6

// @sect3{The main function}
//
// MPI, the parameter file (default step-6.prm) and, after it, overrides as
// the dualcontact program takes them, `--set "Obstacle/Radius=1"`, for the
// experiments of README.md; one message and a non-zero exit status on any
// error.
int
main(int argc, char *argv[])
{
  return dualcontact::tutorial::run_tutorial(
    argc, argv, "step-6", "step-6.prm", Step6::run);
}
