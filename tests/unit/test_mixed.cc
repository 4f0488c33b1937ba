// The mixed displacement-pressure formulation (<Material/Formulation> =
// mixed, doc/mixed.md): patch tests of an incompressible block (nu = 1/2)
// on a rigid plane, whose exact state Taylor-Hood reproduces: every
// contact node carries the applied pressure, and the displacement and the
// pressure field are exact, and so are the pressure and the stress that
// the probes read and the contact refinement indicator takes. Every
// assertion is on a value reduced over all ranks.

#include <deal.II/base/mpi.h>

#include <dualcontact/contact_problem.h>
#include <dualcontact/refinement_indicator.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <string>

#include "scene_run.h"
#include "test_tools.h"

using namespace dualcontact;
using namespace dualcontact_test;

namespace
{
  /** nu = 1/2 in the mixed formulation at degree 2, on `cells`. */
  std::string
  incompressible(const std::string &cells)
  {
    return "subsection Material\n  set Poisson's ratio = 0.5\n"
           "  set Formulation = mixed\nend\n"
           "subsection Discretization\n  set Polynomial degree = 2\nend\n"
           "subsection Geometry\n  set Cell type = " +
           cells + "\nend\n";
  }

  /**
   * The largest |p_i - p| over the pressure DoFs, over |p|; and the
   * solution's distance from the incompressibility constraint.
   */
  template <int dim>
  double
  pressure_deviation(const SceneRun<dim> &run, const double p)
  {
    const MixedBulk<dim> *mixed = run.problem->mixed_bulk();
    REQUIRE(mixed != nullptr);
    TrilinosWrappers::MPI::Vector difference(mixed->pressure);
    difference.add(-p);
    const TrilinosWrappers::MPI::Vector &ghosted = run.problem->displacement();
    TrilinosWrappers::MPI::Vector u(ghosted.locally_owned_elements(), run.comm);
    u = ghosted;
    CHECK(mixed->infeasibility(u) <= 1e-10);
    return difference.linfty_norm() / std::abs(p);
  }

  // E = 1000, nu = 1/2: mu = E/3; the applied pressure P = 1 and shear
  // tau = 0.2 (0.1 along y in 3D)
  constexpr double mu = 1000. / 3.;

  // the largest value of the 'contact' indicator on an owned cell, as
  // 'contact, recorded' (below) computed it last
  double largest_contact_indicator = 0.;

