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
#include <cmath>
#include <filesystem>
#include <map>
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
