// What a run writes for the user to plot (doc/output.md):
// probes.csv (the displacement and stress at <Output/Probe points>, found in
// the distributed mesh), contact_NN.csv (one row per contact node), the
// contact fields on Gamma_C only (contact_NN.pvtu) with a .pvd for the
// cycles, and no file of an earlier, longer run left in the folder. Every
// file is read on rank 0 and its text broadcast, so that every rank asserts
// the same.

#include <deal.II/base/mpi.h>
#include <deal.II/base/mpi_remote_point_evaluation.h>

#include <deal.II/fe/mapping_q.h>

#include <dualcontact/contact_problem.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <regex>
#include <sstream>

#include "scene_run.h"
#include "test_tools.h"

using namespace dualcontact;
using namespace dualcontact_test;

namespace
{
  /** A CSV file of the run: its header and rows, split at commas. */
  struct Csv
  {
    std::vector<std::string>              header;
    std::vector<std::vector<std::string>> rows;

    explicit Csv(const std::string &text)
    {
      std::istringstream in(text);
      std::string        line;
      bool               first = true;
      while (std::getline(in, line))
        {
          std::vector<std::string> fields;
          std::istringstream       cells(line);
          for (std::string cell; std::getline(cells, cell, ',');)
            fields.push_back(cell);
          if (first)
            header = fields;
          else
            rows.push_back(fields);
          first = false;
        }
    }

    bool
    has(const std::string &name) const
    {
      return std::find(header.begin(), header.end(), name) != header.end();
    }

    const std::string &
    text(const std::size_t row, const std::string &name) const
    {
      const auto column = std::find(header.begin(), header.end(), name);
      REQUIRE(column != header.end());
      return rows.at(row).at(column - header.begin());
    }

    double
    number(const std::size_t row, const std::string &name) const
    {
      return std::stod(text(row, name));
    }
  };

  /** The text of a file of rank 0's folder, on every rank of `comm`. */
  std::string
  file_of_rank_0(const std::string &filename,
                 const MPI_Comm     comm = MPI_COMM_WORLD)
  {
    std::string text;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      text = read_text(filename);
    return Utilities::MPI::broadcast(comm, text, 0);
  }

  /** The names of the files in a folder (rank 0's view, on every rank). */
  std::vector<std::string>
  files_in(const std::string &directory)
  {
    std::vector<std::string> names;
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      for (const auto &entry : std::filesystem::directory_iterator(directory))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return Utilities::MPI::broadcast(MPI_COMM_WORLD, names, 0);
  }

  std::string
  cycle_file(const std::string &directory, const unsigned int cycle)
  {
    return directory + "/contact_" + Utilities::int_to_string(cycle, 2) +
           ".csv";
  }

  std::string
  overlay(const std::string &subsection, const std::string &lines)
  {
    return "\nsubsection " + subsection + "\n" + lines + "end\n";
  }
} // namespace

