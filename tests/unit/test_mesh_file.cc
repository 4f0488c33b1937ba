// Meshes from Gmsh files (<Geometry/Type> = mesh file, doc/meshes.md): the
// 2.2 and 4.1 files of prm/meshes/half_disc.geo give the built-in half
// disc's cells and ids; refinement with a manifold converges to the circle
// (without one, to a polygon); the 3D half cylinder's ids and cylinder; the
// Hertz pressure error of the read-in half disc against the built-in one;
// paths relative to the scene file; damaged files; cells of zero measure,
// tangled or folded refused with their element and nodes, and cells listed
// clockwise (left-handed) solved as meant. Every assertion is on a value
// reduced over all ranks.
#include <deal.II/base/mpi.h>

#include <deal.II/distributed/tria.h>

#include <dualcontact/cell_shapes.h>
#include <dualcontact/contact_problem.h>
#include <dualcontact/gmsh_scan.h>
#include <dualcontact/input_error.h>
#include <dualcontact/parameters.h>
#include <dualcontact/scene.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <map>
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
  mesh_path(const std::string &name)
  {
    return std::filesystem::absolute(test_file("../prm/meshes/" + name))
      .lexically_normal()
      .string();
  }

  // the read-in half disc: radius 1 about (0, 0), ids 0 curved, 1 top
  std::string
  mesh_disc(const std::string &file,
            const bool         manifold,
            const unsigned int refinements)
  {
    return "subsection Geometry\n"
           "  set Type = mesh file\n"
           "  set Mesh file = " +
           mesh_path(file) + "\n" +
           (manifold ? "  set Manifolds = 0: circle center 0, 0 radius 1\n" :
                       "") +
           "end\n"
           "subsection Refinement\n"
           "  set Initial global refinement = " +
           std::to_string(refinements) +
           "\n"
           "end\n";
  }

  const std::string built_in_disc = "subsection Geometry\n"
                                    "  set Type = half disc\n"
                                    "  set Center = 0, 0\n"
                                    "  set Radius = 1\n"
                                    "end\n";

  /**
   * Every boundary face of the mesh as (boundary id, centre), over all
   * ranks, sorted: two meshes with the same list have the same boundary
   * and the same ids on it.
   */
  template <int dim>
  std::vector<std::tuple<unsigned int, double, double, double>>
  boundary_faces(const parallel::distributed::Triangulation<dim> &mesh)
  {
    std::vector<std::tuple<unsigned int, double, double, double>> local;
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              const Point<dim> c = face->center();
              // rounded, so that round-off of the two files cannot reorder
              const auto round = [](const double x) {
                return std::round(x * 1e8) / 1e8;
              };
              local.emplace_back(face->boundary_id(),
                                 round(c[0]),
                                 round(c[1]),
                                 dim == 3 ? round(c[dim - 1]) : 0.);
            }
    std::vector<std::tuple<unsigned int, double, double, double>> all;
    for (const auto &part :
         Utilities::MPI::all_gather(mesh.get_communicator(), local))
      all.insert(all.end(), part.begin(), part.end());
    std::sort(all.begin(), all.end());
    return all;
  }

  /**
   * max | distance from the circle's centre (or the cylinder's axis, the z
   * axis) - 1 | over the vertices of the boundary faces with id 0.
   */
  template <int dim>
  double
  distance_from_circle(const parallel::distributed::Triangulation<dim> &mesh)
  {
    double deviation = 0;
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && face->boundary_id() == 0)
            for (const unsigned int v : face->vertex_indices())
              {
                Point<dim> x = face->vertex(v);
                if (dim == 3)
                  x[dim - 1] = 0; // distance from the z axis
                deviation = std::max(deviation, std::abs(x.norm() - 1.));
              }
    return Utilities::MPI::max(deviation, mesh.get_communicator());
  }

  template <int dim>
  double
  smallest_measure(const parallel::distributed::Triangulation<dim> &mesh)
  {
    double smallest = std::numeric_limits<double>::max();
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->is_locally_owned())
        smallest = std::min(smallest, cell->measure());
    return Utilities::MPI::min(smallest, mesh.get_communicator());
  }
} // namespace

TEST_CASE("A half disc read from Gmsh 2.2 and 4.1 files has the built-in half "
          "disc's cells and boundary ids",
          "[mesh][mpi]")
{
  std::vector<std::vector<std::tuple<unsigned int, double, double, double>>>
                            faces;
  std::vector<unsigned int> n_cells;
  for (const std::string &text :
       {mesh_disc("half_disc.msh", true, 2),
        mesh_disc("half_disc_v22.msh", true, 2),
        built_in_disc + "subsection Refinement\n  set Initial "
                        "global refinement = 2\nend\n"})
    {
      Parameters parameters;
      parameters.read_string(text);
      const Scene<2>                          scene(parameters);
      parallel::distributed::Triangulation<2> mesh(MPI_COMM_WORLD);
      scene.create_mesh(mesh);
      n_cells.push_back(mesh.n_global_active_cells());
      faces.push_back(boundary_faces(mesh));
    }
  CHECK(n_cells[0] == 6 * 16);
  CHECK(n_cells[1] == n_cells[0]);
  CHECK(n_cells[2] == n_cells[0]);
  REQUIRE(faces[0].size() == 32); // 16 curved, 16 on the top
  CHECK(faces[1] == faces[0]);
  CHECK(faces[2] == faces[0]);
  unsigned int n_curved = 0;
  for (const auto &face : faces[0])
    n_curved += std::get<0>(face) == 0 ? 1 : 0;
  CHECK(n_curved == 16);
}

TEST_CASE("A read-in disc refined with its manifold converges to the circle, "
          "without it to a polygon",
          "[mesh][mpi]")
{
  for (const unsigned int refinements : {0u, 1u, 2u, 3u, 4u})
    {
      double deviation[2];
      for (const bool manifold : {false, true})
        {
          Parameters parameters;
          parameters.read_string(
            mesh_disc("half_disc.msh", manifold, refinements));
          const Scene<2>                          scene(parameters);
          parallel::distributed::Triangulation<2> mesh(MPI_COMM_WORLD);
          scene.create_mesh(mesh);
          deviation[manifold] = distance_from_circle(mesh);
          // the transfinite interior keeps every cell well shaped
          CHECK(smallest_measure(mesh) > 0.);
        }
      INFO("refinements " << refinements << ": max |r - R| without manifold "
                          << deviation[0] << ", with " << deviation[1]);
      CHECK(deviation[1] <= 1e-12);
      // the straight chord of the coarse mesh's 45 degree arcs:
      // 1 - cos(22.5 degrees) = 0.076 at its middle
      if (refinements > 0)
        CHECK(deviation[0] >= 0.07);
    }
}

