// <Geometry/Type> 'two half discs': two bodies that touch at the centre,
// the lower half of a disc (ball) above it and the upper half of one below
// it: Hertz's problem of two cylinders (spheres) as a contact pair.
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <dualcontact/geometry.h>
#include <dualcontact/input_error.h>
#include <dualcontact/obstacle.h>
#include <dualcontact/parameter_helpers.h>
#include <dualcontact/parameters.h>

#include <cmath>

#include "disc.h"
#include "join_bodies.h"

namespace dualcontact
{
  namespace
  {
    /**
     * Two half discs (3D: half balls) that touch at `contact`: the upper
     * one (radius R1, material id 1) below its flat top, the lower one
     * (radius R2, material id 0) above its flat bottom, the mesh of a lower
     * half disc turned by 180 degrees (about the x axis in 3D), a proper
     * rotation. Boundary ids: 0 on the upper body's curved part, 1 on its
     * top, 2 on the lower body's curved part, 3 on its bottom. The caller
     * attaches the manifolds: the circles (spheres) 0 and 2 and a
     * transfinite interpolation inside.
     */
    template <int dim>
    void
    make_two_half_discs(Triangulation<dim> &result,
                        const Point<dim>   &contact,
                        const double        upper_radius,
                        const double        lower_radius)
    {
      Point<dim> upper_center(contact), lower_center(contact);
      upper_center[dim - 1] += upper_radius;
      lower_center[dim - 1] -= lower_radius;
      Triangulation<dim> upper, lower;
      disc::make_lower_half_disc(upper, upper_center, upper_radius, false);
      disc::make_lower_half_disc(lower, Point<dim>(), lower_radius, false);
      GridTools::transform(
        [&](const Point<dim> &p) {
          Point<dim> q = -p;
          if (dim == 3)
            q[0] = p[0];
          return q + lower_center;
        },
        lower);
      join_bodies<dim>({&lower, &upper}, result);
      // The ids of the faces and, in 3D, of their edges: the manifolds
      // follow the edges' ids, and a new mesh has 0 on every boundary edge.
      // The flat faces first, then the curved ones: a rim edge lies on the
      // sphere (and in the flat side through its centre) and takes the
      // sphere's id.
      for (const bool flat_pass : {true, false})
        for (const auto &cell : result.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              {
                const bool   on_upper = cell->material_id() == 1;
                const double radius   = on_upper ? upper_radius : lower_radius;
                // the flat sides pass through the discs' centres
                const double flat =
                  on_upper ? upper_center[dim - 1] : lower_center[dim - 1];
                const bool is_flat =
                  std::abs(face->center()[dim - 1] - flat) < 1e-8 * radius;
                if (is_flat == flat_pass)
                  face->set_all_boundary_ids((on_upper ? 0 : 2) +
                                             (is_flat ? 1 : 0));
              }
    }

    template <int dim>
    class TwoHalfDiscs : public Geometry<dim>
    {
    public:
      explicit TwoHalfDiscs(const Parameters &parameters)
          : g(parameters.geometry)
      {}

      CellKind
      cell_kind() const override
      {
        return g.cell_kind;
      }

      void
      create_coarse_mesh(Triangulation<dim> &triangulation) const override
      {
        Triangulation<dim> serial;
        const Point<dim>   contact = to_point<dim>(g.center);
        make_two_half_discs(serial, contact, g.radius, g.lower_radius);
        triangulation.copy_triangulation(serial);
        // the curved parts follow their circles (spheres), the interior
        // blends toward them (as for the half disc)
        Point<dim> upper_center(contact), lower_center(contact);
        upper_center[dim - 1] += g.radius;
        lower_center[dim - 1] -= g.lower_radius;
        triangulation.set_all_manifold_ids(1);
        triangulation.set_all_manifold_ids_on_boundary(0, 0);
        triangulation.set_all_manifold_ids_on_boundary(2, 2);
        triangulation.set_manifold(0, SphericalManifold<dim>(upper_center));
        triangulation.set_manifold(2, SphericalManifold<dim>(lower_center));
        TransfiniteInterpolationManifold<dim> inner;
        inner.initialize(triangulation);
        triangulation.set_manifold(1, inner);
      }

      Point<dim>
      center() const override
      {
        return to_point<dim>(g.center);
      }

      double
      characteristic_length() const override
      {
        return std::max(g.radius, g.lower_radius);
      }

    private:
      const GeometryParameters &g;
    };

    template <int dim>
    std::unique_ptr<Geometry<dim>>
    make(const Parameters &parameters, const std::function<void(double)> &)
    {
      return std::make_unique<TwoHalfDiscs<dim>>(parameters);
    }

    void
    declare(EntryDeclarer &declarer)
    {
      declarer.declare_entry("Lower radius",
                             "1",
                             EntryPattern::number(0.),
                             "Two half discs: the lower body's radius "
                             "[length]. Must be positive.");
    }

    void
    parse(ParameterHandler &prm, GeometryParameters &geometry)
    {
      geometry.lower_radius = prm.get_double("Lower radius");
    }

    void
    check_parsed(const GeometryParameters &geometry)
    {
      disc::check_radius(geometry, "the upper half disc");
      if (!(geometry.lower_radius > 0.))
        throw InputError("The entry <Geometry/Lower radius> must be positive: "
                         "a half disc of radius " +
                           number_text(geometry.lower_radius) + " has no area.",
                         exit_invalid_value);
    }

    void
    check_magnitudes(const GeometryParameters &geometry)
    {
      disc::check_magnitudes(geometry);
      check_magnitude(geometry.lower_radius,
                      "Geometry/Lower radius",
                      "[length]",
                      "e.g. mm or km instead of m");
      check_curved_boundary(geometry.lower_radius,
                            geometry.center,
                            "Geometry/Lower radius",
                            geometry.dimension);
    }

    void
    check(const Parameters &parameters)
    {
      if (parameters.geometry.cell_kind == CellKind::simplex)
        throw InputError("The entry <Geometry/Type> 'two half discs' is made "
                         "of quadrilaterals (hexahedra): set <Geometry/Cell "
                         "type> to 'quadrilateral', or read two bodies of "
                         "triangles from a mesh file.",
                         exit_inconsistent);
    }

    std::vector<std::string>
    entries()
    {
      std::vector<std::string> result = disc::entries();
      result.push_back("Lower radius");
      return result;
    }

    const bool registered = register_geometry(
      "two half discs",
      {4,
       "'two half "
       "discs': two bodies that touch at <Geometry/Center>, the lower half of "
       "a disc (ball) of <Geometry/Radius> above it (material id 1; ids 0 on "
       "its curved part, 1 on its flat top) and the upper half of one of "
       "<Geometry/Lower radius> below it (material id 0; ids 2 curved, 3 flat "
       "bottom): Hertz's problem of two cylinders (spheres) as a pair '0: "
       "2'.",
       declare,
       parse,
       entries(),
       {{{"Lower radius"}, "'two half discs'"}},
       {{{"Geometry", "Center", "0, 0, 0"}}},
       check_parsed,
       disc::check_center,
       check_magnitudes,
       check,
       [](const unsigned int) { return 4u; },
       nullptr,
       make<2>,
       make<3>});
  } // namespace
} // namespace dualcontact