TEST_CASE("Probes in the patch scene find the exact displacement and the "
          "uniform stress at degree 1, 2 and 3, in probes.csv too",
          "[output][probes]")
{
  // prm/patch.prm: E = 1000, nu = 0, pressure 1 on the top, the plane y = 0
  // below: u = (0, -y / 1000), sigma_yy = -1, every other component 0, von
  // Mises 1, and FE_Q(k) reproduces it at every degree. The points lie
  // inside, on a vertex of the boundary, on a corner and on cell faces
  // (probably between ranks).
  const unsigned int degree = GENERATE(1u, 2u, 3u);
  INFO("degree " << degree);
  const std::vector<Point<2>> points = {
    {0.5, 0.5}, {2., 1.}, {1.3, 0.2}, {0., 0.}, {1., 0.25}};
  Run                run("patch.prm",
          overlay("Output",
                  "  set Probe points = 0.5, 0.5; 2, 1; 1.3, 0.2; 0, 0; 1, "
                                 "0.25\n") +
            overlay("Discretization",
                    "  set Polynomial degree = " + std::to_string(degree) +
                      "\n"));
  const auto        &values   = run.problem->get_probes().values();
  const unsigned int n_cycles = run.problem->results().size();
  REQUIRE(n_cycles == 2);
  REQUIRE(Utilities::MPI::min(values.size(), MPI_COMM_WORLD) ==
          n_cycles * points.size());

  double u_error = 0., stress_error = 0., point_error = 0.;
  for (unsigned int i = 0; i < values.size(); ++i)
    {
      const auto &v = values[i];
      CHECK(v.cycle == i / points.size());
      point_error  = std::max(point_error, v.point.distance(points[v.probe]));
      u_error      = std::max({u_error,
                               std::abs(v.displacement[0]),
                               std::abs(v.displacement[1] + v.point[1] / 1000.)});
      stress_error = std::max({stress_error,
                               std::abs(v.stress[0][0]),
                               std::abs(v.stress[1][1] + 1.),
                               std::abs(v.stress[0][1]),
                               std::abs(v.stress_zz),
                               std::abs(v.von_mises - 1.)});
    }
  // relative to the largest displacement (1e-3) and stress (1)
  CHECK(Utilities::MPI::max(point_error, MPI_COMM_WORLD) == 0.);
  CHECK(Utilities::MPI::max(u_error, MPI_COMM_WORLD) < 1e-8 * 1e-3);
  CHECK(Utilities::MPI::max(stress_error, MPI_COMM_WORLD) < 1e-8);

  // the file: one row per cycle and probe, the same figures
  const Csv csv(file_of_rank_0(run.directory + "/probes.csv"));
  CHECK(csv.header == std::vector<std::string>{"cycle",
                                               "probe",
                                               "x",
                                               "y",
                                               "u_x",
                                               "u_y",
                                               "sigma_xx",
                                               "sigma_yy",
                                               "sigma_zz",
                                               "sigma_xy",
                                               "von_mises"});
  REQUIRE(csv.rows.size() == n_cycles * points.size());
  for (std::size_t r = 0; r < csv.rows.size(); ++r)
    {
      const unsigned int probe = r % points.size();
      CHECK(csv.number(r, "cycle") == r / points.size());
      CHECK(csv.number(r, "probe") == probe + 1);
      CHECK(csv.number(r, "x") == points[probe][0]);
      CHECK(csv.number(r, "y") == points[probe][1]);
      CHECK(std::abs(csv.number(r, "u_y") + points[probe][1] / 1000.) < 1e-11);
      CHECK(std::abs(csv.number(r, "sigma_yy") + 1.) < 1e-8);
      CHECK(std::abs(csv.number(r, "von_mises") - 1.) < 1e-8);
    }
}

TEST_CASE("A probe outside the body is bad input, found before anything is "
          "written",
          "[output][probes][input]")
{
  const std::string directory =
    temporary_directory("probe_outside", MPI_COMM_WORLD);
  const std::string scene =
    read_text(test_file("prm/include/small_contact.prm"));

  // (3, 0.5) lies to the right of the 2 x 1 block
  Parameters parameters;
  parameters.read_string(
    scene,
    overlay("Output",
            "  set Directory = " + directory +
              "\n  set Probe points = 0.5, 0.5; 3, 0.5\n"));
  std::ostringstream screen;
  const CaughtError  caught = catch_input_error([&]() {
    ContactProblem<2> problem(parameters, MPI_COMM_WORLD, screen);
    problem.run();
  });
  CHECK(caught.thrown);
  CHECK(caught.code == exit_inconsistent);
  CHECK(caught.message == "The point (3, 0.5) (probe 2) of <Output/Probe "
                          "points> lies 1 outside the body (the tolerance "
                          "there is 5e-07).");
  MPI_Barrier(MPI_COMM_WORLD);
  CHECK(Utilities::MPI::max(int(std::filesystem::exists(directory)),
                            MPI_COMM_WORLD) == 0);

  // a point with 3 coordinates in a 2D scene
  const CaughtError three = catch_input_error([&]() {
    Parameters p;
    p.read_string(scene, overlay("Output", "  set Probe points = 1, 0.5, 0\n"));
  });
  CHECK(three.code == exit_inconsistent);
  CHECK(three.message == "The point 1 of <Output/Probe points> has 3 "
                         "coordinates, not 2 (one per dimension).");
}

