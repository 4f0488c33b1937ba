// Two bodies in contact (<Boundary conditions/Contact pairs>, dual mortar):
// the contact patch test on non-matching meshes, frictionless and all
// stick, Hertz's two cylinders, the same from a Gmsh file, Cattaneo-Mindlin
// and Mindlin-Deresiewicz between identical cylinders (tagged [path] as
// well: ctest runs it with the load paths), and the refusals of a pair that
// cannot be one. Every assertion is on a value reduced over all ranks.

#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>

#include <deal.II/distributed/tria.h>

#include <dualcontact/contact_problem.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "scene_run.h"
#include "test_tools.h"

using namespace dualcontact;
using namespace dualcontact_test;

namespace
{
  // prm/two_blocks_patch.prm with the shear q = 0.2 under F = 0.4: the
  // tractions of sigma_xy = 0.2 on the top and the sides, and the shear
  // strain in the exact solution, u_x = q / mu y
  const std::string patch_stick =
    "subsection Boundary conditions\n"
    "  set Tractions = 0: 0.3/0.7; -0.2, 1: -0.3/0.7; 0.2, 3: 0.2; -1\nend\n"
    "subsection Friction\n  set Law = coulomb\n  set Coefficient = 0.4\nend\n"
    "subsection Exact solution\n"
    "  set Displacement = 0.2*2.6/1000*y; -1.3*0.4/0.7/1000*y\nend\n"
    "subsection Solver\n  set Uzawa tolerance = 1e-11\nend\n";
  const std::string tight =
    "subsection Solver\n  set Uzawa tolerance = 1e-11\nend\n";
} // namespace

TEST_CASE("The contact patch test between two bodies on non-matching meshes "
          "(7 over 10 cells, then 14 over 20; quadrilaterals and triangles): "
          "the pressure p at every slave node and the exact displacement, "
          "frictionless and all stick",
          "[pairs]")
{
  for (const bool friction : {false, true})
    for (const std::string cells : {"quadrilateral", "simplex"})
      {
        INFO((friction ? "all stick under the shear 0.2" : "frictionless")
             << " on " << cells << " cells");
        const Run    run("two_blocks_patch.prm",
                      (friction ? patch_stick : tight) +
                        "subsection Geometry\n  set Cell type = " + cells +
                        "\nend\n");
        Tensor<1, 2> q;
        q[0]                = friction ? 0.2 : 0.;
        const auto [l1, l2] = deviation(run, 1., q);
        for (const CycleResult &r : run.problem->results())
          {
            INFO("cycle " << r.mesh.cycle << ": error "
                          << r.errors.error_L2 / r.errors.norm_L2);
            // the upper block's 7 (14) cells: 8 (15) slave nodes, all facing
            // the master
            CHECK(r.solve.n_contact_nodes == 7 * (1u << r.mesh.cycle) + 1);
            CHECK(r.solve.n_uncovered == 0);
            CHECK(r.solve.n_active == r.solve.n_contact_nodes);
            CHECK(r.errors.error_L2 <= 1e-8 * r.errors.norm_L2);
            // the load p times the width 2 crosses the interface, and the
            // forces on the two bodies are equal and opposite
            CHECK(r.zone.contact_force == Approx(2.).epsilon(1e-10));
            for (unsigned int c = 0; c < 2; ++c)
              CHECK(std::abs(r.zone.on_slave_body[c] +
                             r.zone.on_master_body[c]) <= 1e-10 * 2.);
            CHECK(r.zone.on_master_body[1] == Approx(-2.).epsilon(1e-10));
            if (friction)
              {
                CHECK(r.solve.n_stick == r.solve.n_contact_nodes);
                CHECK(r.zone.on_master_body[0] == Approx(0.4).epsilon(1e-10));
              }
          }
        INFO("largest |l1 - p| " << l1 << ", |l2 - q| " << l2);
        CHECK(l1 <= 1e-8);
        CHECK(l2 <= 1e-8);
      }
}

TEST_CASE("The contact patch test between two bodies at degrees 2 and 3: "
          "the dual basis of each segment, A = D M^-1, passes it as at "
          "degree 1",
          "[pairs]")
{
  for (const unsigned int degree : {2u, 3u})
    for (const bool friction : {false, true})
      {
        INFO("degree " << degree << ", "
                       << (friction ? "all stick under the shear 0.2" :
                                      "frictionless"));
        const Run    run("two_blocks_patch.prm",
                      (friction ? patch_stick : tight) +
                        "subsection Discretization\n  set Polynomial degree "
                           "= " +
                        std::to_string(degree) + "\nend\n");
        Tensor<1, 2> q;
        q[0]                = friction ? 0.2 : 0.;
        const auto [l1, l2] = deviation(run, 1., q);
        for (const CycleResult &r : run.problem->results())
          {
            INFO("cycle " << r.mesh.cycle << ": error "
                          << r.errors.error_L2 / r.errors.norm_L2);
            // the support points of the upper block's 7 (14) faces
            CHECK(r.solve.n_contact_nodes ==
                  degree * 7 * (1u << r.mesh.cycle) + 1);
            CHECK(r.solve.n_uncovered == 0);
            CHECK(r.errors.error_L2 <= 1e-8 * r.errors.norm_L2);
            CHECK(r.zone.contact_force == Approx(2.).epsilon(1e-10));
            for (unsigned int c = 0; c < 2; ++c)
              CHECK(std::abs(r.zone.on_slave_body[c] +
                             r.zone.on_master_body[c]) <= 1e-10 * 2.);
          }
        INFO("largest |l1 - p| " << l1 << ", |l2 - q| " << l2);
        CHECK(l1 <= 1e-8);
        CHECK(l2 <= 1e-8);
      }
}

TEST_CASE("The contact patch test between two bodies in 3D on non-matching "
          "meshes (5 x 5 over 7 x 7 faces, then 10 x 10 over 14 x 14; "
          "hexahedra and tetrahedra at degree 1, hexahedra at degree 2 on the "
          "first mesh): the pressure p at every slave node and the exact "
          "displacement, frictionless and all stick",
          "[pairs]")
{
  // prm/two_blocks_patch_3d.prm with the shear q = 0.2 along x under
  // F = 0.4: sigma_xz = 0.2 added to the uniform stress (the tractions
  // (0.2, 0, -1) on the top and -+0.2 along z on the sides x = 0, 2), and
  // the shear strain in the exact solution, u_x = q / mu z
  const std::string stick_3d =
    "subsection Boundary conditions\n"
    "  set Tractions = 0: 0.3/0.7; 0; -0.2, 1: -0.3/0.7; 0; 0.2, "
    "2: 0; 0.3/0.7; 0, 3: 0; -0.3/0.7; 0, 5: 0.2; 0; -1\nend\n"
    "subsection Friction\n  set Law = coulomb\n  set Coefficient = 0.4\nend\n"
    "subsection Exact solution\n"
    "  set Displacement = 0.2*2.6/1000*z; 0; -1.3*0.4/0.7/1000*z\nend\n"
    "subsection Solver\n  set Uzawa tolerance = 1e-11\nend\n";
  for (const bool friction : {false, true})
    for (const auto &[cells, degree] :
         {std::pair<std::string, unsigned int>{"quadrilateral", 1},
          {"simplex", 1},
          {"quadrilateral", 2}})
      {
        INFO((friction ? "all stick under the shear 0.2" : "frictionless")
             << " on " << cells << " cells of degree " << degree);
        const SceneRun<3> run(
          "two_blocks_patch_3d.prm",
          (friction ? stick_3d : tight) +
            "subsection Geometry\n  set Cell type = " + cells +
            "\nend\nsubsection Discretization\n  set Polynomial degree = " +
            std::to_string(degree) + "\nend\n" +
            (degree == 2 ? "subsection Refinement\n  set Number of cycles = "
                           "1\nend\n" :
                           ""));
        Tensor<1, 3> q;
        q[0]                = friction ? 0.2 : 0.;
        const auto [l1, l2] = deviation(run, 1., q);
        for (const CycleResult &r : run.problem->results())
          {
            INFO("cycle " << r.mesh.cycle << ": error "
                          << r.errors.error_L2 / r.errors.norm_L2);
            // the upper block's 5 x 5 (10 x 10) faces: 6 x 6 (11 x 11) slave
            // nodes at degree 1, 11 x 11 at degree 2, all facing the master
            const unsigned int n = degree * 5 * (1u << r.mesh.cycle) + 1;
            CHECK(r.solve.n_contact_nodes == n * n);
            CHECK(r.solve.n_uncovered == 0);
            CHECK(r.solve.n_active == r.solve.n_contact_nodes);
            CHECK(r.errors.error_L2 <= 1e-8 * r.errors.norm_L2);
            // the load p times the area 4 crosses the interface, and the
            // forces on the two bodies are equal and opposite
            CHECK(r.zone.contact_force == Approx(4.).epsilon(1e-10));
            for (unsigned int c = 0; c < 3; ++c)
              CHECK(std::abs(r.zone.on_slave_body[c] +
                             r.zone.on_master_body[c]) <= 1e-10 * 4.);
            CHECK(r.zone.on_master_body[2] == Approx(-4.).epsilon(1e-10));
            if (friction)
              {
                CHECK(r.solve.n_stick == r.solve.n_contact_nodes);
                CHECK(r.zone.on_master_body[0] == Approx(0.8).epsilon(1e-10));
              }
          }
        INFO("largest |l1 - p| " << l1 << ", |l2 - q| " << l2);
        CHECK(l1 <= 1e-8);
        CHECK(l2 <= 1e-8);
      }
}

