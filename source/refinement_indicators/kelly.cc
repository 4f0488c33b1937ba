// The 'kelly' refinement indicator: deal.II's Kelly estimator, the jump of
// the displacement gradient across the faces.
#include <dualcontact/refinement.h>
#include <dualcontact/refinement_indicator.h>

namespace dualcontact
{
  namespace
  {
    template <int dim>
    Vector<float>
    kelly(const IndicatorInput<dim> &input)
    {
      return kelly_indicator(input.mapping, input.dof_handler, input.solution);
    }

    const bool registered = register_refinement_indicator(
      "kelly",
      {"refines (and coarsens) fixed fractions of the cells ranked by "
       "deal.II's Kelly estimator, the jump of the displacement gradient "
       "across faces.",
       nullptr,
       {},
       kelly<2>,
       kelly<3>});
  } // namespace
} // namespace dualcontact