TEST_CASE("A probe on a curved boundary between two vertices, outside the "
          "chord, is evaluated at the nearest point of the mesh; one beyond "
          "the tolerance is refused",
          "[output][probes][input]")
{
  // A half disc of radius 20 hanging from its clamped top, two global
  // refinements: the boundary vertices near the bottom lie at 0 and 11.25
  // degrees, the chord between them 0.0963 inside the circle at its middle.
  // The points 3 degrees from the bottom: on the circle, 0.075 outside the
  // chord; 0.5 beyond the circle; 0.2 inside it, inside the mesh.
  const std::string scene = "subsection Geometry\n"
                            "  set Type = half disc\n"
                            "  set Center = 0, 0\n"
                            "  set Radius = 20\n"
                            "end\n"
                            "subsection Boundary conditions\n"
                            "  set Conditions = 1: fixed\n"
                            "end\n"
                            "subsection Loads\n"
                            "  set Body force = 0; -1\n"
                            "end\n"
                            "subsection Refinement\n"
                            "  set Initial global refinement = 2\n"
                            "  set Number of cycles = 2\n"
                            "end\n";
  const double      angle = 3. * numbers::PI / 180.;
  const auto        at    = [angle](const double r) {
    return Point<2>(r * std::sin(angle), -r * std::cos(angle));
  };
  const Point<2> on_circle = at(20.), beyond = at(20.5), inside = at(19.8);

  // no cell of the first mesh holds the point on the circle
  {
    Parameters parameters;
    parameters.read_string(scene, "");
    const Scene<2>                          geometry(parameters);
    parallel::distributed::Triangulation<2> triangulation(MPI_COMM_WORLD);
    geometry.create_mesh(triangulation);
    const MappingQ<2>                        mapping(1);
    Utilities::MPI::RemotePointEvaluation<2> cache;
    cache.reinit({on_circle, inside}, triangulation, mapping);
    CHECK(!cache.point_found(0));
    CHECK(cache.point_found(1));

    const Probes<2> accepted({{on_circle[0], on_circle[1]}});
    CHECK_NOTHROW(accepted.check_inside(mapping, triangulation));
    const Probes<2> both(
      {{on_circle[0], on_circle[1]}, {beyond[0], beyond[1]}});
    const CaughtError refused =
      catch_input_error([&]() { both.check_inside(mapping, triangulation); });
    CHECK(refused.code == exit_inconsistent);
    CHECK(refused.message ==
          "The point (1.07289, -20.4719) (probe 2) of <Output/Probe points> "
          "lies 0.575 outside the body (the tolerance there is 0.0963).");
  }

  // the run: one value per cycle and probe, the same on every rank, finite,
  // and near the value 0.2 inside (the displacement varies by 4e-4 of
  // itself over 0.2 here)
  std::ostringstream points;
  points << std::setprecision(17) << "  set Probe points = " << on_circle[0]
         << ", " << on_circle[1] << "; " << inside[0] << ", " << inside[1]
         << "\n";
  Run         run("", scene + overlay("Output", points.str()));
  const auto &values = run.problem->get_probes().values();
  REQUIRE(Utilities::MPI::min(values.size(), MPI_COMM_WORLD) == 4);
  REQUIRE(Utilities::MPI::max(values.size(), MPI_COMM_WORLD) == 4);
  for (unsigned int cycle = 0; cycle < 2; ++cycle)
    {
      const auto &on    = values[2 * cycle];
      const auto &close = values[2 * cycle + 1];
      CHECK(on.probe == 0);
      CHECK(on.point == on_circle);
      CHECK(std::isfinite(on.displacement.norm()));
      CHECK(std::isfinite(on.von_mises));
      CHECK(Utilities::MPI::max(on.displacement[1], MPI_COMM_WORLD) ==
            Utilities::MPI::min(on.displacement[1], MPI_COMM_WORLD));
      CHECK((on.displacement - close.displacement).norm() <
            1e-2 * close.displacement.norm());
    }
}

TEST_CASE("contact_NN.csv has one row per contact node along Gamma_C, "
          "adding up to the contact force, with the friction law at every "
          "node",
          "[output][contact]")
{
  // prm/sliding_block.prm: normal and tangential load, partial slip
  Run                run("sliding_block.prm",
          overlay("Refinement", "  set Number of cycles = 1\n"));
  const CycleResult &last = run.last();
  REQUIRE(last.solve.n_slip > 0);
  REQUIRE(last.solve.n_stick > 0);
  const Csv csv(file_of_rank_0(cycle_file(run.directory, 0)));
  CHECK(
    csv.header ==
    std::vector<std::string>{
      "s", "x", "y", "weight", "l1", "l2", "g", "gap", "n_x", "n_y", "status"});
  REQUIRE(csv.rows.size() == last.solve.n_contact_nodes);

  double       force = 0., tangential = 0., max_l1 = 0.;
  unsigned int n_stick = 0, n_slip = 0, n_unsorted = 0, n_wrong = 0;
  for (std::size_t r = 0; r < csv.rows.size(); ++r)
    {
      const double l1 = csv.number(r, "l1"), l2 = csv.number(r, "l2");
      const double g = csv.number(r, "g"), m = csv.number(r, "weight");
      force += m * l1;
      tangential += m * l2;
      max_l1 = std::max(max_l1, l1);
      // the foundation is y = 0: n = (0, -1), s = x (t = (1, 0))
      n_wrong += csv.number(r, "n_x") != 0. || csv.number(r, "n_y") != -1. ||
                 csv.number(r, "s") != csv.number(r, "x") ||
                 csv.number(r, "y") != 0.;
      if (r > 0)
        n_unsorted += !(csv.number(r, "s") > csv.number(r - 1, "s"));
      const std::string &status = csv.text(r, "status");
      if (status == "separated")
        n_wrong += l1 != 0.;
      else if (status == "slip")
        {
          ++n_slip;
          n_wrong += std::abs(std::abs(l2) - g) > 1e-8 * g;
        }
      else
        {
          ++n_stick;
          n_wrong += status != "stick" || !(std::abs(l2) < g);
        }
    }
  CHECK(n_unsorted == 0);
  CHECK(n_wrong == 0);
  CHECK(n_stick == last.solve.n_stick);
  CHECK(n_slip == last.solve.n_slip);
  CHECK(force == Approx(last.zone.contact_force).epsilon(1e-9));
  CHECK(std::abs(tangential) ==
        Approx(last.zone.tangential_force).epsilon(1e-8));
  CHECK(max_l1 == Approx(last.zone.max_pressure).epsilon(1e-9));
}