namespace
{
  // The contact patch test with the slave beyond the master's end: the upper
  // block reaches one upper cell beyond the lower block on each side (2D:
  // 9 cells over [-2/7, 16/7] on 10 over [0, 2]; 3D: 7 x 7 faces over
  // [-0.4, 2.4]^2 on 7 x 7 over [0, 2]^2), so that the master's end lies on
  // an edge of the slave mesh and the slave nodes there are covered on one
  // side only. The uniform stress of the patch test holds in both blocks if
  // the slave faces beyond the master carry the traction the master gives
  // the others, sigma n = (-q, p) on the bottom (a load on the slave id where
  // the master does not hold it); the sides of the upper block take the
  // tractions of the lower one's. A node at the master's end transmits its
  // multiplier over the covered half of its support (its weight there), and
  // l1 = p at every contact node.
  std::string
  overhang(const unsigned int dim, const bool friction)
  {
    const std::string beyond =
      dim == 2 ? "x < 0 || x > 2" : "x < 0 || x > 2 || y < 0 || y > 2";
    const std::string shear = friction ? "-0.2" : "0";
    const std::string load  = "if(" + beyond + ", " + shear + ", 0); " +
                             (dim == 3 ? "0; " : "") + "if(" + beyond +
                             ", 1, 0)";
    return "subsection Geometry\n  set Upper overhang = " +
           std::string(dim == 2 ? "0.2857142857142857" : "0.4") +
           "\n  set Upper subdivisions = " + (dim == 2 ? "9, 3" : "7, 7, 2") +
           "\nend\n"
           "subsection Boundary conditions\n  set Conditions = " +
           (dim == 2 ? "0: traction, 1: traction, 2: fixed, 3: traction, "
                       "5: traction" :
                       "0: traction, 1: traction, 2: traction, 3: traction, "
                       "4: fixed, 5: traction, 7: traction") +
           "\n  set Tractions = " +
           (dim == 2 ? (friction ? "0: 0.3/0.7; -0.2, 1: -0.3/0.7; 0.2, "
                                   "3: 0.2; -1, 5: " :
                                   "0: 0.3/0.7; 0, 1: -0.3/0.7; 0, 3: 0; -1, "
                                   "5: ") :
                       (friction ? "0: 0.3/0.7; 0; -0.2, 1: -0.3/0.7; 0; 0.2, "
                                   "2: 0; 0.3/0.7; 0, 3: 0; -0.3/0.7; 0, "
                                   "5: 0.2; 0; -1, 7: " :
                                   "0: 0.3/0.7; 0; 0, 1: -0.3/0.7; 0; 0, "
                                   "2: 0; 0.3/0.7; 0, 3: 0; -0.3/0.7; 0, "
                                   "5: 0; 0; -1, 7: ")) +
           load + "\nend\n" +
           (friction ?
              "subsection Friction\n  set Law = coulomb\n"
              "  set Coefficient = 0.4\nend\n"
              "subsection Exact solution\n  set Displacement = "
              "0.2*2.6/1000*" +
                std::string(dim == 2 ? "y; " : "z; 0; ") +
                "-1.3*0.4/0.7/1000*" + (dim == 2 ? "y" : "z") + "\nend\n" :
              "") +
           "subsection Exact solution\n  set Contact pressure = if(" + beyond +
           ", 0, 1)\nend\n"
           "subsection Solver\n  set Uzawa tolerance = 1e-11\nend\n";
  }
} // namespace

TEST_CASE("The contact patch test with the slave extending beyond the "
          "master (2D: 7 covered cells of 9 over 10, degrees 1 and 2, "
          "quadrilaterals and triangles; 3D: 5 x 5 covered faces of 7 x 7 "
          "over 7 x 7, hexahedra and tetrahedra at degree 1, hexahedra at "
          "degree 2): the pressure p at every contact node, the exact "
          "displacement, frictionless and all stick",
          "[pairs]")
{
  for (const bool friction : {false, true})
    {
      for (const auto &[cells, degree] :
           {std::pair<std::string, unsigned int>{"quadrilateral", 1},
            {"simplex", 1},
            {"quadrilateral", 2}})
        {
          INFO("2D, " << (friction ? "all stick" : "frictionless") << ", "
                      << cells << " cells of degree " << degree);
          const Run    run("two_blocks_patch.prm",
                        overhang(2, friction) +
                          "subsection Geometry\n  set Cell type = " + cells +
                          "\nend\nsubsection Discretization\n  set "
                             "Polynomial degree = " +
                          std::to_string(degree) + "\nend\n");
          Tensor<1, 2> q;
          q[0]                = friction ? 0.2 : 0.;
          const auto [l1, l2] = deviation(run, 1., q);
          for (const CycleResult &r : run.problem->results())
            {
              const unsigned int cells_across = 1u << r.mesh.cycle;
              INFO("cycle " << r.mesh.cycle << ": error "
                            << r.errors.error_L2 / r.errors.norm_L2);
              // the 7 (14) covered cells' nodes are contact nodes, those of
              // the 2 (4) beyond the master are not
              CHECK(r.solve.n_contact_nodes == degree * 7 * cells_across + 1);
              CHECK(r.solve.n_uncovered == degree * 2 * cells_across);
              CHECK(r.solve.n_active == r.solve.n_contact_nodes);
              CHECK(r.errors.error_L2 <= 1e-8 * r.errors.norm_L2);
              CHECK(r.zone.contact_force == Approx(2.).epsilon(1e-10));
              CHECK(r.zone.on_master_body[1] == Approx(-2.).epsilon(1e-10));
              for (unsigned int c = 0; c < 2; ++c)
                CHECK(std::abs(r.zone.on_slave_body[c] +
                               r.zone.on_master_body[c]) <= 1e-10 * 2.);
              if (friction)
                CHECK(r.solve.n_stick == r.solve.n_contact_nodes);
            }
          INFO("largest |l1 - p| " << l1 << ", |l2 - q| " << l2);
          CHECK(l1 <= 1e-8);
          CHECK(l2 <= 1e-8);
        }
      for (const auto &[cells, degree] :
           {std::pair<std::string, unsigned int>{"quadrilateral", 1},
            {"simplex", 1},
            {"quadrilateral", 2}})
        {
          INFO("3D, " << (friction ? "all stick" : "frictionless") << ", "
                      << cells << " cells of degree " << degree);
          const SceneRun<3> run(
            "two_blocks_patch_3d.prm",
            overhang(3, friction) +
              "subsection Geometry\n  set Cell type = " + cells +
              "\nend\nsubsection Discretization\n  set Polynomial degree = " +
              std::to_string(degree) +
              "\nend\nsubsection Refinement\n  set Number of cycles = 1\n"
              "end\n");
          Tensor<1, 3> q;
          q[0]                 = friction ? 0.2 : 0.;
          const auto [l1, l2]  = deviation(run, 1., q);
          const CycleResult &r = run.last();
          INFO("error " << r.errors.error_L2 / r.errors.norm_L2);
          // the nodes of the 5 x 5 covered faces, and the ring beyond
          const unsigned int n = 5 * degree + 1, all = 7 * degree + 1;
          CHECK(r.solve.n_contact_nodes == n * n);
          CHECK(r.solve.n_uncovered == all * all - n * n);
          CHECK(r.solve.n_active == r.solve.n_contact_nodes);
          CHECK(r.errors.error_L2 <= 1e-8 * r.errors.norm_L2);
          CHECK(r.zone.contact_force == Approx(4.).epsilon(1e-10));
          CHECK(r.zone.on_master_body[2] == Approx(-4.).epsilon(1e-10));
          for (unsigned int c = 0; c < 3; ++c)
            CHECK(std::abs(r.zone.on_slave_body[c] +
                           r.zone.on_master_body[c]) <= 1e-10 * 4.);
          if (friction)
            CHECK(r.solve.n_stick == r.solve.n_contact_nodes);
          INFO("largest |l1 - p| " << l1 << ", |l2 - q| " << l2);
          CHECK(l1 <= 1e-8);
          CHECK(l2 <= 1e-8);
        }
    }
}

TEST_CASE("A body on a body on a rigid plane: the patch test through the "
          "pair and the obstacle at once",
          "[pairs]")
{
  // prm/two_blocks_patch.prm with the lower block's bottom (id 2) on the
  // frictionless plane y = 0 instead of clamped: the same uniform stress,
  // p = 1 across both interfaces; sideways only the proximal term holds
  // the two blocks, at u_x = 0
  const Run    run("two_blocks_patch.prm",
                tight + "subsection Boundary conditions\n  set Conditions = "
                           "0: traction, 1: traction, 2: contact, 3: "
                           "traction\nend\n");
  Tensor<1, 2> q;
  const auto [l1, l2] = deviation(run, 1., q);
  for (const CycleResult &r : run.problem->results())
    {
      INFO("cycle " << r.mesh.cycle << ": error "
                    << r.errors.error_L2 / r.errors.norm_L2);
      // the upper block's slave nodes and the lower block's bottom
      CHECK(r.solve.n_contact_nodes ==
            7 * (1u << r.mesh.cycle) + 1 + 10 * (1u << r.mesh.cycle) + 1);
      CHECK(r.solve.n_active == r.solve.n_contact_nodes);
      CHECK(r.errors.error_L2 <= 1e-8 * r.errors.norm_L2);
      CHECK(r.zone.on_master_body[1] == Approx(-2.).epsilon(1e-10));
      // the plane takes the load of both blocks' tops: 2
      CHECK(std::abs(r.zone.resultant[1] - 2.) <= 1e-10);
    }
  INFO("largest |l1 - p| " << l1);
  CHECK(l1 <= 1e-8);
  // the pair's rows alone in their own file, as in the file of all nodes
  const CsvFile all(run.directory + "/contact_01.csv", run.comm);
  const CsvFile pair(run.directory + "/contact_pair_5_4_01.csv", run.comm);
  CHECK(all.rows() == 15 + 21);
  CHECK(pair.rows() == 15);
  for (unsigned int i = 0; i < pair.rows(); ++i)
    CHECK(std::abs(pair.value(i, "y") - 1.) <= 1e-12);
}

