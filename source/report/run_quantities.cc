// The quantities of every run: the mesh, the linear solves, the
// displacement, the reactions, the wall times and the memory; and those an
// entry asks for: nested iteration, the comparison with a cold start, the
// reference solve. Each quantity is one registration of its parts, the formulas
// of its columns and lines; places and registration: report_quantity.h.
#include <dualcontact/report_quantity.h>

#include "format.h"

namespace dualcontact
{
  namespace
  {
    using namespace report_format;

    const char *axes[] = {"x", "y", "z"};

    /** Every scene: cycle, cells, dofs. */
    const bool mesh_size_registered =
      register_report_quantity("mesh", [](auto &parts) {
        parts.csv = [](const auto &, const CycleResult &r, TableEntries &t) {
          t.add(10, "cycle", r.mesh.cycle);
          t.add(20, "cells", std::uint64_t(r.mesh.n_cells));
          t.add(30, "dofs", std::uint64_t(r.mesh.n_dofs));
        };
        parts.summary =
          [](const auto &, const CycleResult &r, TableEntries &s) {
            s.add(10, "cycle", r.mesh.cycle);
            s.add(20, "cells", std::uint64_t(r.mesh.n_cells));
            s.add(30, "DoFs", std::uint64_t(r.mesh.n_dofs));
          };
        parts.row = [](const auto &, std::vector<RowColumn> &c) {
          using R = CycleResult;
          c.push_back({10, 0, "cycle", 6, [](const R &r) {
                         return count(r.mesh.cycle);
                       }});
          c.push_back({20, 0, "cells", 8, [](const R &r) {
                         return count(r.mesh.n_cells);
                       }});
          c.push_back({30, 0, "DoFs", 9, [](const R &r) {
                         return count(r.mesh.n_dofs);
                       }});
        };
      });

    /**
     * <Refinement/Nested iteration>: warm_start, and with contact
     * carried_min_l1, carried_max_excess.
     */
    const bool nested_iteration_registered =
      register_report_quantity("nested iteration", [](auto &parts) {
        parts.has = [](const Parameters &parameters, const auto &) {
          return parameters.refinement.nested_iteration;
        };
        parts.csv = [](const auto &q, const CycleResult &r, TableEntries &t) {
          t.add(40, "warm_start", r.transfer.warm_start ? 1u : 0u);
          // the multipliers carried over, before their projection
          if (q.scene.effects().contact)
            {
              t.add(50, "carried_min_l1", r.transfer.carried_min_l1);
              t.add(60, "carried_max_excess", r.transfer.carried_max_excess);
            }
        };
      });

    /** Every scene: linear_iterations, amg_setups. */
    const bool linear_solves_registered =
      register_report_quantity("linear solves", [](auto &parts) {
        parts.csv = [](const auto &, const CycleResult &r, TableEntries &t) {
          t.add(170, "linear_iterations", r.solve.cg_iterations);
          t.add(180, "amg_setups", r.solve.amg_setups);
        };
        parts.summary =
          [](const auto &, const CycleResult &r, TableEntries &s) {
            s.add(130, "CG", r.solve.cg_iterations);
          };
        parts.row = [](const auto &, std::vector<RowColumn> &c) {
          c.push_back({90, 0, "CG", 6, [](const CycleResult &r) {
                         return count(r.solve.cg_iterations);
                       }});
        };
        parts.print =
          [](const auto &q, const CycleResult &r, ScreenLines &lines) {
            // with contact, the contact solve's line counts them
            if (!q.scene.effects().contact)
              lines.add(10,
                        "   one linear elasticity solve: " +
                          count(r.solve.cg_iterations) + " CG iterations" +
                          seconds(r.time.solve,
                                  q.parameters.output.print_timing) +
                          '\n');
          };
      });

