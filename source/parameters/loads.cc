// <Loads>: volume loads.
#include <dualcontact/parameters.h>

namespace dualcontact
{
  using namespace dealii;

  void
  LoadParameters::declare_parameters(EntryDeclarer &declarer)
  {
    declarer.enter_subsection("Loads");
    declarer.declare_entry(
      "Body force",
      "0; 0",
      EntryPattern::text(),
      "Body force f per unit volume, 'f_x; f_y' (one component per "
      "dimension) [force/length^3]; each an expression in x, y (z) and the "
      "time t of the load path (<Load path>), with the constants pi, E, nu, "
      "lambda, mu. All zero: no body force is assembled. (3D default: 0; 0; "
      "0.)");
    declarer.leave_subsection();
  }

  void
  LoadParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loads");
    body_force = prm.get("Body force");
    prm.leave_subsection();
  }
} // namespace dualcontact
