// Refinement between cycles: deal.II's Kelly estimator (which the
// indicators of refinement_indicator.h may use), and the marking of the
// cells by an indicator, the same on any partition.
#ifndef dualcontact_refinement_h
#define dualcontact_refinement_h

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/mapping.h>

#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <dualcontact/contact_set.h>

#include <set>

namespace dualcontact
{
  using namespace dealii;

  /**
   * Kelly's indicator per active cell (zero on cells not owned): the jump of
   * the gradient of the ghosted `solution` across interior faces; boundary
   * faces add nothing.
   */
  template <int dim>
  Vector<float>
  kelly_indicator(const Mapping<dim>                  &mapping,
                  const DoFHandler<dim>               &dof_handler,
                  const TrilinosWrappers::MPI::Vector &solution);

  /**
   * The size of an indicator that carries information: the root mean square
   * over the N active cells of ||grad u_h||_{L2(K)},
   * sqrt(sum_K int_K |grad u_h|^2 / N), in the indicators' units (strain
   * times length^(dim/2)). An indicator far below it compares jumps of the
   * gradient far below the gradient itself: round-off and solver
   * tolerance. `solution` is ghosted. Collective.
   */
  template <int dim>
  double
  indicator_scale(const Mapping<dim>                  &mapping,
                  const DoFHandler<dim>               &dof_handler,
                  const TrilinosWrappers::MPI::Vector &solution);

  /**
   * The relative width of the classes in which mark_fixed_number() compares
   * the indicators [-]: far above their round-off (they are stored as
   * float, 6e-8 relative, and differ between partitions by less than 1e-8
   * of the largest on the shipped scenes), far below the differences
   * between indicators that should decide which cells are refined.
   */
  constexpr double indicator_tie_tolerance = 1e-6;

  /**
   * Flag for refinement about floor(refine_fraction N) of the N active
   * cells, those with the largest indicators, and for coarsening about
   * floor(coarsen_fraction N), those with the smallest, the same cells on
   * any number of ranks.
   *
   * A cell's indicator computed on two partitions differs by round-off (the
   * ghost values and the order of the sums differ, and the solvers stop at
   * a tolerance), so cells whose indicators are equal in exact arithmetic
   * (under a uniform or a symmetric load) would be told apart by that
   * round-off. The indicators are therefore compared in classes of width
   * w = tie_tolerance max(largest indicator, `scale`), rounded down to a
   * power of 2: eta is in class round(eta / w). The cells are taken by
   * class, largest first for refinement, smallest first for coarsening,
   * and a class is taken whole or not at all: the class at the threshold
   * is taken if that brings the count at least as close to the target. So
   * cells with equal indicators are all refined or none is, and a
   * symmetric scene keeps a symmetric mesh. `scale` (indicator_scale())
   * puts the indicators that are round-off into class 0: on a uniformly
   * stressed body, where every indicator is, all cells are refined if the
   * fraction is at least one half, none otherwise. The threshold class is
   * found by a bisection on global counts (integers, the same on every
   * partition).
   *
   * The triangulation must not smooth the mesh beyond
   * limit_level_difference_at_vertices, which p4est enforces on the whole
   * forest: deal.II's other smoothing flags act on the flags each rank
   * sees, which depend on the partition (see
   * parallel::distributed::Triangulation's constructor).
   *
   * `indicator` has one entry per active cell; those of the cells not
   * owned are not read. Collective.
   */
  template <int dim>
  void
  mark_fixed_number(Triangulation<dim>  &triangulation,
                    const Vector<float> &indicator,
                    const double         scale,
                    const double         refine_fraction,
                    const double         coarsen_fraction,
                    const double tie_tolerance = indicator_tie_tolerance);
} // namespace dualcontact

#endif
