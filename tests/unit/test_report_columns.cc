// The columns of cycles.csv: a scene writes the columns of the measured
// quantities it has (report_quantity.h) and no others, in the order every
// scene shares. A frictionless 2D scene on a fixed foundation has no
// tangential, obstacle-force or 3D columns; a Coulomb scene has the
// tangential ones and the threshold steps; a 3D scene whose obstacle is
// moved by <Obstacle/Displacement> has the obstacle force and the 3D ones.

#include <deal.II/base/mpi.h>

#include <dualcontact/contact_problem.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "scene_run.h"
#include "test_tools.h"

using namespace dualcontact;
using namespace dualcontact_test;

namespace
{
  /** The header of the run's cycles.csv, rank 0's file on every rank. */
  template <int dim>
  std::vector<std::string>
  columns_of(const SceneRun<dim> &run)
  {
    std::string text;
    if (Utilities::MPI::this_mpi_process(run.comm) == 0)
      text = read_text(run.directory + "/cycles.csv");
    text = Utilities::MPI::broadcast(run.comm, text, 0);
    std::vector<std::string> header;
    std::istringstream       line(text.substr(0, text.find('\n')));
    for (std::string column; std::getline(line, column, ',');)
      header.push_back(column);
    return header;
  }

  bool
  has(const std::vector<std::string> &columns, const std::string &name)
  {
    return std::find(columns.begin(), columns.end(), name) != columns.end();
  }

  /** The columns every scene could write, in their order (doc/output.md). */
  const std::vector<std::string> all_columns = {"cycle",
                                                "cells",
                                                "dofs",
                                                "warm_start",
                                                "carried_min_l1",
                                                "carried_max_excess",
                                                "contact_nodes",
                                                "hanging_contact_nodes",
                                                "active_nodes",
                                                "stick_nodes",
                                                "slip_nodes",
                                                "r",
                                                "chi",
                                                "threshold_steps",
                                                "uzawa_steps",
                                                "newton_steps",
                                                "linear_iterations",
                                                "amg_setups",
                                                "uzawa_rate",
                                                "l1_error_estimate",
                                                "normal_load",
                                                "equilibrium_imbalance",
                                                "contact_force",
                                                "tangential_force",
                                                "max_pressure",
                                                "contact_half_width",
                                                "contact_edge_half_width",
                                                "pressure_error",
                                                "contact_area",
                                                "contact_extent",
                                                "stick_half_width",
                                                "half_width_error",
                                                "stick_half_width_error",
                                                "peak_pressure_error",
                                                "u_l2",
                                                "l2_error",
                                                "h1_error",
                                                "potential_energy",
                                                "cold_uzawa_steps",
                                                "cold_newton_steps",
                                                "cold_threshold_steps",
                                                "cold_time_solve",
                                                "cold_difference_v",
                                                "cold_difference_l1",
                                                "applied_load_x",
                                                "applied_load_y",
                                                "applied_load_z",
                                                "reaction_",
                                                "obstacle_force_x",
                                                "obstacle_force_y",
                                                "obstacle_force_z",
                                                "slave_body_force_x",
                                                "slave_body_force_y",
                                                "slave_body_force_z",
                                                "master_body_force_x",
                                                "master_body_force_y",
                                                "master_body_force_z",
                                                "time_refine",
                                                "time_setup",
                                                "time_assembly",
                                                "time_solve",
                                                "time_output",
                                                "time_total",
                                                "time_elapsed",
                                                "time_newton_matrix",
                                                "time_amg_setup",
                                                "time_cg",
                                                "time_gradient",
                                                "time_multipliers",
                                                "time_reference",
                                                "reference_iterations",
                                                "memory_mb"};

  /**
   * Whether `columns` keep the order of all_columns (the reactions,
   * reaction_<id>_<axis>, count as "reaction_").
   */
  bool
  in_shared_order(const std::vector<std::string> &columns)
  {
    std::size_t next = 0;
    for (const std::string &column : columns)
      {
        const std::string name =
          column.rfind("reaction_", 0) == 0 ? "reaction_" : column;
        const auto found =
          std::find(all_columns.begin() + next, all_columns.end(), name);
        if (found == all_columns.end())
          return false;
        next = found - all_columns.begin();
      }
    return true;
  }