    /**
     * Every scene: u_l2; with <Exact solution/Displacement> also l2_error,
     * h1_error.
     */
    const bool displacement_registered =
      register_report_quantity("displacement", [](auto &parts) {
        constexpr int dim = dimension_of<decltype(parts)>;
        parts.csv = [](const auto &q, const CycleResult &r, TableEntries &t) {
          t.add(350, "u_l2", r.errors.norm_L2);
          if (q.scene.exact_displacement() != nullptr)
            {
              t.add(360, "l2_error", r.errors.error_L2);
              t.add(370, "h1_error", r.errors.error_H1_semi);
            }
        };
        parts.summary =
          [](const auto &q, const CycleResult &r, TableEntries &s) {
            if (q.scene.exact_displacement() != nullptr)
              {
                s.add_error(140, "L2 err", r.errors.error_L2);
                s.add_error(150, "H1 err", r.errors.error_H1_semi);
              }
          };
        parts.format_summary = [](const auto &q, ConvergenceTable &table) {
          if (q.scene.exact_displacement() != nullptr)
            for (const std::string key : {"L2 err", "H1 err"})
              {
                table.set_scientific(key, true);
                table.set_precision(key, 2);
                table.evaluate_convergence_rates(
                  key, "DoFs", ConvergenceTable::reduction_rate_log2, dim);
              }
        };
        parts.row = [](const auto &q, std::vector<RowColumn> &c) {
          using R = CycleResult;
          // without contact, the one figure of the answer
          if (!q.scene.effects().contact)
            c.push_back({180, 1, "||u||_L2", 13, [](const R &r) {
                           return scientific(r.errors.norm_L2, 6);
                         }});
          if (q.scene.exact_displacement() != nullptr)
            {
              c.push_back({190, 0, "L2 err", 10, [](const R &r) {
                             return scientific(r.errors.error_L2);
                           }});
              c.push_back({200, 0, "H1 err", 10, [](const R &r) {
                             return scientific(r.errors.error_H1_semi);
                           }});
            }
        };
        parts.print = [](const auto        &q,
                         const CycleResult &r,
                         ScreenLines       &lines) {
          std::vector<std::string> norms = {"||u||_L2 = " +
                                            scientific(r.errors.norm_L2, 6)};
          if (q.scene.exact_displacement() != nullptr)
            {
              norms.push_back("error L2 = " + scientific(r.errors.error_L2, 6));
              norms.push_back("H1 = " + scientific(r.errors.error_H1_semi, 6));
            }
          lines.add(140, wrap("   ", norms, ", ", "     "));
        };
      });

    /**
     * <Refinement/Compare with cold start>: cold_uzawa_steps,
     * cold_newton_steps, cold_threshold_steps, cold_time_solve,
     * cold_difference_v, cold_difference_l1.
     */
    const bool cold_start_registered =
      register_report_quantity("cold start", [](auto &parts) {
        parts.has = [](const Parameters &parameters, const auto &) {
          return parameters.refinement.compare_cold_start;
        };
        parts.csv = [](const auto &, const CycleResult &r, TableEntries &t) {
          t.add(380, "cold_uzawa_steps", r.cold.uzawa_steps);
          t.add(390, "cold_newton_steps", r.cold.newton_steps);
          t.add(400, "cold_threshold_steps", r.cold.threshold_steps);
          t.add(410, "cold_time_solve", r.cold.time);
          t.add(420, "cold_difference_v", r.cold.difference_v);
          t.add(430, "cold_difference_l1", r.cold.difference_l1);
        };
        parts.print = [](const auto &,
                         const CycleResult &r,
                         ScreenLines       &lines) {
          if (r.cold.uzawa_steps == 0) // the first mesh, or no contact
            return;
          const SolveRecord &solve = r.solve;
          // "time <t> s vs <t> s": tests/run_regression.cmake masks it
          lines.add(90,
                    wrap("   nested iteration against a cold start: ",
                         {"Uzawa " + count(solve.uzawa_steps) + " vs " +
                            count(r.cold.uzawa_steps),
                          "Newton " + count(solve.newton_steps) + " vs " +
                            count(r.cold.newton_steps),
                          "threshold steps " + count(solve.threshold_steps) +
                            " vs " + count(r.cold.threshold_steps),
                          "time " + significant(r.time.solve, 6) + " s vs " +
                            significant(r.cold.time, 6) + " s"},
                         ", ",
                         "     ") +
                      "   solutions differ by " +
                      significant(r.cold.difference_v) + " (v, energy norm), " +
                      significant(r.cold.difference_l1) + " (l1)\n");
        };
      });

