// The potential energy of the displacement, J(u) = 1/2 a(u, u) - f(u), f
// the body force and the tractions: with the energy J_ref of a much finer
// solution it estimates the energy-norm error, |u - u_h|_a ~
// sqrt(2 |J(u_h) - J_ref|) (doc/results_degree.md). Places and
// registration: report_quantity.h.
#include <dualcontact/report_quantity.h>

namespace dualcontact
{
  namespace
  {
    /** Every scene: potential_energy. */
    const bool potential_energy_registered =
      register_report_quantity("potential energy", [](auto &parts) {
        parts.csv = [](const auto &, const CycleResult &r, TableEntries &t) {
          t.add(375, "potential_energy", r.potential_energy);
        };
      });
  } // namespace
} // namespace dualcontact