TEST_CASE("One-pass node-to-segment fails the contact patch test that the "
          "dual mortar passes",
          "[pairs]")
{
  // prm/two_blocks_patch.prm (7 over 10 cells, p = 1) with <Pair coupling>
  // = node to segment: each slave node's gap to the master point below it.
  // The slave forces m_s p reach the master nodes as m_s p phi_j(eta_s),
  // not int p phi_j: the lower block is loaded unevenly, the pressure is
  // not uniform, and the displacement is not the exact one.
  const Run    run("two_blocks_patch.prm",
                tight + "subsection Boundary conditions\n  set Pair coupling "
                           "= node to segment\nend\n");
  Tensor<1, 2> q;
  const auto [l1, l2]  = deviation(run, 1., q);
  const CycleResult &r = run.last();
  INFO("largest |l1 - p| " << l1 << ", displacement error "
                           << r.errors.error_L2 / r.errors.norm_L2);
  CHECK(r.solve.n_contact_nodes == 15);
  // the load still crosses the interface whole, the forces balance
  CHECK(r.zone.contact_force == Approx(2.).epsilon(1e-10));
  CHECK(r.zone.on_master_body[1] == Approx(-2.).epsilon(1e-10));
  // but not as a uniform pressure: measured 0.14 and 1.4 %
  CHECK(l1 > 0.05);
  CHECK(r.errors.error_L2 > 1e-3 * r.errors.norm_L2);
}

TEST_CASE("A contact pair that cannot be one is refused before the solve, "
          "with the pair named",
          "[pairs][errors]")
{
  // (the pair and conditions, the words the message must have)
  const std::vector<std::pair<std::string, std::string>> cases = {
    {"5: 4, 3: 4\n  set Conditions = 0: traction, 1: traction, 2: fixed",
     "names boundary id 4 in two pairs"},
    // both ids on the lower block
    {"4: 2\n  set Conditions = 0: traction, 1: traction, 3: traction",
     "has both sides on one body"},
    {"5: 9", "has no boundary id 9"},
    {"5: 5", "one id with itself"},
    {"5: 2", "gives id 2 the condition 'fixed'"},
    // the upper block's top against the lower block's bottom, 2 behind it
    // (their normals opposite, the two bodies between them): no face of
    // the one lies in front of a face of the other
    {"3: 2\n  set Conditions = 0: traction, 1: traction\n"
     "  set Tractions = 0: 0.3/0.7; 0, 1: -0.3/0.7; 0",
     "has no slave node that faces the master surface"},
    // the upper block's bottom and the lower block's bottom look the same
    // way: no slave node faces the master
    {"5: 2\n  set Conditions = 0: traction, 1: traction, 3: traction",
     "has no slave node that faces the master surface"}};
  for (const auto &[pair, words] : cases)
    {
      const CaughtError error = catch_input_error([&] {
        const Run run("two_blocks_patch.prm",
                      "subsection Boundary conditions\n  set Contact pairs = " +
                        pair + "\nend\n");
      });
      INFO(pair << ": " << error.message);
      CHECK(error.thrown);
      CHECK(error.code == exit_inconsistent);
      CHECK(contains(error.message, words));
    }
  // in 3D: degree 1 on tetrahedra and the dual mortar only
  const std::vector<std::pair<std::string, std::string>> cases_3d = {
    {"subsection Discretization\n  set Polynomial degree = 2\nend\n"
     "subsection Geometry\n  set Cell type = simplex\nend\n",
     "couples two bodies of simplices at degree 1 only"},
    {"subsection Boundary conditions\n  set Pair coupling = node to "
     "segment\nend\n",
     "node to segment is a comparison in 2D"},
    // the upper block's top against the lower block's bottom, 2 behind it
    {"subsection Boundary conditions\n  set Contact pairs = 5: 4\n"
     "  set Conditions = 0: traction, 1: traction, 2: traction, 3: "
     "traction\n  set Tractions = 0: 0.3/0.7; 0; 0, 1: -0.3/0.7; 0; 0, "
     "2: 0; 0.3/0.7; 0, 3: 0; -0.3/0.7; 0\nend\n",
     "has no slave node that faces the master surface"}};
  for (const auto &[overrides, words] : cases_3d)
    {
      const CaughtError error = catch_input_error(
        [&] { const SceneRun<3> run("two_blocks_patch_3d.prm", overrides); });
      INFO(overrides << ": " << error.message);
      CHECK(error.thrown);
      CHECK(error.code == exit_inconsistent);
      CHECK(contains(error.message, words));
    }
}

namespace
{
  /**
   * Two blocks of quadrilaterals (hexahedra) that overlap, written as a
   * Gmsh file (format 2.2): the lower block [0, 2]^(dim - 1) x [0, 1] in
   * 2^(dim - 1) cells, the upper one [0, 2]^(dim - 1) x [1 - depth,
   * 2 - depth] in 3^(dim - 1), one cell high each, so that the upper
   * block's bottom lies `depth` inside the lower one. Material ids 0 and 1;
   * boundary ids as the built-in 'two blocks' has them: 0 to 2 dim - 1 on
   * the outside (x = 0, x = 2, then y, then z in 3D), 2 dim on the lower
   * block's top, 2 dim + 1 on the upper block's bottom.
   */
  template <int dim>
  void
  write_overlapping_blocks_msh(const std::string &file, const double depth)
  {
    std::ostringstream nodes, elements;
    unsigned int       n_nodes = 0, n_elements = 0;
    const auto         element = [&](const unsigned int               type,
                             const unsigned int               tag,
                             const std::vector<unsigned int> &vertices) {
      elements << ++n_elements << ' ' << type << " 2 " << tag << ' ' << tag + 1;
      for (const unsigned int v : vertices)
        elements << ' ' << v;
      elements << '\n';
    };
    for (const unsigned int block : {0u, 1u})
      {
        const unsigned int n      = 2 + block; // cells across
        const double       bottom = block == 0 ? 0. : 1. - depth;
        const unsigned int first  = n_nodes + 1;
        const unsigned int m      = dim == 3 ? n + 1 : 1;
        // the number of the lattice point (i, j, v), v = 0 at the bottom
        const auto at = [&](const unsigned int i,
                            const unsigned int j,
                            const unsigned int v) {
          return first + (v * m + j) * (n + 1) + i;
        };
        for (unsigned int v = 0; v < 2; ++v)
          for (unsigned int j = 0; j < m; ++j)
            for (unsigned int i = 0; i <= n; ++i)
              {
                nodes << ++n_nodes << ' ' << std::setprecision(17) << 2. * i / n
                      << ' ' << (dim == 3 ? 2. * j / n : bottom + v) << ' '
                      << (dim == 3 ? bottom + v : 0.) << '\n';
              }
        const unsigned int lower_id = block == 0 ? 2 * dim - 2 : 2 * dim + 1;
        const unsigned int upper_id = block == 0 ? 2 * dim : 2 * dim - 1;
        if (dim == 2)
          {
            for (unsigned int i = 0; i < n; ++i)
              {
                element(
                  3,
                  block,
                  {at(i, 0, 0), at(i + 1, 0, 0), at(i + 1, 0, 1), at(i, 0, 1)});
                element(1, lower_id, {at(i, 0, 0), at(i + 1, 0, 0)});
                element(1, upper_id, {at(i, 0, 1), at(i + 1, 0, 1)});
              }
            element(1, 0, {at(0, 0, 0), at(0, 0, 1)});
            element(1, 1, {at(n, 0, 0), at(n, 0, 1)});
          }
        else
          for (unsigned int j = 0; j < n; ++j)
            for (unsigned int i = 0; i < n; ++i)
              {
                element(5,
                        block,
                        {at(i, j, 0),
                         at(i + 1, j, 0),
                         at(i + 1, j + 1, 0),
                         at(i, j + 1, 0),
                         at(i, j, 1),
                         at(i + 1, j, 1),
                         at(i + 1, j + 1, 1),
                         at(i, j + 1, 1)});
                for (const unsigned int v : {0u, 1u})
                  element(3,
                          v == 0 ? lower_id : upper_id,
                          {at(i, j, v),
                           at(i + 1, j, v),
                           at(i + 1, j + 1, v),
                           at(i, j + 1, v)});
                // the sides x = 0, x = 2 (along j) and y = 0, y = 2 (along
                // i)
                if (i == 0)
                  element(3,
                          0,
                          {at(0, j, 0),
                           at(0, j + 1, 0),
                           at(0, j + 1, 1),
                           at(0, j, 1)});
                if (i + 1 == n)
                  element(3,
                          1,
                          {at(n, j, 0),
                           at(n, j + 1, 0),
                           at(n, j + 1, 1),
                           at(n, j, 1)});
                if (j == 0)
                  element(3,
                          2,
                          {at(i, 0, 0),
                           at(i + 1, 0, 0),
                           at(i + 1, 0, 1),
                           at(i, 0, 1)});
                if (j + 1 == n)
                  element(3,
                          3,
                          {at(i, n, 0),
                           at(i + 1, n, 0),
                           at(i + 1, n, 1),
                           at(i, n, 1)});
              }
      }
    std::ofstream(file) << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n"
                        << n_nodes << '\n'
                        << nodes.str() << "$EndNodes\n$Elements\n"
                        << n_elements << '\n'
                        << elements.str() << "$EndElements\n";
  }
} // namespace

