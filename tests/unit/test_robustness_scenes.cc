// Robustness of the scenes: lift-off with no contact at
// all, a body pulled off the foundation, zero load, extreme meshes on
// Gamma_C, and parameter files without entries. Every assertion is on a
// value that is the same on all ranks.

#include <deal.II/base/mpi.h>

#include <dualcontact/contact_problem.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "scene_run.h"
#include "test_tools.h"

using namespace dualcontact;
using namespace dualcontact_test;

namespace
{
  /** Largest |a_i - b_i| over all entries of two vectors on the same DoFs. */
  double
  max_difference(const TrilinosWrappers::MPI::Vector &a,
                 const TrilinosWrappers::MPI::Vector &b,
                 const MPI_Comm                       comm)
  {
    double difference = 0;
    for (const auto i : a.locally_owned_elements())
      difference = std::max(difference, std::abs(a[i] - b[i]));
    return Utilities::MPI::max(difference, comm);
  }

  /**
   * The multipliers of the last cycle over all ranks: the largest |l1|,
   * the smallest l1, the largest |l2|, and whether all of them are finite.
   */
  struct Multipliers
  {
    double largest_l1  = 0;
    double smallest_l1 = 0;
    double largest_l2  = 0;
    bool   finite      = true;
  };

  template <int dim>
  Multipliers
  multipliers(const SceneRun<dim> &run)
  {
    const ContactSet<dim> &c = run.problem->contact();
    Multipliers            m;
    m.smallest_l1 = std::numeric_limits<double>::max();
    for (unsigned int s = 0; s < c.n_local_nodes(); ++s)
      {
        m.finite      = m.finite && std::isfinite(c.l1[s]);
        m.largest_l1  = std::max(m.largest_l1, std::abs(c.l1[s]));
        m.smallest_l1 = std::min(m.smallest_l1, c.l1[s]);
        if (s < c.l2.size())
          {
            m.finite     = m.finite && std::isfinite(c.l2[s].norm());
            m.largest_l2 = std::max(m.largest_l2, c.l2[s].norm());
          }
      }
    m.largest_l1  = Utilities::MPI::max(m.largest_l1, run.comm);
    m.smallest_l1 = Utilities::MPI::min(m.smallest_l1, run.comm);
    m.largest_l2  = Utilities::MPI::max(m.largest_l2, run.comm);
    m.finite      = Utilities::MPI::min(int(m.finite), run.comm) == 1;
    return m;
  }

  bool
  is_rank_0()
  {
    return Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  }

  const std::string one_cycle =
    "\nsubsection Refinement\n  set Number of cycles = 1\nend\n";

  // A 2 x 1 block (E = 1000, nu = 0.3) clamped at its top (id 3), its bottom
  // (id 2) on the foundation y = 0 with zero initial gap, hanging under an
  // upward body force: the bottom rises, nothing touches.
  std::string
  hanging_block(const std::string &bottom)
  {
    return R"(
subsection Geometry
  set Upper right corner = 2, 1
  set Subdivisions       = 8, 4
end
subsection Material
  set Young's modulus = 1000
  set Poisson's ratio = 0.3
end
subsection Boundary conditions
  set Conditions = 2: )" +
           bottom + R"(, 3: fixed
end
subsection Loads
  set Body force = 0; 10
end
subsection Foundation
  set Point  = 0, 0
  set Normal = 0, 1
end
subsection Refinement
  set Initial global refinement = 1
  set Number of cycles          = 2
end
)";
  }

  // The half disc of prm/hertz.prm clamped at its flat top (id 1), touching
  // the foundation y = -1 at its lowest point (zero gap there), under an
  // upward body force: the curved part (id 0) rises, nothing touches.
  std::string
  hanging_half_disc(const std::string &curved)
  {
    return R"(
subsection Geometry
  set Type   = half disc
  set Center = 0, 0
  set Radius = 1
end
subsection Material
  set Young's modulus = 1000
  set Poisson's ratio = 0.3
end
subsection Boundary conditions
  set Conditions = 0: )" +
           curved + R"(, 1: fixed
end
subsection Loads
  set Body force = 0; 10
end
subsection Foundation
  set Point  = 0, -1
  set Normal = 0, 1
end
subsection Refinement
  set Initial global refinement = 3
end
)";
  }

  // A 2 x 1 block (E = 1000, nu = 0.3) on the foundation y = 0 (id 2,
  // contact), held sideways by a slider on its left (id 0), loaded on its
  // top by the traction (0, 0.5 - x): it pulls up near x = 0 and pushes down
  // beyond x = 0.5, net load 1 toward the foundation; the left end lifts off.
  std::string
  tilted_load_block(const std::string &upper_right,
                    const std::string &subdivisions)
  {
    return R"(
subsection Geometry
  set Upper right corner = )" +
           upper_right + R"(
  set Subdivisions       = )" +
           subdivisions + R"(
