// Simplices (<Geometry/Cell type> = simplex, or a mesh file of triangles or
// tetrahedra): the patch tests are exact on triangles (P1, P2) and
// tetrahedra (P1), nested meshes carry the fields exactly, Hertz's contact
// on triangles is as accurate as on quadrilaterals, and Coulomb friction
// gives the stick zone of quadrilaterals. Every assertion is on a value
// reduced over all ranks.

#include <deal.II/base/mpi.h>

#include <dualcontact/contact_problem.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>
#include <vector>

#include "scene_run.h"
#include "test_tools.h"

using namespace dualcontact;
using namespace dualcontact_test;

namespace
{
  std::string
  simplices(const unsigned int degree)
  {
    return "subsection Geometry\n  set Cell type = simplex\nend\n"
           "subsection Discretization\n  set Polynomial degree = " +
           std::to_string(degree) + "\nend\n";
  }

  const std::string one_mesh =
    "subsection Refinement\n  set Number of cycles = 1\nend\n";

  // prm/patch.prm (E = 1000, nu = 0, the block [0, 2] x [0, 1] on the
  // plane y = 0, the pressure 1 on its top): u = (0, -1e-3 y)
  const std::string frictionless_2d =
    "subsection Exact solution\n  set Displacement = 0; -0.001 * y\n"
    "  set Contact pressure = 1\nend\n"
    "subsection Solver\n  set Uzawa tolerance = 1e-11\nend\n";

  /**
   * The patch test's figures: every node in contact (and stuck, with
   * friction) with the pressure 1 and the shear q, the displacement exact,
   * the contact force the load.
   */
  template <int dim>
  void
  check_patch(const SceneRun<dim>  &run,
              const Tensor<1, dim> &q,
              const bool            friction,
              const unsigned int    n_nodes,
              const double          force)
  {
    const CycleResult &r = run.last();
    const auto [l1, l2]  = deviation(run, 1., q);
    INFO(dim << "D" << (friction ? " stick" : " frictionless") << ": error "
             << r.errors.error_L2 / r.errors.norm_L2 << ", largest |l1 - 1| "
             << l1 << ", |l2 - q| " << l2);
    CHECK(r.solve.n_contact_nodes == n_nodes);
    CHECK(r.solve.n_active == r.solve.n_contact_nodes);
    CHECK(r.errors.error_L2 <= 1e-10 * r.errors.norm_L2);
    CHECK(r.zone.contact_force == Approx(force).epsilon(1e-10));
    CHECK(l1 <= 1e-8);
    if (friction)
      {
        CHECK(l2 <= 1e-8);
        CHECK(r.solve.n_stick == r.solve.n_contact_nodes);
      }
  }
} // namespace

TEST_CASE("Patch tests on triangles (P1, P2) and tetrahedra (P1): the "
          "pressure 1 at every node and the exact displacement, frictionless "
          "and all stick under shear",
          "[simplex]")
{
  for (const bool friction : {false, true})
    {
      // prm/patch.prm with the shear 0.2 (scene_run.h), or without friction
      for (const unsigned int k : {1u, 2u})
        {
          INFO("P" << k);
          Tensor<1, 2> q;
          q[0] = friction ? 0.2 : 0.;
          // the 16 edges of the plane at the last mesh: 16 k + 1 nodes
          check_patch(Run("patch.prm",
                          simplices(k) +
                            (friction ? patch_stick_2d : frictionless_2d)),
                      q,
                      friction,
                      16 * k + 1,
                      2.);
        }
      // prm/patch_3d.prm itself: the shear (0.2, 0.1) below F p = 0.5; the
      // 4 x 4 squares of the plane, 2 triangles each, on the last mesh:
      // (8 + 1)^2 vertices
      Tensor<1, 3> q;
      q[0] = friction ? 0.2 : 0.;
      q[1] = friction ? 0.1 : 0.;
      check_patch(SceneRun<3>("patch_3d.prm",
                              simplices(1) +
                                (friction ? "subsection Solver\n  set "
                                            "Uzawa tolerance = 1e-11\nend\n" :
                                            patch_frictionless_3d)),
                  q,
                  friction,
                  81,
                  4.);
    }
}

TEST_CASE("Nested meshes of triangles: the fields carried to the refined mesh "
          "are the coarse solution, exact for P1, so the patch test's second "
          "mesh needs one Uzawa step",
          "[simplex]")
{
  const Run   run("patch.prm",
                simplices(1) + frictionless_2d +
                  "subsection Refinement\n  set Number of cycles = 3\nend\n");
  const auto &results = run.problem->results();
  REQUIRE(results.size() == 3);
  for (unsigned int cycle = 1; cycle < 3; ++cycle)
    {
      const CycleResult &r = results[cycle];
      INFO("cycle " << cycle << ": " << r.solve.uzawa_steps
                    << " Uzawa steps, smallest carried l1 "
                    << r.transfer.carried_min_l1);
      CHECK(r.transfer.warm_start);
      // l1 = 1 everywhere: the smallest carried value is the largest
      CHECK(r.transfer.carried_min_l1 == Approx(1.).epsilon(1e-8));
      CHECK(r.solve.uzawa_steps == 1);
      CHECK(r.errors.error_L2 <= 1e-10 * r.errors.norm_L2);
    }
}

