#include <dualcontact/parameters.h>
#include <dualcontact/refinement_indicator.h>
#include <dualcontact/registry.h>

#include <utility>

namespace dualcontact
{
  bool
  register_refinement_indicator(const std::string      &name,
                                RefinementIndicatorKind kind)
  {
    Registry<RefinementIndicatorKind>::instance().add(name, std::move(kind));
    return true;
  }

  std::vector<std::string>
  refinement_indicator_names()
  {
    return Registry<RefinementIndicatorKind>::instance().names();
  }

  const RefinementIndicatorKind &
  refinement_indicator_kind(const std::string &name)
  {
    return Registry<RefinementIndicatorKind>::instance().get(
      name, "refinement indicator", "Refinement/Strategy");
  }

  template <int dim>
  Vector<float>
  compute_indicator(const IndicatorInput<dim> &input)
  {
    const RefinementIndicatorKind &kind =
      refinement_indicator_kind(input.parameters.refinement.strategy);
    if constexpr (dim == 2)
      return kind.indicator_2d(input);
    else
      return kind.indicator_3d(input);
  }

  template Vector<float>
  compute_indicator(const IndicatorInput<2> &);
  template Vector<float>
  compute_indicator(const IndicatorInput<3> &);
} // namespace dualcontact
