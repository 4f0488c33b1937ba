// <Geometry/Type> 'rectangle': an axis-parallel box (2D rectangle, 3D
// cuboid) with the boundary ids 2 d on the lower and 2 d + 1 on the upper
// side along x_d; and the box's entries, which the two blocks share
// (box.h).
#include <deal.II/base/utilities.h>

#include <deal.II/grid/grid_generator.h>

#include <dualcontact/geometry.h>
#include <dualcontact/input_error.h>
#include <dualcontact/obstacle.h>
#include <dualcontact/parameter_helpers.h>
#include <dualcontact/parameters.h>

#include <cmath>

#include "box.h"

namespace dualcontact
{
  namespace box
  {
    void
    declare_parameters(EntryDeclarer &declarer)
    {
      declarer.declare_entry(
        "Lower left corner",
        "0, 0",
        EntryPattern::list(EntryPattern::number(), 2, 3),
        "Rectangle: the corner with the smallest coordinates "
        "[length], one value per dimension (3D default: 0, 0, "
        "0).");
      declarer.declare_entry(
        "Upper right corner",
        "1, 1",
        EntryPattern::list(EntryPattern::number(), 2, 3),
        "Rectangle: the corner with the largest coordinates "
        "[length], one value per dimension (3D default: 1, 1, "
        "1).");
      declarer.declare_entry(
        "Subdivisions",
        "1, 1",
        EntryPattern::list(EntryPattern::whole_number(1), 2, 3),
        "Rectangle: number of cells of the coarse mesh in each "
        "direction [-] (3D default: 1, 1, 1). Two blocks: those of the lower "
        "block.");
    }

    void
    parse_parameters(ParameterHandler &prm, GeometryParameters &geometry)
    {
      geometry.lower_left  = parse_doubles(prm.get("Lower left corner"));
      geometry.upper_right = parse_doubles(prm.get("Upper right corner"));
      geometry.subdivisions.clear();
      for (const int n : Utilities::string_to_int(
             Utilities::split_string_list(prm.get("Subdivisions"), ',')))
        geometry.subdivisions.push_back(n);
    }

    std::vector<std::string>
    entries()
    {
      return {"Lower left corner", "Upper right corner", "Subdivisions"};
    }

    void
    check_counts(const GeometryParameters &geometry)
    {
      const unsigned int dim = geometry.dimension;
      need_values(geometry.lower_left, "Geometry/Lower left corner", dim);
      need_values(geometry.upper_right, "Geometry/Upper right corner", dim);
      if (geometry.subdivisions.size() != dim)
        throw InputError("The entry <Geometry/Subdivisions> needs " +
                           std::to_string(dim) + " values.",
                         exit_inconsistent);
    }

    void
    check_corners(const GeometryParameters &geometry)
    {
      for (unsigned int d = 0; d < geometry.dimension; ++d)
        if (!(geometry.upper_right[d] > geometry.lower_left[d]))
          throw InputError("The entry <Geometry/Upper right corner> must be "
                           "larger than <Geometry/Lower left corner> in "
                           "every coordinate.",
                           exit_inconsistent);
    }

    void
    check_magnitudes(const GeometryParameters &geometry)
    {
      const std::string          lengths     = "e.g. mm or km instead of m";
      const std::vector<double> &lower_left  = geometry.lower_left;
      const std::vector<double> &upper_right = geometry.upper_right;
      if (lower_left.size() == upper_right.size())
        for (std::size_t d = 0; d < lower_left.size(); ++d)
          {
            check_magnitude(upper_right[d] - lower_left[d],
                            "Geometry/Upper right corner",
                            "[length] (a side of the box)",
                            lengths);
            if (std::abs(lower_left[d]) > 1e100)
              check_magnitude(lower_left[d],
                              "Geometry/Lower left corner",
                              "[length]",
                              lengths);
            if (std::abs(upper_right[d]) > 1e100)
              check_magnitude(upper_right[d],
                              "Geometry/Upper right corner",
                              "[length]",
                              lengths);
          }
    }