end
subsection Material
  set Young's modulus = 1000
  set Poisson's ratio = 0.3
end
subsection Boundary conditions
  set Conditions = 0: normal fixed, 2: contact, 3: traction
  set Tractions  = 3: 0; 0.5 - x
end
subsection Foundation
  set Point  = 0, 0
  set Normal = 0, 1
end
)";
  }

  // The same in 3D: a 2 x 2 x 1 box of 2 x 2 x 1 cells (4 faces on
  // Gamma_C), sliders on x = 0 and y = 0, traction (0, 0, 0.5 - x) on its
  // top: net load 2.
  const std::string coarse_box = R"(
subsection Geometry
  set Dimension          = 3
  set Lower left corner  = 0, 0, 0
  set Upper right corner = 2, 2, 1
  set Subdivisions       = 2, 2, 1
end
subsection Material
  set Young's modulus = 1000
  set Poisson's ratio = 0.3
end
subsection Boundary conditions
  set Conditions = 0: normal fixed, 2: normal fixed, 4: contact, 5: traction
  set Tractions  = 5: 0; 0; 0.5 - x
end
subsection Foundation
  set Point  = 0, 0, 0
  set Normal = 0, 0, 1
end
)";

  /**
   * A contact scene on an extreme mesh: it must converge without NaN, the
   * contact force must balance the applied normal load (`load`), the contact
   * conditions must hold at every node, and the iteration counts must stay
   * below the given bounds (measured counts with margin).
   */
  template <int dim>
  void
  check_extreme_mesh(const std::string &name,
                     const std::string &scene,
                     const std::string &overrides,
                     const double       load,
                     const unsigned int max_uzawa,
                     const unsigned int max_newton,
                     const unsigned int max_cg,
                     std::ostream      &table)
  {
    SceneRun<dim>      run(scene, overrides);
    const CycleResult &r = run.last();
    const Multipliers  m = multipliers(run);
    const Conditions   c = check_conditions(run);
    table << name << ": " << r.mesh.n_dofs << " DoFs, "
          << r.solve.n_contact_nodes << " contact nodes, " << r.solve.n_active
          << " active, Uzawa " << r.solve.uzawa_steps << ", Newton "
          << r.solve.newton_steps << ", CG " << r.solve.cg_iterations
          << ", force " << r.zone.contact_force << " (load "
          << r.solve.normal_load << ", rel. diff. "
          << std::abs(r.zone.contact_force - r.solve.normal_load) /
               r.solve.normal_load
          << "), peak " << r.zone.max_pressure << ", min l1 " << c.smallest_l1
          << ", penetration " << c.penetration << ", complementarity "
          << c.complementarity << '\n';
    INFO(name << ": " << r.mesh.n_dofs << " DoFs, Uzawa " << r.solve.uzawa_steps
              << ", Newton " << r.solve.newton_steps << ", CG "
              << r.solve.cg_iterations << ", force " << r.zone.contact_force
              << ", load " << r.solve.normal_load << ", smallest l1 "
              << c.smallest_l1 << ", penetration " << c.penetration
              << ", complementarity " << c.complementarity);
    CHECK(std::isfinite(r.errors.norm_L2));
    CHECK(std::isfinite(max_entry(run.problem->displacement(), run.comm)));
    CHECK(m.finite);
    CHECK(std::abs(r.solve.normal_load - load) <= 1e-10 * load);
    CHECK(std::abs(r.zone.contact_force - r.solve.normal_load) <=
          1e-8 * r.solve.normal_load);
    CHECK(r.solve.n_active >= 1);
    CHECK(c.smallest_l1 >= 0.);
    CHECK(c.penetration <= 1e-7);
    CHECK(c.complementarity <= 1e-7);
    CHECK(r.solve.uzawa_steps <= max_uzawa);
    CHECK(r.solve.newton_steps <= max_newton);
    CHECK(r.solve.cg_iterations <= max_cg);
  }
} // namespace

