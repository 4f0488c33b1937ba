// The quantities of the contact problem: its solve, the friction, the
// errors of the contact zone, its area (3D) and the force on a moved
// obstacle; those of contact pairs are in pair_quantities.cc. Each quantity
// is one registration of its parts, the formulas of its columns and lines;
// places and registration: report_quantity.h.
#include <deal.II/base/numbers.h>

#include <dualcontact/report_quantity.h>

#include <cmath>

#include "format.h"

namespace dualcontact
{
  namespace
  {
    using namespace report_format;

    /** The scenes with contact. */
    const auto contact_scenes = [](const Parameters &, const auto &scene) {
      return scene.effects().contact;
    };

    /** The scenes with contact and a friction law other than 'none'. */
    const auto friction_scenes = [](const Parameters &, const auto &scene) {
      return scene.effects().contact &&
             scene.effects().friction_law().has_friction();
    };

    /** The lines of the contact solve in a cycle's results. */
    template <int dim>
    void
    print_contact_solve(const QuantityFromParts<dim> &q,
                        const CycleResult            &r,
                        ScreenLines                  &lines)
    {
      const std::string  indent = "     ";
      const SolveRecord &solve  = r.solve;
      const auto        &zone   = r.zone;
      lines.add(20,
                wrap("   contact solved: ",
                     {"Uzawa " + count(solve.uzawa_steps),
                      "Newton " + count(solve.newton_steps),
                      "CG " + count(solve.cg_iterations),
                      "AMG set-ups " + count(solve.amg_setups),
                      count(solve.n_active) + " of " +
                        count(solve.n_contact_nodes) + " nodes in contact" +
                        seconds(r.time.solve,
                                q.parameters.output.print_timing)},
                     ", ",
                     indent));
      lines.add(40,
                wrap("   ",
                     {"total contact force " + significant(zone.contact_force) +
                        " (applied load toward the obstacle " +
                        significant(solve.normal_load) + ")",
                      "peak pressure " + significant(zone.max_pressure)},
                     ", ",
                     indent));
      if (dim == 2)
        lines.add(50,
                  "   contact half-width " + significant(zone.half_width) +
                    " (nodes), " + significant(zone.edge_half_width) +
                    " (edges extrapolated)\n");
      if (zone.mirrored > 0)
        lines.add(60,
                  std::string("   (the model ends at the zone's centre: "
                              "measured as mirrored across ") +
                    (zone.mirrored == 1 ? "that plane" : "those planes") +
                    (dim == 3 ? ", area of the whole zone" : "") + ")\n");
      if (solve.n_hanging_contact > 0)
        lines.add(80,
                  "   " + count(solve.n_hanging_contact) +
                    " hanging nodes on Gamma_C (no contact condition of their "
                    "own)\n");
      if (solve.n_uncovered > 0)
        lines.add(82,
                  "   " + count(solve.n_uncovered) +
                    " nodes of the slave surfaces face no master surface "
                    "(no contact nodes)\n");
      if (solve.n_corner_contact > 0)
        lines.add(85,
                  "   " +
                    count(types::global_dof_index(solve.n_corner_contact)) +
                    " contact nodes face a corner or an edge of the "
                    "obstacle and take the body's normal\n");
      lines.add(110,
                "   Uzawa contraction rate " + scientific(solve.rate) +
                  ", remaining error of l1 about " +
                  scientific(solve.estimated_l1_error) +
                  " (d rho/(1 - rho), doc/theory.md §6)\n");
    }

