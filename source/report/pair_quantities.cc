// The quantities of a scene with contact pairs between bodies: the
// contact forces on the slave and master bodies, each pair's force apart,
// and the time of pairing the surfaces (doc/two_bodies.md). Places and
// registration: report_quantity.h.
#include <dualcontact/report_quantity.h>

#include <cmath>

#include "format.h"

namespace dualcontact
{
  namespace
  {
    using namespace report_format;

    /**
     * Contact pairs: slave_body_force_x, _y (_z) and master_body_force_x,
     * _y (_z), the contact forces on the slave and on the master bodies
     * (doc/two_bodies.md), equal and opposite; contact_force apart,
     * obstacle_contact_force (with an obstacle too) and pair_S_M_force for
     * each pair, each along the mean normal of its own nodes;
     * time_pairing, the wall time of pairing the surfaces on the mesh [s].
     */
    const bool pair_forces_registered =
      register_report_quantity("contact pair forces", [](auto &parts) {
        constexpr int dim = dimension_of<decltype(parts)>;
        parts.has         = [](const Parameters &, const auto &scene) {
          return !scene.contact_pairs().empty();
        };
        parts.csv = [](const auto &q, const CycleResult &r, TableEntries &t) {
          const char *axes[] = {"x", "y", "z"};
          for (unsigned int c = 0; c < dim; ++c)
            t.add(466,
                  std::string("slave_body_force_") + axes[c],
                  r.zone.on_slave_body[c]);
          for (unsigned int c = 0; c < dim; ++c)
            t.add(467,
                  std::string("master_body_force_") + axes[c],
                  r.zone.on_master_body[c]);
          // contact_force apart: the obstacle's and each pair's
          if (q.scene.effects().obstacle_contact)
            t.add(468, "obstacle_contact_force", r.zone.obstacle_force);
          unsigned int p = 0;
          for (const auto &[slave_id, master_id] : q.scene.contact_pairs())
            t.add(469,
                  "pair_" + std::to_string(slave_id) + "_" +
                    std::to_string(master_id) + "_force",
                  p < r.zone.pair_force.size() ? r.zone.pair_force[p++] : 0.);
          t.add(485, "time_pairing", r.solve.pairing_time);
        };
        parts.print = [](const auto        &q,
                         const CycleResult &r,
                         ScreenLines       &lines) {
          // the total contact force apart: the obstacle's and each pair's,
          // each along its own nodes' mean normal
          std::vector<std::string> parts;
          if (q.scene.effects().obstacle_contact)
            parts.push_back("on the obstacle " +
                            significant(r.zone.obstacle_force));
          unsigned int p = 0;
          for (const auto &[slave_id, master_id] : q.scene.contact_pairs())
            if (p < r.zone.pair_force.size())
              parts.push_back("pair " + std::to_string(slave_id) + ": " +
                              std::to_string(master_id) + " " +
                              significant(r.zone.pair_force[p++]));
          lines.add(44, wrap("   contact force: ", parts, ", ", "     "));
          std::string slave, master;
          double      sum = 0., size = 0.;
          for (unsigned int c = 0; c < dim; ++c)
            {
              slave +=
                (c == 0 ? "(" : ", ") + significant(r.zone.on_slave_body[c]);
              master +=
                (c == 0 ? "(" : ", ") + significant(r.zone.on_master_body[c]);
              sum +=
                std::pow(r.zone.on_slave_body[c] + r.zone.on_master_body[c], 2);
              size += std::pow(r.zone.on_slave_body[c], 2);
            }
          lines.add(45,
                    wrap("   contact pairs: ",
                         {"force on the slave bodies " + slave + ")",
                          "on the master bodies " + master + ")",
                          "their sum " +
                            scientific(size > 0. ? std::sqrt(sum / size) : 0.,
                                       1) +
                            " of either (relative)"},
                         ", ",
                         "     "));
        };
      });
  } // namespace
} // namespace dualcontact
