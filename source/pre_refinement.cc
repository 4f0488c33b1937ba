// The pre-refinement of the initial mesh: the cells near the obstacle, or
// in a scene whose contact is between bodies near the other body's paired
// surface, refined <Geometry/Pre-refinement steps> times in a band that
// shrinks by the grading; with the initial global refinement before it.
#include <deal.II/base/mpi.h>

#include <dualcontact/pair_band.h>
#include <dualcontact/scene.h>

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <vector>

namespace dualcontact
{
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
    // around the pairs' surfaces (PairBand).
    const bool toward_pairs =
      !effects_.obstacle_contact && !contact_pairs().empty();
    if (toward_pairs)
      farthest = std::numeric_limits<double>::max();

    double distance = g.pre_refinement_distance;
    for (unsigned int step = 0; step < g.pre_refinement_steps;
         ++step, distance *= g.pre_refinement_grading)
      {
        std::optional<PairBand<dim>> band;
        if (toward_pairs)
          band.emplace(triangulation, contact_pairs(), distance);
        // (a replicated mesh of simplices refines the cells that every
        // rank flags alike: all of them are flagged)
        unsigned int n_flagged = 0;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() || simplex)
            for (const unsigned int v : cell->vertex_indices())
              if (band ? band->near(cell, v) :
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
