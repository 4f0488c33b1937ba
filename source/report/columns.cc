// The column layouts of the report's tables: the loops a scene runs, the
// columns of its Uzawa rows, and the quantities' columns of the row a quiet
// run prints per cycle.
#include "columns.h"

#include <algorithm>

namespace dualcontact
{
  namespace report_format
  {
    template <int dim>
    Loops
    loops_of(const Parameters &parameters, const Scene<dim> &scene)
    {
      const Effects &effects = scene.effects();
      Loops          loops;
      loops.contact  = effects.contact;
      loops.friction = effects.contact && effects.friction_law().has_friction();
      loops.coulomb =
        loops.friction && effects.friction_law().depends_on_pressure();
      loops.nested = loops.coulomb &&
                     parameters.friction.strategy == FrictionStrategy::nested;
      loops.merged = loops.coulomb && !loops.nested;
      return loops;
    }

    /**
     * The columns of the Uzawa rows of a scene: what the step did, the node
     * counts, the relative changes and the two contact conditions (what the
     * stopping test looks at), and its wall time. A step without friction
     * (the frictionless start of the threshold iteration) or without an
     * update of g has '-' in those columns.
     */
    std::vector<Column<UzawaRow>>
    uzawa_columns(const Loops &loops, const bool timing)
    {
      using R            = UzawaRow;
      const auto count   = [](const auto n) { return std::to_string(n); };
      const auto or_dash = [](const bool applies, const std::string &x) {
        return applies ? x : std::string("-");
      };
      std::vector<Column<R>> c = {
        {"Newton", 8, [=](const R &r) { return count(r.record.newton_steps); }},
        {"CG", 6, [=](const R &r) { return count(r.record.cg_iterations); }},
        {"active", 8, [=](const R &r) { return count(r.record.n_active); }}};
      if (loops.friction)
        c.push_back({"stick/slip", 12, [=](const R &r) {
                       return or_dash(r.friction,
                                      count(r.record.n_stick) + "/" +
                                        count(r.record.n_slip));
                     }});
      c.push_back({"d(l1)", 10, [](const R &r) {
                     return scientific(r.record.change_l1);
                   }});
      if (loops.friction)
        c.push_back({"d(l2)", 10, [=](const R &r) {
                       return or_dash(r.friction,
                                      scientific(r.record.change_l2));
                     }});
      c.push_back(
        {"d(v)", 10, [](const R &r) { return scientific(r.record.change_v); }});
      if (loops.merged)
        c.push_back({"d(g)", 10, [=](const R &r) {
                       return or_dash(r.merged, scientific(r.record.change_g));
                     }});
      c.push_back({"viol.", 10, [](const R &r) {
                     return scientific(r.record.violation);
                   }});
      c.push_back({"compl.", 10, [](const R &r) {
                     return scientific(r.record.complementarity);
                   }});
      if (timing)
        c.push_back(
          {"time [s]", 10, [](const R &r) { return fixed(r.record.time, 3); }});
      return c;
    }

    /** The same columns for every Uzawa solve of a scene. */
    template <int dim>
    std::vector<Column<UzawaRow>>
    uzawa_columns_of(const Parameters &parameters, const Scene<dim> &scene)
    {
      return uzawa_columns(loops_of(parameters, scene),
                           parameters.output.print_timing);
    }

    /**
     * The quantities' columns of the row a quiet run prints per cycle, in
     * the order of their places, without those of the largest priority
     * while the row is wider than a screen line (the summary table has
     * them all).
     */
    template <int dim>
    std::vector<Column<CycleResult>>
    row_columns(
      const std::vector<std::unique_ptr<ReportQuantity<dim>>> &quantities)
    {
      std::vector<RowColumn> all;
      for (const auto &quantity : quantities)
        quantity->row_columns(all);
      std::stable_sort(all.begin(),
                       all.end(),
                       [](const RowColumn &a, const RowColumn &b) {
                         return a.place < b.place;
                       });
      std::vector<Column<CycleResult>> kept;
      for (int lowest = 3; lowest >= 0; --lowest)
        {
          kept.clear();
          for (const RowColumn &c : all)
            if (static_cast<int>(c.priority) <= lowest)
              kept.push_back({c.title, c.width, c.entry});
          if (table_width("", kept) <= line_width)
            break;
        }
      return kept;
    }

    template Loops
    loops_of(const Parameters &parameters, const Scene<2> &scene);
    template std::vector<Column<UzawaRow>>
    uzawa_columns_of(const Parameters &parameters, const Scene<2> &scene);
    template std::vector<Column<CycleResult>>
    row_columns(
      const std::vector<std::unique_ptr<ReportQuantity<2>>> &quantities);
    template Loops
    loops_of(const Parameters &parameters, const Scene<3> &scene);
    template std::vector<Column<UzawaRow>>
    uzawa_columns_of(const Parameters &parameters, const Scene<3> &scene);
    template std::vector<Column<CycleResult>>
    row_columns(
      const std::vector<std::unique_ptr<ReportQuantity<3>>> &quantities);
  } // namespace report_format
} // namespace dualcontact
