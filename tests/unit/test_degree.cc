// Elements of degree k (<Discretization/Polynomial degree>): the patch tests
// are exact at every degree, in 2D and 3D, without and with friction. Every
// assertion is on a value reduced over all ranks.

#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>

#include <dualcontact/contact_problem.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>

#include "scene_run.h"
#include "test_tools.h"

using namespace dualcontact;
using namespace dualcontact_test;

namespace
{
  std::string
  degree(const unsigned int k)
  {
    return "subsection Discretization\n  set Polynomial degree = " +
           std::to_string(k) + "\nend\n";
  }

} // namespace

TEST_CASE("Patch test at degree 1, 2 and 3: every nodal pressure equals the "
          "applied pressure, every node in contact",
          "[degree]")
{
  for (const unsigned int k : {1u, 2u, 3u})
    {
      const Run          run("patch.prm", degree(k));
      const CycleResult &r = run.last();
      const auto [l1, l2]  = deviation(run, 1., Tensor<1, 2>());
      INFO("degree " << k << ": " << r.solve.n_contact_nodes
                     << " contact nodes, largest |l1 - 1| " << l1);
      // 16 faces on the plane at the last mesh: 16 k + 1 support points
      CHECK(r.solve.n_contact_nodes == 16 * k + 1);
      CHECK(r.solve.n_active == r.solve.n_contact_nodes);
      CHECK(std::abs(r.zone.contact_force - 2.) <= 1e-10 * 2.);
      CHECK(l1 <= 1e-8);
    }
}

TEST_CASE("3D friction patch at degree 2 and 3: a uniform pressure and shear "
          "below F p stick everywhere with the exact tractions",
          "[degree]")
{
  for (const unsigned int k : {2u, 3u})
    {
      const SceneRun<3>  run("patch_3d.prm",
                            degree(k) + "subsection Solver\n  set Uzawa "
                                         "tolerance = 1e-11\nend\n");
      const CycleResult &r = run.last();
      Tensor<1, 3>       q;
      q[0]                = 0.2;
      q[1]                = 0.1;
      const auto [l1, l2] = deviation(run, 1., q);
      INFO("degree " << k << ": error " << r.errors.error_L2 / r.errors.norm_L2
                     << ", largest |l1 - 1| " << l1 << ", |l2 - q| " << l2);
      CHECK(r.errors.error_L2 <= 1e-10 * r.errors.norm_L2);
      CHECK(r.zone.contact_force == Approx(4.).epsilon(1e-10));
      CHECK(r.zone.resultant[0] == Approx(-0.8).epsilon(1e-8));
      CHECK(r.zone.resultant[1] == Approx(-0.4).epsilon(1e-8));
      CHECK(l1 <= 1e-8);
      CHECK(l2 <= 1e-8);
      CHECK(r.solve.n_slip == 0);
      CHECK(r.solve.n_stick == r.solve.n_contact_nodes);
    }
}

TEST_CASE("Nearly incompressible Hertz (nu = 0.49): degree 2 gives the peak "
          "pressure within 1 % on fewer than 1e5 DoFs, degree 1 on as many "
          "DoFs does not",
          "[degree]")
{
  // prm/hertz.prm (R = 1, E = 1000, P = 2 q on the top) at nu = 0.49, with
  // Hertz's pressure for that nu: E* = E / (1 - nu^2),
  // a = sqrt(4 P R / (pi E*)), p0 = 2 P / (pi a).
  const double       nu = 0.49, E = 1000., P = 2 * 4.315374524161804;
  const double       E_star = E / (1. - nu * nu);
  const double       a      = std::sqrt(4. * P / (numbers::PI * E_star));
  const double       p0     = 2. * P / (numbers::PI * a);
  std::ostringstream exact;
  exact.precision(16);
  exact << "subsection Material\n  set Poisson's ratio = " << nu
        << "\nend\nsubsection Exact solution\n  set Contact pressure = " << p0
        << " * sqrt(max(0, 1 - x^2 / " << a * a
        << "))\n  set Contact half-width = " << a
        << "\n  set Peak pressure = " << p0 << "\nend\n";

  // degree 1 with its two cycles and degree 2 on the first mesh have about
  // as many DoFs (19538 and 19818)
  double peak_error[3] = {};
  for (const unsigned int k : {1u, 2u})
    {
      const Run          run("hertz.prm",
                    exact.str() + degree(k) +
                      (k == 2 ? "subsection Refinement\n  set Number of "
                                         "cycles = 1\nend\n" :
                                         ""));
      const CycleResult &r = run.last();
      peak_error[k]        = r.zone.max_pressure / p0 - 1.;
      INFO("degree " << k << ": " << r.mesh.n_dofs << " DoFs, peak "
                     << r.zone.max_pressure << " against p0 = " << p0 << " ("
                     << 100. * peak_error[k] << " %), half-width "
                     << r.zone.half_width << " against a = " << a
                     << ", pressure error " << r.zone.pressure_error);
      CHECK(r.mesh.n_dofs <= 100000);
      CHECK(std::abs(r.zone.contact_force - P) <= 1e-6 * P);
      if (k == 2)
        {
          CHECK(std::abs(peak_error[k]) <= 0.01);
          CHECK(std::abs(r.zone.peak_pressure_error) <= 0.01);
          CHECK(r.zone.pressure_error <= 0.02);
        }
    }
  // Q1 locks: its peak is high, and by more than Q2's error
  INFO("peak errors: degree 1 " << peak_error[1] << ", degree 2 "
                                << peak_error[2]);
  CHECK(peak_error[1] > 0.02);
  CHECK(std::abs(peak_error[2]) < 0.5 * peak_error[1]);
}

