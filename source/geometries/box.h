// What the axis-parallel boxes (the rectangle, the two blocks) share: the
// entries of the box's corners and subdivisions with their checks, its
// centre and size, and its count of cells (defined in rectangle.cc).
#ifndef dualcontact_geometries_box_h
#define dualcontact_geometries_box_h

#include <deal.II/base/point.h>

#include <dualcontact/entry_declaration.h>
#include <dualcontact/geometry.h>
#include <dualcontact/parameters.h>

#include <string>
#include <utility>
#include <vector>

namespace dualcontact
{
  namespace box
  {
    using namespace dealii;

    /** <Geometry/Lower left corner>, <Upper right corner>, <Subdivisions>. */
    void
    declare_parameters(EntryDeclarer &declarer);
    void
    parse_parameters(ParameterHandler &prm, GeometryParameters &geometry);

    /** The entries above, as the ineffective-entry rules name them. */
    std::vector<std::string>
    entries();

    /** The counts of the corners' coordinates and of the subdivisions. */
    void
    check_counts(const GeometryParameters &geometry);
    /** Upper right above lower left in every coordinate. */
    void
    check_corners(const GeometryParameters &geometry);
    void
    check_magnitudes(const GeometryParameters &geometry);

    /** <Geometry/Subdivisions> with its values (the memory check). */
    std::vector<std::pair<std::string, std::string>>
    size_entries(const GeometryParameters &geometry);

    /**
     * The cells of a box of `subdivisions`, taken in double (three of them
     * overflow an integer long before the memory runs out): 2 triangles or
     * 5 tetrahedra per cell on simplices.
     */
    template <int dim>
    double
    n_cells(const std::vector<unsigned int> &subdivisions, bool simplex)
    {
      double n = simplex ? (dim == 2 ? 2. : 5.) : 1.;
      for (const unsigned int s : subdivisions)
        n *= s;
      return n;
    }

    /** The middle of the box and its longest side. */
    template <int dim>
    Point<dim>
    center(const GeometryParameters &geometry);
    double
    longest_side(const GeometryParameters &geometry, unsigned int dim);

    /**
     * What a box-shaped geometry answers alike: its cell kind, centre and
     * size from the <Geometry> entries it keeps.
     */
    template <int dim>
    class BoxGeometry : public Geometry<dim>
    {
    public:
      explicit BoxGeometry(const Parameters &parameters)
          : g(parameters.geometry)
      {}

      CellKind
      cell_kind() const override
      {
        return g.cell_kind;
      }

      Point<dim>
      center() const override
      {
        return box::center<dim>(g);
      }

      double
      characteristic_length() const override
      {
        return box::longest_side(g, dim);
      }

    protected:
      const GeometryParameters &g;
    };
  } // namespace box
} // namespace dualcontact

#endif
