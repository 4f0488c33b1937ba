#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <dualcontact/report.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <sstream>

namespace dualcontact
{
  void
  CsvTable::write_csv(std::ostream &out) const
  {
    const std::vector<std::string> &keys = column_order;
    for (unsigned int c = 0; c < keys.size(); ++c)
      out << (c > 0 ? "," : "") << keys[c];
    out << '\n';
    const std::size_t rows = n_rows();
    for (std::size_t i = 0; i < rows; ++i)
      {
        for (unsigned int c = 0; c < keys.size(); ++c)
          {
            const auto &entries = columns.at(keys[c]).entries;
            if (c > 0)
              out << ',';
            if (i < entries.size())
              {
                entries[i].cache_string(true, 10); // small residuals too
                out << entries[i].get_cached_string();
              }
          }
        out << '\n';
      }
  }

  std::string
  to_string(const Loop loop)
  {
    switch (loop)
      {
        case Loop::threshold:
          return "threshold";
        case Loop::uzawa:
          return "uzawa";
        default:
          return "newton";
      }
  }

  SolveTimes &
  SolveTimes::operator+=(const SolveTimes &other)
  {
    newton_matrix += other.newton_matrix;
    amg_setup += other.amg_setup;
    cg += other.cg;
    gradient += other.gradient;
    multipliers += other.multipliers;
    return *this;
  }

  void
  ContactStatistics::add(const ContactStatistics &part)
  {
    times += part.times;
    threshold_steps += part.threshold_steps;
    uzawa_steps += part.uzawa_steps;
    newton_steps += part.newton_steps;
    cg_iterations += part.cg_iterations;
    amg_setups += part.amg_setups;
    n_active           = part.n_active;
    n_stick            = part.n_stick;
    n_slip             = part.n_slip;
    rate               = part.rate;
    estimated_l1_error = part.estimated_l1_error;
    change_g           = part.change_g;
    chi_scale          = part.chi_scale;
    at_roundoff_floor  = part.at_roundoff_floor;
  }

  namespace
  {
    // No screen line is longer: a terminal or an editor shows it whole.
    constexpr std::size_t line_width = 120;

    /** Characters, not bytes: "§" is one. */
    std::size_t
    n_characters(const std::string &text)
    {
      return std::count_if(text.begin(), text.end(), [](const char c) {
        return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
      });
    }

    std::string
    scientific(const double x, const int digits = 2)
    {
      std::ostringstream s;
      s << std::scientific << std::setprecision(digits) << x;
      return s.str();
    }

    std::string
    fixed(const double x, const int digits)
    {
      std::ostringstream s;
      s << std::fixed << std::setprecision(digits) << x;
      return s.str();
    }

    /** With `digits` significant digits, as a result is printed. */
    std::string
    significant(const double x, const int digits = 8)
    {
      std::ostringstream s;
      s << std::setprecision(digits) << x;
      return s.str();
    }

    /**
     * `prefix`, then the items joined by `separator`, as many lines as it
     * takes: a line breaks between two items (keeping the separator's
     * punctuation) where the next one would pass line_width, and goes on
     * after `indent`. Each line ends in '\n'.
     */
    std::string
    wrap(const std::string              &prefix,
         const std::vector<std::string> &items,
         const std::string              &separator,
         const std::string              &indent)
    {
      std::string punctuation = separator;
      while (!punctuation.empty() && punctuation.back() == ' ')
        punctuation.pop_back();
      std::string text, line = prefix;
      for (std::size_t i = 0; i < items.size(); ++i)
        {
          // room for the punctuation a break after this item would add
          const std::string room =
            i + 1 < items.size() ? punctuation : std::string();
          if (i == 0)
            line += items[i];
          else if (n_characters(line + separator + items[i] + room) <=
                   line_width)
            line += separator + items[i];
          else
            {
              text += line + punctuation + '\n';
              line = indent + items[i];
            }
        }
      return text + line + '\n';
    }

    /** A text wrapped at its blanks. */
    std::string
    wrap_words(const std::string &prefix,
               const std::string &text,
               const std::string &indent)
    {
      std::vector<std::string> words;
      std::istringstream       in(text);
      for (std::string word; in >> word;)
        words.push_back(word);
      return wrap(prefix, words, " ", indent);
    }

    /** One column of a table printed row by row: title, width, entry. */
    template <typename Row>
    struct Column
    {
      std::string                             title;
      std::size_t                             width;
      std::function<std::string(const Row &)> entry;

      /** At least one blank before the title. */
      std::size_t
      room() const
      {
        return std::max(width, title.size() + 1);
      }
    };

    /** `label`, then each column's title or entry right-aligned in it. */
    template <typename Row>
    std::string
    table_line(const std::string              &label,
               const std::vector<Column<Row>> &columns,
               const Row                      *row)
    {
      std::ostringstream line;
      line << label;
      // at least one blank between two columns, however wide an entry
      for (const Column<Row> &c : columns)
        line << ' ' << std::setw(c.room() - 1)
             << (row ? c.entry(*row) : c.title);
      return line.str() + '\n';
    }