  template <int dim>
  Vector<float>
  recorded_contact_indicator(const IndicatorInput<dim> &input)
  {
    const Vector<float> eta =
      refinement_indicator_kind("contact").indicator_2d(input);
    largest_contact_indicator = 0.;
    for (const auto &cell : input.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        largest_contact_indicator =
          std::max<double>(largest_contact_indicator,
                           eta[cell->active_cell_index()]);
    return eta;
  }

  const bool registered_recorded_contact = register_refinement_indicator(
    "contact, recorded",
    {"'contact', its largest value kept for the tests.",
     nullptr,
     {},
     recorded_contact_indicator<2>,
     nullptr});
} // namespace

TEST_CASE("Incompressible patch, frictionless, in plane strain: uniaxial "
          "compression on quadrilaterals and triangles, l1 = P at every "
          "node, u and p exact",
          "[mixed]")
{
  // sigma_yy = -P, sigma_xx = 0, sigma_zz = nu sigma_yy: eps_xx = -eps_yy
  // = (1 - nu^2) P / E = 0.75e-3, p = -tr(sigma)/3 = P/2
  for (const std::string cells : {"quadrilateral", "simplex"})
    {
      const SceneRun<2> run(
        "patch.prm",
        incompressible(cells) +
          "subsection Solver\n  set Uzawa tolerance = 1e-11\nend\n"
          "subsection Exact solution\n  set Displacement = 0.00075 * x; "
          "-0.00075 * y\n  set Contact pressure = 1\nend\n");
      const CycleResult &r = run.last();
      const auto [l1, l2]  = deviation(run, 1., Tensor<1, 2>());
      const double p_error = pressure_deviation(run, 0.5);
      INFO(cells << ": " << r.solve.n_contact_nodes
                 << " contact nodes, |l1 - P| " << l1
                 << ", |u - u_exact| / |u| "
                 << r.errors.error_L2 / r.errors.norm_L2 << ", |p - P/2| / P/2 "
                 << p_error);
      CHECK(r.solve.n_active == r.solve.n_contact_nodes);
      CHECK(l1 <= 1e-8);
      CHECK(r.errors.error_L2 <= 1e-10 * r.errors.norm_L2);
      CHECK(p_error <= 1e-10);
      CHECK(r.zone.contact_force == Approx(2.).epsilon(1e-10));
    }
}

TEST_CASE("Incompressible patch, all stick, in plane strain: a hydrostatic "
          "pressure and a shear below F P on quadrilaterals and triangles, "
          "l1 = P, l2 = tau, u and p exact",
          "[mixed]")
{
  // sigma = -P I + tau (e_x e_y + e_y e_x): dev sigma is the shear alone,
  // u = (tau / mu) y e_x, p = P; the sides carry sigma n
  for (const std::string cells : {"quadrilateral", "simplex"})
    {
      const SceneRun<2> run(
        "patch.prm",
        incompressible(cells) +
          "subsection Boundary conditions\n  set Conditions = 0: traction, "
          "1: traction, 2: contact, 3: traction\n  set Tractions = 0: 1; "
          "-0.2, 1: -1; 0.2, 3: 0.2; -1\nend\n"
          "subsection Friction\n  set Law = coulomb\n  set Coefficient = "
          "0.4\nend\n"
          "subsection Solver\n  set Uzawa tolerance = 1e-11\nend\n"
          "subsection Exact solution\n  set Displacement = " +
          std::to_string(0.2 / mu) +
          " * y; 0\n  set Contact pressure = 1\nend\n");
      const CycleResult &r = run.last();
      Tensor<1, 2>       tau;
      tau[0]               = 0.2;
      const auto [l1, l2]  = deviation(run, 1., tau);
      const double p_error = pressure_deviation(run, 1.);
      INFO(cells << ": |l1 - P| " << l1 << ", |l2 - tau| " << l2
                 << ", |u - u_exact| / |u| "
                 << r.errors.error_L2 / r.errors.norm_L2 << ", |p - P| / P "
                 << p_error);
      CHECK(r.solve.n_stick == r.solve.n_contact_nodes);
      CHECK(l1 <= 1e-8);
      CHECK(l2 <= 1e-8);
      CHECK(r.errors.error_L2 <= 1e-10 * r.errors.norm_L2);
      CHECK(p_error <= 1e-10);
    }
}

TEST_CASE("Incompressible patch in 3D on hexahedra: uniaxial and "
          "frictionless, and all stick under a hydrostatic pressure and a "
          "shear",
          "[mixed]")
{
  SECTION("uniaxial compression, frictionless, on two sliders")
  {
    // sigma_zz = -P: eps_xx = eps_yy = nu P / E, eps_zz = -P / E, p = P/3
    const SceneRun<3>  run("patch_3d.prm",
                          incompressible("quadrilateral") +
                            "subsection Boundary conditions\n  set Conditions "
                             "= 0: normal fixed, 1: traction, 2: normal "
                             "fixed, 3: traction, 4: contact, 5: "
                             "traction\n  set Tractions = 1: 0; 0; 0, 3: 0; 0; "
                             "0, 5: 0; 0; -1\nend\n"
                             "subsection Friction\n  set Law = none\nend\n"
                             "subsection Solver\n  set Uzawa tolerance = "
                             "1e-11\nend\n"
                             "subsection Exact solution\n  set Displacement = "
                             "0.0005 * x; 0.0005 * y; -0.001 * z\nend\n");
    const CycleResult &r = run.last();
    const auto [l1, l2]  = deviation(run, 1., Tensor<1, 3>());
    const double p_error = pressure_deviation(run, 1. / 3.);
    INFO("|l1 - P| " << l1 << ", |u - u_exact| / |u| "
                     << r.errors.error_L2 / r.errors.norm_L2 << ", |p - P/3| / "
                     << "P/3 " << p_error);
    CHECK(r.solve.n_active == r.solve.n_contact_nodes);
    CHECK(l1 <= 1e-8);
    CHECK(r.errors.error_L2 <= 1e-10 * r.errors.norm_L2);
    CHECK(p_error <= 1e-10);
    CHECK(r.zone.contact_force == Approx(4.).epsilon(1e-10));
  }
  SECTION("all stick")
  {
    const SceneRun<3> run(
      "patch_3d.prm",
      incompressible("quadrilateral") +
        "subsection Boundary conditions\n  set Tractions = 0: 1; 0; -0.2, "
        "1: -1; 0; 0.2, 2: 0; 1; -0.1, 3: 0; -1; 0.1, 5: 0.2; 0.1; "
        "-1\nend\n"
        "subsection Solver\n  set Uzawa tolerance = 1e-11\nend\n"
        "subsection Exact solution\n  set Displacement = " +
        std::to_string(0.2 / mu) + " * z; " + std::to_string(0.1 / mu) +
        " * z; 0\nend\n");
    const CycleResult &r = run.last();
    Tensor<1, 3>       tau;
    tau[0]               = 0.2;
    tau[1]               = 0.1;
    const auto [l1, l2]  = deviation(run, 1., tau);
    const double p_error = pressure_deviation(run, 1.);
    INFO("|l1 - P| " << l1 << ", |l2 - tau| " << l2 << ", |u - u_exact| / |u| "
                     << r.errors.error_L2 / r.errors.norm_L2 << ", |p - P| / P "
                     << p_error);
    CHECK(r.solve.n_stick == r.solve.n_contact_nodes);
    CHECK(l1 <= 1e-8);
    CHECK(l2 <= 1e-8);
    CHECK(r.errors.error_L2 <= 1e-10 * r.errors.norm_L2);
    CHECK(p_error <= 1e-10);
  }
}

TEST_CASE("Hertz at nu = 1/2 (prm/hertz_incompressible.prm): Q2/Q1 gives "
          "the peak pressure and the half-width within 1 %, the load "
          "balanced",
          "[mixed]")
{
  const SceneRun<2>  run("hertz_incompressible.prm",
                        "subsection Refinement\n  set Number of cycles = "
                         "1\nend\n");
  const CycleResult &r = run.last();
  INFO("peak " << r.zone.peak_pressure_error << ", half-width "
               << r.zone.half_width_error << ", pressure L2 "
               << r.zone.pressure_error << ", " << r.mesh.n_dofs << " DoFs, "
               << r.solve.cg_iterations << " MINRES over "
               << r.solve.newton_steps << " Newton steps");
  CHECK(std::abs(r.zone.peak_pressure_error) <= 0.01);
  CHECK(std::abs(r.zone.half_width_error) <= 0.01);
  CHECK(r.zone.pressure_error <= 0.01);
  CHECK(r.zone.contact_force == Approx(8.630749048323608).epsilon(1e-8));
}

TEST_CASE("Probes in the mixed formulation read the pressure field: in the "
          "incompressible patch under uniaxial compression they find p = "
          "P/2 and the stress 2 mu dev eps - p I exactly, on quadrilaterals "
          "and triangles, and probes.csv has the column pressure",
          "[mixed][probes]")
{
  // the first patch test's state: sigma_yy = -P, sigma_xx = sigma_xy = 0,
  // sigma_zz = -p = -P/2, von Mises sqrt(3)/2 P. The points lie inside, on
  // corners and on faces between cells (probably between ranks).
  const std::string points = "0.5, 0.5; 2, 1; 1.3, 0.2; 0, 0; 1, 0.25";
  for (const std::string cells : {"quadrilateral", "simplex"})
    {
      const SceneRun<2> run(
        "patch.prm",
        incompressible(cells) +
          "subsection Solver\n  set Uzawa tolerance = 1e-11\nend\n"
          "subsection Output\n  set Probe points = " +
          points + "\nend\n");
      const auto &values = run.problem->get_probes().values();
      REQUIRE(Utilities::MPI::min(values.size(), run.comm) ==
              5 * run.problem->results().size());
      double p_error = 0., stress_error = 0.;
      for (const auto &v : values)
        {
          p_error      = std::max(p_error, std::abs(v.pressure - 0.5));
          stress_error = std::max({stress_error,
                                   std::abs(v.stress[0][0]),
                                   std::abs(v.stress[1][1] + 1.),
                                   std::abs(v.stress[0][1]),
                                   std::abs(v.stress_zz + 0.5),
                                   std::abs(v.von_mises - std::sqrt(0.75))});
        }
      // (P = 1: the errors are relative)
      p_error      = Utilities::MPI::max(p_error, run.comm);
      stress_error = Utilities::MPI::max(stress_error, run.comm);
      INFO(cells << ": |p - P/2| " << p_error << ", |sigma - sigma_exact| "
                 << stress_error);
      CHECK(p_error <= 1e-10);
      CHECK(stress_error <= 1e-10);

      // the file: the columns of displacements, then pressure
      std::string text;
      if (Utilities::MPI::this_mpi_process(run.comm) == 0)
        text = read_text(run.directory + "/probes.csv");
      text = Utilities::MPI::broadcast(run.comm, text, 0);
      std::istringstream lines(text);
      std::string        line;
      std::getline(lines, line);
      CHECK(line == "cycle,probe,x,y,u_x,u_y,sigma_xx,sigma_yy,sigma_zz,"
                    "sigma_xy,von_mises,pressure");
      unsigned int n_rows = 0;
      for (; std::getline(lines, line); ++n_rows)
        CHECK(std::abs(std::stod(line.substr(line.rfind(',') + 1)) - 0.5) <=
              1e-10);
      CHECK(n_rows == values.size());
    }
}

TEST_CASE("The contact refinement indicator takes the pressure field: in the "
          "incompressible patch under uniaxial compression sigma(u_h) n = "
          "-P n on Gamma_C, and the indicator vanishes",
          "[mixed][refinement]")
{
  // Kelly's jumps vanish in a uniform state, and the residual on Gamma_C,
  // 2 mu dev eps(u_h) n - p_h n + l1 n, too; without -p n it would be P/2
  // there, an indicator of about h P / (2 E) = 1e-4 on the cells at the
  // plane. (Quadrilaterals: deal.II 9.4 refines meshes of triangles
  // globally only.)
  largest_contact_indicator = 1.;
  const SceneRun<2> run(
    "patch.prm",
    incompressible("quadrilateral") +
      "subsection Solver\n  set Uzawa tolerance = 1e-11\nend\n"
      "subsection Refinement\n  set Strategy = contact, recorded\nend\n");
  const double largest =
    Utilities::MPI::max(largest_contact_indicator, run.comm);
  INFO("largest indicator " << largest);
  CHECK(largest <= 1e-10);
}