TEST_CASE("Lift-off: a held body pulled away from the foundation touches "
          "nowhere and has the plain elastic solution",
          "[robustness]")
{
  const std::vector<
    std::pair<std::string, std::string (*)(const std::string &)>>
    scenes = {{"hanging block", hanging_block},
              {"hanging half disc", hanging_half_disc}};
  for (const auto &[name, scene] : scenes)
    {
      Run contact("", scene("contact"));
      Run free("", scene("free"));
      REQUIRE(contact.problem->results().size() ==
              free.problem->results().size());
      for (std::size_t k = 0; k < contact.problem->results().size(); ++k)
        {
          const CycleResult &a = contact.problem->results()[k];
          const CycleResult &b = free.problem->results()[k];
          INFO(name << ", cycle " << k << ": " << a.mesh.n_dofs << " DoFs, "
                    << a.solve.n_contact_nodes << " contact nodes, "
                    << a.solve.uzawa_steps << " Uzawa steps, ||u|| "
                    << a.errors.norm_L2 << " against " << b.errors.norm_L2);
          CHECK(a.mesh.n_dofs == b.mesh.n_dofs);
          CHECK(a.solve.n_contact_nodes > 0);
          CHECK(a.solve.n_active == 0);
          CHECK(a.zone.contact_force == 0.);
          CHECK(a.zone.max_pressure == 0.);
          CHECK(a.solve.normal_load < 0.); // the net load pulls away
          CHECK(std::isfinite(a.errors.norm_L2));
          CHECK(b.errors.norm_L2 > 0.);
          CHECK(std::abs(a.errors.norm_L2 - b.errors.norm_L2) <=
                1e-8 * b.errors.norm_L2);
        }
      const Multipliers m = multipliers(contact);
      const double u_max  = max_entry(free.problem->displacement(), free.comm);
      const double difference = max_difference(contact.problem->displacement(),
                                               free.problem->displacement(),
                                               contact.comm);
      INFO(name << ": max |u_contact - u_free| / max |u_free| = "
                << difference / u_max << ", largest l1 " << m.largest_l1);
      CHECK(m.finite);
      CHECK(m.largest_l1 == 0.);
      CHECK(u_max > 0.);
      CHECK(difference <= 1e-8 * u_max);
      if (is_rank_0())
        std::cout << "Lift-off, " << name << ": " << contact.last().mesh.n_dofs
                  << " DoFs, " << contact.last().solve.uzawa_steps << " Uzawa, "
                  << contact.last().solve.newton_steps << " Newton, "
                  << contact.last().solve.cg_iterations
                  << " CG; max |u_contact - u_free| / max |u_free| = "
                  << difference / u_max << '\n';
    }
}

TEST_CASE("A body held only by contact and pulled away: no equilibrium, "
          "exit code 7, nothing written",
          "[robustness]")
{
  // The half disc of prm/hertz.prm with the traction on its top reversed.
  const std::string directory =
    temporary_directory("pulled_off", MPI_COMM_WORLD);
  Parameters parameters;
  parameters.read_string(
    read_text(test_file("../prm/hertz.prm")),
    one_cycle +
      "\nsubsection Boundary conditions\n  set Tractions = 1: 0; "
      "4.315374524161804\nend\nsubsection Geometry\n  set Pre-refinement "
      "steps = 0\nend\nsubsection Refinement\n  set Initial global "
      "refinement = 2\nend\nsubsection Output\n  set Directory = " +
      directory + "\nend\n");
  std::ostringstream screen;
  CaughtError        error;
  {
    // caught while the problem still exists, as in main.cc
    ContactProblem<2> problem(parameters, MPI_COMM_WORLD, screen);
    error = catch_input_error([&]() { problem.run(); });
  }
  INFO(error.message);
  CHECK(error.thrown);
  CHECK(error.code == exit_no_equilibrium);
  CHECK(error.message.find("No equilibrium: the net load pulls the body "
                           "away from the obstacle") != std::string::npos);
  MPI_Barrier(MPI_COMM_WORLD);
  CHECK(!std::filesystem::exists(directory));
  remove_directory(directory, MPI_COMM_WORLD);
}

TEST_CASE("Zero load: zero displacement and multipliers in one Uzawa step",
          "[robustness]")
{
  // prm/paper_block.prm (Coulomb friction, semi-coercive) with both
  // tractions zero, on two meshes; prm/hertz.prm (frictionless, held only by
  // contact) with the pressure on its top zero.
  Run paper("paper_block.prm",
            "\nsubsection Boundary conditions\n  set Tractions = 0: 0; 0, "
            "3: 0; 0\nend\nsubsection Refinement\n  set Number of cycles = "
            "2\nend\n");
  Run hertz("hertz.prm",
            one_cycle + "\nsubsection Boundary conditions\n  set Tractions "
                        "= 1: 0; 0\nend\n");
  for (const Run *run : {&paper, &hertz})
    {
      const Multipliers m = multipliers(*run);
      const double u_max  = max_entry(run->problem->displacement(), run->comm);
      for (const CycleResult &r : run->problem->results())
        {
          INFO("cycle " << r.mesh.cycle << ": " << r.mesh.n_dofs << " DoFs, "
                        << r.solve.uzawa_steps << " Uzawa, "
                        << r.solve.newton_steps << " Newton, "
                        << r.solve.cg_iterations << " CG, "
                        << r.solve.threshold_steps << " threshold steps, ||u|| "
                        << r.errors.norm_L2 << ", force "
                        << r.zone.contact_force);
          CHECK(r.solve.n_contact_nodes > 0);
          CHECK(r.solve.uzawa_steps == 1);
          CHECK(r.errors.norm_L2 == 0.);
          CHECK(r.solve.normal_load == 0.);
          CHECK(r.zone.contact_force == 0.);
          CHECK(r.zone.tangential_force == 0.);
          CHECK(r.zone.max_pressure == 0.);
          CHECK(r.solve.n_active == 0);
          if (is_rank_0())
            std::cout << "Zero load, cycle " << r.mesh.cycle << ": "
                      << r.mesh.n_dofs << " DoFs, " << r.solve.n_contact_nodes
                      << " contact nodes, " << r.solve.uzawa_steps << " Uzawa, "
                      << r.solve.newton_steps << " Newton, "
                      << r.solve.cg_iterations << " CG, "
                      << r.solve.threshold_steps << " threshold, ||u|| "
                      << r.errors.norm_L2 << ", force " << r.zone.contact_force
                      << '\n';
        }
      INFO("max |u| " << u_max << ", max |l1| " << m.largest_l1 << ", max |l2| "
                      << m.largest_l2);
      CHECK(m.finite);
      CHECK(u_max == 0.);
      CHECK(m.largest_l1 == 0.);
      CHECK(m.largest_l2 == 0.);
    }
}