    /**
     * Contact: contact_nodes, hanging_contact_nodes, active_nodes, r, chi,
     * uzawa_steps, newton_steps, uzawa_rate, l1_error_estimate,
     * normal_load, contact_force, max_pressure, contact_half_width,
     * contact_edge_half_width.
     */
    const bool contact_solve_registered =
      register_report_quantity("contact solve", [](auto &parts) {
        constexpr int dim = dimension_of<decltype(parts)>;
        parts.has         = contact_scenes;
        parts.csv = [](const auto &, const CycleResult &r, TableEntries &t) {
          t.add(70, "contact_nodes", std::uint64_t(r.solve.n_contact_nodes));
          t.add(80,
                "hanging_contact_nodes",
                std::uint64_t(r.solve.n_hanging_contact));
          t.add(90, "active_nodes", std::uint64_t(r.solve.n_active));
          t.add(120, "r", r.solve.r);
          t.add(130, "chi", r.solve.chi);
          t.add(150, "uzawa_steps", r.solve.uzawa_steps);
          t.add(160, "newton_steps", r.solve.newton_steps);
          t.add(190, "uzawa_rate", r.solve.rate);
          t.add(200, "l1_error_estimate", r.solve.estimated_l1_error);
          t.add(210, "normal_load", r.solve.normal_load);
          t.add(230, "contact_force", r.zone.contact_force);
          t.add(250, "max_pressure", r.zone.max_pressure);
          t.add(260, "contact_half_width", r.zone.half_width);
          t.add(270, "contact_edge_half_width", r.zone.edge_half_width);
        };
        parts.summary =
          [](const auto &, const CycleResult &r, TableEntries &s) {
            s.add(40, "nodes", std::uint64_t(r.solve.n_contact_nodes));
            s.add(110, "Uzawa", r.solve.uzawa_steps);
            s.add(120, "Newton", r.solve.newton_steps);
          };
        parts.row = [](const auto &, std::vector<RowColumn> &c) {
          using R = CycleResult;
          c.push_back({40, 0, "nodes", 7, [](const R &r) {
                         return count(r.solve.n_contact_nodes);
                       }});
          c.push_back({50, 0, "active", 7, [](const R &r) {
                         return count(r.solve.n_active);
                       }});
          c.push_back({70, 0, "Uzawa", 6, [](const R &r) {
                         return count(r.solve.uzawa_steps);
                       }});
          c.push_back({80, 0, "Newton", 7, [](const R &r) {
                         return count(r.solve.newton_steps);
                       }});
          c.push_back({100, 0, "force", 12, [](const R &r) {
                         return significant(r.zone.contact_force, 6);
                       }});
          c.push_back({110, 0, "load", 12, [](const R &r) {
                         return significant(r.solve.normal_load, 6);
                       }});
        };
        parts.print = print_contact_solve<dim>;
      });

    /**
     * Contact: time_newton_matrix, time_amg_setup, time_cg, time_gradient,
     * time_multipliers.
     */
    const bool contact_solve_times_registered =
      register_report_quantity("contact solve times", [](auto &parts) {
        parts.has = contact_scenes;
        parts.csv = [](const auto &, const CycleResult &r, TableEntries &t) {
          t.add(530, "time_newton_matrix", r.solve.times.newton_matrix);
          t.add(540, "time_amg_setup", r.solve.times.amg_setup);
          t.add(550, "time_cg", r.solve.times.cg);
          t.add(560, "time_gradient", r.solve.times.gradient);
          t.add(570, "time_multipliers", r.solve.times.multipliers);
        };
        parts.print = [](const auto        &q,
                         const CycleResult &r,
                         ScreenLines       &lines) {
          if (!q.parameters.output.print_timing)
            return;
          const SolveTimes &t = r.solve.times;
          lines.add(
            30,
            wrap("   where the solve's time went: ",
                 {"Newton matrices " + significant(t.newton_matrix, 3) + " s",
                  "AMG set-ups " + significant(t.amg_setup, 3) + " s",
                  "CG " + significant(t.cg, 3) + " s",
                  "gradients and line searches " + significant(t.gradient, 3) +
                    " s",
                  "multiplier updates " + significant(t.multipliers, 3) + " s"},
                 ", ",
                 "     "));
        };
      });

    /**
     * A friction law other than 'none': stick_nodes, slip_nodes,
     * tangential_force, stick_half_width.
     */
    const bool friction_registered =
      register_report_quantity("friction", [](auto &parts) {
        constexpr int dim = dimension_of<decltype(parts)>;
        parts.has         = friction_scenes;
        parts.csv = [](const auto &, const CycleResult &r, TableEntries &t) {
          t.add(100, "stick_nodes", std::uint64_t(r.solve.n_stick));
          t.add(110, "slip_nodes", std::uint64_t(r.solve.n_slip));
          t.add(240, "tangential_force", r.zone.tangential_force);
          t.add(310, "stick_half_width", r.zone.stick_half_width);
        };
        parts.row = [](const auto &, std::vector<RowColumn> &c) {
          using R = CycleResult;
          c.push_back({120, 2, "stick/slip", 11, [](const R &r) {
                         return count(r.solve.n_stick) + "/" +
                                count(r.solve.n_slip);
                       }});
          c.push_back({130, 1, "tangential", 12, [](const R &r) {
                         return significant(r.zone.tangential_force, 6);
                       }});
        };
        parts.print =
          [](const auto &, const CycleResult &r, ScreenLines &lines) {
            std::vector<std::string> items = {
              count(r.solve.n_stick) + " stick, " + count(r.solve.n_slip) +
                " slip nodes",
              (dim == 2 ? "stick half-width " : "stick radius ") +
                significant(r.zone.stick_half_width),
              "total tangential force " + significant(r.zone.tangential_force)};
            if (r.solve.threshold_steps > 0)
              items.push_back(count(r.solve.threshold_steps) +
                              " threshold steps");
            lines.add(100, wrap("   friction: ", items, ", ", "     "));
          };
      });

