// Two bodies in contact (<Boundary conditions/Contact pairs>, dual mortar):
// the contact patch test on non-matching meshes, frictionless and all
// stick, and the refusals of a pair that cannot be one. Every assertion is
// on a value reduced over all ranks.

#include <deal.II/base/mpi.h>

#include <deal.II/distributed/tria.h>

#include <dualcontact/contact_problem.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>

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
    // the upper block's top against the lower block's bottom, 2 below it
    {"3: 2\n  set Conditions = 0: traction, 1: traction\n"
     "  set Tractions = 0: 0.3/0.7; 0, 1: -0.3/0.7; 0",
     "starts with the bodies overlapping: slave nodes lie up to 2.00e+00 "
     "[length] inside the master body (at (0.00e+00, 2.00e+00))"},
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
      const CycleResult &r       = run.last();
      const double       element = largest_spacing(run, 0.15);
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