TEST_CASE("Extreme meshes on Gamma_C: 100:1 cells, two contact faces, a "
          "contact zone inside one cell",
          "[robustness]")
{
  std::ostringstream table;
  // (a) aspect ratio 100: flat cells 0.5 x 0.005 (4 faces on Gamma_C, 200
  // layers), tall cells 0.01 x 1 (200 faces on Gamma_C, one layer), and a
  // thin 2 x 0.01 strip of two 1 x 0.01 cells
  check_extreme_mesh<2>("flat cells 100:1",
                        "",
                        tilted_load_block("2, 1", "4, 200"),
                        1.,
                        20,
                        25,
                        1700,
                        table);
  check_extreme_mesh<2>("tall cells 1:100",
                        "",
                        tilted_load_block("2, 1", "200, 1"),
                        1.,
                        140,
                        160,
                        500,
                        table);
  check_extreme_mesh<2>("thin strip, 2 cells 100:1",
                        "",
                        tilted_load_block("2, 0.01", "2, 1"),
                        1.,
                        10,
                        12,
                        12,
                        table);
  // (b) two faces on Gamma_C (three contact nodes); in 3D four faces
  check_extreme_mesh<2>("2 x 2 cells",
                        "",
                        tilted_load_block("2, 1", "2, 2"),
                        1.,
                        15,
                        18,
                        18,
                        table);
  check_extreme_mesh<3>(
    "3D, 2 x 2 faces on Gamma_C", "", coarse_box, 2., 15, 18, 18, table);
  // (c) Hertz (a = 0.1) on meshes far coarser than the contact zone: no
  // pre-refinement, h about 0.4 and 0.8 at the contact
  const double hertz_P = 2 * 4.315374524161804;
  for (const unsigned int refinements : {0u, 1u})
    check_extreme_mesh<2>(
      "Hertz, " + std::to_string(refinements) + " global refinement(s)",
      "hertz.prm",
      one_cycle +
        "\nsubsection Geometry\n  set Pre-refinement steps = "
        "0\nend\nsubsection Refinement\n  set Initial global "
        "refinement = " +
        std::to_string(refinements) + "\nend\n",
      hertz_P,
      15,
      15,
      15,
      table);
  if (is_rank_0())
    std::cout << "Extreme meshes:\n" << table.str();
}

TEST_CASE("A parameter file without entries (empty, only comments, only "
          "empty subsections) is rejected with exit code 3",
          "[robustness]")
{
  const unsigned int rank = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  const std::string  directory =
    temporary_directory("no_entries", MPI_COMM_WORLD) + "_" +
    std::to_string(rank);
  std::filesystem::create_directories(directory);
  const std::vector<std::pair<std::string, std::string>> files = {
    {"empty.prm", ""},
    {"blank.prm", "\n   \n\t\n"},
    {"comments.prm", "# a comment\n  # another one\n"},
    {"subsections.prm",
     "subsection Material\n  # set Young's modulus = "
     "1\nend\nsubsection Output\nend\n"}};
  for (const auto &[name, text] : files)
    {
      const std::string filename = directory + "/" + name;
      std::ofstream(filename) << text;
      const CaughtError error = catch_input_error([&]() {
        Parameters parameters;
        parameters.read_file(filename);
      });
      INFO(name << ": " << error.message);
      CHECK(error.thrown);
      CHECK(error.code == exit_cannot_read_file);
      CHECK(error.message.find("<" + filename + "> has no entries") !=
            std::string::npos);
    }
  std::filesystem::remove_all(directory);
}