    template <typename Row>
    std::size_t
    table_width(const std::string &label, const std::vector<Column<Row>> &c)
    {
      std::size_t width = label.size();
      for (const auto &column : c)
        width += column.room();
      return width;
    }

    /** The loops a scene runs: what its columns and its legend show. */
    struct Loops
    {
      bool contact  = false;
      bool friction = false; // l2 and stick/slip
      bool coulomb  = false; // g = F l1: the threshold iteration
      bool nested   = false; // its steps around Uzawa solves
      bool merged   = false; // g updated in each Uzawa step
    };

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

    /** A Uzawa step, and whether it had friction and updated g. */
    struct UzawaRow
    {
      IterationRecord record;
      bool            friction;
      bool            merged;
    };

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

    const std::string uzawa_label = "   Uzawa";

    /** The legend's rows: a term, and what it means in this log. */
    std::string
    legend_line(const std::string &term, const std::string &meaning)
    {
      const std::string indent(18, ' ');
      std::string       first = "  " + term;
      first.resize(std::max<std::size_t>(first.size() + 1, indent.size()), ' ');
      return wrap_words(first, meaning, indent);
    }
  } // namespace

  template <int dim>
  Report<dim>::Report(const Parameters  &parameters,
                      const Scene<dim>  &scene,
                      const TimerOutput &timer,
                      MPI_Comm           mpi_communicator,
                      std::ostream      &out)
      : parameters(parameters)
      , scene(scene)
      , timer(timer)
      , mpi_communicator(mpi_communicator)
      , pcout(out, Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
  {}

  template <int dim>
  bool
  Report<dim>::shows(const Verbosity level) const
  {
    return static_cast<int>(parameters.output.verbosity) >=
           static_cast<int>(level);
  }

  template <int dim>
  std::string
  Report<dim>::seconds(const double t) const
  {
    std::ostringstream s;
    if (parameters.output.print_timing)
      s << "  (" << std::fixed << std::setprecision(3) << t << " s)";
    return s.str();
  }

  template <int dim>
  double
  Report<dim>::phase_time(const std::string &section) const
  {
    const auto totals = timer.get_summary_data(TimerOutput::total_wall_time);
    const auto now    = totals.find(section);
    if (now == totals.end())
      return 0.;
    const auto before = previous_totals.find(section);
    return now->second -
           (before == previous_totals.end() ? 0. : before->second);
  }

  namespace
  {
    /**
     * The columns of the row a quiet run prints per cycle: the mesh, the
     * contact nodes, the loops' steps, then the answer (contact force against
     * the load it balances, friction, errors where known) and the time.
     * Columns of lower priority (a larger number) are left out while the row
     * would be wider than line_width; the summary table has them all.
     */
    template <int dim>
    std::vector<Column<CycleResult>>
    cycle_columns(const Parameters &parameters, const Scene<dim> &scene)
    {
      using R           = CycleResult;
      const Loops loops = loops_of(parameters, scene);
      const auto  count = [](const auto n) { return std::to_string(n); };
      std::vector<std::pair<unsigned int, Column<R>>> c;
      c.push_back(
        {0, {"cycle", 6, [=](const R &r) { return count(r.mesh.cycle); }}});
      c.push_back(
        {0, {"cells", 8, [=](const R &r) { return count(r.mesh.n_cells); }}});
      c.push_back(
        {0, {"DoFs", 9, [=](const R &r) { return count(r.mesh.n_dofs); }}});
      if (loops.contact)
        {
          c.push_back({0, {"nodes", 7, [=](const R &r) {
                             return count(r.solve.n_contact_nodes);
                           }}});
          c.push_back({0, {"active", 7, [=](const R &r) {
                             return count(r.solve.n_active);
                           }}});
          if (loops.nested)
            c.push_back({1, {"threshold", 10, [=](const R &r) {
                               return count(r.solve.threshold_steps);
                             }}});
          c.push_back({0, {"Uzawa", 6, [=](const R &r) {
                             return count(r.solve.uzawa_steps);
                           }}});
          c.push_back({0, {"Newton", 7, [=](const R &r) {
                             return count(r.solve.newton_steps);
                           }}});
        }
      c.push_back({0, {"CG", 6, [=](const R &r) {
                         return count(r.solve.cg_iterations);
                       }}});
      if (loops.contact)
        {
          c.push_back({0, {"force", 12, [](const R &r) {
                             return significant(r.zone.contact_force, 6);
                           }}});
          c.push_back({0, {"load", 12, [](const R &r) {
                             return significant(r.solve.normal_load, 6);
                           }}});
          if (loops.friction)
            {
              c.push_back({2, {"stick/slip", 11, [=](const R &r) {
                                 return count(r.solve.n_stick) + "/" +
                                        count(r.solve.n_slip);
                               }}});
              c.push_back({1, {"tangential", 12, [](const R &r) {
                                 return significant(r.zone.tangential_force, 6);
                               }}});
            }
          if (scene.exact_pressure() != nullptr)
            c.push_back({0, {"p L2 err", 10, [](const R &r) {
                               return scientific(r.zone.pressure_error);
                             }}});
          if (parameters.exact.contact_half_width > 0.)
            c.push_back({3, {"a err", 10, [](const R &r) {
                               return scientific(r.zone.half_width_error);
                             }}});
          if (parameters.exact.stick_half_width > 0.)
            c.push_back({3, {"c err", 10, [](const R &r) {
                               return scientific(r.zone.stick_half_width_error);
                             }}});
          if (parameters.exact.peak_pressure > 0.)
            c.push_back({3, {"p0 err", 10, [](const R &r) {
                               return scientific(r.zone.peak_pressure_error);
                             }}});
        }
      else
        c.push_back({1, {"||u||_L2", 13, [](const R &r) {
                           return scientific(r.errors.u_l2, 6);
                         }}});
      if (scene.exact_displacement() != nullptr)
        {
          c.push_back({0, {"L2 err", 10, [](const R &r) {
                             return scientific(r.errors.l2);
                           }}});
          c.push_back({0, {"H1 err", 10, [](const R &r) {
                             return scientific(r.errors.h1_semi);
                           }}});
        }
      // the cycle's own wall time (time.total counts all cycles so far)
      if (parameters.output.print_timing)
        c.push_back({0, {"time [s]", 9, [](const R &r) {
                           return fixed(r.time.cycle, 3);
                         }}});

      std::vector<Column<R>> kept;
      for (int lowest = 3; lowest >= 0; --lowest)
        {
          kept.clear();
          for (const auto &[priority, column] : c)
            if (static_cast<int>(priority) <= lowest)
              kept.push_back(column);
          if (table_width("", kept) <= line_width)
            break;
        }
      return kept;
    }
  } // namespace

  template <int dim>
  void
  Report<dim>::print_scene() const
  {
    pcout << "dualcontact: " << dim << "D, "
          << to_string(parameters.geometry.type)
          << ", E = " << parameters.material.youngs_modulus
          << ", nu = " << parameters.material.poissons_ratio << ", "
          << Utilities::MPI::n_mpi_processes(mpi_communicator)
          << " MPI rank(s)\n";
    std::vector<std::string> parts;
    for (const auto &[id, condition] : parameters.boundary.conditions)
      parts.push_back("id " + std::to_string(id) + " " + to_string(condition));
    pcout << wrap("Boundary parts: ", parts, ", ", "  ");
    pcout << "Effects composed for this scene:\n" << scene.effects().describe();
  }

  template <int dim>
  void
  Report<dim>::print_legend() const
  {
    const Loops loops = loops_of(parameters, scene);
    pcout << "Legend (README.md, \"Reading the output\", explains every "
             "figure):\n";
    if (!loops.contact)
      {
        pcout << legend_line("CG",
                             "conjugate-gradient iterations (algebraic "
                             "multigrid preconditioner) of the elasticity "
                             "solve");
        return;
      }
    pcout << legend_line("r, r_t, chi",
                         "normal and (with friction) tangential augmentation "
                         "[stress/length] and proximal weight "
                         "[stress/length^2] of the modified Lagrangian");
    pcout << legend_line("Uzawa k",
                         std::string("step k of the Uzawa iteration: a "
                                     "proximal step, then l1 (pressure)") +
                           (loops.friction ? ", l2 (friction traction)" : "") +
                           " updated");
    pcout << legend_line("Newton, CG",
                         "the Newton steps in it, the conjugate-gradient "
                         "iterations of their solves (AMG: algebraic "
                         "multigrid)");
    pcout << legend_line("active",
                         "contact nodes in contact (l1 > 0)" +
                           std::string(loops.friction ?
                                         "; stick/slip: those with "
                                         "|l2| < g and with |l2| = g" :
                                         ""));
    pcout << legend_line("d(x)",
                         std::string("relative change of x in the step: "
                                     "x = l1, v (displacement)") +
                           (loops.friction ? ", l2" : "") +
                           (loops.coulomb ? ", g (friction threshold F l1)" :
                                            ""));
    pcout << legend_line("viol., compl.",
                         "largest penetration (v_n - g0)^+ / max |v|, and "
                         "max l1 |g0 - v_n| / (max l1 max |v|)");
    if (loops.nested)
      pcout << legend_line("threshold step",
                           "one step of the threshold iteration: a converged "
                           "Uzawa solve, then g = F l1");
    if (shows(Verbosity::detailed))
      {
        pcout << legend_line("Newton j",
                             "a Newton step, above its Uzawa row: gradient "
                             "|grad| / |b| before it, CG, new AMG, step length "
                             "alpha");
        pcout << legend_line("done",
                             "the Newton step whose gradient test ended the "
                             "Newton iteration");
      }
  }

  template <int dim>
  void
  Report<dim>::start_cycle(const MeshFigures     &mesh,
                           const TransferFigures &transfer)
  {
    if (!shows(Verbosity::normal))
      return;
    if (mesh.cycle == 0) // once, after the scene
      print_legend();
    pcout << "Cycle " << mesh.cycle << ": " << mesh.n_cells << " cells, "
          << mesh.n_dofs << " DoFs" << seconds(phase_time("setup system"));
    if (mesh.cycle > 0)
      pcout << ", refined (" << parameters.refinement.strategy
            << (!transfer.warm_start    ? "" :
                scene.effects().contact ? ", v and multipliers carried over" :
                                          ", v carried over")
            << ")" << seconds(phase_time("refine mesh"));
    pcout << '\n';
  }

  template <int dim>
  void
  Report<dim>::start_contact_solve(const SolveFigures &solve)
  {
    uzawa_header_shown = false;
    if (!shows(Verbosity::normal))
      return;
    pcout << "   contact: " << solve.n_contact_nodes
          << " nodes, r = " << solve.r;
    if (solve.r_t > 0.)
      pcout << ", r_t = " << solve.r_t;
    pcout << ", chi = " << solve.chi << '\n';
  }

  template <int dim>
  void
  Report<dim>::start_cold_start() const
  {
    if (shows(Verbosity::normal))
      pcout << "   cold start, for comparison with nested iteration:\n";
  }

  template <int dim>
  void
  Report<dim>::end_cold_start() const
  {
    if (shows(Verbosity::normal))
      pcout << "   nested start from the previous mesh:\n";
  }

  template <int dim>
  void
  Report<dim>::newton_step(const IterationRecord &record)
  {
    iteration_log.push_back(record);
    iteration_log.back().cycle = cycle_results.size();
    if (!shows(Verbosity::detailed))
      return;
    // the last record of a proximal step is the test that ended it: no
    // linear solve, no line search
    std::vector<std::string> items = {"gradient " +
                                      scientific(record.gradient)};
    if (record.cg_iterations == 0 && record.step_length == 0.)
      items.push_back("done");
    else
      {
        items.push_back("CG " + std::to_string(record.cg_iterations));
        if (record.amg_setups > 0)
          items.push_back("new AMG");
        items.push_back("active " + std::to_string(record.n_active));
        items.push_back("alpha " + scientific(record.step_length));
      }
    print_uzawa_header(record.uzawa_step); // Newton rows come first
    std::ostringstream label;
    label << "      Newton " << std::setw(2) << record.index << ": ";
    if (parameters.output.print_timing)
      items.back() += seconds(record.time);
    pcout << wrap(label.str(), items, ", ", "          ") << std::flush;
  }

  namespace
  {
    /** The same columns for every Uzawa solve of a scene. */
    template <int dim>
    std::vector<Column<UzawaRow>>
    uzawa_columns_of(const Parameters &parameters, const Scene<dim> &scene)
    {
      return uzawa_columns(loops_of(parameters, scene),
                           parameters.output.print_timing);
    }
  } // namespace

  template <int dim>
  void
  Report<dim>::print_uzawa_header(const unsigned int uzawa_step)
  {
    // Once per Uzawa solve, before its first row (a Newton row at detailed):
    // a solve starts where the step count does.
    if (uzawa_header_shown && uzawa_step > last_uzawa_row)
      return;
    pcout << table_line<UzawaRow>(uzawa_label + " step",
                                  uzawa_columns_of(parameters, scene),
                                  nullptr);
    uzawa_header_shown = true;
    last_uzawa_row     = 0;
  }

  template <int dim>
  void
  Report<dim>::uzawa_step(const IterationRecord &record,
                          const bool             friction,
                          const bool             merged)
  {
    iteration_log.push_back(record);
    iteration_log.back().cycle = cycle_results.size();
    if (!shows(Verbosity::normal))
      return;
    print_uzawa_header(record.uzawa_step);
    std::ostringstream label;
    label << uzawa_label << std::setw(5) << record.uzawa_step;
    const UzawaRow row = {record, friction, merged};
    pcout << table_line(label.str(), uzawa_columns_of(parameters, scene), &row)
          << std::flush;
    last_uzawa_row = record.uzawa_step;
  }

  template <int dim>
  void
  Report<dim>::threshold_step(const IterationRecord &record)
  {
    iteration_log.push_back(record);
    iteration_log.back().cycle = cycle_results.size();
    if (!shows(Verbosity::normal))
      return;
    std::ostringstream label;
    label << "   threshold step " << std::setw(3) << record.index << ": ";
    pcout << wrap(label.str(),
                  {"Uzawa " + std::to_string(record.uzawa_steps),
                   "Newton " + std::to_string(record.newton_steps),
                   "CG " + std::to_string(record.cg_iterations),
                   "active " + std::to_string(record.n_active),
                   "stick/slip " + std::to_string(record.n_stick) + "/" +
                     std::to_string(record.n_slip),
                   "d(g) " + scientific(record.change_g)},
                  ", ",
                  "      ")
          << std::flush;
  }

  template <int dim>
  void
  Report<dim>::note(const std::string &text)
  {
    if (shows(Verbosity::normal))
      pcout << wrap_words("   ", text, "     ") << std::flush;
  }

  template <int dim>
  void
  Report<dim>::warning(const std::string &text)
  {
    pcout << wrap_words("Warning: ", text, "         ") << std::flush;
  }

  template <int dim>
  void
  Report<dim>::print_cycle_row(const CycleResult &r) const
  {
    const auto columns = cycle_columns(parameters, scene);
    if (r.mesh.cycle == 0) // the header, once, after the scene
      pcout << table_line<CycleResult>("", columns, nullptr);
    pcout << table_line("", columns, &r) << std::flush;
  }

  template <int dim>
  void
  Report<dim>::print_cycle(const CycleResult &r) const
  {
    if (!scene.effects().contact)
      pcout << "   one linear elasticity solve: " << r.solve.cg_iterations
            << " CG iterations" << seconds(r.time.solve) << '\n';
    else
      print_contact_results(r);
    print_reactions(r.reactions, r.zone);
    std::vector<std::string> norms = {"||u||_L2 = " +
                                      scientific(r.errors.u_l2, 6)};
    if (scene.exact_displacement() != nullptr)
      {
        norms.push_back("error L2 = " + scientific(r.errors.l2, 6));
        norms.push_back("H1 = " + scientific(r.errors.h1_semi, 6));
      }
    pcout << wrap("   ", norms, ", ", "     ");
  }

  template <int dim>
  void
  Report<dim>::print_contact_results(const CycleResult &r) const
  {
    const std::string         indent = "     ";
    const SolveFigures       &solve  = r.solve;
    const ContactZoneFigures &zone   = r.zone;
    pcout << wrap("   contact solved: ",
                  {"Uzawa " + std::to_string(solve.uzawa_steps),
                   "Newton " + std::to_string(solve.newton_steps),
                   "CG " + std::to_string(solve.cg_iterations),
                   "AMG set-ups " + std::to_string(solve.amg_setups),
                   std::to_string(solve.n_active) + " of " +
                     std::to_string(solve.n_contact_nodes) +
                     " nodes in contact" + seconds(r.time.solve)},
                  ", ",
                  indent);
    if (parameters.output.print_timing)
      {
        const SolveTimes &t = solve.times;
        pcout << wrap(
          "   where the solve's time went: ",
          {"Newton matrices " + significant(t.newton_matrix, 3) + " s",
           "AMG set-ups " + significant(t.amg_setup, 3) + " s",
           "CG " + significant(t.cg, 3) + " s",
           "gradients and line searches " + significant(t.gradient, 3) + " s",
           "multiplier updates " + significant(t.multipliers, 3) + " s"},
          ", ",
          indent);
      }
    std::vector<std::string> zone_items = {
      "total contact force " + significant(zone.contact_force) +
        " (applied load toward the obstacle " + significant(solve.normal_load) +
        ")",
      "peak pressure " + significant(zone.max_pressure)};
    pcout << wrap("   ", zone_items, ", ", indent);
    if (dim == 2)
      pcout << "   contact half-width " << significant(zone.half_width)
            << " (nodes), " << significant(zone.edge_half_width)
            << " (edges extrapolated)\n";
    else
      pcout << wrap(
        "   contact radius ",
        {significant(zone.half_width) +
           " (nodes on two lines through the centre), " +
           significant(zone.edge_half_width) + " (edges extrapolated)",
         "area " + significant(zone.area) + " (the disc of radius " +
           significant(std::sqrt(zone.area / numbers::PI)) + ")",
         "extent " + significant(zone.extent)},
        ", ",
        indent);
    if (zone.mirrored > 0)
      pcout << "   (the model ends at the zone's centre: measured as mirrored "
               "across "
            << (zone.mirrored == 1 ? "that plane" : "those planes")
            << (dim == 3 ? ", area of the whole zone" : "") << ")\n";
    std::vector<std::string> errors;
    if (scene.exact_pressure() != nullptr)
      errors.push_back("pressure (L2) " + significant(zone.pressure_error));
    if (parameters.exact.contact_half_width > 0.)
      errors.push_back((dim == 2 ? "half-width " : "radius ") +
                       significant(zone.half_width_error));
    if (parameters.exact.stick_half_width > 0.)
      errors.push_back((dim == 2 ? "stick half-width " : "stick radius ") +
                       significant(zone.stick_half_width_error));
    if (parameters.exact.peak_pressure > 0.)
      errors.push_back("peak " + significant(zone.peak_pressure_error));
    if (!errors.empty())
      pcout << wrap("   relative errors: ", errors, ", ", indent);
    if (solve.n_hanging_contact > 0)
      pcout << "   " << solve.n_hanging_contact
            << " hanging nodes on Gamma_C (no contact condition of their "
               "own)\n";
    if (r.cold.uzawa_steps > 0)
      {
        // "time <t> s vs <t> s": tests/run_regression.cmake masks it
        pcout << wrap("   nested iteration against a cold start: ",
                      {"Uzawa " + std::to_string(solve.uzawa_steps) + " vs " +
                         std::to_string(r.cold.uzawa_steps),
                       "Newton " + std::to_string(solve.newton_steps) + " vs " +
                         std::to_string(r.cold.newton_steps),
                       "threshold steps " +
                         std::to_string(solve.threshold_steps) + " vs " +
                         std::to_string(r.cold.threshold_steps),
                       "time " + significant(r.time.solve, 6) + " s vs " +
                         significant(r.cold.time, 6) + " s"},
                      ", ",
                      indent);
        pcout << "   solutions differ by " << significant(r.cold.difference_v)
              << " (v, energy norm), " << significant(r.cold.difference_l1)
              << " (l1)\n";
      }
    if (scene.effects().friction_law().has_friction())
      {
        std::vector<std::string> items = {
          std::to_string(solve.n_stick) + " stick, " +
            std::to_string(solve.n_slip) + " slip nodes",
          (dim == 2 ? "stick half-width " : "stick radius ") +
            significant(zone.stick_half_width),
          "total tangential force " + significant(zone.tangential_force)};
        if (solve.threshold_steps > 0)
          items.push_back(std::to_string(solve.threshold_steps) +
                          " threshold steps");
        pcout << wrap("   friction: ", items, ", ", indent);
      }
    pcout << "   Uzawa contraction rate " << scientific(solve.rate)
          << ", remaining error of l1 about "
          << scientific(solve.estimated_l1_error)
          << " (d rho/(1 - rho), doc/theory.md §6)\n";
    if (parameters.solver.time_reference_solve)
      pcout << "   reference: one linear solve on this mesh "
            << solve.reference_iterations << " CG iterations"
            << seconds(solve.time_reference) << ", contact / linear = "
            << fixed((r.time.assembly + r.time.solve) /
                       (r.time.assembly + solve.time_reference),
                     2)
            << " (assembly included)\n";
  }

  template <int dim>
  void
  Report<dim>::print_reactions(const ReactionFigures    &reactions,
                               const ContactZoneFigures &zone) const
  {
    // with the contact force they balance
    if (reactions.on_id.empty())
      return;
    const auto vector = [](const std::array<double, 3> &f) {
      std::string s = "(" + significant(f[0]);
      for (unsigned int c = 1; c < dim; ++c)
        s += ", " + significant(f[c]);
      return s + ")";
    };
    std::vector<std::string> items;
    for (const auto &[id, f] : reactions.on_id)
      items.push_back("id " + std::to_string(id) + " " + vector(f));
    items.push_back("applied loads " + vector(reactions.applied_load));
    if (scene.effects().contact)
      {
        std::array<double, 3> on_obstacle{};
        for (unsigned int c = 0; c < dim; ++c)
          on_obstacle[c] = -zone.resultant[c];
        items.push_back("force on the obstacle " + vector(on_obstacle));
      }
    items.push_back("imbalance " + scientific(reactions.imbalance, 1) +
                    " (relative)");
    pcout << wrap("   reactions on the body: ", items, "; ", "     ");
  }

  template <int dim>
  void
  Report<dim>::add_table_rows(const CycleResult &r)
  {
    const Effects &effects  = scene.effects();
    const bool     friction = effects.friction_law().has_friction();
    const bool     coulomb =
      friction && effects.friction_law().depends_on_pressure();

    // every figure, in cycles.csv
    CsvTable &t = cycle_table;
    t.add_value("cycle", r.mesh.cycle);
    t.add_value("cells", static_cast<std::uint64_t>(r.mesh.n_cells));
    t.add_value("dofs", static_cast<std::uint64_t>(r.mesh.n_dofs));
    t.add_value("warm_start", r.transfer.warm_start ? 1u : 0u);
    t.add_value("carried_min_l1", r.transfer.carried_min_l1);
    t.add_value("carried_max_excess", r.transfer.carried_max_excess);
    t.add_value("contact_nodes",
                static_cast<std::uint64_t>(r.solve.n_contact_nodes));
    t.add_value("hanging_contact_nodes",
                static_cast<std::uint64_t>(r.solve.n_hanging_contact));
    t.add_value("active_nodes", static_cast<std::uint64_t>(r.solve.n_active));
    t.add_value("stick_nodes", static_cast<std::uint64_t>(r.solve.n_stick));
    t.add_value("slip_nodes", static_cast<std::uint64_t>(r.solve.n_slip));
    t.add_value("r", r.solve.r);
    t.add_value("chi", r.solve.chi);
    t.add_value("threshold_steps", r.solve.threshold_steps);
    t.add_value("uzawa_steps", r.solve.uzawa_steps);
    t.add_value("newton_steps", r.solve.newton_steps);
    t.add_value("linear_iterations", r.solve.cg_iterations);
    t.add_value("amg_setups", r.solve.amg_setups);
    t.add_value("uzawa_rate", r.solve.rate);
    t.add_value("l1_error_estimate", r.solve.estimated_l1_error);
    t.add_value("normal_load", r.solve.normal_load);
    t.add_value("equilibrium_imbalance", r.reactions.imbalance);
    t.add_value("contact_force", r.zone.contact_force);
    t.add_value("tangential_force", r.zone.tangential_force);
    t.add_value("max_pressure", r.zone.max_pressure);
    t.add_value("contact_half_width", r.zone.half_width);
    t.add_value("contact_edge_half_width", r.zone.edge_half_width);
    t.add_value("pressure_error", r.zone.pressure_error);
    t.add_value("contact_area", r.zone.area);
    t.add_value("contact_extent", r.zone.extent);
    t.add_value("stick_half_width", r.zone.stick_half_width);
    t.add_value("half_width_error", r.zone.half_width_error);
    t.add_value("stick_half_width_error", r.zone.stick_half_width_error);
    t.add_value("peak_pressure_error", r.zone.peak_pressure_error);
    t.add_value("u_l2", r.errors.u_l2);
    t.add_value("l2_error", r.errors.l2);
    t.add_value("h1_error", r.errors.h1_semi);
    t.add_value("cold_uzawa_steps", r.cold.uzawa_steps);
    t.add_value("cold_newton_steps", r.cold.newton_steps);
    t.add_value("cold_threshold_steps", r.cold.threshold_steps);
    t.add_value("cold_time_solve", r.cold.time);
    t.add_value("cold_difference_v", r.cold.difference_v);
    t.add_value("cold_difference_l1", r.cold.difference_l1);
    const char *axes[] = {"x", "y", "z"};
    for (unsigned int c = 0; c < dim; ++c)
      t.add_value(std::string("applied_load_") + axes[c],
                  r.reactions.applied_load[c]);
    for (const auto &[id, f] : r.reactions.on_id)
      for (unsigned int c = 0; c < dim; ++c)
        t.add_value("reaction_" + std::to_string(id) + "_" + axes[c], f[c]);
    // the force of the body on the obstacle (an indenter's reaction)
    for (unsigned int c = 0; c < dim; ++c)
      t.add_value(std::string("obstacle_force_") + axes[c],
                  -r.zone.resultant[c]);
    t.add_value("time_refine", r.time.refine);
    t.add_value("time_setup", r.time.setup);
    t.add_value("time_assembly", r.time.assembly);
    t.add_value("time_solve", r.time.solve);
    t.add_value("time_output", r.time.output);
    t.add_value("time_total", r.time.total);
    t.add_value("time_newton_matrix", r.solve.times.newton_matrix);
    t.add_value("time_amg_setup", r.solve.times.amg_setup);
    t.add_value("time_cg", r.solve.times.cg);
    t.add_value("time_gradient", r.solve.times.gradient);
    t.add_value("time_multipliers", r.solve.times.multipliers);
    t.add_value("time_reference", r.solve.time_reference);
    t.add_value("reference_iterations", r.solve.reference_iterations);
    t.add_value("memory_mb", r.memory_mb);

    // the summary on screen: only what the scene has
    ConvergenceTable &s         = screen_table;
    const auto        add_error = [&](const std::string &key, const double e) {
      s.add_value(key, e);
      if (std::find(error_columns.begin(), error_columns.end(), key) ==
          error_columns.end())
        error_columns.push_back(key);
    };
    s.add_value("cycle", r.mesh.cycle);
    s.add_value("cells", static_cast<std::uint64_t>(r.mesh.n_cells));
    s.add_value("DoFs", static_cast<std::uint64_t>(r.mesh.n_dofs));
    if (effects.contact)
      {
        s.add_value("nodes",
                    static_cast<std::uint64_t>(r.solve.n_contact_nodes));
        if (dim == 3)
          s.add_value("hanging",
                      static_cast<std::uint64_t>(r.solve.n_hanging_contact));
        // relative errors, where the scene gives something to compare with
        if (scene.exact_pressure() != nullptr)
          add_error("p L2 err", r.zone.pressure_error);
        if (parameters.exact.contact_half_width > 0.)
          add_error("a err", r.zone.half_width_error);
        if (parameters.exact.stick_half_width > 0.)
          add_error("c err", r.zone.stick_half_width_error);
        if (parameters.exact.peak_pressure > 0.)
          add_error("p0 err", r.zone.peak_pressure_error);
        if (coulomb)
          s.add_value("threshold", r.solve.threshold_steps);
        s.add_value("Uzawa", r.solve.uzawa_steps);
        s.add_value("Newton", r.solve.newton_steps);
      }
    s.add_value("CG", r.solve.cg_iterations);
    if (scene.exact_displacement() != nullptr)
      {
        add_error("L2 err", r.errors.l2);
        add_error("H1 err", r.errors.h1_semi);
      }
    if (parameters.output.print_timing)
      {
        s.add_value("refine", r.time.refine);
        s.add_value("assemble", r.time.assembly);
        s.add_value("solve", r.time.solve);
        s.add_value("total", r.time.total);
      }
  }

  template <int dim>
  void
  Report<dim>::write_csv_files() const
  {
    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return;
    const std::string &directory = parameters.output.directory;
    {
      std::ofstream csv(directory + "/cycles.csv");
      cycle_table.write_csv(csv);
    }
    if (!scene.effects().contact)
      return;
    CsvTable t;
    for (const IterationRecord &r : iteration_log)
      {
        t.add_value("cycle", r.cycle);
        t.add_value("loop", to_string(r.loop));
        t.add_value("uzawa_step", r.uzawa_step);
        t.add_value("index", r.index);
        t.add_value("uzawa_steps", r.uzawa_steps);
        t.add_value("newton_steps", r.newton_steps);
        t.add_value("cg_iterations", r.cg_iterations);
        t.add_value("amg_setups", r.amg_setups);
        t.add_value("n_active", static_cast<std::uint64_t>(r.n_active));
        t.add_value("n_stick", static_cast<std::uint64_t>(r.n_stick));
        t.add_value("n_slip", static_cast<std::uint64_t>(r.n_slip));
        t.add_value("gradient", r.gradient);
        t.add_value("step_length", r.step_length);
        t.add_value("change_l1", r.change_l1);
        t.add_value("change_l2", r.change_l2);
        t.add_value("change_g", r.change_g);
        t.add_value("change_v", r.change_v);
        t.add_value("violation", r.violation);
        t.add_value("complementarity", r.complementarity);
        t.add_value("time", r.time);
      }
    std::ofstream csv(directory + "/iterations.csv");
    t.write_csv(csv);
  }

  template <int dim>
  const CycleResult &
  Report<dim>::end_cycle(const CycleResult &figures)
  {
    CycleResult result   = figures;
    result.time.refine   = phase_time("refine mesh");
    result.time.setup    = phase_time("setup system");
    result.time.assembly = phase_time("assemble system");
    result.time.solve    = phase_time("solve");
    result.time.output   = phase_time("output results");
    result.cold.time     = phase_time("cold start (comparison)");
    result.time.cycle    = result.time.refine + result.time.setup +
                        result.time.assembly + result.time.solve +
                        result.time.output + phase_time("postprocess") +
                        phase_time("measure contact zone");
    result.time.total =
      (cycle_results.empty() ? 0. : cycle_results.back().time.total) +
      result.time.cycle;
    Utilities::System::MemoryStats stats;
    Utilities::System::get_memory_stats(stats);
    result.memory_mb =
      Utilities::MPI::sum(static_cast<double>(stats.VmHWM), mpi_communicator) /
      1024.;
    previous_totals = timer.get_summary_data(TimerOutput::total_wall_time);

    if (shows(Verbosity::normal))
      print_cycle(result);
    else
      print_cycle_row(result);
    cycle_results.push_back(result);
    add_table_rows(result);
    write_csv_files();
    return cycle_results.back();
  }

  template <int dim>
  void
  Report<dim>::finish() const
  {
    // rates per DoF (dim log(e_{k-1}/e_k) / log(N_k/N_{k-1})): the order in
    // h for uniform refinement, and still meaningful for adaptive meshes
    ConvergenceTable table = screen_table;
    for (const std::string key :
         {"p L2 err", "a err", "p0 err", "L2 err", "H1 err"})
      if (std::find(error_columns.begin(), error_columns.end(), key) !=
          error_columns.end())
        {
          table.set_scientific(key, true);
          table.set_precision(key, 2);
          if (key != "a err" && key != "p0 err")
            table.evaluate_convergence_rates(
              key, "DoFs", ConvergenceTable::reduction_rate_log2, dim);
        }
    for (const std::string key : {"refine", "assemble", "solve", "total"})
      if (parameters.output.print_timing)
        table.set_precision(key, 3);
    std::vector<std::string> about = {
      parameters.refinement.strategy + " refinement" +
      (parameters.refinement.nested_iteration ? ", nested iteration" :
                                                ", cold starts")};
    if (scene.effects().contact)
      about.push_back("nodes: contact nodes on Gamma_C");
    if (!error_columns.empty())
      about.push_back(
        std::string(scene.effects().contact ? "contact errors relative, " :
                                              "") +
        "an error's rate per DoF, dim log(e_{k-1}/e_k) / log(N_k/N_{k-1}), "
        "beside it");
    if (parameters.output.print_timing)
      about.push_back("times in s"); // tests/run_regression.cmake looks for it
    about.back() += "):";
    pcout << '\n' << wrap("Summary (", about, "; ", "  ");
    if (pcout.is_active())
      table.write_text(pcout.get_stream(), TableHandler::table_with_headers);
    pcout << "Output written to " << parameters.output.directory << "/\n";
    if (parameters.output.print_timing)
      timer.print_summary();
  }

  template class Report<2>;
  template class Report<3>;
} // namespace dualcontact
