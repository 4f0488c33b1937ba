// <Exact solution>: what is known of the solution, for the errors.
#include <deal.II/base/utilities.h>

#include <dualcontact/friction_law.h>
#include <dualcontact/input_error.h>
#include <dualcontact/parameter_helpers.h>
#include <dualcontact/parameters.h>

namespace dualcontact
{
  using namespace dealii;

  void
  ExactSolutionParameters::declare_parameters(EntryDeclarer &declarer)
  {
    declarer.enter_subsection("Exact solution");
    declarer.declare_entry(
      "Displacement",
      "",
      EntryPattern::text(),
      "If known, the exact displacement 'u_x; u_y' [length] as expressions "
      "in x, y (z) with the constants pi, E, nu, lambda, mu; the L2 and H1 "
      "errors are then reported per cycle. Empty: none is known.");
    declarer.declare_entry(
      "Contact pressure",
      "",
      EntryPattern::text(),
      "If known, the exact contact pressure p = -sigma_n on the contact "
      "boundary [stress], an expression in x, y (z) with the constants pi, "
      "E, nu, lambda, mu (functions such as sqrt, max may be used); the "
      "relative L2 error on Gamma_C of l1 (interpolated between the contact nodes) is then reported per cycle. "
      "Empty: none is known.");
    declarer.declare_entry(
      "Contact half-width",
      "0",
      EntryPattern::number(0.),
      "If known, the exact half-width a of the contact zone [length] in 2D, "
      "its radius in 3D; the relative error of the computed one (edges "
      "extrapolated; in 3D along two lines through the zone's centre, where "
      "the contact begins) is then reported per cycle. The zone is measured "
      "whole: a model cut by symmetry planes through that centre (a half or "
      "quarter ball) is measured as mirrored across them; a zone cut "
      "anywhere else is measured as the part in the model. 0: not known.");
    declarer.declare_entry(
      "Stick half-width",
      "0",
      EntryPattern::number(0.),
      "If known, the exact half-width c of the stick zone [length] in 2D, "
      "its radius in 3D (e.g. Cattaneo-Mindlin); the relative error of the "
      "computed one (each end half-way between the last sticking and the "
      "first slipping node) is then reported per cycle. Needs friction. 0: "
      "not known.");
    declarer.declare_entry("Peak pressure",
                           "0",
                           EntryPattern::number(0.),
                           "If known, the exact largest contact pressure p0 "
                           "[stress]; the relative error of max l1 is then "
                           "reported per cycle. 0: not known.");
    declarer.leave_subsection();
  }

  void
  ExactSolutionParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Exact solution");
    displacement       = Utilities::trim(prm.get("Displacement"));
    contact_pressure   = Utilities::trim(prm.get("Contact pressure"));
    contact_half_width = prm.get_double("Contact half-width");
    stick_half_width   = prm.get_double("Stick half-width");
    peak_pressure      = prm.get_double("Peak pressure");
    prm.leave_subsection();
  }

  std::vector<IneffectiveRule>
  ExactSolutionParameters::ineffective_rules(const Parameters &parameters) const
  {
    const bool         contact = parameters.boundary.has_contact();
    const std::string &law     = parameters.friction.law;
    return {{!contact,
             "Exact solution",
             {"Contact pressure",
              "Contact half-width",
              "Stick half-width",
              "Peak pressure"},
             "the scene has no contact boundary"},
            {contact && create_friction_law(law)->parameter_entry().empty(),
             "Exact solution",
             {"Stick half-width"},
             "<Friction/Law> is " + quoted(law) +
               " (frictionless): there is no stick zone"}};
  }
} // namespace dualcontact