TEST_CASE("The 3D half cylinder has ids 0 to 3 and its curved faces stay on "
          "the cylinder",
          "[mesh][mpi]")
{
  Parameters parameters;
  parameters.read_string(
    "subsection Geometry\n"
    "  set Dimension = 3\n"
    "  set Type = mesh file\n"
    "  set Mesh file = " +
    mesh_path("half_cylinder.msh") +
    "\n"
    "  set Manifolds = 0: cylinder center 0, 0, 0 axis 0, 0, 1 radius 1\n"
    "end\n"
    "subsection Boundary conditions\n"
    "  set Conditions = 0: fixed, 1: free, 2: normal fixed, 3: normal fixed\n"
    "end\n"
    "subsection Refinement\n"
    "  set Initial global refinement = 2\n"
    "end\n");
  const Scene<3> scene(parameters);
  CHECK(std::abs(scene.characteristic_length() - 2.) <= 1e-12);
  parallel::distributed::Triangulation<3> mesh(MPI_COMM_WORLD);
  scene.create_mesh(mesh);
  CHECK(mesh.n_global_active_cells() == 6 * 64);
  std::map<unsigned int, unsigned int> n_faces;
  for (const auto &face : boundary_faces(mesh))
    ++n_faces[std::get<0>(face)];
  CHECK(n_faces == std::map<unsigned int, unsigned int>{
                     {0, 4 * 16}, {1, 4 * 16}, {2, 6 * 16}, {3, 6 * 16}});
  CHECK(distance_from_circle(mesh) <= 1e-12);
  CHECK(smallest_measure(mesh) > 0.);
}

TEST_CASE("Hertz on the read-in half disc: the pressure error matches the "
          "built-in half disc's on every cycle",
          "[mesh][contact]")
{
  // prm/hertz.prm and prm/mesh_hertz.prm, one global refinement less and
  // three cycles (about 1300, 5000 and 19500 DoFs)
  const std::string cycles = "subsection Refinement\n"
                             "  set Initial global refinement = 3\n"
                             "  set Number of cycles = 3\n"
                             "end\n";
  Run               built_in("hertz.prm", cycles);
  Run               read_in("mesh_hertz.prm",
              cycles + "subsection Geometry\n  set Mesh file = " +
                mesh_path("half_disc.msh") + "\nend\n");
  const auto       &a = built_in.problem->results();
  const auto       &b = read_in.problem->results();
  REQUIRE(a.size() == 3);
  REQUIRE(b.size() == 3);
  for (unsigned int cycle = 0; cycle < 3; ++cycle)
    {
      INFO("cycle " << cycle << ": DoFs " << a[cycle].mesh.n_dofs << " / "
                    << b[cycle].mesh.n_dofs << ", pressure error built-in "
                    << a[cycle].zone.pressure_error << ", read-in "
                    << b[cycle].zone.pressure_error);
      // the same mesh: the same DoFs, and the same error up to the
      // tolerances of the iterations
      CHECK(b[cycle].mesh.n_dofs == a[cycle].mesh.n_dofs);
      CHECK(b[cycle].zone.pressure_error <=
            1.02 * a[cycle].zone.pressure_error);
      CHECK(b[cycle].zone.pressure_error >=
            a[cycle].zone.pressure_error / 1.02);
      if (cycle > 0)
        {
          CHECK(a[cycle].zone.pressure_error <
                a[cycle - 1].zone.pressure_error);
          CHECK(b[cycle].zone.pressure_error <
                b[cycle - 1].zone.pressure_error);
        }
    }
}

TEST_CASE("The mesh file is found relative to the scene file's folder, an "
          "override relative to the working directory",
          "[mesh][parameters]")
{
  const std::string scene =
    std::filesystem::absolute(test_file("../prm/mesh_hertz.prm"))
      .lexically_normal()
      .string();
  Parameters parameters;
  parameters.read_file(scene);
  CHECK(parameters.geometry.mesh_file == mesh_path("half_disc.msh"));
  CHECK(parameters.geometry.mesh_file_given == "meshes/half_disc.msh");
  // the listing of the run (parameters.prm) repeats it from anywhere
  CHECK(parameters.parameter_file.find(mesh_path("half_disc.msh")) !=
        std::string::npos);

  Parameters overridden;
  overridden.read_file(scene, {"Geometry/Mesh file=meshes/half_disc.msh"});
  CHECK(overridden.geometry.mesh_file ==
        (std::filesystem::current_path() / "meshes/half_disc.msh")
          .lexically_normal()
          .string());
}

TEST_CASE("Mesh file and manifolds without a mesh file type have no effect",
          "[mesh][parameters]")
{
  Parameters parameters;
  parameters.read_string("subsection Geometry\n"
                         "  set Mesh file = some.msh\n"
                         "  set Manifolds = 0: circle center 0, 0 radius 1\n"
                         "end\n");
  const std::vector<std::string> warnings = parameters.ineffective_entries();
  std::string                    all;
  for (const std::string &warning : warnings)
    all += warning + "\n";
  INFO(all);
  CHECK(all.find("<Geometry/Mesh file> has no effect: <Geometry/Type> is "
                 "'rectangle' (it is for 'mesh file')") != std::string::npos);
  CHECK(all.find("<Geometry/Manifolds> has no effect") != std::string::npos);
}

TEST_CASE("A scene on a mesh file with a bad manifold or id is an input error "
          "before any mesh is built",
          "[mesh][parameters]")
{
  const auto error = [](const std::string &extra) {
    return catch_input_error([&]() {
      Parameters parameters;
      parameters.read_string(mesh_disc("half_disc.msh", false, 0) + extra);
      const Scene<2> scene(parameters);
    });
  };
  const auto wrong_radius =
    error("subsection Geometry\n  set Manifolds = 0: circle center 0, 0 radius "
          "1.01\nend\n");
  CHECK(wrong_radius.code == exit_inconsistent);
  CHECK(wrong_radius.message.find("not the radius 1.01") != std::string::npos);
  const auto sphere_in_2d =
    error("subsection Geometry\n  set Manifolds = 0: sphere center 0, 0 radius "
          "1\nend\n");
  CHECK(sphere_in_2d.code == exit_inconsistent);
  CHECK(sphere_in_2d.message.find("in 2D use 'circle'") != std::string::npos);
  const auto unknown_id =
    error("subsection Boundary conditions\n  set Conditions = 3: fixed\nend\n");
  CHECK(unknown_id.code == exit_inconsistent);
  CHECK(unknown_id.message.find("names boundary id 3") != std::string::npos);
}

