// Meshes from Gmsh files (<Geometry/Type> = mesh file, doc/meshes.md): the
// 2.2 and 4.1 files of prm/meshes/half_disc.geo give the built-in half
// disc's cells and ids; refinement with a manifold converges to the circle
// (without one, to a polygon); the 3D half cylinder's ids and cylinder; the
// Hertz pressure error of the read-in half disc against the built-in one;
// paths relative to the scene file. Every assertion is on a value reduced
// over all ranks.
#include <deal.II/base/mpi.h>

#include <deal.II/distributed/tria.h>

#include <dualcontact/contact_problem.h>
#include <dualcontact/input_error.h>
#include <dualcontact/parameters.h>
#include <dualcontact/scene.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
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
