// The pre-refinement of the initial mesh: the cells near the obstacle, or
// in a scene whose contact is between bodies near the other body's paired
// surface, refined <Geometry/Pre-refinement steps> times in a band that
// shrinks by the grading; with the initial global refinement before it.
#include <deal.II/base/mpi.h>

#include <dualcontact/scene.h>

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <vector>

namespace dualcontact
{
  namespace
  {
    /**
     * The pre-refinement band of a scene whose contact is between bodies:
     * the vertices of the pairs' surfaces (slave and master ids) of all
     * ranks with their bodies, binned in squares (cubes) of the band's
     * width, so that a vertex finds those within the width in the 3^dim
     * bins around it.
     */
    template <int dim>
    class PairBand
    {
    public:
      PairBand() = default;

      PairBand(const Triangulation<dim> &triangulation,
               const std::map<types::boundary_id, types::boundary_id> &pairs,
               const double                                            width)
          : width(std::max(width, std::numeric_limits<double>::min()))
          , bodies(bodies_of_coarse_cells(triangulation))
      {
        std::set<types::boundary_id> ids;
        for (const auto &[slave, master] : pairs)
          {
            ids.insert(slave);
            ids.insert(master);
          }
        std::vector<double> local;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const auto &face : cell->face_iterators())
              if (face->at_boundary() && ids.count(face->boundary_id()))
                for (const unsigned int v : face->vertex_indices())
                  {
                    for (unsigned int d = 0; d < dim; ++d)
                      local.push_back(face->vertex(v)[d]);
                    local.push_back(body_of<dim>(cell, bodies));
                  }
        for (const auto &part :
             Utilities::MPI::all_gather(triangulation.get_communicator(),
                                        local))
          for (std::size_t i = 0; i + dim < part.size(); i += dim + 1)
            {
              Point<dim> x;
              for (unsigned int d = 0; d < dim; ++d)
                x[d] = part[i + d];
              bins[bin_of(x)].emplace_back(
                x, static_cast<unsigned int>(part[i + dim]));
            }
      }

      /** Whether vertex v of `cell` lies within the width of another body's
       * paired surface. */
      template <typename Iterator>
      bool
      near(const Iterator &cell, const unsigned int v) const
      {
        const Point<dim>   x    = cell->vertex(v);
        const unsigned int body = body_of<dim>(cell, bodies);
        const auto         home = bin_of(x);
        for (unsigned int k = 0; k < std::pow(3, dim); ++k)
          {
            auto         key  = home;
            unsigned int rest = k;
            for (unsigned int d = 0; d < dim; ++d, rest /= 3)
              key[d] += static_cast<long>(rest % 3) - 1;
            const auto it = bins.find(key);
            if (it != bins.end())
              for (const auto &[p, other] : it->second)
                if (other != body && x.distance(p) <= width)
                  return true;
          }
        return false;
      }

    private:
      std::array<long, dim>
      bin_of(const Point<dim> &x) const
      {
        std::array<long, dim> key;
        for (unsigned int d = 0; d < dim; ++d)
          key[d] = static_cast<long>(std::floor(x[d] / width));
        return key;
      }

      double                    width = 0.;
      std::vector<unsigned int> bodies;
      std::map<std::array<long, dim>,
               std::vector<std::pair<Point<dim>, unsigned int>>>
        bins;
    };
  } // namespace

  template <int dim>
  void
  Scene<dim>::refine_initial_mesh(
    parallel::TriangulationBase<dim>  &triangulation,
    const std::function<void(double)> &before_refining) const
  {
    const GeometryParameters &g        = parameters.geometry;
    const bool                simplex  = discretization_->mesh_is_replicated();
    const double              children = std::pow(2., dim);
    if (before_refining)
      before_refining(
        triangulation.n_global_active_cells() *
        std::pow(children, parameters.refinement.initial_global_refinement));
    triangulation.refine_global(
      parameters.refinement.initial_global_refinement);

    // A step whose band reaches the vertex farthest from the foundation
    // refines every cell: what the remaining steps make at least is known
    // before they are made.
    double farthest = -std::numeric_limits<double>::max();
    if (before_refining && g.pre_refinement_steps > 0)
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const unsigned int v : cell->vertex_indices())
              farthest = std::max(farthest, initial_gap(cell->vertex(v)));
        farthest =
          Utilities::MPI::max(farthest, triangulation.get_communicator());
      }

    // In a scene whose contact is between bodies only, the band lies
    // around the pairs' surfaces: a cell is near if one of its vertices
    // lies within the distance of a vertex of another body's paired
    // surface (PairBand).
    const bool toward_pairs =
      !effects_.obstacle_contact && !contact_pairs().empty();
    if (toward_pairs)
      farthest = std::numeric_limits<double>::max();

    double distance = g.pre_refinement_distance;
    for (unsigned int step = 0; step < g.pre_refinement_steps;
         ++step, distance *= g.pre_refinement_grading)
      {
        const PairBand<dim> band =
          toward_pairs ?
            PairBand<dim>(triangulation, contact_pairs(), distance) :
            PairBand<dim>();
        // (a replicated mesh of simplices refines the cells that every
        // rank flags alike: all of them are flagged)
        unsigned int n_flagged = 0;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() || simplex)
            for (const unsigned int v : cell->vertex_indices())
              if (toward_pairs ? band.near(cell, v) :
                                 initial_gap(cell->vertex(v)) <= distance)
                {
                  cell->set_refine_flag();
                  n_flagged += cell->is_locally_owned() ? 1 : 0;
                  break;
                }
        if (before_refining)
          {
            double n_cells =
              triangulation.n_global_active_cells() +
              (children - 1.) *
                Utilities::MPI::sum(n_flagged,
                                    triangulation.get_communicator());
            double later = distance * g.pre_refinement_grading;
            for (unsigned int next = step + 1;
                 next < g.pre_refinement_steps && later >= farthest;
                 ++next, later *= g.pre_refinement_grading)
              n_cells *= children;
            before_refining(n_cells);
          }
        triangulation.execute_coarsening_and_refinement();
      }
  }


  template void
  Scene<2>::refine_initial_mesh(parallel::TriangulationBase<2> &,
                                const std::function<void(double)> &) const;
  template void
  Scene<3>::refine_initial_mesh(parallel::TriangulationBase<3> &,
                                const std::function<void(double)> &) const;
} // namespace dualcontact
