// <Geometry/Type> 'two blocks': the rectangle's box cut at half its height
// into two bodies whose meshes need not match across the cut, a contact
// pair (doc/two_bodies.md).
#include <deal.II/base/utilities.h>

#include <deal.II/grid/grid_generator.h>

#include <dualcontact/geometry.h>
#include <dualcontact/input_error.h>
#include <dualcontact/obstacle.h>
#include <dualcontact/parameters.h>

#include <array>
#include <cmath>

#include "box.h"
#include "join_bodies.h"

namespace dualcontact
{
  namespace
  {
    /**
     * Two boxes [lower, cut_low] and [cut_high, upper] that touch on the cut
     * x_{dim-1} = cut, each subdivided on its own, in one coarse mesh whose
     * vertices on the cut are not shared: two bodies. Boundary ids as a
     * box's (2 d on each block's lower, 2 d + 1 on its upper side along
     * x_d), and
     * on the cut 2 dim for the lower block's top and 2 dim + 1 for the upper
     * block's bottom; material id 0 for the lower and 1 for the upper block.
     */
    template <int dim>
    void
    make_two_blocks(Triangulation<dim>              &result,
                    const std::vector<unsigned int> &lower_subdivisions,
                    const std::vector<unsigned int> &upper_subdivisions,
                    const Point<dim>                &lower,
                    const Point<dim>                &cut_low,
                    const Point<dim>                &cut_high,
                    const Point<dim>                &upper,
                    const bool                       simplex)
    {
      std::array<Triangulation<dim>, 2> blocks;
      for (const unsigned int block : {0u, 1u})
        {
          const auto &n = block == 0 ? lower_subdivisions : upper_subdivisions;
          const Point<dim> &a = block == 0 ? lower : cut_high;
          const Point<dim> &b = block == 0 ? cut_low : upper;
          if (simplex)
            GridGenerator::subdivided_hyper_rectangle_with_simplices(
              blocks[block], n, a, b);
          else
            GridGenerator::subdivided_hyper_rectangle(blocks[block], n, a, b);
        }
      join_bodies<dim>({&blocks[0], &blocks[1]}, result);
      const double cut = cut_low[dim - 1];
      for (const auto &cell : result.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              const Point<dim> x = face->center();
              // the corners of the face's block
              const bool        lower_block = cell->material_id() == 0;
              const Point<dim> &a           = lower_block ? lower : cut_high;
              const Point<dim> &b           = lower_block ? cut_low : upper;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  const double tolerance = 1e-10 * (b[d] - a[d]);
                  if (d == dim - 1 && std::abs(x[d] - cut) < tolerance)
                    face->set_boundary_id(2 * dim + cell->material_id());
                  else if (std::abs(x[d] - a[d]) < tolerance)
                    face->set_boundary_id(2 * d);
                  else if (std::abs(x[d] - b[d]) < tolerance)
                    face->set_boundary_id(2 * d + 1);
                }
            }
    }

    template <int dim>
    class TwoBlocks : public box::BoxGeometry<dim>
    {
    public:
      using box::BoxGeometry<dim>::BoxGeometry;

      double
      n_coarse_cells() const override
      {
        const bool simplex = g.cell_kind == CellKind::simplex;
        return box::n_cells<dim>(g.subdivisions, simplex) +
               box::n_cells<dim>(g.upper_subdivisions, simplex);
      }

      void
      create_coarse_mesh(Triangulation<dim> &triangulation) const override
      {
        const Point<dim> lower = to_point<dim>(g.lower_left);
        const Point<dim> upper = to_point<dim>(g.upper_right);
        Point<dim>       cut_low(upper), cut_high(lower), top(upper);
        const double     cut = 0.5 * (lower[dim - 1] + upper[dim - 1]);
        cut_low[dim - 1]     = cut;
        cut_high[dim - 1]    = cut;
        // the upper block reaches beyond the lower one across the cut
        for (unsigned int d = 0; d + 1 < dim; ++d)
          {
            cut_high[d] -= g.upper_overhang;
            top[d] += g.upper_overhang;
          }
        Triangulation<dim> serial;
        make_two_blocks(serial,
                        {g.subdivisions.begin(), g.subdivisions.end()},
                        {g.upper_subdivisions.begin(),
                         g.upper_subdivisions.end()},
                        lower,
                        cut_low,
                        cut_high,
                        top,
                        g.cell_kind == CellKind::simplex);
        triangulation.copy_triangulation(serial);
      }

    private:
      using box::BoxGeometry<dim>::g;
    };

    template <int dim>
    std::unique_ptr<Geometry<dim>>
    make(const Parameters &parameters, const std::function<void(double)> &)
    {
      return std::make_unique<TwoBlocks<dim>>(parameters);
    }

    void
    declare(EntryDeclarer &declarer)
    {
      declarer.declare_entry(
        "Upper subdivisions",
        "1, 1",
        EntryPattern::list(EntryPattern::whole_number(1), 2, 3),
        "Two blocks: number of cells of the upper block's coarse mesh in each "
        "direction [-] (3D default: 1, 1, 1); across the cut they need not "
        "match the lower block's.");
      declarer.declare_entry(
        "Upper overhang",
        "0",
        EntryPattern::number(0.),
        "Two blocks: how far the upper block reaches beyond the lower one on "
        "each side across the cut (along x, and y in 3D) [length]. 0: both "
        "blocks span the box. The upper block's bottom beyond the lower one "
        "keeps the bottom's id (5 in 2D, 7 in 3D): a slave surface that "
        "extends beyond its master.");
    }

    void
    parse(ParameterHandler &prm, GeometryParameters &geometry)
    {
      geometry.upper_subdivisions.clear();
      for (const int n : Utilities::string_to_int(
             Utilities::split_string_list(prm.get("Upper subdivisions"), ',')))
        geometry.upper_subdivisions.push_back(n);
      geometry.upper_overhang = prm.get_double("Upper overhang");
    }

    void
    check_sizes(const GeometryParameters &geometry)
    {
      box::check_counts(geometry);
      if (geometry.upper_subdivisions.size() != geometry.dimension)
        throw InputError("The entry <Geometry/Upper subdivisions> needs " +
                           std::to_string(geometry.dimension) + " values.",
                         exit_inconsistent);
      box::check_corners(geometry);
    }

    std::vector<std::string>
    entries()
    {
      std::vector<std::string> result = box::entries();
      result.insert(result.end(), {"Upper subdivisions", "Upper overhang"});
      return result;
    }

    const bool registered = register_geometry(
      "two blocks",
      {3,
       "'two blocks': the "
       "rectangle's box cut at half its height (2D: y, 3D: z) into two bodies "
       "whose meshes need not match across the cut (<Geometry/Subdivisions> "
       "for the lower, <Geometry/Upper subdivisions> for the upper block), "
       "with the rectangle's ids on the outside (the lower block's bottom "
       "2 in 2D, 4 in 3D; the upper block's top 3, 5) and on the cut the ids "
       "4 (2D; 6 in 3D) for the lower block's top and 5 (7) for the upper "
       "block's bottom, material id 0 for the lower and 1 for the upper "
       "block: a pair for <Boundary conditions/Contact pairs>.",
       declare,
       parse,
       entries(),
       {{{"Upper subdivisions", "Upper overhang"}, "'two blocks'"}},
       {},
       nullptr,
       check_sizes,
       box::check_magnitudes,
       nullptr,
       [](const unsigned int dim) { return 2 * dim + 2; },
       box::size_entries,
       make<2>,
       make<3>});
  } // namespace
} // namespace dualcontact
