// The quantities of a load path of several steps (doc/theory.md §11): which
// step, at what time, where the obstacle is, and the energy friction
// dissipated. Each quantity is one registration of its parts, the formulas of
// its columns and lines; places and registration: report_quantity.h.
#include <dualcontact/report_quantity.h>

#include "format.h"

namespace dualcontact
{
  namespace
  {
    using namespace report_format;

    /**
     * A load path of several steps: step, time; with adaptive <Load
     * path/Step control> step_size, cuts (the failed tries before the step
     * converged) and listed (which listed time it reaches, 0: a sub-step
     * short of it); with contact predictor (the
     * factor of the extrapolation the step started from, 0: none); with
     * friction dissipation, dissipation_total; with an obstacle moved by
     * <Obstacle/Displacement> obstacle_displacement_x, _y (_z); the mean
     * displacement of each loaded boundary part i, displacement_i_x, _y (_z).
     */
    const bool load_step_registered =
      register_report_quantity("load step", [](auto &parts) {
        constexpr int dim = dimension_of<decltype(parts)>;
        parts.has         = [](const Parameters &parameters, const auto &) {
          return parameters.load_path.step_times().size() > 1;
        };
        parts.csv = [](const auto &q, const CycleResult &r, TableEntries &t) {
          static const char *axes[] = {"x", "y", "z"};
          t.add(4, "step", r.step.step);
          t.add(6, "time", r.step.time);
          if (q.parameters.load_path.adaptive_steps)
            {
              t.add(7, "step_size", r.step.step_size);
              t.add(8, "cuts", r.step.cuts);
              t.add(9, "listed", r.step.listed);
            }
          if (q.scene.effects().contact)
            t.add(152, "predictor", r.solve.predictor);
          if (q.scene.effects().contact &&
              q.scene.effects().friction_law().has_friction())
            {
              t.add(315, "dissipation", r.step.dissipation);
              t.add(316, "dissipation_total", r.step.dissipation_total);
            }
          if (q.scene.obstacle_moves())
            {
              for (unsigned int c = 0; c < dim; ++c)
                t.add(465,
                      std::string("obstacle_displacement_") + axes[c],
                      r.step.obstacle_displacement[c]);
            }
          for (const auto &[id, u] : r.step.boundary_displacement)
            for (unsigned int c = 0; c < dim; ++c)
              t.add(455,
                    "displacement_" + std::to_string(id) + "_" + axes[c],
                    u[c]);
        };
      });
  } // namespace
} // namespace dualcontact
