// Report: what a run prints, from the scene and the legend through the
// loops' lines to a cycle's results and the summary at the end. The column
// layouts, the load path's lines and the CSV writers are in
// source/report/columns.cc, load_path_lines.cc and csv_writers.cc.
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <dualcontact/report.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "report/columns.h"
#include "report/format.h"
#include "report/loop_figure.h"

namespace dualcontact
{
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
    using namespace report_format;

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
      , quantities(report_quantities(parameters, scene))
      , loop_figure(std::make_unique<LoopFigure<dim>>())
  {}

  template <int dim>
  Report<dim>::~Report() = default;

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
    return report_format::seconds(t, parameters.output.print_timing);
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

  template <int dim>
  void
  Report<dim>::print_scene() const
  {
    // the simplices and their element (quadrilaterals are the default)
    const std::string cells = scene.discretization().cells_in_words();
    pcout << "dualcontact: " << dim << "D, " << parameters.geometry.type
          << cells << ", E = " << parameters.material.youngs_modulus
          << ", nu = " << parameters.material.poissons_ratio << ", "
          << Utilities::MPI::n_mpi_processes(mpi_communicator)
          << " MPI rank(s)\n";
    pcout << wrap(
      "Boundary parts: ", parameters.boundary.parts_in_words(), ", ", "  ");
    pcout << "Effects composed for this scene:\n" << scene.effects().describe();
  }

  template <int dim>
  void
  Report<dim>::print_legend() const
  {
    const Loops loops = loops_of(parameters, scene);
    pcout << "Legend (doc/output.md explains every figure):\n";
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
  Report<dim>::start_cycle(const MeshRecord     &mesh,
                           const TransferRecord &transfer)
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
  Report<dim>::start_contact_solve(const SolveRecord &solve)
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
    iteration_log.back().cycle = cycles_before + cycle_results.size();
    iteration_log.back().step  = steps_before + step_results.size() + 1;
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
    iteration_log.back().cycle = cycles_before + cycle_results.size();
    iteration_log.back().step  = steps_before + step_results.size() + 1;
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
    iteration_log.back().cycle = cycles_before + cycle_results.size();
    iteration_log.back().step  = steps_before + step_results.size() + 1;
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
    const auto columns = row_columns(quantities);
    if (r.mesh.cycle == 0) // the header, once, after the scene
      pcout << table_line<CycleResult>("", columns, nullptr);
    pcout << table_line("", columns, &r) << std::flush;
  }

  template <int dim>
  void
  Report<dim>::print_cycle(const CycleResult &r) const
  {
    ScreenLines lines;
    for (const auto &quantity : quantities)
      quantity->print(r, lines);
    pcout << lines.text();
  }

  template <int dim>
  void
  Report<dim>::add_table_rows(const CycleResult &r)
  {
    // every quantity the scene has, in cycles.csv; the summary on screen
    TableEntries csv, summary;
    for (const auto &quantity : quantities)
      {
        quantity->csv_entries(r, csv);
        quantity->summary_entries(r, summary);
      }
    csv.write_to(cycle_table);
    summary.write_to(screen_table);
    summary_has_errors = summary.has_errors();
  }

  template <int dim>
  void
  Report<dim>::complete_times(CycleResult &result)
  {
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
    const std::vector<CycleResult> &before =
      step_results.empty() ? cycle_results : step_results;
    result.time.total =
      (before.empty() ? total_before : before.back().time.total) +
      result.time.cycle;
    result.time.elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    Utilities::System::MemoryStats stats;
    Utilities::System::get_memory_stats(stats);
    result.memory_mb =
      Utilities::MPI::sum(static_cast<double>(stats.VmHWM), mpi_communicator) /
      1024.;
    previous_totals = timer.get_summary_data(TimerOutput::total_wall_time);
  }

  template <int dim>
  const CycleResult &
  Report<dim>::end_cycle(const CycleResult &measured)
  {
    CycleResult result = measured;
    complete_times(result);
    if (shows(Verbosity::normal))
      print_cycle(result);
    else
      print_cycle_row(result);
    cycle_results.push_back(result);
    add_table_rows(result);
    write_cycles_csv();
    append_iterations_csv();
    return cycle_results.back();
  }

  template <int dim>
  double
  Report<dim>::total_time() const
  {
    return step_results.empty() ? total_before : step_results.back().time.total;
  }

  template <int dim>
  std::string
  Report<dim>::loop_figure_state() const
  {
    return loop_figure->state();
  }

  template <int dim>
  bool
  Report<dim>::load_loop_figure_state(const std::string &state)
  {
    return loop_figure->load(state);
  }

  template <int dim>
  void
  Report<dim>::finish() const
  {
    // an error's order, dim log(e_{k-1}/e_k) / log(N_k/N_{k-1}) (dim times
    // the rate per DoF): the order in h for uniform refinement, and still
    // meaningful for adaptive meshes
    if (cycle_results.empty())
      {
        // a run resumed from a checkpoint: its cycles were the stopped
        // run's (cycles.csv)
        pcout << "Output written to " << parameters.output.directory << "/\n";
        if (parameters.output.print_timing)
          timer.print_summary();
        return;
      }
    ConvergenceTable table = screen_table;
    for (const auto &quantity : quantities)
      quantity->format_summary(table);
    std::vector<std::string> about = {
      parameters.refinement.strategy + " refinement" +
      (parameters.refinement.nested_iteration ? ", nested iteration" :
                                                ", cold starts")};
    if (scene.effects().contact)
      about.push_back("nodes: contact nodes on Gamma_C");
    if (summary_has_errors)
      about.push_back(
        std::string(scene.effects().contact ? "contact errors relative, " :
                                              "") +
        "an error's order, dim log(e_{k-1}/e_k) / log(N_k/N_{k-1}), beside "
        "it");
    if (parameters.output.print_timing)
      {
        about.push_back("MB, kB/DoF: peak memory of all ranks, and per DoF");
        about.push_back("times in s"); // tests/run_regression.cmake looks
                                       // for it
      }
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