TEST_CASE("A sphere or a cylinder with the wrong axis on the half cylinder's "
          "curved faces is an input error",
          "[mesh][parameters]")
{
  for (const std::string manifold :
       {"0: sphere center 0, 0, 0 radius 1",
        "0: cylinder center 0, 0, 0 axis 1, 0, 0 radius 1"})
    {
      const auto error = catch_input_error([&]() {
        Parameters parameters;
        parameters.read_string("subsection Geometry\n"
                               "  set Dimension = 3\n"
                               "  set Type = mesh file\n"
                               "  set Mesh file = " +
                               mesh_path("half_cylinder.msh") +
                               "\n"
                               "  set Manifolds = " +
                               manifold +
                               "\n"
                               "end\n"
                               "subsection Boundary conditions\n"
                               "  set Conditions = 0: fixed\n"
                               "end\n");
        const Scene<3> scene(parameters);
      });
      INFO(manifold << ": " << error.message);
      CHECK(error.code == exit_inconsistent);
      CHECK(error.message.find("The entry <Geometry/Manifolds> puts boundary "
                               "id 0 on a ") != std::string::npos);
    }
}

namespace
{
  /**
   * The text of prm/meshes/<name> with its first line that reads `line`
   * (spaces at its ends aside) replaced by `replacement` (which may hold
   * line breaks; "" leaves an empty line).
   */
  std::string
  damaged(const std::string &name,
          const std::string &line,
          const std::string &replacement)
  {
    std::istringstream in(read_text(mesh_path(name)));
    std::string        text, current;
    bool               found = false;
    while (std::getline(in, current))
      {
        const auto first = current.find_first_not_of(' ');
        const auto last  = current.find_last_not_of(' ');
        const bool match = !found && first != std::string::npos &&
                           current.substr(first, last - first + 1) == line;
        text += (match ? replacement : current) + "\n";
        found = found || match;
      }
    INFO(name << " has no line '" << line << "'");
    REQUIRE(found);
    return text;
  }

  /** The InputError a 2D scene on a mesh file with text `text` throws. */
  CaughtError
  error_of_mesh(const std::string &text)
  {
    const std::string directory =
      temporary_directory("damaged_mesh_" +
                            std::to_string(
                              Utilities::MPI::this_mpi_process(MPI_COMM_WORLD)),
                          MPI_COMM_SELF);
    std::filesystem::create_directories(directory);
    const std::string file = directory + "/mesh.msh";
    std::ofstream(file) << text;
    const CaughtError error = catch_input_error([&] {
      Parameters parameters;
      parameters.read_string("subsection Geometry\n"
                             "  set Type = mesh file\n"
                             "  set Mesh file = " +
                             file +
                             "\n"
                             "end\n");
      const Scene<2> scene(parameters);
    });
    std::filesystem::remove_all(directory);
    return error;
  }
} // namespace