    std::vector<std::pair<std::string, std::string>>
    size_entries(const GeometryParameters &geometry)
    {
      std::string n;
      for (const unsigned int s : geometry.subdivisions)
        n += (n.empty() ? "" : ", ") + std::to_string(s);
      return {{"Geometry/Subdivisions", n}};
    }

    template <int dim>
    Point<dim>
    center(const GeometryParameters &geometry)
    {
      return 0.5 * (to_point<dim>(geometry.lower_left) +
                    to_point<dim>(geometry.upper_right));
    }

    double
    longest_side(const GeometryParameters &geometry, const unsigned int dim)
    {
      double length = 0;
      for (unsigned int d = 0; d < dim; ++d)
        length =
          std::max(length, geometry.upper_right[d] - geometry.lower_left[d]);
      return length;
    }

    template Point<2>
    center(const GeometryParameters &);
    template Point<3>
    center(const GeometryParameters &);
  } // namespace box

  namespace
  {
    template <int dim>
    class Rectangle : public box::BoxGeometry<dim>
    {
    public:
      using box::BoxGeometry<dim>::BoxGeometry;

      double
      n_coarse_cells() const override
      {
        return box::n_cells<dim>(g.subdivisions,
                                 g.cell_kind == CellKind::simplex);
      }

      void
      create_coarse_mesh(Triangulation<dim> &triangulation) const override
      {
        std::vector<unsigned int> repetitions(g.subdivisions.begin(),
                                              g.subdivisions.end());
        const Point<dim>          lower = to_point<dim>(g.lower_left);
        const Point<dim>          upper = to_point<dim>(g.upper_right);
        if (g.cell_kind != CellKind::simplex)
          {
            GridGenerator::subdivided_hyper_rectangle(
              triangulation, repetitions, lower, upper, /*colorize=*/true);
            return;
          }
        // deal.II 9.4 does not colorize this one: the ids of the
        // quadrilaterals' box, 2 d on the lower and 2 d + 1 on the upper
        // side along x_d, by hand
        Triangulation<dim> serial;
        GridGenerator::subdivided_hyper_rectangle_with_simplices(serial,
                                                                 repetitions,
                                                                 lower,
                                                                 upper);
        for (const auto &face : serial.active_face_iterators())
          if (face->at_boundary())
            for (unsigned int d = 0; d < dim; ++d)
              {
                const double tolerance = 1e-10 * (upper[d] - lower[d]);
                if (std::abs(face->center()[d] - lower[d]) < tolerance)
                  face->set_boundary_id(2 * d);
                else if (std::abs(face->center()[d] - upper[d]) < tolerance)
                  face->set_boundary_id(2 * d + 1);
              }
        triangulation.copy_triangulation(serial);
      }

    private:
      using box::BoxGeometry<dim>::g;
    };

    template <int dim>
    std::unique_ptr<Geometry<dim>>
    make(const Parameters &parameters, const std::function<void(double)> &)
    {
      return std::make_unique<Rectangle<dim>>(parameters);
    }

    void
    check_sizes(const GeometryParameters &geometry)
    {
      box::check_counts(geometry);
      box::check_corners(geometry);
    }

    const bool registered = register_geometry(
      "rectangle",
      {0,
       "'rectangle': an axis-parallel box with boundary ids "
       "0 (x = x_min), 1 (x = x_max), 2 (y = y_min), 3 (y = y_max) (and 4, 5 "
       "for z in 3D).",
       box::declare_parameters,
       box::parse_parameters,
       box::entries(),
       {{box::entries(), "the rectangle"}},
       {{{"Geometry", "Lower left corner", "0, 0, 0"}},
        {{"Geometry", "Upper right corner", "1, 1, 1"}},
        {{"Geometry", "Subdivisions", "1, 1, 1"}}},
       nullptr,
       check_sizes,
       box::check_magnitudes,
       nullptr,
       [](const unsigned int dim) { return 2 * dim; },
       box::size_entries,
       make<2>,
       make<3>});
  } // namespace
} // namespace dualcontact
