// The registry of the kinds of geometry (geometry.h), and what the kinds
// share: the curved boundaries' checks and the conversion to simplices.
#include <deal.II/base/numbers.h>

#include <deal.II/grid/grid_generator.h>

#include <dualcontact/geometry.h>
#include <dualcontact/input_error.h>
#include <dualcontact/mesh_file.h>
#include <dualcontact/parameters.h>
#include <dualcontact/registry.h>

#include <algorithm>
#include <cmath>

namespace dualcontact
{
  bool
  register_geometry(const std::string &name, GeometryKind kind)
  {
    Registry<GeometryKind>::instance().add(name, std::move(kind));
    return true;
  }

  std::vector<std::string>
  geometry_names()
  {
    std::vector<std::string> names = Registry<GeometryKind>::instance().names();
    std::stable_sort(names.begin(),
                     names.end(),
                     [](const std::string &a, const std::string &b) {
                       return geometry_kind(a).listing_position <
                              geometry_kind(b).listing_position;
                     });
    return names;
  }

  const GeometryKind &
  geometry_kind(const std::string &name)
  {
    return Registry<GeometryKind>::instance().get(name,
                                                  "geometry",
                                                  "Geometry/Type");
  }

  template <int dim>
  std::unique_ptr<Geometry<dim>>
  create_geometry(const Parameters                  &parameters,
                  const std::function<void(double)> &before_building)
  {
    const GeometryKind &kind = geometry_kind(parameters.geometry.type);
    if constexpr (dim == 2)
      return kind.create_2d(parameters, before_building);
    else
      return kind.create_3d(parameters, before_building);
  }

  unsigned int
  n_geometry_boundary_ids(const GeometryParameters &geometry)
  {
    const GeometryKind &kind = geometry_kind(geometry.type);
    return kind.n_boundary_ids == nullptr ?
             numbers::invalid_unsigned_int :
             kind.n_boundary_ids(geometry.dimension);
  }

  void
  check_curved_boundary(const double               radius,
                        const std::vector<double> &center,
                        const std::string         &entry,
                        const unsigned int         dim)
  {
    // deal.II's manifolds (the curved boundaries and the cells next to
    // them) work with absolute tolerances of about 1e-10, and its
    // transfinite interpolation in 3D loses its accuracy far from the
    // origin against the cell size: radii below 1e-6 and, in 3D, centres
    // farther than 100 radii from the origin fail inside deal.II while the
    // mesh is refined.
    if (radius < 1e-6)
      throw InputError("The entry <" + entry +
                         "> gives a curved boundary "
                         "the radius " +
                         format_number(radius) +
                         ", below 1e-6 [length]: deal.II's manifolds, "
                         "which refine curved boundaries, use absolute "
                         "tolerances of about 1e-10 and fail for such "
                         "small cells. Use smaller units (e.g. "
                         "micrometres instead of metres); the results do "
                         "not depend on them.",
                       exit_invalid_value);
    double distance = 0.;
    for (const double c : center)
      distance += c * c;
    distance = std::sqrt(distance);
    if (dim == 3 && distance > 100. * radius)
      throw InputError("The entry <" + entry +
                         "> puts the centre of a "
                         "curved boundary " +
                         format_number(distance) +
                         " from the origin, more than 100 times its "
                         "radius " +
                         format_number(radius) +
                         ": in 3D, deal.II's transfinite interpolation of "
                         "the cells next to it fails that far from the "
                         "origin. Move the origin near the body (shift the "
                         "centre, the foundation or obstacle, and the "
                         "expressions that use x, y, z).",
                       exit_invalid_value);
  }

  template <int dim>
  void
  convert_to_simplices(Triangulation<dim>                  &mesh,
                       const std::vector<BoundaryManifold> &curves)
  {
    Triangulation<dim> simplices;
    GridGenerator::convert_hypercube_to_simplex_mesh(mesh, simplices);
    snap_to_manifolds(curves, simplices);
    mesh.clear();
    mesh.copy_triangulation(simplices);
  }

  template std::unique_ptr<Geometry<2>>
  create_geometry(const Parameters &, const std::function<void(double)> &);
  template std::unique_ptr<Geometry<3>>
  create_geometry(const Parameters &, const std::function<void(double)> &);
  template void
  convert_to_simplices(Triangulation<2> &,
                       const std::vector<BoundaryManifold> &);
  template void
  convert_to_simplices(Triangulation<3> &,
                       const std::vector<BoundaryManifold> &);
} // namespace dualcontact