TEST_CASE("A damaged Gmsh file is refused before deal.II's reader sees it, "
          "with what is wrong and where",
          "[mesh][errors]")
{
  const std::string v41 = "half_disc.msh", v22 = "half_disc_v22.msh";
  // (file, line, replacement, the message from "can be read: " on)
  const std::vector<std::array<std::string, 4>> cases = {
    // 4.1: $Nodes
    {{v41,
      "0 3 0 1",
      "0 3 0 2",
      "its $Nodes block 3 (line 48) announces 2 nodes but holds 1."}},
    {{v41,
      "0 3 0 1",
      "0 3 0 0",
      "its $Nodes block 3 (line 48) announces 0 nodes but holds 1."}},
    {{v41,
      "3",
      "",
      "line 49, where the tag of node 1 of its $Nodes block 3 should be, is "
      "empty."}},
    {{v41,
      "25 11 1 11",
      "25 12 1 11",
      "its $Nodes section (line 40) announces 12 nodes in all, but its "
      "blocks hold 11."}},
    {{v41,
      "25 11 1 11",
      "26 11 1 11",
      "its $Nodes section (line 40) announces 26 blocks but holds 25."}},
    {{v41,
      "25 11 1 11",
      "24 11 1 11",
      "its $Nodes section holds more than the 24 blocks it announces, or "
      "does not end with $EndNodes (line 88: '2 6 0 0')."}},
    {{v41,
      "25 11 1 11",
      "25 11 1 12",
      "its $Nodes header gives the node tags as 1 to 12, but they run from "
      "1 to 11."}},
    {{v41,
      "0.55647 0 0",
      "0.55647 0",
      "the coordinates of node 3 of its $Nodes block 3 (line 50: '0.55647 "
      "0') are 2 numbers, not 3 (x y z)."}},
    {{v41,
      "0.55647 0 0",
      "0.55647 nan 0",
      "a coordinate of node 3 (line 50) is 'nan', not a finite number."}},
    {{v41, "3", "1", "its $Nodes section defines node 1 twice."}},
    {{v41,
      "3",
      "-3",
      "a node tag of its $Nodes block 3 (line 49) is '-3', not a whole "
      "number from 1 to 2147483647."}},
    {{v41,
      "0 3 0 1",
      "0 3 1 1",
      "its $Nodes block 3 (line 48), on a point, has parametric "
      "coordinates, which deal.II's reader misreads"}},
    {{v41,
      "$EndNodes",
      "",
      "its $Nodes section holds more than the 25 blocks it announces, or "
      "does not end with $EndNodes (line 90: '$Elements')."}},
    // 4.1: $Elements
    {{v41,
      "12 1 9 10 6",
      "12 1 9 999 6",
      "its element 12 (line 115) refers to node 999, which $Nodes does not "
      "define."}},
    {{v41,
      "12 1 9 10 6",
      "12 1 9 10",
      "its element 12 (line 115) lists 3 nodes, but a quadrilateral has 4."}},
    {{v41,
      "12 1 9 10 6",
      "12 1 9 10 6 7",
      "its element 12 (line 115) lists 5 nodes, but a quadrilateral has 4."}},
    {{v41,
      "12 1 9 10 6",
      "12 1 9 9 6",
      "its element 12 (line 115) lists node 9 twice."}},
    {{v41, "3 2 5", "3 2 2", "its element 3 (line 97) lists node 2 twice."}},
    {{v41,
      "2 4 3 1",
      "7 4 3 1",
      "the entity dimension of its $Elements block 12 (line 114) is '7', "
      "not a whole number from 0 to 3."}},
    {{v41,
      "2 4 3 1",
      "2 44 3 1",
      "its $Elements block 12 (line 114) belongs to surface 44, which "
      "$Entities does not define."}},
    {{v41,
      "2 4 3 1",
      "1 4 3 1",
      "its $Elements block 12 (line 114) holds quadrilateral elements but "
      "belongs to a curve."}},
    {{v41,
      "2 6 3 1",
      "2 6 3 2",
      "its $Elements block 14 (line 118) announces 2 elements but holds 1."}},
    {{v41,
      "2 5 3 1",
      "2 5 3 2",
      "its $Elements block 13 (line 116) announces 2 elements but holds 1."}},
    {{v41,
      "2 6 3 1",
      "2 6 3 0",
      "its $Elements block 14 (line 118) announces 0 elements but holds 1."}},
    {{v41,
      "14 14 1 14",
      "14 13 1 14",
      "its $Elements section (line 90) announces 13 elements in all, but "
      "its blocks hold 14."}},
    {{v41,
      "14 14 1 14",
      "14 14 1 15",
      "its $Elements header gives the element tags as 1 to 15, but they run "
      "from 1 to 14."}},
    {{v41,
      "$EndElements",
      "$EndElement",
      "its $Elements section holds more than the 14 blocks it announces, or "
      "does not end with $EndElements (line 120: '$EndElement')."}},
    // 4.1: $Entities and the order of the sections
    {{v41,
      "11 16 6 0",
      "11 17 6 0",
      "its $Entities section (line 4) announces 34 entities (11 points, 17 "
      "curves, 6 surfaces, 0 volumes) but holds 33."}},
    {{v41,
      "11 16 6 0",
      "11 16 6 4000000000",
      "the number of volumes of its $Entities section (line 5) is "
      "'4000000000', not a whole number from 0 to 2147483647."}},
    {{v41,
      "1 0 0 0 0.55647 0 0 1 1 2 1 -3",
      "1 0 0 0 0.55647 0 0 2 1 5 2 1 -3",
      "its $Entities curve 1 (line 17) is in 2 physical groups; deal.II's "
      "reader takes one at most (its number becomes the boundary id)."}},
    {{v41,
      "1 0 0 0 0.55647 0 0 1 1 2 1 -3",
      "1 0 0 0 0.55647 0 0 1 -1 2 1 -3",
      "the physical tag of its $Entities curve 1 (line 17) is '-1', not a "
      "whole number from 0 to 2147483647."}},
    {{v41,
      "1 0 0 0 0.55647 0 0 1 1 2 1 -3",
      "1 0 0 0 0.55647 0 0 1 1 3 1 -3",
      "its $Entities curve 1 (line 17) has 12 numbers where its counts (1 "
      "physical tag, 3 bounding entities) make 13."}},
    {{v41,
      "$EndEntities",
      "",
      "its $Entities section (line 4) has no "
      "$EndEntities."}},
    {{v41,
      "$EndEntities",
      "$EndEntities\n$Comments\nmade by hand\n$EndComments",
      "its section $Comments (line 40) stands where deal.II's reader "
      "expects $Nodes (before it only $PartitionedEntities)."}},
    {{v41,
      "$EndNodes",
      "$EndNodes\n$Periodic\n0\n$EndPeriodic",
      "its section $Periodic (line 90) stands where deal.II's reader "
      "expects $Elements (right after $EndNodes)."}},
    // 2.2
    {{v22,
      "11",
      "12",
      "its $Nodes section (line 4) announces 12 nodes but holds 11."}},
    {{v22,
      "11",
      "10",
      "its $Nodes section (line 4) announces 10 nodes but holds 11."}},
    {{v22,
      "12 3 2 1 4 1 9 10 6",
      "12 3 2 1 4 1 9 999 6",
      "its element 12 (line 31) refers to node 999, which $Nodes does not "
      "define."}},
    {{v22,
      "12 3 2 1 4 1 9 10 6",
      "12 3 2 1 4 1 9 10",
      "its element 12 (line 31) lists 3 nodes, but a quadrilateral has 4."}},
    {{v22,
      "12 3 2 1 4 1 9 10 6",
      "12 3 2 -1 4 1 9 10 6",
      "the physical tag of its element 12 (line 31) is '-1', not a whole "
      "number from 0 to 2147483647."}},
    {{v22,
      "12 3 2 1 4 1 9 10 6",
      "12 3 4000000000 1 4 1 9 10 6",
      "the number of tags of its element 12 (line 31) is '4000000000', not "
      "a whole number from 0 to 6."}},
    {{v22,
      "14",
      "15",
      "its $Elements section (line 18) announces 15 elements but holds 14."}},
    {{v22,
      "14",
      "13",
      "its $Elements section (line 18) announces 13 elements but holds 14."}},
    {{v22,
      "$EndMeshFormat",
      "$EndMeshFormat\n$PhysicalNames\n1\n1 0 \"curved\"",
      "its $PhysicalNames section does not end with $EndPhysicalNames where "
      "it should (line 7: '$Nodes')."}},
    {{v22,
      "$EndMeshFormat",
      "$EndMeshFormat\n$Entities\n0 0 0 0\n$EndEntities",
      "its section $Entities (line 4) stands where deal.II's reader expects "
      "$Nodes (before it only $PhysicalNames)."}},
    {{v22, "$EndElements", "", "it ends inside its $Elements section."}},
  };
  for (const auto &[file, line, replacement, expected] : cases)
    {
      const CaughtError error = error_of_mesh(damaged(file, line, replacement));
      INFO(file << ": '" << line << "' -> '" << replacement
                << "': " << error.message);
      CHECK(error.code == exit_cannot_read_file);
      CHECK(error.message.find("is not a Gmsh mesh that can be read: " +
                               expected) != std::string::npos);
    }
}

