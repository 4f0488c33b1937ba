// <Geometry/Type> 'half disc' (3D: half ball) and 'quarter disc' (2D): the
// body below its flat top through the centre, its curved boundary a circle
// (sphere) that refinement follows; and the discs' entries, which the two
// half discs share (disc.h).
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <dualcontact/geometry.h>
#include <dualcontact/input_error.h>
#include <dualcontact/obstacle.h>
#include <dualcontact/parameter_helpers.h>
#include <dualcontact/parameters.h>

#include <cmath>

#include "disc.h"

namespace dualcontact
{
  namespace disc
  {
    void
    declare_parameters(EntryDeclarer &declarer)
    {
      declarer.declare_entry(
        "Center",
        "0, 0",
        EntryPattern::list(EntryPattern::number(), 2, 3),
        "Half disc (3D: half ball): centre of the disc, i.e. "
        "the middle of the flat top; the curved part lies below "
        "it, toward -y (3D: -z) [length] (3D default: 0, 0, "
        "0).");
      declarer.declare_entry("Radius",
                             "1",
                             EntryPattern::number(0.),
                             "Half disc: radius R [length]. Must be positive. "
                             "Two half discs: the upper body's radius.");
    }

    void
    parse_parameters(ParameterHandler &prm, GeometryParameters &geometry)
    {
      geometry.center = parse_doubles(prm.get("Center"));
      geometry.radius = prm.get_double("Radius");
    }

    std::vector<std::string>
    entries()
    {
      return {"Center", "Radius"};
    }

    void
    check_radius(const GeometryParameters &geometry, const std::string &what)
    {
      if (!(geometry.radius > 0.))
        throw InputError("The entry <Geometry/Radius> must be positive: " +
                           what + " of radius " + number_text(geometry.radius) +
                           " has no area.",
                         exit_invalid_value);
    }

    void
    check_center(const GeometryParameters &geometry)
    {
      need_values(geometry.center, "Geometry/Center", geometry.dimension);
    }

    void
    check_magnitudes(const GeometryParameters &geometry)
    {
      check_magnitude(geometry.radius,
                      "Geometry/Radius",
                      "[length]",
                      "e.g. mm or km instead of m");
      check_curved_boundary(geometry.radius,
                            geometry.center,
                            "Geometry/Radius",
                            geometry.dimension);
    }

    template <int dim>
    void
    make_lower_half_disc(Triangulation<dim> &result,
                         const Point<dim>   &center,
                         const double        radius,
                         const bool          quarter)
    {
      const auto turn = [&](const auto &rotation) {
        Triangulation<dim> part;
        if (dim == 2)
          GridGenerator::quarter_hyper_ball(part, Point<dim>(), radius);
        else
          GridGenerator::half_hyper_ball(part, Point<dim>(), radius);
        GridTools::transform(rotation, part);
        return part;
      };
      const auto lower_right = turn([&](const Point<dim> &p) {
        Point<dim> q;
        if (dim == 2)
          q = Point<dim>(p[1], -p[0]);
        else // a proper rotation: (x,y,z) -> (-y, z, -x)
          {
            q[0]       = -p[1];
            q[1]       = p[dim - 1];
            q[dim - 1] = -p[0];
          }
        return q + center;
      });
      if (dim == 2 && !quarter)
        GridGenerator::merge_triangulations(lower_right,
                                            turn([&](const Point<dim> &p) {
                                              return center - p;
                                            }),
                                            result);
      else
        result.copy_triangulation(lower_right);
      result.reset_all_manifolds();
    }

    template void
    make_lower_half_disc(Triangulation<2> &, const Point<2> &, double, bool);
    template void
    make_lower_half_disc(Triangulation<3> &, const Point<3> &, double, bool);
  } // namespace disc

  namespace
  {
    template <int dim>
    class HalfDisc : public Geometry<dim>
    {
    public:
      HalfDisc(const Parameters &parameters, const bool quarter)
          : g(parameters.geometry)
          , quarter(quarter)
      {}

      CellKind
      cell_kind() const override
      {
        return g.cell_kind;
      }

