// What the discs (the half disc, the quarter disc, the two half discs)
// share: the entries of the centre and the radius with their checks, and
// the mesh of the lower half disc (defined in half_disc.cc).
#ifndef dualcontact_geometries_disc_h
#define dualcontact_geometries_disc_h

#include <deal.II/base/point.h>

#include <deal.II/grid/tria.h>

#include <dualcontact/entry_declaration.h>
#include <dualcontact/parameters.h>

#include <string>
#include <vector>

namespace dualcontact
{
  namespace disc
  {
    using namespace dealii;

    /** <Geometry/Center> and <Geometry/Radius>. */
    void
    declare_parameters(EntryDeclarer &declarer);
    void
    parse_parameters(ParameterHandler &prm, GeometryParameters &geometry);

    /** The entries above, as the ineffective-entry rules name them. */
    std::vector<std::string>
    entries();

    /**
     * <Geometry/Radius> positive (the patterns allow 0, which would fail
     * late, inside deal.II's mesh or manifold code): `what` names the body
     * in the message ("a half disc").
     */
    void
    check_radius(const GeometryParameters &geometry, const std::string &what);

    /** <Geometry/Center> has a coordinate per dimension. */
    void
    check_center(const GeometryParameters &geometry);

    /** <Geometry/Radius>'s magnitude, and its curve's (geometry.h). */
    void
    check_magnitudes(const GeometryParameters &geometry);

    /**
     * The half disc (3D: half ball) below its flat top through `center`,
     * normal +e_{dim-1}, or in 2D with `quarter` its lower right quarter; no
     * manifolds, ids 0. In 2D both are made of deal.II's quarter ball (the
     * quadrant x, y >= 0) turned by -90 degrees (lower right quarter) and,
     * for the half disc, by 180 degrees (lower left quarter): the quarter
     * ball is symmetric about its diagonal, so the half disc's mesh is
     * symmetric about the line x = x_c, which is a mesh line, and its right
     * half is exactly the quarter disc's mesh. In 3D the half ball x >= 0
     * is turned so that its cut plane is the top.
     */
    template <int dim>
    void
    make_lower_half_disc(Triangulation<dim> &result,
                         const Point<dim>   &center,
                         double              radius,
                         bool                quarter);
  } // namespace disc
} // namespace dualcontact

#endif