TEST_CASE("Gmsh files of format 4.0, and 4.1 with parametric coordinates on "
          "a surface, are read",
          "[mesh]")
{
  // a unit square of one quadrilateral, 'gmsh -2 -format msh40' (id 0 on
  // the bottom, 1 on the other sides)
  const std::string v40 = "$MeshFormat\n4 0 8\n$EndMeshFormat\n"
                          "$Entities\n4 4 1 0\n"
                          "1 0 0 0 0 0 0 0\n2 1 0 0 1 0 0 0\n"
                          "3 1 1 0 1 1 0 0\n4 0 1 0 0 1 0 0\n"
                          "1 0 0 0 1 0 0 1 0 2 1 -2\n"
                          "2 1 0 0 1 1 0 1 1 2 2 -3\n"
                          "3 0 1 0 1 1 0 1 1 2 3 -4\n"
                          "4 0 0 0 0 1 0 1 1 2 4 -1\n"
                          "1 0 0 0 1 1 0 1 1 4 1 2 3 4\n"
                          "$EndEntities\n"
                          "$Nodes\n9 4\n1 0 0 1\n1 0 0 0\n2 0 0 1\n2 1 0 0\n"
                          "3 0 0 1\n3 1 1 0\n4 0 0 1\n4 0 1 0\n"
                          "1 1 0 0\n2 1 0 0\n3 1 0 0\n4 1 0 0\n1 2 0 0\n"
                          "$EndNodes\n"
                          "$Elements\n5 5\n1 1 1 1\n1 1 2\n2 1 1 1\n2 2 3\n"
                          "3 1 1 1\n3 3 4\n4 1 1 1\n4 4 1\n1 2 3 1\n"
                          "5 1 2 3 4\n$EndElements\n";
  // the square as 2 x 2 quadrilaterals in 4.1, the middle node with its
  // parametric coordinates (u, v) on the surface ('Mesh.SaveParametric =
  // 1;', written without those of the nodes on curves, which deal.II's
  // reader would misread)
  const std::string v41_parametric =
    "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
    "$Entities\n4 4 1 0\n"
    "1 0 0 0 0\n2 1 0 0 0\n3 1 1 0 0\n4 0 1 0 0\n"
    "1 0 0 0 1 0 0 1 0 2 1 -2\n"
    "2 1 0 0 1 1 0 1 1 2 2 -3\n"
    "3 0 1 0 1 1 0 1 1 2 3 -4\n"
    "4 0 0 0 0 1 0 1 1 2 4 -1\n"
    "1 0 0 0 1 1 0 1 1 4 1 2 3 4\n"
    "$EndEntities\n"
    "$Nodes\n9 9 1 9\n0 1 0 1\n1\n0 0 0\n0 2 0 1\n2\n1 0 0\n"
    "0 3 0 1\n3\n1 1 0\n0 4 0 1\n4\n0 1 0\n1 1 0 1\n5\n0.5 0 0\n"
    "1 2 0 1\n6\n1 0.5 0\n1 3 0 1\n7\n0.5 1 0\n1 4 0 1\n8\n0 0.5 0\n"
    "2 1 1 1\n9\n0.5 0.5 0 0.5 0.5\n"
    "$EndNodes\n"
    "$Elements\n5 12 1 12\n1 1 1 2\n1 1 5\n2 5 2\n1 2 1 2\n3 2 6\n4 6 3\n"
    "1 3 1 2\n5 3 7\n6 7 4\n1 4 1 2\n7 4 8\n8 8 1\n2 1 3 4\n9 1 5 9 8\n"
    "10 8 9 7 4\n11 5 2 6 9\n12 9 6 3 7\n$EndElements\n";
  for (const auto &[name, text, n_cells] :
       std::vector<std::tuple<std::string, std::string, unsigned int>>{
         {"4.0", v40, 1}, {"4.1 parametric", v41_parametric, 4}})
    {
      const std::string directory = temporary_directory(
        "mesh_format_" +
          std::to_string(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD)),
        MPI_COMM_SELF);
      std::filesystem::create_directories(directory);
      std::ofstream(directory + "/mesh.msh") << text;
      Parameters parameters;
      parameters.read_string("subsection Geometry\n"
                             "  set Type = mesh file\n"
                             "  set Mesh file = " +
                             directory +
                             "/mesh.msh\n"
                             "end\n"
                             "subsection Boundary conditions\n"
                             "  set Conditions = 0: fixed, 1: free\n"
                             "end\n");
      INFO("format " << name);
      const Scene<2>                          scene(parameters);
      parallel::distributed::Triangulation<2> mesh(MPI_COMM_WORLD);
      scene.create_mesh(mesh);
      CHECK(mesh.n_global_active_cells() == n_cells);
      // the vertices where the file puts them: the square's area
      double area = 0.;
      for (const auto &cell : mesh.active_cell_iterators())
        if (cell->is_locally_owned())
          area += cell->measure();
      CHECK(Utilities::MPI::sum(area, MPI_COMM_WORLD) == Approx(1.));
      std::filesystem::remove_all(directory);
    }
}

namespace
{
  using Coordinates = std::array<double, 3>;