TEST_CASE("3D Hertz at degree 1, 2 and 3 (a rigid sphere on a block): on "
          "one mesh the pressure error falls with the degree, the radius is "
          "within a node spacing of Hertz's",
          "[degree]")
{
  // prm/indenter_sphere_3d.prm (Hertz: a = 0.1, p0 = 69.948) one global
  // level coarser than the scene: the contact faces have the side
  // h = 2 / 2^(1 + 4) = 0.0625 (one global level, four pre-refinement
  // steps). The largest spacing of their support points is h at degree 1,
  // h / 2 at degree 2 and h / sqrt(5) at degree 3 (the Gauss-Lobatto points
  // 0, (1 -+ 1 / sqrt(5)) / 2, 1: the middle gap).
  const double h                 = 2. / 32.;
  const double spacing[4]        = {0., h, h / 2., h / std::sqrt(5.)};
  double       pressure_error[4] = {};
  for (const unsigned int k : {1u, 2u, 3u})
    {
      const SceneRun<3>  run("indenter_sphere_3d.prm",
                            degree(k) +
                              "subsection Refinement\n  set Initial global "
                               "refinement = 1\n  set Number of cycles = 1\n"
                               "end\n");
      const CycleResult &r = run.last();
      pressure_error[k]    = r.zone.pressure_error;
      INFO("degree " << k << ": " << r.mesh.n_dofs << " DoFs, pressure error "
                     << r.zone.pressure_error << ", peak error "
                     << r.zone.peak_pressure_error << ", radius "
                     << r.zone.half_width << " (error "
                     << r.zone.half_width_error << "), imbalance "
                     << r.reactions.imbalance);
      CHECK(std::abs(r.zone.half_width - 0.1) <= spacing[k]);
      CHECK(std::abs(r.zone.peak_pressure_error) <= 0.05);
      CHECK(r.reactions.imbalance <= 1e-8);
    }
  // measured 0.29, 0.106, 0.091 (765, 4644 and 13659 DoFs)
  CHECK(pressure_error[1] <= 0.30);
  CHECK(pressure_error[2] <= 0.4 * pressure_error[1]);
  CHECK(pressure_error[3] < pressure_error[2]);
}

TEST_CASE("Patch tests at degree 1, 2 and 3 in 2D with friction and in 3D "
          "without: exact tractions at every node, every node in contact",
          "[degree]")
{
  for (const unsigned int k : {1u, 2u, 3u})
    {
      {
        const Run          run("patch.prm", degree(k) + patch_stick_2d);
        const CycleResult &r = run.last();
        Tensor<1, 2>       q;
        q[0]                = 0.2;
        const auto [l1, l2] = deviation(run, 1., q);
        INFO("2D, degree " << k << ": error "
                           << r.errors.error_L2 / r.errors.norm_L2
                           << ", largest |l1 - 1| " << l1 << ", |l2 - q| "
                           << l2);
        // 16 faces on the plane at the last mesh: 16 k + 1 support points
        CHECK(r.solve.n_contact_nodes == 16 * k + 1);
        CHECK(r.solve.n_stick == r.solve.n_contact_nodes);
        CHECK(r.errors.error_L2 <= 1e-10 * r.errors.norm_L2);
        CHECK(r.zone.contact_force == Approx(2.).epsilon(1e-10));
        CHECK(l1 <= 1e-8);
        CHECK(l2 <= 1e-8);
      }
      {
        const SceneRun<3>  run("patch_3d.prm",
                              degree(k) + patch_frictionless_3d +
                                "subsection Refinement\n  set Number of "
                                 "cycles = 1\nend\n");
        const CycleResult &r = run.last();
        const auto [l1, l2]  = deviation(run, 1., Tensor<1, 3>());
        INFO("3D, degree " << k << ": error "
                           << r.errors.error_L2 / r.errors.norm_L2
                           << ", largest |l1 - 1| " << l1);
        // 4 x 4 faces on the plane: (4 k + 1)^2 support points
        CHECK(r.solve.n_contact_nodes == (4 * k + 1) * (4 * k + 1));
        CHECK(r.solve.n_active == r.solve.n_contact_nodes);
        CHECK(r.errors.error_L2 <= 1e-10 * r.errors.norm_L2);
        CHECK(r.zone.contact_force == Approx(4.).epsilon(1e-10));
        CHECK(l1 <= 1e-8);
      }
    }
}
