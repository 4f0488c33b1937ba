// The pre-refinement band of a scene whose contact is between bodies only:
// the cells near another body's paired surface.
#ifndef dualcontact_pair_band_h
#define dualcontact_pair_band_h

#include <deal.II/base/point.h>

#include <deal.II/grid/tria.h>

#include <dualcontact/bodies.h>

#include <array>
#include <map>
#include <optional>
#include <utility>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  /**
   * The vertices of the pairs' surfaces (slave and master ids) of all
   * ranks with their bodies, binned in squares (cubes) of the band's
   * width, so that a vertex finds those within the width in the 3^dim bins
   * around it. Collective.
   */
  template <int dim>
  class PairBand
  {
  public:
    PairBand(const Triangulation<dim> &triangulation,
             const std::map<types::boundary_id, types::boundary_id> &pairs,
             double                                                  width);

    /** Whether vertex v of `cell` lies within the width of another body's
     * paired surface. */
    bool
    near(const typename Triangulation<dim>::active_cell_iterator &cell,
         unsigned int                                             v) const;

  private:
    std::array<long, dim>
    bin_of(const Point<dim> &x) const;

    double      width;
    Bodies<dim> bodies;
    std::map<std::array<long, dim>,
             std::vector<std::pair<Point<dim>, unsigned int>>>
      bins;
  };
} // namespace dualcontact

#endif