  const std::vector<std::string> tangential = {"stick_nodes",
                                               "slip_nodes",
                                               "tangential_force",
                                               "stick_half_width"};
  const std::vector<std::string> obstacle   = {"obstacle_force_x",
                                               "obstacle_force_y",
                                               "obstacle_force_z"};
  const std::vector<std::string> three_d    = {"contact_area",
                                               "contact_extent",
                                               "applied_load_z"};

  const std::string one_cycle =
    "subsection Refinement\n  set Number of cycles = 1\nend\n";
} // namespace

TEST_CASE("cycles.csv of a frictionless 2D scene on a fixed foundation has "
          "no tangential, obstacle-force or 3D columns",
          "[report][columns]")
{
  const Run                      run("hertz.prm", one_cycle);
  const std::vector<std::string> columns = columns_of(run);
  CHECK(in_shared_order(columns));
  for (const std::string name : {"cycle",
                                 "dofs",
                                 "contact_nodes",
                                 "uzawa_steps",
                                 "contact_force",
                                 "equilibrium_imbalance",
                                 "applied_load_y",
                                 "time_total",
                                 "memory_mb"})
    CHECK(has(columns, name));
  // the scene's <Exact solution> gives the pressure, a and p0, not c
  for (const std::string name :
       {"pressure_error", "half_width_error", "peak_pressure_error"})
    CHECK(has(columns, name));
  for (const std::string name : {"stick_half_width_error",
                                 "threshold_steps",
                                 "l2_error",
                                 "cold_uzawa_steps",
                                 "time_reference"})
    CHECK_FALSE(has(columns, name));
  for (const auto *group : {&tangential, &obstacle, &three_d})
    for (const std::string &name : *group)
      CHECK_FALSE(has(columns, name));
}

TEST_CASE("cycles.csv of a Coulomb scene has the tangential columns, the "
          "threshold steps and the signed force on the obstacle",
          "[report][columns]")
{
  const Run                      run("hertz_friction.prm", one_cycle);
  const std::vector<std::string> columns = columns_of(run);
  CHECK(in_shared_order(columns));
  for (const std::string &name : tangential)
    CHECK(has(columns, name));
  CHECK(has(columns, "threshold_steps"));
  // tangential_force is a magnitude; the vector has its sign
  CHECK(has(columns, "obstacle_force_x"));
  CHECK(has(columns, "obstacle_force_y"));
  CHECK_FALSE(has(columns, "obstacle_force_z"));
  for (const std::string &name : three_d)
    CHECK_FALSE(has(columns, name));
}

TEST_CASE("cycles.csv of a 3D scene with an obstacle moved by "
          "<Obstacle/Displacement> has the obstacle-force and 3D columns",
          "[report][columns][3d]")
{
  // prm/indenter_sphere_3d.prm, the sphere pressed 0.0005 further down
  const SceneRun<3>              run("indenter_sphere_3d.prm",
                        one_cycle + "subsection Obstacle\n  set Displacement "
                                                 "= 0, 0, -0.0005\nend\n");
  const std::vector<std::string> columns = columns_of(run);
  CHECK(in_shared_order(columns));
  for (const auto *group : {&obstacle, &three_d})
    for (const std::string &name : *group)
      CHECK(has(columns, name));
  for (const std::string &name : tangential)
    CHECK_FALSE(has(columns, name));
  // the force on the sphere is the contact force, straight up
  const CycleResult &last = run.last();
  CHECK(-last.zone.resultant[2] > 0.);
}

TEST_CASE("potential_energy of the contact patch test is the exact "
          "J = 1/2 a(u, u) - f(u) = -p^2 |top| H / (2 E)",
          "[report][columns]")
{
  // prm/patch.prm: u_y = -p y / E on the 2 x 1 block, exact at k = 1; the
  // contact does no work (u_n = g0 = 0), so a(u, u) = f(u) and J = -f(u)/2
  // = -(1 * 2 * 1 / 1000) / 2
  const Run run("patch.prm", one_cycle);
  CHECK(has(columns_of(run), "potential_energy"));
  CHECK(std::abs(run.last().potential_energy + 1e-3) < 1e-9);
}