TEST_CASE("Two bodies that overlap at the start by a fraction of an element "
          "are refused, in 2D and 3D, with the overlap measured",
          "[pairs][errors]")
{
  // prm/two_blocks_patch.prm and prm/two_blocks_patch_3d.prm on two blocks
  // one cell high whose contact faces (2/3 of the upper block's, 1 of the
  // lower block's wide) overlap by 0.1: the faces stay paired (the overlap
  // is within mortar::facing_tolerance()), and every slave node lies 0.1
  // inside the master body, more than a tenth of its spacing (m_s in 2D,
  // its square root in 3D, at most 2/3)
  const std::string directory =
    temporary_directory("overlapping_blocks", MPI_COMM_WORLD);
  const std::string file_2d = directory + "/overlapping_2d.msh";
  const std::string file_3d = directory + "/overlapping_3d.msh";
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      std::filesystem::create_directories(directory);
      write_overlapping_blocks_msh<2>(file_2d, 0.1);
      write_overlapping_blocks_msh<3>(file_3d, 0.1);
    }
  MPI_Barrier(MPI_COMM_WORLD);
  const auto mesh = [](const std::string &file) {
    return "subsection Geometry\n  set Type = mesh file\n  set Mesh file = " +
           file + "\nend\n";
  };
  const std::string words =
    "starts with the bodies overlapping: slave nodes lie up to 1.00e-01 "
    "[length] inside the master body";
  const CaughtError error_2d = catch_input_error(
    [&] { const Run run("two_blocks_patch.prm", mesh(file_2d)); });
  INFO("2D: " << error_2d.message);
  CHECK(error_2d.thrown);
  CHECK(error_2d.code == exit_inconsistent);
  CHECK(contains(error_2d.message, words));
  const CaughtError error_3d = catch_input_error(
    [&] { const SceneRun<3> run("two_blocks_patch_3d.prm", mesh(file_3d)); });
  INFO("3D: " << error_3d.message);
  CHECK(error_3d.thrown);
  CHECK(error_3d.code == exit_inconsistent);
  CHECK(contains(error_3d.message, words));
  remove_directory(directory, MPI_COMM_WORLD);
}

namespace
{
  /**
   * The largest difference of a pair's slave gap g0_s from the exact one,
   * over all ranks' contact nodes of the last mesh, relative to the
   * element there, and the number of nodes compared: two half discs
   * (balls) touching at the origin, the lower one of radius `lower` the
   * slave, the upper one of radius `upper` the master. The exact gap is the
   * distance from the slave node along its contact direction n_s to the
   * upper circle (sphere), where the line meets its lower half; a node
   * whose line misses it is not compared. The element at a node is the
   * distance to its nearest other contact node times the degree (the
   * nodes of a face of degree k are h / k apart).
   */
  template <int dim>
  std::pair<double, unsigned int>
  gap_deviation(const SceneRun<dim> &run,
                const double         upper,
                const unsigned int   degree)
  {
    const ContactSet<dim>  &contact = run.problem->contact();
    std::vector<Point<dim>> local;
    for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
      local.push_back(contact.nodes[s].position);
    std::vector<Point<dim>> all;
    for (const auto &part : Utilities::MPI::all_gather(run.comm, local))
      all.insert(all.end(), part.begin(), part.end());
    Point<dim> centre;
    centre[dim - 1]       = upper;
    double       worst    = 0.;
    unsigned int compared = 0;
    for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
      {
        const ContactNode<dim> &node = contact.nodes[s];
        // |x + t n - c|^2 = R^2: t^2 + 2 b t + q = 0
        const Tensor<1, dim> d = node.position - centre;
        const double         b = node.normal * d;
        const double         q = d.norm_square() - upper * upper;
        if (b * b - q < 0.)
          continue;
        const double t = -b - std::sqrt(b * b - q);
        if ((node.position + t * node.normal)[dim - 1] > upper)
          continue;
        double nearest = std::numeric_limits<double>::max();
        for (const Point<dim> &x : all)
          if (x.distance(node.position) > 1e-12)
            nearest = std::min(nearest, x.distance(node.position));
        worst = std::max(worst, std::abs(node.gap0 - t) / (degree * nearest));
        ++compared;
      }
    return {Utilities::MPI::max(worst, run.comm),
            Utilities::MPI::sum(compared, run.comm)};
  }
} // namespace

TEST_CASE("Two coarse discs and two coarse balls, the lower one the slave, "
          "are accepted, and every slave node's gap is the exact one to a "
          "fraction of an element",
          "[pairs]")
{
  // prm/two_cylinders.prm with R1 = 3 (upper, the master) and R2 = 2.8
  // (lower, the slave) at degree 2, on the coarse mesh refined once and
  // then halved (no pre-refinement), and prm/two_spheres.prm with the
  // lower ball the slave on the coarse mesh refined once and graded once.
  // The nodes beyond where the master faces face the slave see a part of
  // the master only; at some the point sum_j c_sj x_j lies far beyond the
  // master nodes (a gap of -7, more than the radii), and they face no
  // master (contact_pairs.cc). The gaps are exact to round-off where the
  // bodies touch; the largest differences, 0.38 of an element in 2D and
  // 0.27 in 3D, are at the partly covered nodes farthest from it, where
  // the master point of the dual basis lies beside the line along n_s on
  // a master surface inclined to it (gaps of 0.6 and 0.15).
  const std::string pair_2_0 =
    "subsection Boundary conditions\n  set Contact pairs = 2: 0\nend\n";
  {
    const Run run("two_cylinders.prm",
                  pair_2_0 +
                    "subsection Geometry\n  set Radius = 3\n"
                    "  set Lower radius = 2.8\n"
                    "  set Pre-refinement steps = 0\nend\n"
                    "subsection Discretization\n"
                    "  set Polynomial degree = 2\nend\n"
                    "subsection Refinement\n  set Initial global refinement "
                    "= 1\n  set Number of cycles = 2\nend\n");
    const auto [worst, compared] = gap_deviation(run, 3., 2);
    INFO("2D: " << compared << " of " << run.last().solve.n_contact_nodes
                << " contact nodes compared, the largest gap error " << worst
                << " of an element");
    CHECK(compared >= run.last().solve.n_contact_nodes / 2);
    CHECK(worst <= 0.5);
  }
  {
    const SceneRun<3> run("two_spheres.prm",
                          pair_2_0 +
                            "subsection Geometry\n"
                            "  set Pre-refinement steps = 1\nend\n"
                            "subsection Refinement\n  set Initial global "
                            "refinement = 1\n  set Number of cycles = "
                            "1\nend\n");
    const auto [worst, compared] = gap_deviation(run, 1., 1);
    INFO("3D: " << compared << " of " << run.last().solve.n_contact_nodes
                << " contact nodes compared, the largest gap error " << worst
                << " of an element");
    CHECK(compared >= run.last().solve.n_contact_nodes / 2);
    CHECK(worst <= 0.5);
  }
}

namespace
{
  // Two blocks on non-matching meshes, the upper one's bottom (id 5) the
  // slave, E = 1000, nu = 0.3; the conditions and loads come with each test
  std::string
  two_blocks(const std::string &boundary,
             const std::string &more         = "",
             const std::string &subdivisions = "10, 4")
  {
    return "subsection Geometry\n  set Type = two blocks\n  set Lower left "
           "corner = 0, 0\n  set Upper right corner = 2, 2\n  set "
           "Subdivisions = " +
           subdivisions +
           "\n  set Upper subdivisions = 7, 3\nend\n"
           "subsection Material\n  set Young's modulus = 1000\n  set "
           "Poisson's ratio = 0.3\nend\nsubsection Boundary conditions\n" +
           boundary + "end\n" + more;
  }

  const std::string coulomb =
    "subsection Friction\n  set Law = coulomb\n  set Coefficient = 0.4\nend\n";
} // namespace

TEST_CASE("A body that only its contact pair could hold, not pressed onto "
          "the other body by its loads, is refused (exit 7); without loads "
          "it rests",
          "[pairs][errors]")
{
  // prm/two_cylinders.prm: nothing holds the upper body but the contact
  for (const std::string traction : {"0; 4.3", "1; 0"})
    {
      const CaughtError error = catch_input_error([&] {
        const Run run("two_cylinders.prm",
                      "subsection Boundary conditions\n  set Tractions = 1: " +
                        traction + "\nend\n");
      });
      INFO("traction " << traction << ": " << error.message);
      CHECK(error.thrown);
      CHECK(error.code == exit_no_equilibrium);
      CHECK(contains(error.message,
                     "nothing holds the body with boundary ids 0, 1"));
    }
  // sliders that hold a block sideways only: pulled off the other block,
  // it is refused as well (a solve would end with exit 1, v drifting)
  {
    const CaughtError error = catch_input_error([&] {
      const Run run("",
                    two_blocks("  set Conditions = 0: normal fixed, 1: normal "
                               "fixed, 2: fixed, 3: traction\n  set Tractions "
                               "= 3: -0.3; 1\n  set Contact pairs = 4: 5\n"));
    });
    INFO(error.message);
    CHECK(error.thrown);
    CHECK(error.code == exit_no_equilibrium);
    CHECK(contains(error.message,
                   "the supports of the body with boundary ids 0, 1, 3, 5 "
                   "leave it free to move along the normal of its contact "
                   "pair"));
  }
  // a body without load is in equilibrium at u = 0, touching the other
  const Run run("two_cylinders.prm",
                "subsection Boundary conditions\n  set Tractions = 1: 0; "
                "0\nend\nsubsection Refinement\n  set Number of cycles = "
                "1\nend\n");
  CHECK(run.last().zone.contact_force == 0.);
  CHECK(run.problem->displacement().linfty_norm() < 1e-12);
}