  /**
   * A Gmsh file (format 2.2) of the block [0, 2] x [0, 1] of 4 x 2 squares
   * (dim = 2; node 1 + i + 5 j at (i, j) / 2), or of the cube [0, 1]^3 of
   * 2 x 2 x 2 cubes (node 1 + i + 3 j + 9 k at (i, j, k) / 2), with
   * `simplices` each square cut into two triangles along the diagonal from
   * its first node, each cube into five tetrahedra (the one of its even
   * corners, i + j + k even, and one at each odd corner). Boundary ids: 1
   * at the bottom (y = 0, z = 0), 2 at the top, 3 at x = 0, 4 at x = 2
   * (2D) or y = 0 (3D), 5 on the other two sides (3D); the cells' id is
   * 10. The boundary elements come first, then the cells (the squares
   * row by row, the cubes with k fastest), every cell listed
   * counterclockwise (right-handed) except the cells c (0, 1, ... among the
   * cells) where `turned(c)`. `moved` puts some nodes elsewhere. The
   * meshes of tests/prm/bad/mesh_{folded,zero,tangled}_*.prm are these
   * with one node moved.
   */
  std::string
  block_msh(const unsigned int                       dim,
            const bool                               simplices,
            const std::function<bool(unsigned int)> &turned = {},
            const std::map<int, Coordinates>        &moved  = {})
  {
    std::map<int, Coordinates> nodes;
    // (Gmsh type, physical id, nodes)
    std::vector<std::tuple<int, int, std::vector<int>>> elements;
    std::vector<std::vector<int>>                       cells;
    if (dim == 2)
      {
        const auto n = [](const int i, const int j) { return 1 + i + 5 * j; };
        for (int j = 0; j < 3; ++j)
          for (int i = 0; i < 5; ++i)
            nodes[n(i, j)] = {{0.5 * i, 0.5 * j, 0.}};
        for (int i = 0; i < 4; ++i)
          elements.push_back({1, 1, {n(i, 0), n(i + 1, 0)}});
        for (int i = 0; i < 4; ++i)
          elements.push_back({1, 2, {n(i + 1, 2), n(i, 2)}});
        for (int j = 0; j < 2; ++j)
          elements.push_back({1, 3, {n(0, j + 1), n(0, j)}});
        for (int j = 0; j < 2; ++j)
          elements.push_back({1, 4, {n(4, j), n(4, j + 1)}});
        for (int j = 0; j < 2; ++j)
          for (int i = 0; i < 4; ++i)
            {
              const int a = n(i, j), b = n(i + 1, j), c = n(i + 1, j + 1),
                        d = n(i, j + 1);
              if (simplices)
                {
                  cells.push_back({a, b, c});
                  cells.push_back({a, c, d});
                }
              else
                cells.push_back({a, b, c, d});
            }
      }
    else
      {
        using Index  = std::array<int, 3>;
        const auto n = [](const Index &x) {
          return 1 + x[0] + 3 * x[1] + 9 * x[2];
        };
        const auto even = [](const Index &x) {
          return (x[0] + x[1] + x[2]) % 2 == 0;
        };
        for (int k = 0; k < 3; ++k)
          for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i)
              nodes[n({{i, j, k}})] = {{0.5 * i, 0.5 * j, 0.5 * k}};
        // the boundary squares; of tetrahedra, each cut along the diagonal
        // of its even corners
        for (const auto &[axis, value, id] :
             std::vector<std::array<int, 3>>{{{2, 0, 1}},
                                             {{2, 2, 2}},
                                             {{0, 0, 3}},
                                             {{1, 0, 4}},
                                             {{0, 2, 5}},
                                             {{1, 2, 5}}})
          {
            const int a = axis == 0 ? 1 : 0, b = axis == 2 ? 1 : 2;
            for (int p = 0; p < 2; ++p)
              for (int q = 0; q < 2; ++q)
                {
                  std::vector<Index> corners;
                  for (const auto &[da, db] : std::vector<std::pair<int, int>>{
                         {0, 0}, {1, 0}, {1, 1}, {0, 1}})
                    {
                      Index x;
                      x[axis] = value;
                      x[a]    = p + da;
                      x[b]    = q + db;
                      corners.push_back(x);
                    }
                  std::vector<int> e, o;
                  for (const Index &x : corners)
                    (even(x) ? e : o).push_back(n(x));
                  if (simplices)
                    for (const int x : o)
                      elements.push_back({2, id, {e[0], x, e[1]}});
                  else
                    elements.push_back({3,
                                        id,
                                        {n(corners[0]),
                                         n(corners[1]),
                                         n(corners[2]),
                                         n(corners[3])}});
                }
          }
        for (int i = 0; i < 2; ++i)
          for (int j = 0; j < 2; ++j)
            for (int k = 0; k < 2; ++k)
              {
                std::vector<Index> corners;
                for (int a = 0; a < 2; ++a)
                  for (int b = 0; b < 2; ++b)
                    for (int c = 0; c < 2; ++c)
                      corners.push_back({{i + a, j + b, k + c}});
                if (!simplices)
                  {
                    std::vector<int> hexahedron;
                    for (const Index &d : std::vector<Index>{{{0, 0, 0}},
                                                             {{1, 0, 0}},
                                                             {{1, 1, 0}},
                                                             {{0, 1, 0}},
                                                             {{0, 0, 1}},
                                                             {{1, 0, 1}},
                                                             {{1, 1, 1}},
                                                             {{0, 1, 1}}})
                      hexahedron.push_back(n({{i + d[0], j + d[1], k + d[2]}}));
                    cells.push_back(hexahedron);
                    continue;
                  }
                std::vector<std::vector<int>> tetrahedra(1);
                for (const Index &x : corners)
                  if (even(x))
                    tetrahedra[0].push_back(n(x));
                for (const Index &x : corners)
                  if (!even(x))
                    {
                      tetrahedra.push_back({n(x)});
                      for (const Index &y : corners)
                        if (std::abs(y[0] - x[0]) + std::abs(y[1] - x[1]) +
                              std::abs(y[2] - x[2]) ==
                            1)
                          tetrahedra.back().push_back(n(y));
                    }
                for (std::vector<int> &t : tetrahedra)
                  {
                    // right-handed
                    std::array<Coordinates, 3> e;
                    for (unsigned int k = 0; k < 3; ++k)
                      for (unsigned int d = 0; d < 3; ++d)
                        e[k][d] = nodes[t[k + 1]][d] - nodes[t[0]][d];
                    if (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                          e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                          e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]) <
                        0.)
                      std::swap(t[2], t[3]);
                    cells.push_back(t);
                  }
              }
      }
    for (unsigned int c = 0; c < cells.size(); ++c)
      {
        std::vector<int> &v = cells[c];
        if (turned && turned(c))
          {
            // clockwise, or left-handed
            if (v.size() == 8)
              std::rotate(v.begin(), v.begin() + 4, v.end());
            else
              std::reverse(v.begin() + 1, v.end());
          }
        elements.push_back({v.size() == 3 ? 2 :
                            v.size() == 8 ? 5 :
                            dim == 2      ? 3 :
                                            4,
                            10,
                            v});
      }
    for (const auto &[tag, x] : moved)
      nodes[tag] = x;

    std::ostringstream text;
    text << std::setprecision(10) << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
         << "$Nodes\n"
         << nodes.size() << "\n";
    for (const auto &[tag, x] : nodes)
      text << tag << ' ' << x[0] << ' ' << x[1] << ' ' << x[2] << '\n';
    text << "$EndNodes\n$Elements\n" << elements.size() << '\n';
    unsigned int tag = 0;
    for (const auto &[type, id, element_nodes] : elements)
      {
        text << ++tag << ' ' << type << " 2 " << id << ' ' << id;
        for (const int node : element_nodes)
          text << ' ' << node;
        text << '\n';
      }
    text << "$EndElements\n";
    return text.str();
  }

  /**
   * What check_cell_shapes() says of the cells of dimension `dim` of a
   * Gmsh file's text, from "element" on ("" if nothing).
   */
  std::string
  shape_error(const std::string &text, const unsigned int dim)
  {
    std::istringstream in(text);
    const CaughtError  error = catch_input_error(
      [&] { check_cell_shapes(scan_msh(in, "'mesh'"), dim, "'mesh'"); });
    if (!error.thrown)
      return "";
    CHECK(error.code == exit_cannot_read_file);
    const std::string prefix = "The mesh 'mesh' is damaged: ";
    CHECK(error.message.substr(0, prefix.size()) == prefix);
    const auto end = error.message.find("; mesh the body again");
    return error.message.substr(prefix.size(),
                                end == std::string::npos ? std::string::npos :
                                                           end - prefix.size());
  }
} // namespace