    /**
     * Every scene: equilibrium_imbalance, applied_load_x, _y (_z), and
     * reaction_<id>_x, ... for each 'fixed' or 'normal fixed' id; on a mesh
     * of several bodies body_<b>_applied_load_x, ... and
     * body_<b>_reaction_x, ... for each body b.
     */
    const bool reactions_registered =
      register_report_quantity("reactions", [](auto &parts) {
        constexpr int dim = dimension_of<decltype(parts)>;
        parts.csv = [](const auto &, const CycleResult &r, TableEntries &t) {
          t.add(220, "equilibrium_imbalance", r.reactions.imbalance);
          for (unsigned int c = 0; c < dim; ++c)
            t.add(440,
                  std::string("applied_load_") + axes[c],
                  r.reactions.applied_load[c]);
          for (const auto &[id, f] : r.reactions.on_id)
            for (unsigned int c = 0; c < dim; ++c)
              t.add(450,
                    "reaction_" + std::to_string(id) + "_" + axes[c],
                    f[c]);
          // a mesh of several bodies: each one's loads and reactions
          for (unsigned int b = 0; b < r.reactions.on_body.size(); ++b)
            for (unsigned int c = 0; c < dim; ++c)
              {
                const std::string body = "body_" + std::to_string(b);
                t.add(445,
                      body + "_applied_load_" + axes[c],
                      r.reactions.load_on_body[b][c]);
                t.add(451,
                      body + "_reaction_" + axes[c],
                      r.reactions.on_body[b][c]);
                if (b < r.reactions.contact_on_body.size())
                  t.add(452,
                        body + "_contact_" + axes[c],
                        r.reactions.contact_on_body[b][c]);
              }
        };
        parts.print = [](const auto        &q,
                         const CycleResult &r,
                         ScreenLines       &lines) {
          // with the contact force they balance (each body of several)
          if (r.reactions.on_id.empty() && r.reactions.on_body.empty())
            return;
          const auto vector = [](const std::array<double, 3> &f) {
            std::string s = "(" + significant(f[0]);
            for (unsigned int c = 1; c < dim; ++c)
              s += ", " + significant(f[c]);
            return s + ")";
          };
          std::vector<std::string> items;
          for (const auto &[id, f] : r.reactions.on_id)
            items.push_back("id " + std::to_string(id) + " " + vector(f));
          items.push_back("applied loads " + vector(r.reactions.applied_load));
          if (q.scene.effects().contact)
            {
              std::array<double, 3> on_obstacle{};
              for (unsigned int c = 0; c < dim; ++c)
                on_obstacle[c] = -r.zone.resultant[c];
              items.push_back("force on the obstacle " + vector(on_obstacle));
            }
          items.push_back("imbalance " + scientific(r.reactions.imbalance, 1) +
                          " (relative)");
          lines.add(130,
                    wrap("   reactions on the body: ", items, "; ", "     "));
          std::vector<std::string> bodies;
          for (unsigned int b = 0; b < r.reactions.on_body.size(); ++b)
            bodies.push_back(
              "body " + std::to_string(b) + ": reactions " +
              vector(r.reactions.on_body[b]) + ", loads " +
              vector(r.reactions.load_on_body[b]) +
              (b < r.reactions.contact_on_body.size() ?
                 ", contact " + vector(r.reactions.contact_on_body[b]) :
                 std::string()));
          if (!bodies.empty())
            lines.add(131, wrap("   per body: ", bodies, "; ", "     "));
        };
      });