TEST_CASE("Hertz on triangles: the peak pressure within 1 % and the contact "
          "half-width within one contact element on fewer than 1e5 DoFs, on "
          "the built-in half disc and on a Gmsh mesh of triangles",
          "[simplex]")
{
  // prm/hertz.prm (a = 0.1, p0 = 54.945): the built-in half disc, each of
  // its quadrilaterals into 8 triangles, the pre-refinement toward the
  // plane, P1 on two meshes and P2 on the first; prm/mesh_hertz_triangles.prm:
  // 368 graded triangles from Gmsh, 3 global refinements, one mesh
  const std::vector<std::pair<std::string, std::string>> scenes = {
    {"hertz.prm", simplices(1)},
    {"hertz.prm", simplices(2) + one_mesh},
    {"mesh_hertz_triangles.prm",
     one_mesh + "subsection Geometry\n  set Mesh file = " +
       test_file("../prm/meshes/half_disc_triangles.msh") + "\nend\n"}};
  for (const auto &[scene, overrides] : scenes)
    {
      const Run          run(scene, overrides);
      const CycleResult &r = run.last();
      // the contact element within 2 a of the centre
      const double element = largest_spacing(run, 0.2);
      INFO(scene << ": " << r.mesh.n_dofs << " DoFs, peak error "
                 << r.zone.max_pressure / 54.94505494505495 - 1.
                 << ", half-width " << r.zone.edge_half_width
                 << ", contact element " << element);
      CHECK(r.mesh.n_dofs <= 100000);
      CHECK(std::abs(r.zone.max_pressure / 54.94505494505495 - 1.) <= 0.01);
      CHECK(std::abs(r.zone.edge_half_width - 0.1) <= element);
      CHECK(r.zone.pressure_error <= 0.02);
      // P2 with the quadratic map of its cells, the nodes in the middle of
      // the contact faces on the circle: measured 0.0034 at 71662 DoFs (on
      // hertz_adaptive's meshes, with those nodes on the chords, P2 had
      // 1.8e-2 at 72098 DoFs, and 4.6e-3 with them on the circle)
      if (run.parameters.discretization.degree == 2)
        CHECK(r.zone.pressure_error <= 0.005);
    }
}

TEST_CASE("Hertz on tetrahedra: the peak pressure within 3 % and the contact "
          "radius within one contact element on fewer than 3e5 DoFs, on a "
          "Gmsh octant of the ball",
          "[simplex]")
{
  // prm/hertz_3d_tetrahedra.prm (a = 0.1, p0 = 69.948): 1011 nodes graded
  // toward the contact, halved twice (152139 DoFs)
  const SceneRun<3> run(
    "hertz_3d_tetrahedra.prm",
    "subsection Geometry\n  set Mesh file = " +
      test_file("../prm/meshes/ball_octant_tetrahedra.msh") + "\nend\n");
  const CycleResult &r       = run.last();
  const double       p0      = 69.94756151337502;
  const double       element = line_spacing(run, 0.1);
  INFO(r.mesh.n_dofs << " DoFs, peak error " << r.zone.max_pressure / p0 - 1.
                     << ", radius " << r.zone.edge_half_width
                     << ", contact element " << element << ", L2 error "
                     << r.zone.pressure_error);
  CHECK(r.mesh.n_dofs <= 300000);
  CHECK(std::abs(r.zone.max_pressure / p0 - 1.) <= 0.03);
  CHECK(element > 0.);
  CHECK(std::abs(r.zone.edge_half_width - 0.1) <= element);
  CHECK(r.zone.pressure_error <= 0.03);
  // the load on the quarter of the top, pi / 4 of its area: the faceted
  // circle of the mesh's top has 5e-4 less
  CHECK(r.zone.contact_force ==
        Approx(0.46638811162460175 * numbers::PI / 4.).epsilon(1e-3));
}

TEST_CASE("Coulomb friction on triangles: hertz_friction's stick half-width "
          "within one contact element of Q1's on a mesh of as many contact "
          "nodes",
          "[simplex]")
{
  // Q1 on its second mesh (361 contact nodes, 19538 DoFs), P1 triangles
  // on their first (355 nodes, 18158 DoFs)
  const Run          quadrilaterals("hertz_friction.prm", "");
  const Run          triangles("hertz_friction.prm", simplices(1) + one_mesh);
  const CycleResult &q       = quadrilaterals.last();
  const CycleResult &t       = triangles.last();
  const double       element = largest_spacing(triangles, 0.1);
  INFO("stick half-width: Q1 "
       << q.zone.stick_half_width << " (" << q.solve.n_contact_nodes
       << " nodes), P1 " << t.zone.stick_half_width << " ("
       << t.solve.n_contact_nodes << " nodes), contact element " << element);
  CHECK(std::abs(t.zone.stick_half_width - q.zone.stick_half_width) <= element);
  CHECK(t.solve.n_slip > 0);
  CHECK(t.zone.contact_force == Approx(q.zone.contact_force).epsilon(1e-8));
}