namespace
{
  // the two cylinders of prm/two_cylinders.prm with E2 = 3 E1 and R2 = 2 R1:
  // the lower body (id 0) E = 3000, the upper (id 1) 1000; E* = 824.18,
  // R* = 2/3, and the load P = 9.7096 for a = 0.1 again, p0 = 61.813
  const std::string dissimilar =
    "subsection Geometry\n  set Lower radius = 2\nend\n"
    "subsection Material\n  set Young's modulus = 3000\n"
    "  set Materials by id = 1: 1000, 0.3\nend\n"
    "subsection Boundary conditions\n"
    "  set Tractions = 1: 0; -4.8547963396820295\nend\n"
    "subsection Exact solution\n"
    "  set Contact pressure = 61.81318681318682 * sqrt(max(0, 1 - x^2 / "
    "0.01))\n"
    "  set Peak pressure = 61.81318681318682\nend\n";

} // namespace

TEST_CASE("Hertz, two cylinders (prm/two_cylinders.prm): identical, then E2 "
          "= 3 E1 and R2 = 2 R1; the peak pressure within 1 % and the "
          "half-width within one contact element at 1e5 DoFs",
          "[pairs]")
{
  for (const bool same : {true, false})
    {
      INFO((same ? "identical cylinders" : "E2 = 3 E1, R2 = 2 R1"));
      const Run          run("two_cylinders.prm", same ? "" : dissimilar);
      const CycleResult &r = run.last();
      // the contact element at the zone's edge, a = 0.1
      const double element = largest_spacing(run, 0.11);
      INFO("DoFs " << r.mesh.n_dofs << ", peak error "
                   << r.zone.peak_pressure_error << ", half-width "
                   << r.zone.edge_half_width << " (element " << element
                   << "), pressure error " << r.zone.pressure_error);
      CHECK(r.mesh.n_dofs <= 100000);
      // the slave half circle beyond 60 degrees faces no master segment
      CHECK(r.solve.n_uncovered > 0);
      CHECK(std::abs(r.zone.peak_pressure_error) <= 0.01);
      CHECK(element > 0.);
      CHECK(std::abs(r.zone.edge_half_width - 0.1) <= element);
      // the load crosses the interface, and the bodies' forces balance
      CHECK(r.zone.contact_force ==
            Approx(same ? 8.630749048323608 : 9.709592679364059).epsilon(1e-8));
      CHECK(std::abs(r.zone.on_slave_body[1] + r.zone.on_master_body[1]) <=
            1e-10 * std::abs(r.zone.on_slave_body[1]));
      // the pressure converges under halving
      const auto &results = run.problem->results();
      CHECK(results.back().zone.pressure_error <
            0.6 * results[results.size() - 2].zone.pressure_error);
    }
}

TEST_CASE("Hertz, two spheres (prm/two_spheres.prm): the peak pressure "
          "within 2 % and the contact radius within one contact element at "
          "3e5 DoFs",
          "[pairs]")
{
  const SceneRun<3>  run("two_spheres.prm", "");
  const CycleResult &r = run.last();
  // Hertz for the load the discrete top carries (a polygon of the disc of
  // radius 1 under q = 0.466388): a and p0 scale as P^(1/3) from a = 0.1,
  // p0 = 69.948 at P = pi q
  const double P       = r.zone.contact_force;
  const double scale   = std::cbrt(P / (numbers::PI * 0.46638811162460175));
  const double a       = 0.1 * scale;
  const double p0      = 69.94756151337502 * scale;
  const double element = line_spacing(run, a);
  INFO("DoFs " << r.mesh.n_dofs << ", P " << P << ", peak "
               << r.zone.max_pressure << " (Hertz " << p0 << "), radius "
               << r.zone.edge_half_width << " (Hertz " << a << ", element "
               << element << ")");
  CHECK(r.mesh.n_dofs <= 300000);
  CHECK(std::abs(r.zone.max_pressure - p0) <= 0.02 * p0);
  CHECK(element > 0.);
  CHECK(std::abs(r.zone.edge_half_width - a) <= element);
  // the load crosses the interface whole, and the bodies' forces balance
  CHECK(r.zone.on_slave_body[2] == Approx(P).epsilon(1e-8));
  for (unsigned int c = 0; c < 3; ++c)
    CHECK(std::abs(r.zone.on_slave_body[c] + r.zone.on_master_body[c]) <=
          1e-10 * P);
  // the upper ball's sideways motions and its turn about the axis are held
  // by nothing but the proximal term: every mesh converges all the same
  for (const CycleResult &cycle : run.problem->results())
    CHECK(cycle.solve.uzawa_steps <= 15);
}

TEST_CASE("Hertz, two cylinders at degree 2 (curved faces along their "
          "chords): the peak within 1 % and the half-width within one node "
          "spacing",
          "[pairs]")
{
  const Run          run("two_cylinders.prm",
                "subsection Discretization\n  set Polynomial degree = 2\nend\n"
                         "subsection Refinement\n  set Number of cycles = 1\nend\n");
  const CycleResult &r       = run.last();
  const double       spacing = largest_spacing(run, 0.11);
  INFO("DoFs " << r.mesh.n_dofs << ", peak error " << r.zone.peak_pressure_error
               << ", half-width " << r.zone.edge_half_width << " (node spacing "
               << spacing << "), pressure error " << r.zone.pressure_error);
  CHECK(r.mesh.n_dofs <= 100000);
  CHECK(std::abs(r.zone.peak_pressure_error) <= 0.01);
  CHECK(spacing > 0.);
  CHECK(std::abs(r.zone.edge_half_width - 0.1) <= spacing);
  CHECK(r.zone.pressure_error <= 0.02);
  CHECK(std::abs(r.zone.on_slave_body[1] + r.zone.on_master_body[1]) <=
        1e-10 * std::abs(r.zone.on_slave_body[1]));
}

namespace
{
  /**
   * The coarse mesh of prm/two_cylinders.prm written as a Gmsh file (format
   * 2.2) by hand: every vertex its own node, so that the bodies share none
   * where they touch; quadrilaterals with their material ids as physical
   * surfaces, boundary lines with their boundary ids as physical curves.
   */
  void
  write_two_cylinders_msh(const std::string &file)
  {
    Parameters parameters;
    parameters.read_string(read_text(test_file("../prm/two_cylinders.prm")),
                           "subsection Refinement\n  set Initial global "
                           "refinement = 0\nend\n"
                           "subsection Geometry\n  set Pre-refinement steps "
                           "= 0\nend\n");
    const Scene<2>                          scene(parameters);
    parallel::distributed::Triangulation<2> coarse(MPI_COMM_SELF);
    scene.create_mesh(coarse);
    std::ostringstream nodes, elements;
    unsigned int       n_elements = 0;
    for (unsigned int v = 0; v < coarse.n_vertices(); ++v)
      nodes << v + 1 << ' ' << std::setprecision(17) << coarse.get_vertices()[v]
            << " 0\n";
    for (const auto &cell : coarse.active_cell_iterators())
      {
        elements << ++n_elements << " 3 2 " << int(cell->material_id()) << " "
                 << 1 + cell->material_id();
        for (const unsigned int v : {0u, 1u, 3u, 2u}) // counterclockwise
          elements << ' ' << cell->vertex_index(v) + 1;
        elements << '\n';
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            elements << ++n_elements << " 1 2 " << int(face->boundary_id())
                     << ' ' << 10 + face->boundary_id() << ' '
                     << face->vertex_index(0) + 1 << ' '
                     << face->vertex_index(1) + 1 << '\n';
      }
    std::ofstream(file) << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n"
                        << coarse.n_vertices() << '\n'
                        << nodes.str() << "$EndNodes\n$Elements\n"
                        << n_elements << '\n'
                        << elements.str() << "$EndElements\n";
  }
} // namespace

TEST_CASE("Two bodies read from a Gmsh file, their nodes where they touch "
          "not shared, give the built-in geometry's answer on the same mesh",
          "[pairs][mesh]")
{
  const std::string directory =
    temporary_directory("two_cylinders_msh", MPI_COMM_WORLD);
  const std::string file = directory + "/two_cylinders.msh";
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      std::filesystem::create_directories(directory);
      write_two_cylinders_msh(file);
    }
  MPI_Barrier(MPI_COMM_WORLD);
  const std::string two_meshes =
    "subsection Refinement\n  set Number of cycles = 2\nend\n"
    "subsection Geometry\n  set Pre-refinement steps = 0\nend\n";
  const Run built_in("two_cylinders.prm", two_meshes);
  const Run from_file("two_cylinders.prm",
                      two_meshes +
                        "subsection Geometry\n  set Type = mesh file\n"
                        "  set Mesh file = " +
                        file +
                        "\n  set Manifolds = 0: circle center 0, 1 radius 1; "
                        "2: circle center 0, -1 radius 1\nend\n");
  for (unsigned int cycle = 0; cycle < 2; ++cycle)
    {
      const CycleResult &a = built_in.problem->results()[cycle];
      const CycleResult &b = from_file.problem->results()[cycle];
      INFO("cycle " << cycle << ": peak " << a.zone.max_pressure << " and "
                    << b.zone.max_pressure << ", half-width "
                    << a.zone.edge_half_width << " and "
                    << b.zone.edge_half_width);
      CHECK(a.mesh.n_dofs == b.mesh.n_dofs);
      CHECK(a.solve.n_contact_nodes == b.solve.n_contact_nodes);
      CHECK(b.zone.max_pressure == Approx(a.zone.max_pressure).epsilon(1e-6));
      CHECK(b.zone.edge_half_width ==
            Approx(a.zone.edge_half_width).epsilon(1e-6));
      CHECK(b.zone.pressure_error ==
            Approx(a.zone.pressure_error).epsilon(1e-5));
    }
  remove_directory(directory, MPI_COMM_WORLD);
}