TEST_CASE("contact_NN.csv has the exact pressure where the scene gives one",
          "[output][contact]")
{
  // prm/hertz.prm: p(x) = 54.945... sqrt(1 - x^2 / 0.01)
  Run run("hertz.prm", overlay("Refinement", "  set Number of cycles = 1\n"));
  const Csv csv(file_of_rank_0(cycle_file(run.directory, 0)));
  REQUIRE(csv.has("exact_pressure"));
  REQUIRE(csv.rows.size() == run.last().solve.n_contact_nodes);
  double error = 0.;
  for (std::size_t r = 0; r < csv.rows.size(); ++r)
    {
      const double x = csv.number(r, "x");
      error          = std::max(error,
                       std::abs(csv.number(r, "exact_pressure") -
                                54.94505494505495 *
                                  std::sqrt(std::max(0., 1 - x * x / 0.01))));
    }
  CHECK(error < 1e-8);
  // the frictionless contact: in contact or separated, never stick/slip
  for (std::size_t r = 0; r < csv.rows.size(); ++r)
    CHECK((csv.text(r, "status") == "contact" ||
           csv.text(r, "status") == "separated"));
}

namespace
{
  // The scene solved on all ranks and on each rank alone (one cycle): the
  // same rows in the same order, in 2D along the boundary, in 3D along the
  // first mean tangent and then the second.
  template <int dim>
  void
  check_contact_csv_same_on_all_ranks(const std::string &scene)
  {
    const std::string one_cycle =
      overlay("Refinement", "  set Number of cycles = 1\n");
    const SceneRun<dim> world(scene, one_cycle);
    const SceneRun<dim> alone(scene, one_cycle, MPI_COMM_SELF);
    const Csv           a(file_of_rank_0(cycle_file(world.directory, 0)));
    const Csv           b(read_text(cycle_file(alone.directory, 0)));
    REQUIRE(a.header == b.header);
    REQUIRE(Utilities::MPI::min(b.rows.size(), MPI_COMM_WORLD) ==
            a.rows.size());
    REQUIRE(Utilities::MPI::max(b.rows.size(), MPI_COMM_WORLD) ==
            a.rows.size());
    // the same nodes in the same order with the same status; the figures
    // to the solver's tolerance, relative to the column's largest value
    unsigned int n_different = 0;
    double       difference  = 0.;
    for (const std::string &column : a.header)
      {
        double largest = 0.;
        for (std::size_t r = 0; r < a.rows.size(); ++r)
          if (column != "status")
            largest = std::max(largest, std::abs(a.number(r, column)));
        for (std::size_t r = 0; r < a.rows.size(); ++r)
          if (column == "status" || column == "s" || column == "x" ||
              column == "y" || column == "z" || column == "weight")
            n_different += a.text(r, column) != b.text(r, column);
          else if (largest > 0.)
            difference =
              std::max(difference,
                       std::abs(a.number(r, column) - b.number(r, column)) /
                         largest);
      }
    CHECK(Utilities::MPI::max(n_different, MPI_COMM_WORLD) == 0);
    CHECK(Utilities::MPI::max(difference, MPI_COMM_WORLD) < 1e-6);
  }
} // namespace

TEST_CASE("contact_NN.csv is the same on all ranks and on one (2D)",
          "[output][contact][mpi]")
{
  check_contact_csv_same_on_all_ranks<2>("sliding_block.prm");
}

TEST_CASE("contact_NN.csv is the same on all ranks and on one (3D)",
          "[output][contact][mpi][3d]")
{
  check_contact_csv_same_on_all_ranks<3>("indenter_sphere_3d.prm");
}