TEST_CASE("The paper's way (prm/paper_block_p1.prm: P1 triangles, the "
          "threshold iteration nested) against Q1 on the same nodes: the "
          "same contact force, the pressures within 3 % (rms)",
          "[simplex]")
{
  // 40 x 20 squares, each 2 triangles: both meshes have the same 81 nodes
  // on the wall at the last cycle
  const Run  triangles("paper_block_p1.prm", "");
  const Run  quadrilaterals("paper_block.prm", "");
  const auto p1 = triangles.pressures();
  const auto q1 = quadrilaterals.pressures();
  REQUIRE(p1.size() == q1.size());
  double difference = 0., norm = 0.;
  for (std::size_t i = 0; i < p1.size(); ++i)
    {
      REQUIRE(std::abs(p1[i].first - q1[i].first) <= 1e-12);
      difference += std::pow(p1[i].second - q1[i].second, 2);
      norm += std::pow(q1[i].second, 2);
    }
  const double rms = std::sqrt(difference / norm);
  INFO(p1.size() << " nodes, the pressures' relative rms difference " << rms);
  CHECK(triangles.last().zone.contact_force == Approx(30.).epsilon(1e-8));
  CHECK(quadrilaterals.last().zone.contact_force == Approx(30.).epsilon(1e-8));
  // measured 0.022: the largest differences at the top corner, where the
  // stress is singular
  CHECK(rms <= 0.03);
}

TEST_CASE("The GRECO plate (SSNV128: Coulomb friction along a proportional "
          "load path) on triangles against quadrilaterals on the same "
          "nodes: every node in the same state, the tractions within a few "
          "per cent",
          "[simplex]")
{
  // prm/greco_plate.prm, 16 x 16 squares halved once, 5 load steps; the
  // triangles are the squares cut in two, so both meshes have the same 33
  // nodes on the bottom at t = 1
  const Run triangles("greco_plate.prm", simplices(1));
  const Run quadrilaterals("greco_plate.prm", "");
  // (x, state, l1, l2) of every contact node on every rank, sorted by x
  const auto nodes = [](const Run &run) {
    const ContactSet<2> &contact = run.problem->contact();
    std::vector<std::tuple<double, int, double, double>> local;
    for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
      local.emplace_back(contact.nodes[s].position[0],
                         static_cast<int>(contact.status(s)),
                         contact.l1[s],
                         contact.l2[s][0]);
    std::vector<std::tuple<double, int, double, double>> all;
    for (const auto &part : Utilities::MPI::all_gather(run.comm, local))
      all.insert(all.end(), part.begin(), part.end());
    std::sort(all.begin(), all.end());
    return all;
  };
  const auto p1 = nodes(triangles);
  const auto q1 = nodes(quadrilaterals);
  REQUIRE(p1.size() == 33);
  REQUIRE(q1.size() == p1.size());
  double       d1 = 0., n1 = 0., d2 = 0., n2 = 0.;
  unsigned int same_state = 0;
  for (std::size_t i = 0; i < p1.size(); ++i)
    {
      const auto &[x, state, l1, l2]     = p1[i];
      const auto &[xq, stateq, l1q, l2q] = q1[i];
      REQUIRE(std::abs(x - xq) <= 1e-12);
      same_state += (state == stateq);
      d1 += std::pow(l1 - l1q, 2);
      n1 += std::pow(l1q, 2);
      d2 += std::pow(l2 - l2q, 2);
      n2 += std::pow(l2q, 2);
    }
  const CycleResult &t = triangles.last();
  const CycleResult &q = quadrilaterals.last();
  INFO("stick/slip: P1 " << t.solve.n_stick << "/" << t.solve.n_slip << ", Q1 "
                         << q.solve.n_stick << "/" << q.solve.n_slip
                         << "; rms difference of l1 " << std::sqrt(d1 / n1)
                         << ", of l2 " << std::sqrt(d2 / n2));
  CHECK(same_state == p1.size());
  CHECK(t.solve.n_stick > 0);
  CHECK(t.solve.n_slip > t.solve.n_stick);
  // measured 0.015 and 0.028: the largest differences next to the corner
  // x = 0.04 and where slip turns into stick
  CHECK(std::sqrt(d1 / n1) <= 0.025);
  CHECK(std::sqrt(d2 / n2) <= 0.04);
  CHECK(t.zone.contact_force == Approx(q.zone.contact_force).epsilon(1e-8));
}