TEST_CASE("A cell of zero measure, a tangled quadrilateral or hexahedron and "
          "a cell folded over its neighbours are refused naming the element "
          "and its nodes; cells listed clockwise or left-handed are not",
          "[mesh][errors]")
{
  const std::function<bool(unsigned int)> as_meant,
    all = [](unsigned int) { return true; };
  const std::function<bool(unsigned int)> every_other = [](unsigned int c) {
    return c % 2 == 1;
  };
  for (const unsigned int dim : {2u, 3u})
    for (const bool simplices : {true, false})
      for (const auto &turned : {as_meant, all, every_other})
        {
          INFO(dim << "D, simplices " << simplices);
          CHECK(shape_error(block_msh(dim, simplices, turned), dim) == "");
        }

  const std::string folded_18 =
    "element 18 (nodes 3 9 8) is folded: it overlaps its neighbours (it and "
    "element 15 lie on the same side of their common edge, nodes 8 3)";
  const std::string folded_18_turned =
    "element 18 (nodes 3 8 9) is folded: it overlaps its neighbours (it and "
    "element 15 lie on the same side of their common edge, nodes 3 8)";
  const std::string folded_53 =
    "element 53 (nodes 14 13 5 11) is folded: it overlaps its neighbours (it "
    "and element 49 lie on the same side of their common face, nodes 13 5 11)";
  // (dimension, simplices, the cells turned, the nodes moved, the message)
  const std::vector<std::tuple<unsigned int,
                               bool,
                               std::function<bool(unsigned int)>,
                               std::map<int, Coordinates>,
                               std::string>>
    cases = {
      // a triangle turned over past its edge 3-9, whichever way the
      // cells are listed
      {2, true, as_meant, {{8, {{1.35, 0.25, 0.}}}}, folded_18},
      {2, true, every_other, {{8, {{1.35, 0.25, 0.}}}}, folded_18_turned},
      {2, true, all, {{8, {{1.35, 0.25, 0.}}}}, folded_18_turned},
      // a boundary triangle turned inside out past the bottom
      {2,
       true,
       as_meant,
       {{8, {{0.8, -0.1, 0.}}}},
       "element 15 (nodes 2 3 8) is folded: it overlaps its neighbours (it "
       "and element 16 lie on the same side of their common edge, nodes 8 2)"},
      {2,
       true,
       as_meant,
       {{8, {{1.25, 0.25, 0.}}}},
       "element 18 (nodes 3 9 8) has zero area: its nodes are on one line"},
      {2,
       true,
       as_meant,
       {{8, {{1.5, 0.5, 0.}}}},
       "element 18 (nodes 3 9 8) has zero area: its nodes are on one line"},
      // a quadrilateral not convex at node 8, or with a straight angle
      {2,
       false,
       as_meant,
       {{8, {{0.7, 0.2, 0.}}}},
       "element 14 (nodes 2 3 8 7) is tangled: its Jacobian at node 8 has the "
       "opposite sign of that at nodes 2 3 7 (it crosses itself or is not "
       "convex)"},
      {2,
       false,
       every_other,
       {{8, {{0.7, 0.2, 0.}}}},
       "element 14 (nodes 2 7 8 3) is tangled: its Jacobian at node 8 has the "
       "opposite sign of that at nodes 2 7 3 (it crosses itself or is not "
       "convex)"},
      // a straight angle at node 8 is a sound cell (its Jacobian is
      // positive inside); an edge of zero length is not
      {2, false, as_meant, {{8, {{0.75, 0.25, 0.}}}}, ""},
      {2,
       false,
       as_meant,
       {{8, {{1., 0., 0.}}}},
       "element 14 (nodes 2 3 8 7) is degenerate at nodes 3 8: its Jacobian "
       "is zero there, at half its corners or more (an edge of zero length, "
       "or two edges in line at each)"},
      // a tetrahedron turned over past its face 13-5-11, or flat on it
      {3, true, as_meant, {{14, {{0.3, 0.3, 0.3}}}}, folded_53},
      {3, true, every_other, {{14, {{0.3, 0.3, 0.3}}}}, folded_53},
      {3,
       true,
       as_meant,
       {{14, {{0.4, 0.3, 0.3}}}},
       "element 53 (nodes 14 13 5 11) has zero volume: its nodes are on one "
       "plane"},
      // a hexahedron turned inside out at node 14, or flat there
      {3,
       false,
       as_meant,
       {{14, {{0.2, 0.2, 0.2}}}},
       "element 25 (nodes 1 2 5 4 10 11 14 13) is tangled: its Jacobian at "
       "node 14 has the opposite sign of that at nodes 1 2 5 4 10 11 13 (it "
       "is turned inside out at a corner)"},
      {3,
       false,
       all,
       {{14, {{0.2, 0.2, 0.2}}}},
       "element 25 (nodes 10 11 14 13 1 2 5 4) is tangled: its Jacobian at "
       "node 14 has the opposite sign of that at nodes 10 11 13 1 2 5 4 (it "
       "is turned inside out at a corner)"},
      {3, false, as_meant, {{14, {{0.4, 0.3, 0.3}}}}, ""}};
  for (const auto &[dim, simplices, turned, moved, expected] : cases)
    {
      const std::string error =
        shape_error(block_msh(dim, simplices, turned, moved), dim);
      INFO(dim << "D, simplices " << simplices << ": " << error);
      CHECK(error == expected);
    }

  // a quadrilateral that crosses itself: element 14 listed 2 3 7 8
  std::string       bow_tie   = block_msh(2, false);
  const std::string square_14 = "\n14 3 2 10 10 2 3 8 7\n";
  REQUIRE(bow_tie.find(square_14) != std::string::npos);
  bow_tie.replace(bow_tie.find(square_14),
                  square_14.size(),
                  "\n14 3 2 10 10 2 3 7 8\n");
  CHECK(shape_error(bow_tie, 2) ==
        "element 14 (nodes 2 3 7 8) is tangled: its Jacobian at nodes 7 8 has "
        "the opposite sign of that at nodes 2 3 (it crosses itself or is not "
        "convex)");

  // three cells in a row, the third folded back over the middle one: its
  // own shape is sound (listed the other way round), but it lies on the
  // same side of the face it shares with the middle one; a quadrilateral
  // and a hexahedron
  const std::string folded_quad =
    "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n8\n"
    "1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0.5 0.2 0\n6 0.5 0.8 0\n"
    "7 -1 0 0\n8 -1 1 0\n$EndNodes\n$Elements\n3\n"
    "1 3 2 10 10 7 1 4 8\n2 3 2 10 10 1 2 3 4\n3 3 2 10 10 2 5 6 3\n"
    "$EndElements\n";
  CHECK(shape_error(folded_quad, 2) ==
        "element 3 (nodes 2 5 6 3) is folded: it overlaps its neighbours (it "
        "and element 2 lie on the same side of their common edge, nodes 3 2)");
  const std::string folded_hexahedron =
    "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n16\n"
    "1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0 0 1\n6 1 0 1\n7 1 1 1\n"
    "8 0 1 1\n9 0.5 0.2 0.2\n10 0.5 0.8 0.2\n11 0.5 0.8 0.8\n"
    "12 0.5 0.2 0.8\n13 -1 0 0\n14 -1 1 0\n15 -1 1 1\n16 -1 0 1\n"
    "$EndNodes\n$Elements\n3\n"
    "1 5 2 10 10 13 1 4 14 16 5 8 15\n"
    "2 5 2 10 10 1 2 3 4 5 6 7 8\n"
    "3 5 2 10 10 2 9 10 3 6 12 11 7\n$EndElements\n";
  CHECK(shape_error(folded_hexahedron, 3) ==
        "element 3 (nodes 2 9 10 3 6 12 11 7) is folded: it overlaps its "
        "neighbours (it and element 2 lie on the same side of their common "
        "face, nodes 2 6 7 3)");
  // three triangles on one edge
  const std::string three_on_an_edge =
    "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n"
    "1 0 0 0\n2 1 0 0\n3 0.5 1 0\n4 0.5 -1 0\n5 0.5 2 0\n$EndNodes\n"
    "$Elements\n3\n1 2 2 10 10 1 2 3\n2 2 2 10 10 2 1 4\n"
    "3 2 2 10 10 1 2 5\n$EndElements\n";
  CHECK(shape_error(three_on_an_edge, 2) ==
        "element 1 (nodes 1 2 3) is folded: it overlaps its neighbours (its "
        "edge, nodes 1 2, is an edge of 3 elements)");

  // through the reader, in format 4.1: the half disc's middle node 1 moved
  // from (0, 0) to (0, -0.7), past node 6 at (0, -0.56), which makes a bow
  // tie of the quadrilateral 9
  const CaughtError moved =
    error_of_mesh(damaged("half_disc.msh", "0 0 0", "0 -0.7 0"));
  INFO(moved.message);
  CHECK(moved.code == exit_cannot_read_file);
  CHECK(moved.message.find(
          "/mesh.msh' is damaged: element 9 (nodes 6 4 3 1) is tangled: its "
          "Jacobian at nodes 4 3 has the opposite sign of that at nodes 6 1 "
          "(it crosses itself or is not convex); mesh the body again or move "
          "the element's nodes (doc/meshes.md).") != std::string::npos);
}

