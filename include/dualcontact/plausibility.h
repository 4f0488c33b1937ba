// Checks that a scene and its solution make physical sense, beyond what the
// equations enforce (doc/theory.md §8): the body starts outside the
// foundation, with the foundation's normal pointing into it; after a solve
// no boundary without the contact condition passes through the foundation,
// and the displacements stay small against the body, as the small-strain
// model assumes.
#ifndef dualcontact_plausibility_h
#define dualcontact_plausibility_h

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/mapping.h>

#include <deal.II/lac/trilinos_vector.h>

#include <dualcontact/records.h>
#include <dualcontact/scene.h>


namespace dualcontact
{
  using namespace dealii;

  /**
   * Stop with an input error (exit status 6) if the body lies on the wrong
   * side of the foundation plane: entirely (the normal is reversed: it must
   * point from the foundation into the body), or with part of its contact
   * boundary (the body starts inside the foundation). Positions within
   * 1e-8 of the body's size of the plane count as on it.
   */
  template <int dim>
  void
  check_initial_position(const Triangulation<dim> &triangulation,
                         const Scene<dim>         &scene);


  /**
   * The deformed body against the foundation and the small-strain model:
   * - a boundary without the contact condition that passes through the
   *   foundation by more than 1e-3 of the body's size stops the run with
   *   an input error (exit status 6) that names its id; by less (but more
   *   than round-off), a warning;
   * - displacements above 5 % of the body's size give a warning (the
   *   model is linear: small displacements and strains).
   * Both are checked at the support points of the element (the vertices
   * and, at degree k >= 2, the points between them), placed by `mapping`.
   * `solution` is ghosted.
   */
  template <int dim>
  PositionRecord
  check_deformed_position(const Mapping<dim>                  &mapping,
                          const DoFHandler<dim>               &dof_handler,
                          const TrilinosWrappers::MPI::Vector &solution,
                          const Scene<dim>                    &scene);
} // namespace dualcontact

#endif