TEST_CASE("Two blocks of triangles read from a Gmsh file pass the contact "
          "patch test with either block the slave (pairs 4: 5 and 5: 4)",
          "[pairs][mesh][simplex]")
{
  // tests/prm/two_blocks_triangles.msh: prm/two_blocks_patch.prm's box in
  // 5 x 2 squares under 3 x 2, each cut into two triangles. A contact face
  // of a triangle holds two of its three vertices; the third, opposite the
  // face, is no node of it (support_on_face() in discretization.h, where
  // FE_SimplexP's has_support_on_face() counts every function): with the
  // lower block's top the slave, such a vertex of its top row of triangles
  // (weight 0 up to round-off) is no slave node either.
  std::vector<double> forces;
  for (const std::string pair : {"4: 5", "5: 4"})
    {
      INFO("the contact pair " << pair);
      const Run    run("two_blocks_patch.prm",
                    tight +
                      "subsection Geometry\n  set Type = mesh file\n"
                         "  set Mesh file = " +
                      test_file("prm/two_blocks_triangles.msh") +
                      "\nend\nsubsection Boundary conditions\n"
                         "  set Contact pairs = " +
                      pair + "\nend\n");
      Tensor<1, 2> q;
      const auto [l1, l2] = deviation(run, 1., q);
      for (const CycleResult &r : run.problem->results())
        {
          INFO("cycle " << r.mesh.cycle << ": error "
                        << r.errors.error_L2 / r.errors.norm_L2);
          // the slave's nodes: the lower block's 5 (10) faces or the upper
          // block's 3 (6), all facing the master
          CHECK(r.solve.n_contact_nodes ==
                (pair == "4: 5" ? 5 : 3) * (1u << r.mesh.cycle) + 1);
          CHECK(r.solve.n_uncovered == 0);
          CHECK(r.errors.error_L2 <= 1e-8 * r.errors.norm_L2);
          CHECK(r.zone.contact_force == Approx(2.).epsilon(1e-10));
          for (unsigned int c = 0; c < 2; ++c)
            CHECK(std::abs(r.zone.on_slave_body[c] +
                           r.zone.on_master_body[c]) <= 1e-10 * 2.);
        }
      INFO("largest |l1 - p| " << l1);
      CHECK(l1 <= 1e-8);
      forces.push_back(run.last().zone.contact_force);
    }
  REQUIRE(forces.size() == 2);
  CHECK(forces[0] == Approx(forces[1]).epsilon(1e-10));
}

TEST_CASE("A pair whose surface ends at a coarse edge of a boundary split "
          "into ids, refined on one side of the edge at degree 2: its nodes "
          "that hang on a node off the surface, on the slave or on the "
          "master, are coupled",
          "[pairs][mesh]")
{
  // tests/prm/block_on_split_top.msh: a block on the middle of a row of
  // three hexahedra whose top has id 6 in the middle and 8 at the ends.
  // Refined toward the pair, the middle hexahedron and the one on the
  // right are split, the one on the left is not: on the edge x = 1 of the
  // middle top the nodes of degree 2 hang on the DoF inside the coarse
  // edge, which lies on the left top (id 8) alone. The load on the upper
  // block's top, 1 on 0.8 x 0.6, crosses the interface whole.
  const std::string scene =
    "subsection Geometry\n  set Dimension = 3\n  set Type = mesh file\n"
    "  set Mesh file = " +
    test_file("prm/block_on_split_top.msh") +
    "\n  set Pre-refinement steps = 1\n"
    "  set Pre-refinement distance = 0.5\nend\n"
    "subsection Discretization\n  set Polynomial degree = 2\nend\n"
    "subsection Refinement\n  set Number of cycles = 1\nend\n"
    "subsection Boundary conditions\n  set Conditions = 4: fixed, 5: "
    "traction\n  set Tractions = 5: 0; 0; -1\n  set Contact pairs = ";
  for (const std::string pair : {"7: 6", "6: 7"})
    {
      const SceneRun<3>  run("", scene + pair + "\nend\n");
      const CycleResult &r = run.last();
      INFO("the contact pair " << pair << ": " << r.solve.n_contact_nodes
                               << " contact nodes, "
                               << r.solve.n_hanging_contact << " hanging");
      CHECK(r.zone.contact_force == Approx(0.48).epsilon(1e-8));
      for (unsigned int c = 0; c < 3; ++c)
        CHECK(std::abs(r.zone.on_slave_body[c] + r.zone.on_master_body[c]) <=
              1e-10 * 0.48);
      // with the lower block's top the slave, its hanging nodes at x = 1
      if (pair == "6: 7")
        CHECK(r.solve.n_hanging_contact > 0);
    }
}

TEST_CASE("Cattaneo-Mindlin and Mindlin-Deresiewicz between two identical "
          "cylinders at nu = 0.3 with Q1 (beta = 0): stick zones, tractions "
          "and the energy of a cycle",
          "[path][pairs]")
{
  const Run                       run("two_cylinders_cattaneo.prm", "");
  const std::vector<CycleResult> &steps = run.problem->steps();
  REQUIRE(steps.size() == 11);
  const double F  = 0.3;
  const double nu = run.parameters.material.poissons_ratio;
  // two bodies of one material, R1 = R2 = 1
  const double E_star =
    run.parameters.material.youngs_modulus / (2. * (1. - nu * nu));
  const double R_star = 0.5;
  // Q along the first shear (step 3 is Q*), signed by the clamp's reaction
  const double sign = steps[2].reactions.on_id.at(1)[0] > 0. ? 1. : -1.;
  const auto   Q    = [&](const unsigned int n) {
    return sign * steps[n].reactions.on_id.at(1)[0];
  };
  const double P  = steps[0].zone.contact_force;
  const double a  = std::sqrt(4. * P * R_star / (numbers::PI * E_star));
  const double p0 = 2. * P / (numbers::PI * a);
  const double h  = largest_spacing(run, 1.2 * a);
  INFO("P = " << P << ", a = " << a << ", contact element " << h
              << ", Q*/(F P) = " << Q(2) / (F * P));
  CHECK(Q(2) / (F * P) > 0.6);
  CHECK(h > 0.);

  // q_d(x) = F (p0/a) sqrt(d^2 - x^2), the branches' superpositions
  const auto q_d = [&](const double x, const double d) {
    return F * p0 / a * std::sqrt(std::max(d * d - x * x, 0.));
  };
  // the turning points: Q* at step 3, -Q* at step 7, Q* at step 11
  const double c_up   = a * std::sqrt(1. - Q(2) / (F * P));
  const double c_down = a * std::sqrt(1. + Q(6) / (F * P));
  for (unsigned int n = 1; n < 11; ++n)
    {
      // beta = 0: the shear leaves the normal force as it was
      CHECK(std::abs(steps[n].zone.contact_force - P) <= 1e-6 * P);
      double                        c = 0.;
      std::function<double(double)> q;
      if (n <= 2) // loading from 0 to Q*
        {
          c = a * std::sqrt(1. - Q(n) / (F * P));
          q = [&, c](double x) { return q_d(x, a) - q_d(x, c); };
        }
      else if (n <= 6) // unloading from Q* to -Q*
        {
          c = a * std::sqrt(1. - (Q(2) - Q(n)) / (2. * F * P));
          q = [&, c](double x) {
            return -q_d(x, a) + 2. * q_d(x, c) - q_d(x, c_up);
          };
        }
      else // reloading from -Q* to Q*
        {
          c = a * std::sqrt(1. - (Q(n) - Q(6)) / (2. * F * P));
          q = [&, c](double x) {
            return q_d(x, a) - 2. * q_d(x, c) + q_d(x, c_down);
          };
        }
      const double measured = steps[n].zone.stick_half_width;
      INFO("step " << n + 1 << ": Q/(F P) = " << Q(n) / (F * P)
                   << ", stick half-width " << measured << " against " << c
                   << " (" << (measured - c) / h << " contact elements)");
      CHECK(std::abs(measured - c) <= h);

      // the tangential traction of contact_pair_0_2_step_NNN.csv (the
      // pair's rows of contact_step_NNN.csv) against the
      // branch's superposition, RMS over |x| < a with the nodal weights
      std::ostringstream name;
      name << run.directory << "/contact_pair_0_2_step_" << std::setw(3)
           << std::setfill('0') << n + 1 << ".csv";
      const CsvFile table(name.str(), run.comm);
      double        sum = 0., measure = 0.;
      for (unsigned int i = 0; i < table.rows(); ++i)
        {
          const double x = table.value(i, "x");
          if (std::abs(x) >= a)
            continue;
          const double w = table.value(i, "weight");
          const double e = sign * table.value(i, "l2") - q(x);
          sum += w * e * e;
          measure += w;
        }
      const double rms = std::sqrt(sum / measure) / (F * p0);
      INFO("step " << n + 1 << ": RMS traction error " << rms << " F p0");
      CHECK(measure > 1.9 * a);
      CHECK(rms <= 0.03);
      // the forces on the two bodies are equal and opposite
      for (const unsigned int d : {0u, 1u})
        CHECK(std::abs(steps[n].zone.on_slave_body[d] +
                       steps[n].zone.on_master_body[d]) <= 1e-10 * P);
      // each body in equilibrium: its reactions, its loads (none) and the
      // contact force on it; the lower half disc is body 0, the master
      const ReactionRecord &reactions = steps[n].reactions;
      REQUIRE(reactions.on_body.size() == 2);
      for (const unsigned int d : {0u, 1u})
        {
          CHECK(std::abs(reactions.on_body[0][d] +
                         reactions.load_on_body[0][d] +
                         steps[n].zone.on_master_body[d]) <= 1e-8 * P);
          CHECK(std::abs(reactions.on_body[1][d] +
                         reactions.load_on_body[1][d] +
                         steps[n].zone.on_slave_body[d]) <= 1e-8 * P);
          CHECK(reactions.on_body[1][d] == reactions.on_id.at(1)[d]);
        }
    }

  // The energy of the cycle Q* -> -Q* -> Q* (steps 3-11): the dissipation
  // summed over its steps against the work of the loads, the loop of Q
  // over the clamp's displacement (Simpson's rule on each half cycle's four
  // equal displacement steps: the branches are smooth between the turning
  // points), and against the closed form W_2D of doc/theory.md §11.
  const auto displacement = [&](const unsigned int n) {
    return sign * steps[n].step.boundary_displacement.at(1)[0];
  };
  const auto simpson = [&](const unsigned int i) {
    const double dx = displacement(i + 1) - displacement(i);
    return dx / 3. *
           (Q(i) + 4. * Q(i + 1) + 2. * Q(i + 2) + 4. * Q(i + 3) + Q(i + 4));
  };
  const double work = simpson(2) + simpson(6);
  const double dissipated =
    steps[10].step.dissipation_total - steps[2].step.dissipation_total;
  // W_2D = 16 F^2 p0^2 / (E* a) int_c^a sqrt(1 - x^2/a^2) S(x) dx, the
  // midpoint rule on 20000 intervals
  const double       c           = c_up;
  double             integral    = 0.;
  const unsigned int n_intervals = 20000;
  for (unsigned int k = 0; k < n_intervals; ++k)
    {
      const double x = c + (a - c) * (k + 0.5) / n_intervals;
      const double r = std::sqrt(x * x - c * c);
      const double S = 0.5 * (x * r - c * c * std::log((x + r) / c));
      integral += std::sqrt(1. - x * x / (a * a)) * S * (a - c) / n_intervals;
    }
  const double closed_form = 16. * F * F * p0 * p0 / (E_star * a) * integral;
  INFO("dissipated over the cycle " << dissipated << ", work of the loads "
                                    << work << ", closed form " << closed_form);
  CHECK(std::abs(work - dissipated) <= 0.02 * dissipated);
  CHECK(std::abs(dissipated - closed_form) <= 0.05 * closed_form);
}