TEST_CASE("Cells listed clockwise (left-handed), all or some, are read as "
          "meant: the block pressed by 10 onto the plane has the pressure 10 "
          "at every contact node",
          "[mesh][simplex]")
{
  const std::string directory =
    temporary_directory("clockwise_msh", MPI_COMM_WORLD);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::filesystem::create_directories(directory);
  const std::function<bool(unsigned int)> all = [](unsigned int) {
    return true;
  };
  const std::function<bool(unsigned int)> every_other = [](unsigned int c) {
    return c % 2 == 1;
  };
  // (dimension, simplices, the cells turned)
  const std::vector<
    std::tuple<unsigned int, bool, std::function<bool(unsigned int)>>>
               cases = {{2, true, all},
                        {2, true, every_other},
                        {2, false, every_other},
                        {3, true, every_other},
                        {3, false, all},
                        {3, false, every_other}};
  unsigned int n     = 0;
  for (const auto &[dim, simplices, turned] : cases)
    {
      const std::string file =
        directory + "/block_" + std::to_string(n++) + ".msh";
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::ofstream(file) << block_msh(dim, simplices, turned);
      MPI_Barrier(MPI_COMM_WORLD);
      // E = 1000, nu = 0.3, pressed by 10 on its top, held sideways by
      // sliders: the uniform pressure 10 on the plane, which P1 and Q1
      // give exactly
      const std::string scene =
        "subsection Geometry\n  set Dimension = " + std::to_string(dim) +
        "\n  set Type = mesh file\n  set Mesh file = " + file +
        "\nend\n"
        "subsection Material\n  set Young's modulus = 1000\n"
        "  set Poisson's ratio = 0.3\nend\n"
        "subsection Boundary conditions\n" +
        (dim == 2 ? "  set Conditions = 1: contact, 2: traction, 3: normal "
                    "fixed, 4: free\n  set Tractions = 2: 0; -10\n" :
                    "  set Conditions = 1: contact, 2: traction, 3: normal "
                    "fixed, 4: normal fixed, 5: free\n"
                    "  set Tractions = 2: 0; 0; -10\n") +
        "end\n"
        "subsection Foundation\n" +
        (dim == 2 ? "  set Point = 0, 0\n  set Normal = 0, 1\n" :
                    "  set Point = 0, 0, 0\n  set Normal = 0, 0, 1\n") +
        "end\n"
        "subsection Refinement\n  set Initial global refinement = 1\n"
        "  set Number of cycles = 1\nend\n"
        "subsection Solver\n  set Uzawa tolerance = 1e-11\nend\n";
      INFO(dim << "D, simplices " << simplices);
      if (dim == 2)
        {
          const SceneRun<2> run("", scene);
          // 8 edges of the plane: 9 nodes
          CHECK(run.last().solve.n_contact_nodes == 9);
          CHECK(run.last().zone.contact_force == Approx(20.).epsilon(1e-10));
          CHECK(deviation(run, 10., Tensor<1, 2>()).first <= 1e-7);
        }
      else
        {
          const SceneRun<3> run("", scene);
          // 4 x 4 squares of the plane: 25 nodes
          CHECK(run.last().solve.n_contact_nodes == 25);
          CHECK(run.last().zone.contact_force == Approx(10.).epsilon(1e-10));
          CHECK(deviation(run, 10., Tensor<1, 3>()).first <= 1e-7);
        }
    }
  remove_directory(directory, MPI_COMM_WORLD);
}
