// <Material>: isotropic linear elasticity.
#include <deal.II/base/utilities.h>

#include <dualcontact/input_error.h>
#include <dualcontact/parameter_helpers.h>
#include <dualcontact/parameters.h>

namespace dualcontact
{
  using namespace dealii;

  double
  MaterialParameters::lambda() const
  {
    return youngs_modulus * poissons_ratio /
           ((1. + poissons_ratio) * (1. - 2. * poissons_ratio));
  }

  double
  MaterialParameters::mu() const
  {
    return youngs_modulus / (2. * (1. + poissons_ratio));
  }

  void
  MaterialParameters::declare_parameters(EntryDeclarer &declarer)
  {
    declarer.enter_subsection("Material");
    declarer.declare_entry(
      "Young's modulus",
      "1",
      EntryPattern::number(0.),
      "Young's modulus E [stress = force/length^2, e.g. Pa "
      "in N-m-Pa or MPa in N-mm-MPa]. Must be positive.");
    declarer.declare_entry("Poisson's ratio",
                           "0.3",
                           EntryPattern::number(-1., 0.5),
                           "Poisson's ratio nu [-], in (-1, 0.5). 2D is plane "
                           "strain.");
    declarer.leave_subsection();
  }

  void
  MaterialParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    youngs_modulus = prm.get_double("Young's modulus");
    poissons_ratio = prm.get_double("Poisson's ratio");
    prm.leave_subsection();
    // Patterns::Double has closed bounds; the open ends are checked here.
    if (!(youngs_modulus > 0.))
      throw InputError("The entry <Material/Young's modulus> must be positive.",
                       exit_invalid_value);
    if (!(poissons_ratio > -1. && poissons_ratio < 0.5))
      throw InputError("The entry <Material/Poisson's ratio> must lie in the "
                       "open interval (-1, 0.5).",
                       exit_invalid_value);
  }

  void
  MaterialParameters::check_magnitudes() const
  {
    check_magnitude(youngs_modulus,
                    "Material/Young's modulus",
                    "[stress]",
                    "e.g. MPa or GPa instead of Pa");
  }
} // namespace dualcontact