    /** Friction bounded by F l1 (Coulomb): threshold_steps. */
    const bool threshold_steps_registered =
      register_report_quantity("threshold iteration", [](auto &parts) {
        parts.has = [](const Parameters &parameters, const auto &scene) {
          return friction_scenes(parameters, scene) &&
                 scene.effects().friction_law().depends_on_pressure();
        };
        parts.csv = [](const auto &, const CycleResult &r, TableEntries &t) {
          t.add(140, "threshold_steps", r.solve.threshold_steps);
        };
        parts.summary =
          [](const auto &, const CycleResult &r, TableEntries &s) {
            s.add(100, "threshold", r.solve.threshold_steps);
          };
        parts.row = [](const auto &q, std::vector<RowColumn> &c) {
          // g updated in each Uzawa step (merged): no steps of its own
          if (q.parameters.friction.strategy == FrictionStrategy::nested)
            c.push_back({60, 1, "threshold", 10, [](const CycleResult &r) {
                           return count(r.solve.threshold_steps);
                         }});
        };
      });

    /**
     * Contact with something of <Exact solution> to compare with, each
     * column where its exact value is given: pressure_error,
     * half_width_error, stick_half_width_error, peak_pressure_error.
     */
    const bool contact_errors_registered =
      register_report_quantity("contact errors", [](auto &parts) {
        constexpr int dim = dimension_of<decltype(parts)>;
        parts.has = [](const Parameters &parameters, const auto &scene) {
          const ExactSolutionParameters &exact = parameters.exact;
          return scene.effects().contact &&
                 (scene.exact_pressure() != nullptr ||
                  exact.contact_half_width > 0. ||
                  exact.stick_half_width > 0. || exact.peak_pressure > 0.);
        };
        parts.csv = [](const auto &q, const CycleResult &r, TableEntries &t) {
          const ExactSolutionParameters &exact = q.parameters.exact;
          if (q.scene.exact_pressure() != nullptr)
            t.add(280, "pressure_error", r.zone.pressure_error);
          if (exact.contact_half_width > 0.)
            t.add(320, "half_width_error", r.zone.half_width_error);
          if (exact.stick_half_width > 0.)
            t.add(330, "stick_half_width_error", r.zone.stick_half_width_error);
          if (exact.peak_pressure > 0.)
            t.add(340, "peak_pressure_error", r.zone.peak_pressure_error);
        };
        parts.summary =
          [](const auto &q, const CycleResult &r, TableEntries &s) {
            const ExactSolutionParameters &exact = q.parameters.exact;
            if (q.scene.exact_pressure() != nullptr)
              s.add_error(60, "p L2 err", r.zone.pressure_error);
            if (exact.contact_half_width > 0.)
              s.add_error(70, "a err", r.zone.half_width_error);
            if (exact.stick_half_width > 0.)
              s.add_error(80, "c err", r.zone.stick_half_width_error);
            if (exact.peak_pressure > 0.)
              s.add_error(90, "p0 err", r.zone.peak_pressure_error);
          };
        parts.format_summary = [](const auto &q, ConvergenceTable &table) {
          // a rate for the pressure's L2 error only: the errors of a and p0 are
          // signed and change sign, where a log rate means nothing; c err keeps
          // the table's default format
          const ExactSolutionParameters &exact = q.parameters.exact;
          const std::vector<std::pair<std::string, bool>> keys = {
            {"p L2 err", q.scene.exact_pressure() != nullptr},
            {"a err", exact.contact_half_width > 0.},
            {"p0 err", exact.peak_pressure > 0.}};
          for (const auto &[key, known] : keys)
            if (known)
              {
                table.set_scientific(key, true);
                table.set_precision(key, 2);
                if (key == "p L2 err")
                  table.evaluate_convergence_rates(
                    key, "DoFs", ConvergenceTable::reduction_rate_log2, dim);
              }
        };
        parts.row = [](const auto &q, std::vector<RowColumn> &c) {
          using R                              = CycleResult;
          const ExactSolutionParameters &exact = q.parameters.exact;
          if (q.scene.exact_pressure() != nullptr)
            c.push_back({140, 0, "p L2 err", 10, [](const R &r) {
                           return scientific(r.zone.pressure_error);
                         }});
          if (exact.contact_half_width > 0.)
            c.push_back({150, 3, "a err", 10, [](const R &r) {
                           return scientific(r.zone.half_width_error);
                         }});
          if (exact.stick_half_width > 0.)
            c.push_back({160, 3, "c err", 10, [](const R &r) {
                           return scientific(r.zone.stick_half_width_error);
                         }});
          if (exact.peak_pressure > 0.)
            c.push_back({170, 3, "p0 err", 10, [](const R &r) {
                           return scientific(r.zone.peak_pressure_error);
                         }});
        };
        parts.print = [](const auto        &q,
                         const CycleResult &r,
                         ScreenLines       &lines) {
          const ExactSolutionParameters &exact = q.parameters.exact;
          std::vector<std::string>       errors;
          if (q.scene.exact_pressure() != nullptr)
            errors.push_back("pressure (L2) " +
                             significant(r.zone.pressure_error));
          if (exact.contact_half_width > 0.)
            errors.push_back((dim == 2 ? "half-width " : "radius ") +
                             significant(r.zone.half_width_error));
          if (exact.stick_half_width > 0.)
            errors.push_back(
              (dim == 2 ? "stick half-width " : "stick radius ") +
              significant(r.zone.stick_half_width_error));
          if (exact.peak_pressure > 0.)
            errors.push_back("peak " + significant(r.zone.peak_pressure_error));
          lines.add(70, wrap("   relative errors: ", errors, ", ", "     "));
        };
      });