    /**
     * <Solver/Time a reference linear solve>: time_reference,
     * reference_iterations.
     */
    const bool reference_solve_registered =
      register_report_quantity("reference solve", [](auto &parts) {
        parts.has = [](const Parameters &parameters, const auto &) {
          return parameters.solver.time_reference_solve;
        };
        parts.csv = [](const auto &, const CycleResult &r, TableEntries &t) {
          t.add(580, "time_reference", r.solve.time_reference);
          t.add(590, "reference_iterations", r.solve.reference_iterations);
        };
        parts.print =
          [](const auto &q, const CycleResult &r, ScreenLines &lines) {
            // what the contact solve costs against one linear solve
            if (!q.scene.effects().contact)
              return;
            lines.add(120,
                      "   reference: one linear solve on this mesh " +
                        count(r.solve.reference_iterations) + " CG iterations" +
                        seconds(r.solve.time_reference,
                                q.parameters.output.print_timing) +
                        ", contact / linear = " +
                        fixed((r.time.assembly + r.time.solve) /
                                (r.time.assembly + r.solve.time_reference),
                              2) +
                        " (assembly included)\n");
          };
      });

    /**
     * Every scene: time_refine, time_setup, time_assembly, time_solve,
     * time_output, time_total, time_elapsed.
     */
    const bool wall_times_registered =
      register_report_quantity("wall times", [](auto &parts) {
        parts.csv = [](const auto &, const CycleResult &r, TableEntries &t) {
          t.add(470, "time_refine", r.time.refine);
          t.add(480, "time_setup", r.time.setup);
          t.add(490, "time_assembly", r.time.assembly);
          t.add(500, "time_solve", r.time.solve);
          t.add(510, "time_output", r.time.output);
          t.add(520, "time_total", r.time.total);
          t.add(525, "time_elapsed", r.time.elapsed);
        };
        parts.summary =
          [](const auto &q, const CycleResult &r, TableEntries &s) {
            if (!q.parameters.output.print_timing)
              return;
            s.add(160, "refine", r.time.refine);
            s.add(170, "assemble", r.time.assembly);
            s.add(180, "solve", r.time.solve);
            s.add(190, "total", r.time.total);
          };
        parts.format_summary = [](const auto &q, ConvergenceTable &table) {
          if (q.parameters.output.print_timing)
            for (const std::string key :
                 {"refine", "assemble", "solve", "total"})
              table.set_precision(key, 3);
        };
        parts.row = [](const auto &q, std::vector<RowColumn> &c) {
          // the cycle's own wall time (time.total counts all cycles so far)
          if (q.parameters.output.print_timing)
            c.push_back({210, 0, "time [s]", 9, [](const CycleResult &r) {
                           return fixed(r.time.cycle, 3);
                         }});
        };
      });

    /**
     * Every scene: memory_mb; in the summary beside the times (it varies
     * from run to run as they do), with the memory per DoF, which shows
     * what a degree or a mesh costs in memory.
     */
    const bool memory_registered =
      register_report_quantity("memory", [](auto &parts) {
        parts.csv = [](const auto &, const CycleResult &r, TableEntries &t) {
          t.add(600, "memory_mb", r.memory_mb);
        };
        parts.summary =
          [](const auto &q, const CycleResult &r, TableEntries &s) {
            if (!q.parameters.output.print_timing || r.mesh.n_dofs == 0)
              return;
            s.add(200, "MB", r.memory_mb);
            s.add(210, "kB/DoF", 1024. * r.memory_mb / r.mesh.n_dofs);
          };
        parts.format_summary = [](const auto &q, ConvergenceTable &table) {
          if (q.parameters.output.print_timing)
            {
              table.set_precision("MB", 0);
              table.set_precision("kB/DoF", 2);
            }
        };
      });
  } // namespace
} // namespace dualcontact