TEST_CASE("A slider on one side of two blocks with friction between them: "
          "the slider's reaction takes the tangential multiplier of the "
          "contact nodes it holds, and every body balances",
          "[pairs]")
{
  // id 0 (the left sides of both blocks) holds the x-motion of the pair's
  // end nodes, slave and master: the friction there acts on DoFs that the
  // slider constrains, which its reaction must count
  const Run          run("",
                two_blocks("  set Conditions = 0: normal fixed, 2: fixed, 3: "
                                    "traction\n  set Tractions = 3: 0; -1\n  set "
                                    "Contact pairs = 5: 4\n",
                           coulomb));
  const CycleResult &r = run.last();
  INFO("imbalance " << r.reactions.imbalance << ", slider "
                    << r.reactions.on_id.at(0)[0]);
  CHECK(r.reactions.imbalance < 1e-10);
  // the slider holds the upper block sideways against the friction of
  // its end node (0.0455 measured)
  REQUIRE(r.reactions.on_body.size() == 2);
  CHECK(std::abs(r.reactions.on_body[1][0]) > 1e-2);
  for (unsigned int b = 0; b < 2; ++b)
    for (unsigned int c = 0; c < 2; ++c)
      CHECK(std::abs(r.reactions.on_body[b][c] +
                     r.reactions.load_on_body[b][c] +
                     r.reactions.contact_on_body[b][c]) < 1e-10);
}

TEST_CASE("Sliders on the sides of two blocks with given or Coulomb "
          "friction between them (2D and 3D): friction acts along the "
          "tangents the sliders leave free, and the Uzawa iteration takes a "
          "few steps, as without the sliders",
          "[pairs]")
{
  // The pair's end nodes lie on the sliders: a friction multiplier along
  // the held tangent would move the master alone, through the few c_sj of
  // the node's end, a mode so weak that the iteration would contract at
  // 0.98 a step and stop after 500 (exit 1).
  const std::string given =
    "subsection Friction\n  set Law = given\n  set Threshold = 0.3\nend\n";
  for (const std::string &friction : {given, coulomb})
    {
      const Run          run("",
                    two_blocks("  set Conditions = 0: normal fixed, 1: "
                                        "normal fixed, 2: fixed, 3: traction\n  set "
                                        "Tractions = 3: 0.25; -1\n  set Contact pairs "
                                        "= 5: 4\n",
                               friction));
      const CycleResult &r = run.last();
      INFO(friction << "Uzawa steps " << r.solve.uzawa_steps << ", imbalance "
                    << r.reactions.imbalance);
      CHECK(r.solve.uzawa_steps <= 20);
      CHECK(r.reactions.imbalance < 1e-10);
      // the two end nodes: no tangent, no friction
      const ContactSet<2> &contact = run.problem->contact();
      unsigned int         held    = 0;
      for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
        if (contact.nodes[s].tangents[0].norm() == 0.)
          {
            ++held;
            CHECK(contact.l2[s].norm() == 0.);
          }
      CHECK(Utilities::MPI::sum(held, MPI_COMM_WORLD) == 2);
    }
  // 3D: sliders on one x side and one y side, the shear along both
  for (const std::string &friction : {given, coulomb})
    {
      const SceneRun<3>  run("",
                            "subsection Geometry\n  set Dimension = 3\n  set "
                             "Type = two blocks\n  set Lower left corner = 0, "
                             "0, 0\n  set Upper right corner = 2, 2, 2\n  set "
                             "Subdivisions = 3, 3, 1\n  set Upper subdivisions "
                             "= 2, 2, 1\nend\nsubsection Material\n  set "
                             "Young's modulus = 1000\n  set Poisson's ratio = "
                             "0.3\nend\nsubsection Boundary conditions\n  set "
                             "Conditions = 0: normal fixed, 2: normal fixed, "
                             "4: fixed, 5: traction\n  set Tractions = 5: "
                             "0.15; 0.2; -1\n  set Contact pairs = 7: 6\nend\n"
                             "subsection Refinement\n  set Initial global "
                             "refinement = 1\nend\n" +
                              friction);
      const CycleResult &r = run.last();
      INFO(friction << "Uzawa steps " << r.solve.uzawa_steps << ", imbalance "
                    << r.reactions.imbalance);
      CHECK(r.solve.uzawa_steps <= 25);
      CHECK(r.reactions.imbalance < 1e-10);
    }
}

TEST_CASE("An upper block reaching beyond the lower one as the slave, in 3D "
          "with Coulomb friction: a slave node that the master covers by a "
          "sliver takes a whole node's augmentation, and the Uzawa iteration "
          "takes a few steps",
          "[pairs]")
{
  // The corner nodes beyond the lower block's edges are covered by 5e-4 of
  // their weight: with m_s r alone their gaps would converge at 0.87 a
  // step without friction (129 Uzawa steps) and at 0.98 with it (exit 1
  // after 500).
  for (const std::string law : {"none", "coulomb"})
    {
      const std::string shear =
        law == "none" ? "0; 0" : "2.636e-06; -3.514e-06";
      const SceneRun<3>  run("",
                            "subsection Geometry\n  set Dimension = 3\n  set "
                             "Type = two blocks\n  set Lower left corner = "
                             "-0.861, -1.68, 1.64\n  set Upper right corner = "
                             "0.959, -0.61, 2.734\n  set Upper overhang = "
                             "0.45\n  set Subdivisions = 2, 3, 1\n  set Upper "
                             "subdivisions = 3, 3, 2\nend\nsubsection "
                             "Material\n  set Young's modulus = 0.036\n  set "
                             "Poisson's ratio = 0.05\nend\nsubsection Boundary "
                             "conditions\n  set Conditions = 4: fixed, 5: "
                             "traction\n  set Contact pairs = 7: 6\n  set "
                             "Tractions = 5: " +
                              shear +
                              "; -6.12e-05\nend\nsubsection Friction\n  set "
                               "Law = " +
                              law +
                              "\n  set Coefficient = 1\nend\nsubsection "
                               "Refinement\n  set Initial global refinement = "
                               "1\nend\n");
      const CycleResult &r = run.last();
      INFO(law << ": Uzawa steps " << r.solve.uzawa_steps << ", imbalance "
               << r.reactions.imbalance);
      CHECK(r.solve.uzawa_steps <= (law == "none" ? 10u : 20u));
      CHECK(r.reactions.imbalance < 1e-8);
      CHECK(r.solve.n_contact_nodes == 19);
    }
}