    /** Contact in 3D: contact_area, contact_extent. */
    const bool contact_area_registered =
      register_report_quantity("contact area", [](auto &parts) {
        constexpr int dim = dimension_of<decltype(parts)>;
        parts.has         = [](const Parameters &, const auto &scene) {
          return dim == 3 && scene.effects().contact;
        };
        parts.csv = [](const auto &, const CycleResult &r, TableEntries &t) {
          t.add(290, "contact_area", r.zone.area);
          t.add(300, "contact_extent", r.zone.extent);
        };
        parts.summary =
          [](const auto &, const CycleResult &r, TableEntries &s) {
            // hanging nodes on Gamma_C come with adaptive meshes in 3D
            s.add(50, "hanging", std::uint64_t(r.solve.n_hanging_contact));
          };
        parts.print = [](const auto &,
                         const CycleResult &r,
                         ScreenLines       &lines) {
          const auto &zone = r.zone;
          lines.add(
            50,
            wrap("   contact radius ",
                 {significant(zone.half_width) +
                    " (nodes on two lines through the centre), " +
                    significant(zone.edge_half_width) + " (edges extrapolated)",
                  "area " + significant(zone.area) + " (the disc of radius " +
                    significant(std::sqrt(zone.area / numbers::PI)) + ")",
                  "extent " + significant(zone.extent)},
                 ", ",
                 "     "));
        };
      });

    /**
     * A scene with friction, an obstacle moved by <Obstacle/Displacement>,
     * or a load path of several steps: obstacle_force_x, _y (_z), the
     * force of the body on the obstacle with its sign (tangential_force is
     * the magnitude of its tangential part).
     */
    const bool obstacle_force_registered =
      register_report_quantity("obstacle force", [](auto &parts) {
        constexpr int dim = dimension_of<decltype(parts)>;
        parts.has = [](const Parameters &parameters, const auto &scene) {
          return scene.effects().obstacle_contact &&
                 (scene.effects().friction_law().has_friction() ||
                  scene.obstacle_moves() ||
                  parameters.load_path.step_times().size() > 1);
        };
        parts.csv = [](const auto &, const CycleResult &r, TableEntries &t) {
          // the force of the body on the obstacle
          const char *axes[] = {"x", "y", "z"};
          for (unsigned int c = 0; c < dim; ++c)
            t.add(460,
                  std::string("obstacle_force_") + axes[c],
                  -r.zone.resultant[c]);
        };
      });
  } // namespace
} // namespace dualcontact
