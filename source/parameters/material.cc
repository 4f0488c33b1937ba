// <Material>: isotropic linear elasticity.
#include <deal.II/base/utilities.h>

#include <dualcontact/input_error.h>
#include <dualcontact/parameter_helpers.h>
#include <dualcontact/parameters.h>

namespace dualcontact
{
  using namespace dealii;

  std::string
  mixed_pair_refusal(const CellKind kind, const unsigned int degree)
  {
    if (degree >= 2)
      return "";
    return kind == CellKind::simplex ?
             "The mixed formulation pairs P_k displacements with a P_{k-1} "
             "pressure (Taylor-Hood), and degree 1 would pair P1 with P0, "
             "which fails the inf-sup condition (it locks as P1 alone does): "
             "set <Discretization/Polynomial degree> = 2 for P2/P1." :
             "The mixed formulation pairs Q_k displacements with a Q_{k-1} "
             "pressure (Taylor-Hood), and degree 1 would pair Q1 with Q0, "
             "which fails the inf-sup condition (checkerboard pressure "
             "modes): set <Discretization/Polynomial degree> = 2 for Q2/Q1 (or 3 for "
             "Q3/Q2).";
  }

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
    declarer.declare_entry(
      "Poisson's ratio",
      "0.3",
      EntryPattern::number(-1., 0.5),
      "Poisson's ratio nu [-], in (-1, 0.5); 0.5 (incompressible) with "
      "<Formulation> = mixed. 2D is plane strain.");
    declarer.declare_entry(
      "Formulation",
      "displacement",
      EntryPattern::selection("displacement|mixed"),
      "How the bodies are discretised. 'displacement': in displacements "
      "alone (FE_Q(k)^dim), the cheapest, accurate to about nu = 0.45 at "
      "degree 1 and 0.49 at degree 2, beyond which the elements lock (too "
      "stiff, the pressure wrong). 'mixed': displacements and the pressure "
      "p = -kappa div u [stress] as a second field (Taylor-Hood: Q_k/Q_{k-1} "
      "or P_k/P_{k-1}, so <Discretization/Polynomial degree> >= 2), whose accuracy does "
      "not depend on nu up to and including nu = 0.5: rubber, seals, "
      "incompressible bodies. Each linear solve is then a saddle-point "
      "system solved by MINRES (doc/mixed.md).");
    declarer.declare_entry(
      "Materials by id",
      "",
      EntryPattern::map(EntryPattern::whole_number(0, 254),
                        EntryPattern::list(EntryPattern::number(), 2, 2),
                        0,
                        dealii::Patterns::Map::max_int_value,
                        ";"),
      "The bodies of other materials, as 'material id: E, nu' separated by "
      "';', e.g. '1: 3000, 0.3; 2: 500, 0.25' (E [stress], nu [-] as "
      "above). The cells with an id listed take "
      "its E and nu, those with id 0 <Young's modulus> and <Poisson's ratio>; "
      "once the list is not empty, a cell of any other id is an error. "
      "Material ids come from the geometry ('two blocks': 0 for the lower, 1 "
      "for the upper block) or a mesh file (Gmsh's physical groups of "
      "surfaces in 2D, volumes in 3D). Empty: one material everywhere.");
    declarer.leave_subsection();
  }

  void
  MaterialParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    youngs_modulus = prm.get_double("Young's modulus");
    poissons_ratio = prm.get_double("Poisson's ratio");
    formulation    = prm.get("Formulation") == "mixed" ? Formulation::mixed :
                                                         Formulation::displacement;
    by_id.clear();
    {
      for (const std::string &item :
           Utilities::split_string_list(prm.get("Materials by id"), ';'))
        {
          const auto colon  = item.find(':');
          const int  id     = Utilities::string_to_int(item.substr(0, colon));
          const auto values = parse_doubles(item.substr(colon + 1));
          const std::string entry = "Material/Materials by id";
          if (values.size() != 2)
            throw InputError("The entry <" + entry + "> gives material id " +
                               std::to_string(id) + " " +
                               std::to_string(values.size()) +
                               " numbers: it takes 'id: E, nu'.",
                             exit_invalid_value);
          if (!by_id.emplace(id, std::make_pair(values[0], values[1])).second)
            throw InputError("The entry <" + entry + "> names material id " +
                               std::to_string(id) + " twice.",
                             exit_inconsistent);
          if (!(values[0] > 0.))
            throw InputError("The entry <" + entry + "> gives material id " +
                               std::to_string(id) + " the Young's modulus " +
                               format_number(values[0]) +
                               ": it must be positive.",
                             exit_invalid_value);
          if (!(values[1] > -1. && values[1] <= 0.5))
            throw InputError("The entry <" + entry + "> gives material id " +
                               std::to_string(id) + " the Poisson's ratio " +
                               format_number(values[1]) +
                               ": it must lie in (-1, 0.5].",
                             exit_invalid_value);
          check_incompressible(values[1], entry);
        }
    }
    prm.leave_subsection();
    // Patterns::Double has closed bounds; the open ends are checked here.
    if (!(youngs_modulus > 0.))
      throw InputError("The entry <Material/Young's modulus> must be positive.",
                       exit_invalid_value);
    if (!(poissons_ratio > -1. && poissons_ratio <= 0.5))
      throw InputError("The entry <Material/Poisson's ratio> must lie in "
                       "(-1, 0.5].",
                       exit_invalid_value);
    check_incompressible(poissons_ratio, "Material/Poisson's ratio");
  }

  void
  MaterialParameters::check_incompressible(const double       nu,
                                           const std::string &entry) const
  {
    // lambda = E nu / ((1 + nu)(1 - 2 nu)) is infinite at nu = 1/2: only
    // the pressure of the mixed formulation, whose 1/kappa is zero there,
    // can carry the constraint div u = 0
    if (nu >= 0.5 && formulation == Formulation::displacement)
      throw InputError("The entry <" + entry +
                         "> is 0.5, an incompressible "
                         "body, which displacement elements cannot represent "
                         "(lambda is infinite): set <Material/Formulation> = "
                         "mixed.",
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
