// Geometry: boundary ids of the rectangle, shape and ids of the half disc,
// pre-refinement toward the foundation. Meshes are distributed over
// MPI_COMM_WORLD; every figure is reduced over all ranks before it is checked.
#include <deal.II/base/mpi.h>

#include <deal.II/distributed/tria.h>

#include <dualcontact/parameters.h>
#include <dualcontact/scene.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace dualcontact;

namespace
{
  Parameters
  read(const std::string &text)
  {
    Parameters parameters;
    parameters.read_string(text);
    return parameters;
  }

  const std::string half_disc = "subsection Geometry\n"
                                "  set Type = half disc\n"
                                "  set Center = 1, 2\n"
                                "  set Radius = 0.5\n"
                                "end\n";
  const Point<2>    center(1., 2.);
  const double      radius = 0.5;
} // namespace

TEST_CASE("The rectangle's boundary ids 0..3 are x_min, x_max, y_min, y_max",
          "[geometry][mpi]")
{
  const Parameters parameters = read("subsection Geometry\n"
                                     "  set Lower left corner = -1, 2\n"
                                     "  set Upper right corner = 3, 3\n"
                                     "  set Subdivisions = 4, 1\n"
                                     "end\n"
                                     "subsection Refinement\n"
                                     "  set Initial global refinement = 2\n"
                                     "end\n");
  const Scene<2>   scene(parameters);
  parallel::distributed::Triangulation<2> triangulation(MPI_COMM_WORLD);
  scene.create_mesh(triangulation);

  // per id: number of faces, and the faces whose centre is off the side
  unsigned int n_faces[4]  = {0, 0, 0, 0};
  unsigned int n_wrong     = 0;
  unsigned int n_other_ids = 0;
  double       length[4]   = {0, 0, 0, 0};
  for (const auto &cell : triangulation.active_cell_iterators())
    if (cell->is_locally_owned())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const types::boundary_id id = face->boundary_id();
            if (id > 3)
              {
                ++n_other_ids;
                continue;
              }
            ++n_faces[id];
            length[id] += face->measure();
            const Point<2> c           = face->center();
            const double   distance[4] = {std::abs(c[0] + 1.),
                                          std::abs(c[0] - 3.),
                                          std::abs(c[1] - 2.),
                                          std::abs(c[1] - 3.)};
            if (distance[id] > 1e-12)
              ++n_wrong;
          }

  CHECK(Utilities::MPI::sum(n_wrong, MPI_COMM_WORLD) == 0);
  CHECK(Utilities::MPI::sum(n_other_ids, MPI_COMM_WORLD) == 0);
  const double expected_length[4] = {1., 1., 4., 4.};
  for (unsigned int id = 0; id < 4; ++id)
    {
      CHECK(Utilities::MPI::sum(n_faces[id], MPI_COMM_WORLD) > 0);
      CHECK(Utilities::MPI::sum(length[id], MPI_COMM_WORLD) ==
            Approx(expected_length[id]).epsilon(1e-12));
    }
  CHECK(triangulation.n_global_active_cells() == 4 * 16);
}

TEST_CASE("The half disc has the area pi R^2/2 to 1e-3 after 4 refinements, "
          "and the error shrinks as h^2",
          "[geometry][mpi]")
{
  // Sum of cell->measure(): the area of the polygon through the boundary
  // vertices, which lie on the circle. Its deficit is that of a polygon
  // inscribed in the half circle, ~ (pi/n)^2/6 for n arcs: it must shrink by
  // 4 per refinement (if the refinement did not follow the circle it would
  // stay at the coarse mesh's deficit).
  const auto deficit = [](const unsigned int n_refinements) {
    const Parameters parameters =
      read(half_disc +
           "subsection Refinement\n"
           "  set Initial global refinement = " +
           std::to_string(n_refinements) + "\nend\n");
    const Scene<2>                          scene(parameters);
    parallel::distributed::Triangulation<2> triangulation(MPI_COMM_WORLD);
    scene.create_mesh(triangulation);
    double area = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        area += cell->measure();
    area               = Utilities::MPI::sum(area, MPI_COMM_WORLD);
    const double exact = numbers::PI * radius * radius / 2;
    return (exact - area) / exact;
  };

  const double deficit_4 = deficit(4);
  const double deficit_5 = deficit(5);
  INFO("relative area deficit after 4 refinements: "
       << deficit_4 << ", after 5: " << deficit_5);
  CHECK(deficit_4 > 0); // straight-edged cells lie inside the circle
  CHECK(deficit_4 < 1e-3);
  CHECK(deficit_4 / deficit_5 == Approx(4.).margin(0.2));
}