TEST_CASE("The contact fields are written on Gamma_C only, a .pvd lists "
          "every cycle, and no file of an earlier, longer run is left",
          "[output][vtu]")
{
  const std::string directory =
    temporary_directory("output_files", MPI_COMM_WORLD);
  const std::string scene =
    read_text(test_file("prm/include/small_contact.prm"));
  // small_contact.prm: 4 x 2 cells, Gamma_C the bottom (4 faces on the
  // first mesh), frictionless
  const auto run = [&](const unsigned int n_cycles) {
    Parameters parameters;
    parameters.read_string(
      scene,
      overlay("Output",
              "  set Directory = " + directory +
                "\n  set Write vtu = true\n  set Probe points = 1, 0.5\n") +
        overlay("Refinement",
                "  set Number of cycles = " + std::to_string(n_cycles) + "\n"));
    std::ostringstream screen;
    ContactProblem<2>  problem(parameters, MPI_COMM_WORLD, screen);
    problem.run();
  };
  run(5);
  const std::vector<std::string> five = files_in(directory);
  CHECK(std::count(five.begin(), five.end(), "contact_04.csv") == 1);
  CHECK(std::count(five.begin(), five.end(), "solution_04.pvtu") == 1);
  // a file of the user's stays
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::ofstream(directory + "/notes.txt") << "mine\n";
  run(3);

  const std::vector<std::string> three = files_in(directory);
  unsigned int                   n_old = 0;
  for (const std::string &name : three)
    n_old += std::regex_search(name, std::regex("_0[34][.]"));
  CHECK(n_old == 0);
  for (const std::string name : {"notes.txt",
                                 "probes.csv",
                                 "cycles.csv",
                                 "solution.pvd",
                                 "contact.pvd",
                                 "contact_02.csv",
                                 "contact_02.pvtu",
                                 "solution_02.pvtu"})
    CHECK(std::count(three.begin(), three.end(), name) == 1);

  // each .pvd lists the three cycles, in order
  for (const std::string name : {"solution", "contact"})
    {
      const std::string pvd = file_of_rank_0(directory + "/" + name + ".pvd");
      std::vector<std::string> listed;
      const std::regex dataset("timestep=\"([0-9]+)\"[^>]*file=\"([^\"]+)\"");
      for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), dataset);
           it != std::sregex_iterator();
           ++it)
        listed.push_back((*it)[1].str() + " " + (*it)[2].str());
      CHECK(listed == std::vector<std::string>{"0 " + name + "_00.pvtu",
                                               "1 " + name + "_01.pvtu",
                                               "2 " + name + "_02.pvtu"});
    }
  // probes.csv: the three cycles of this run only
  CHECK(Csv(file_of_rank_0(directory + "/probes.csv")).rows.size() == 3);

  // the volume has no contact field; the boundary output has them, on the
  // faces of Gamma_C: 4 x 2^cycle of them, over all pieces
  const std::string volume = file_of_rank_0(directory + "/solution_02.pvtu");
  CHECK(volume.find("displacement") != std::string::npos);
  CHECK(volume.find("von_mises") != std::string::npos);
  CHECK(volume.find("contact_pressure") == std::string::npos);
  CHECK(volume.find("gap") == std::string::npos);
  const std::string boundary = file_of_rank_0(directory + "/contact_02.pvtu");
  for (const std::string field : {"contact_pressure",
                                  "gap",
                                  "contact_status",
                                  "normal",
                                  "tangential_slip",
                                  "displacement"})
    CHECK(boundary.find("Name=\"" + field + "\"") != std::string::npos);
  CHECK(boundary.find("friction_threshold") == std::string::npos);
  for (unsigned int cycle = 0; cycle < 3; ++cycle)
    {
      unsigned int      n_faces = 0;
      const std::string pvtu    = file_of_rank_0(
        directory + "/contact_" + Utilities::int_to_string(cycle, 2) + ".pvtu");
      const std::regex piece("Source=\"([^\"]+)\"");
      for (auto it = std::sregex_iterator(pvtu.begin(), pvtu.end(), piece);
           it != std::sregex_iterator();
           ++it)
        {
          const std::string vtu =
            file_of_rank_0(directory + "/" + (*it)[1].str());
          std::smatch cells;
          REQUIRE(std::regex_search(vtu,
                                    cells,
                                    std::regex("NumberOfCells=\"([0-9]+)\"")));
          n_faces += std::stoi(cells[1].str());
        }
      CHECK(n_faces == 4u << cycle);
    }
  remove_directory(directory, MPI_COMM_WORLD);
}