      void
      create_coarse_mesh(Triangulation<dim> &triangulation) const override
      {
        const bool         simplex = g.cell_kind == CellKind::simplex;
        const Point<dim>   center  = to_point<dim>(g.center);
        Triangulation<dim> serial;
        disc::make_lower_half_disc(serial, center, g.radius, quarter);

        // Boundary ids: 1 on the flat top, 2 on the symmetry line of the
        // quarter disc, 0 on the curved part.
        const double tolerance = 1e-8 * g.radius;
        for (const auto &face : serial.active_face_iterators())
          if (face->at_boundary())
            {
              const Point<dim> x = face->center();
              if (std::abs(x[dim - 1] - center[dim - 1]) < tolerance)
                face->set_boundary_id(1);
              else if (quarter && std::abs(x[0] - center[0]) < tolerance)
                face->set_boundary_id(2);
              else
                face->set_boundary_id(0);
            }
        if (simplex)
          {
            // each quadrilateral into 8 triangles (hexahedron into 24
            // tetrahedra); the vertices this puts on the middle of the
            // curved faces' chords go onto the circle (sphere)
            BoundaryManifold curve;
            curve.id     = 0;
            curve.kind   = dim == 2 ? BoundaryManifold::Kind::circle :
                                      BoundaryManifold::Kind::sphere;
            curve.center = g.center;
            curve.radius = g.radius;
            convert_to_simplices(serial, {curve});
          }
        triangulation.copy_triangulation(serial);
        attach_manifolds(triangulation, center, simplex);
      }

      Point<dim>
      center() const override
      {
        return to_point<dim>(g.center);
      }

      double
      characteristic_length() const override
      {
        return g.radius;
      }

    private:
      /**
       * The curved boundary follows the circle; on quadrilaterals the
       * interior blends smoothly toward it, so refined cells stay well
       * shaped (deal.II 9.4's transfinite interpolation takes no
       * simplices: their cells stay flat).
       */
      static void
      attach_manifolds(Triangulation<dim> &triangulation,
                       const Point<dim>   &center,
                       const bool          simplex)
      {
        triangulation.set_all_manifold_ids(simplex ? numbers::flat_manifold_id :
                                                     1);
        if (simplex)
          {
            // by hand: deal.II 9.4's set_all_manifold_ids_on_boundary()
            // asks a triangle for a fourth face
            for (const auto &face : triangulation.active_face_iterators())
              if (face->at_boundary() && face->boundary_id() == 0)
                face->set_all_manifold_ids(0);
          }
        else
          triangulation.set_all_manifold_ids_on_boundary(0, 0);
        triangulation.set_manifold(0, SphericalManifold<dim>(center));
        if (!simplex)
          {
            TransfiniteInterpolationManifold<dim> inner;
            inner.initialize(triangulation);
            triangulation.set_manifold(1, inner);
          }
      }

      const GeometryParameters &g;
      const bool                quarter;
    };

    template <int dim, bool quarter>
    std::unique_ptr<Geometry<dim>>
    make(const Parameters &parameters, const std::function<void(double)> &)
    {
      return std::make_unique<HalfDisc<dim>>(parameters, quarter);
    }

    void
    check_half_disc(const GeometryParameters &geometry)
    {
      disc::check_radius(geometry, "a half disc");
    }

    void
    check_quarter_disc(const GeometryParameters &geometry)
    {
      disc::check_radius(geometry, "a quarter disc");
    }

    void
    check_quarter_disc_dimension(const Parameters &parameters)
    {
      if (parameters.geometry.dimension != 2)
        throw InputError("The entry <Geometry/Type> 'quarter disc' exists in "
                         "2D only.",
                         exit_inconsistent);
    }

    const bool registered_half = register_geometry(
      "half disc",
      {1,
       "'half disc': the lower half of a disc (ball in 3D) of "
       "the given radius and centre, with boundary ids 0 (the curved part) "
       "and 1 (the flat top); refinement follows the circle.",
       disc::declare_parameters,
       disc::parse_parameters,
       disc::entries(),
       {{disc::entries(), "the discs"}},
       {{{"Geometry", "Center", "0, 0, 0"}}},
       check_half_disc,
       disc::check_center,
       disc::check_magnitudes,
       nullptr,
       [](const unsigned int) { return 2u; },
       nullptr,
       make<2, false>,
       make<3, false>});

    const bool registered_quarter = register_geometry(
      "quarter disc",
      {2,
       "'quarter disc' "
       "(2D): the lower right quarter (x >= x_c, y <= y_c) with ids 0 (curved), "
       "1 (flat top) and 2 (the symmetry line x = x_c).",
       disc::declare_parameters,
       disc::parse_parameters,
       disc::entries(),
       {{disc::entries(), "the discs"}},
       {{{"Geometry", "Center", "0, 0, 0"}}},
       check_quarter_disc,
       disc::check_center,
       disc::check_magnitudes,
       check_quarter_disc_dimension,
       [](const unsigned int) { return 3u; },
       nullptr,
       make<2, true>,
       make<3, true>});
  } // namespace
} // namespace dualcontact