TEST_CASE("Two blocks stacked on the plane: the obstacle's force and the "
          "pair's apart, whichever side is the slave",
          "[pairs]")
{
  // the pair's normal (the lower block's top, or the upper one's bottom)
  // and the plane's must not be averaged: the plane holds 2, the pair 2
  for (const std::string subdivisions : {"3, 4", "4, 4"})
    for (const std::string pair : {"5: 4", "4: 5"})
      {
        const Run          run("",
                      two_blocks("  set Conditions = 2: contact, 3: "
                                          "traction\n  set Tractions = 3: 0; -1\n  set "
                                          "Contact pairs = " +
                                   pair + "\n",
                                 "",
                                 subdivisions));
        const CycleResult &r = run.last();
        INFO("lower block " << subdivisions << ", pair " << pair);
        CHECK(r.zone.obstacle_force == Approx(2.).epsilon(1e-10));
        REQUIRE(r.zone.pair_force.size() == 1);
        CHECK(r.zone.pair_force[0] == Approx(2.).epsilon(1e-10));
        CHECK(r.zone.contact_force == Approx(4.).epsilon(1e-10));
        CHECK(r.reactions.imbalance < 1e-10);
        REQUIRE(r.reactions.contact_on_body.size() == 2);
        // the lower block: the plane's 2 up, the upper block's 2 down
        CHECK(std::abs(r.reactions.contact_on_body[0][1]) < 1e-10);
        CHECK(r.reactions.contact_on_body[1][1] == Approx(2.).epsilon(1e-10));
      }
}

TEST_CASE("A block held sideways by friction alone on another: every start "
          "of the threshold iteration solves it, and the tangential load "
          "friction cannot hold is refused before the solve (exit 7)",
          "[pairs][errors]")
{
  // the top traction (0.2, -1) on the upper block: Q / (F N) = 0.5 at F =
  // 0.4; g = 0 (nested) or the frictionless pressure could not hold it,
  // and the iteration starts from the mean pressure of the pair
  const std::string scene =
    two_blocks("  set Conditions = 2: fixed, 3: traction\n  set Tractions = "
               "3: 0.2; -1\n  set Contact pairs = 5: 4\n");
  const Run          merged("", scene + coulomb);
  const CycleResult &m = merged.last();
  CHECK(m.reactions.imbalance < 1e-10);
  for (const std::string start : {"  set Threshold iteration = nested\n",
                                  "  set Initial threshold = frictionless\n"})
    {
      const Run          run("",
                    scene +
                      "subsection Friction\n  set Law = coulomb\n  set "
                               "Coefficient = 0.4\n" +
                      start + "end\n");
      const CycleResult &r = run.last();
      INFO(start);
      CHECK(r.reactions.imbalance < 1e-10);
      CHECK(r.zone.tangential_force == Approx(0.4).epsilon(1e-6));
      CHECK(r.zone.contact_force == Approx(m.zone.contact_force).epsilon(1e-8));
    }
  // the tangential load 0.4 against F N = 0.2 and 0 (frictionless)
  for (const std::string friction :
       {"subsection Friction\n  set Law = coulomb\n  set Coefficient = "
        "0.1\nend\n",
        "subsection Friction\n  set Law = none\n  set Coefficient = 0\nend\n"})
    {
      const CaughtError error =
        catch_input_error([&] { const Run run("", scene + friction); });
      INFO(friction << error.message);
      CHECK(error.thrown);
      CHECK(error.code == exit_no_equilibrium);
      CHECK(contains(error.message,
                     "the net tangential load 4.00e-01 on the body with "
                     "boundary ids 0, 1, 3, 5 exceeds what friction can "
                     "resist"));
    }
}

TEST_CASE("A load path that unloads two bodies to zero: the last step rests "
          "at zero contact force",
          "[pairs][path]")
{
  const Run   run("",
                two_blocks("  set Conditions = 2: fixed, 3: traction\n  set "
                             "Tractions = 3: 0; -if(t <= 1, t, 2 - t)\n  set "
                             "Contact pairs = 5: 4\n",
                           "subsection Load path\n  set Number of steps = "
                             "4\n  set End time = 2\nend\n"));
  const auto &steps = run.problem->steps();
  REQUIRE(steps.size() == 4);
  CHECK(steps[1].zone.contact_force == Approx(2.).epsilon(1e-8));
  CHECK(std::abs(steps[3].zone.contact_force) < 1e-10);
  CHECK(steps[3].reactions.imbalance < 1e-6);
  // Coulomb friction and a shear, with the predictor, merged and nested:
  // the last step starts from thresholds of round-off size, and its change
  // of g is measured against the previous step's g too (relative to g
  // alone it stalls at d(g) 5e-3, exit 1)
  for (const std::string iteration : {"merged", "nested"})
    {
      const Run   path("",
                     two_blocks("  set Conditions = 2: fixed, 3: traction\n"
                                  "  set Tractions = 3: 0.1 * if(t <= 1, t, 2 "
                                  "- t); -if(t <= 1, t, 2 - t)\n  set Contact "
                                  "pairs = 5: 4\n",
                                "subsection Friction\n  set Law = coulomb\n"
                                  "  set Coefficient = 0.4\n  set Threshold "
                                  "iteration = " +
                                  iteration +
                                  "\nend\nsubsection Load path\n  set Number "
                                    "of steps = 4\n  set End time = 2\nend\n"));
      const auto &path_steps = path.problem->steps();
      INFO(iteration);
      REQUIRE(path_steps.size() == 4);
      CHECK(path_steps[1].zone.contact_force == Approx(2.).epsilon(1e-8));
      CHECK(std::abs(path_steps[3].zone.contact_force) < 1e-10);
      CHECK(path_steps[3].reactions.imbalance < 1e-6);
    }
}

TEST_CASE("A pair cut by its planes of symmetry: the half of two cylinders "
          "gives the whole model's pressure and half-width, a quarter of two "
          "balls converges to Hertz's; both balance",
          "[pairs]")
{
  // the sliders on the symmetry plane hold the pair's end nodes sideways:
  // their contact force goes into the sliders' reactions, and on 2 ranks a
  // master DoF on the plane off a rank's cells is known as constrained
  const std::string one_mesh =
    "subsection Refinement\n  set Number of cycles = 1\n  set Initial "
    "global refinement = 3\nend\nsubsection Geometry\n  set Pre-refinement "
    "steps = 3\nend\n";
  const Run          whole("two_cylinders.prm", one_mesh);
  const Run          half("../tests/prm/two_cylinders_half.prm",
                 one_mesh + "subsection Geometry\n  set Mesh file = " +
                   test_file("prm/meshes/two_quarter_discs.msh") + "\nend\n");
  const CycleResult &w = whole.last(), &h = half.last();
  INFO("whole: " << w.mesh.n_dofs << " DoFs, peak " << w.zone.max_pressure
                 << ", half-width " << w.zone.half_width << "; half: "
                 << h.mesh.n_dofs << " DoFs, peak " << h.zone.max_pressure
                 << ", half-width " << h.zone.half_width);
  CHECK(h.mesh.n_cells * 2 == w.mesh.n_cells);
  // (the same to the Uzawa tolerance, 1e-8: the sliders turn the normals
  // of the pair's nodes on the cut into its plane, as they lie in the
  // whole model)
  CHECK(h.zone.max_pressure == Approx(w.zone.max_pressure).epsilon(1e-8));
  CHECK(h.zone.half_width == Approx(w.zone.half_width).epsilon(1e-10));
  CHECK(h.zone.edge_half_width == Approx(w.zone.edge_half_width).epsilon(1e-8));
  CHECK(h.zone.pressure_error == Approx(w.zone.pressure_error).epsilon(1e-8));
  CHECK(2. * h.zone.contact_force ==
        Approx(w.zone.contact_force).epsilon(1e-8));
  CHECK(h.reactions.imbalance < 1e-10);

  // a quarter of two balls (tetrahedra, 7113 DoFs): +4.7 % peak and -1.8 %
  // radius measured (+2.4 % and -0.8 % on the next mesh, 49416 DoFs)
  const SceneRun<3> quarter(
    "../tests/prm/two_spheres_quarter.prm",
    "subsection Refinement\n  set Number of cycles = 1\nend\nsubsection "
    "Geometry\n  set Mesh file = " +
      test_file("prm/meshes/two_sphere_octants.msh") + "\nend\n");
  const CycleResult &q = quarter.last();
  // Hertz for the load the discrete top carries, four times the quarter's
  const double P  = 4. * q.zone.contact_force;
  const double k  = std::cbrt(P / (numbers::PI * 0.46638811162460175));
  const double a  = 0.1 * k;
  const double p0 = 69.94756151337502 * k;
  INFO("quarter: " << q.mesh.n_dofs << " DoFs, P " << P << ", peak "
                   << q.zone.max_pressure << " (Hertz " << p0 << "), radius "
                   << q.zone.edge_half_width << " (Hertz " << a << ")");
  CHECK(q.reactions.imbalance < 1e-10);
  CHECK(q.zone.contact_force == Approx(q.solve.normal_load).epsilon(1e-8));
  CHECK(std::abs(q.zone.max_pressure / p0 - 1.) < 0.06);
  CHECK(std::abs(q.zone.edge_half_width / a - 1.) < 0.03);
  CHECK(q.zone.mirrored == 2);
}