TEST_CASE("The half disc's id 0 is the lower half circle, id 1 the flat top",
          "[geometry][mpi]")
{
  const Parameters parameters =
    read(half_disc +
         "subsection Refinement\n  set Initial global refinement = 4\nend\n");
  const Scene<2>                          scene(parameters);
  parallel::distributed::Triangulation<2> triangulation(MPI_COMM_WORLD);
  scene.create_mesh(triangulation);

  unsigned int n_curved = 0, n_flat = 0, n_other_ids = 0;
  double       worst_radius_error = 0; // |distance of face centre - R| / R
  double       highest_curved     = -std::numeric_limits<double>::max();
  double       worst_flat_offset  = 0; // |y - center_y| / R
  double       flat_length        = 0;
  for (const auto &cell : triangulation.active_cell_iterators())
    if (cell->is_locally_owned())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            // the centre on the manifold: on the circle for id 0
            const Point<2> c = face->center(/*respect_manifold=*/true);
            if (face->boundary_id() == 0)
              {
                ++n_curved;
                worst_radius_error =
                  std::max(worst_radius_error,
                           std::abs(c.distance(center) - radius) / radius);
                highest_curved = std::max(highest_curved, c[1] - center[1]);
              }
            else if (face->boundary_id() == 1)
              {
                ++n_flat;
                flat_length += face->measure();
                for (const unsigned int v : face->vertex_indices())
                  worst_flat_offset =
                    std::max(worst_flat_offset,
                             std::abs(face->vertex(v)[1] - center[1]) / radius);
              }
            else
              ++n_other_ids;
          }

  const MPI_Comm comm = MPI_COMM_WORLD;
  CHECK(Utilities::MPI::sum(n_curved, comm) > 0);
  CHECK(Utilities::MPI::sum(n_flat, comm) > 0);
  CHECK(Utilities::MPI::sum(n_other_ids, comm) == 0);
  CHECK(Utilities::MPI::max(worst_radius_error, comm) < 1e-3);
  CHECK(Utilities::MPI::max(highest_curved, comm) < 0.);
  CHECK(Utilities::MPI::max(worst_flat_offset, comm) < 1e-12);
  CHECK(Utilities::MPI::sum(flat_length, comm) ==
        Approx(2 * radius).epsilon(1e-12));
}

namespace
{
  /** Figures of the half-disc mesh near the foundation (its lowest point). */
  struct BottomCells
  {
    double       smallest_diameter = 0; // of the cells at the lowest point
    unsigned int finest_level      = 0; // of the cells at the lowest point
    unsigned int coarsest_at_top   = 0; // of the cells near the flat top
    double       largest_diameter  = 0; // of all cells
  };

  BottomCells
  half_disc_on_foundation(const unsigned int pre_refinement_steps)
  {
    // the foundation touches the half disc at its lowest point (1, 1.5);
    // cells within 0.1 R of it are pre-refined
    const Parameters                        parameters = read(half_disc +
                                       "subsection Boundary conditions\n"
                                                              "  set Conditions = 0: contact\n"
                                                              "end\n"
                                                              "subsection Foundation\n"
                                                              "  set Point = 1, 1.5\n"
                                                              "  set Normal = 0, 1\n"
                                                              "end\n"
                                                              "subsection Geometry\n"
                                                              "  set Pre-refinement steps = " +
                                       std::to_string(pre_refinement_steps) +
                                       "\n"
                                                              "  set Pre-refinement distance = 0.05\n"
                                                              "end\n"
                                                              "subsection Refinement\n"
                                                              "  set Initial global refinement = 2\n"
                                                              "end\n");
    const Scene<2>                          scene(parameters);
    parallel::distributed::Triangulation<2> triangulation(MPI_COMM_WORLD);
    scene.create_mesh(triangulation);

    const Point<2> bottom(1., 1.5);
    double         smallest    = std::numeric_limits<double>::max();
    double         largest     = 0;
    unsigned int   n_at_bottom = 0, finest = 0;
    unsigned int   coarsest_at_top = std::numeric_limits<unsigned int>::max();
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto level = static_cast<unsigned int>(cell->level());
          largest          = std::max(largest, cell->diameter());
          for (const unsigned int v : cell->vertex_indices())
            if (cell->vertex(v).distance(bottom) < 1e-10)
              {
                ++n_at_bottom;
                smallest = std::min(smallest, cell->diameter());
                finest   = std::max(finest, level);
              }
          if (cell->center()[1] > center[1] - 0.1 * radius)
            coarsest_at_top = std::min(coarsest_at_top, level);
        }

    const MPI_Comm comm = MPI_COMM_WORLD;
    REQUIRE(Utilities::MPI::sum(n_at_bottom, comm) > 0);
    BottomCells result;
    result.smallest_diameter = Utilities::MPI::min(smallest, comm);
    result.finest_level      = Utilities::MPI::max(finest, comm);
    result.coarsest_at_top   = Utilities::MPI::min(coarsest_at_top, comm);
    result.largest_diameter  = Utilities::MPI::max(largest, comm);
    return result;
  }
} // namespace

TEST_CASE("Pre-refinement refines the cells at the foundation 3 more times "
          "and only there",
          "[geometry][mpi]")
{
  const BottomCells plain   = half_disc_on_foundation(0);
  const BottomCells refined = half_disc_on_foundation(3);
  INFO("without pre-refinement: smallest cell at the bottom "
       << plain.smallest_diameter << ", largest cell "
       << plain.largest_diameter);
  INFO("with 3 steps: smallest cell at the bottom "
       << refined.smallest_diameter << ", largest cell "
       << refined.largest_diameter << ", ratio "
       << refined.largest_diameter / refined.smallest_diameter);

  // 2 global refinements everywhere, 3 more at the bottom, none at the top
  CHECK(plain.finest_level == 2);
  CHECK(refined.finest_level == 5);
  CHECK(refined.coarsest_at_top == 2);
  // Three halvings make a cell 8 times smaller if it is straight; the cells
  // at the bottom follow the circle, which makes it ~7.8, both against the
  // same cells without pre-refinement and against the largest cell.
  const double shrink = plain.smallest_diameter / refined.smallest_diameter;
  CHECK(shrink > 7.);
  CHECK(shrink < 8.5);
  CHECK(refined.largest_diameter > 7 * refined.smallest_diameter);
}
