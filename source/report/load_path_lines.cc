// The report's lines of a load path: a step's start, a cut step and its
// retry, a solved step's line and its row of steps.csv, and the resumption
// from a checkpoint.
#include <deal.II/base/mpi.h>

#include <dualcontact/report.h>

#include <algorithm>
#include <iomanip>
#include <sstream>

#include "columns.h"
#include "loop_figure.h"

namespace dualcontact
{
  using namespace report_format;

  template <int dim>
  void
  Report<dim>::start_step(const StepRecord &step)
  {
    // memory flat along a long path: of the later steps' iterations, only
    // the last step's stay in memory (iterations.csv has all of them)
    const auto first_later =
      std::find_if(iteration_log.begin(),
                   iteration_log.end(),
                   [](const IterationRecord &r) { return r.step > 1; });
    const auto written = iteration_log.begin() + iterations_written;
    if (first_later < written)
      {
        iterations_written -= written - first_later;
        iteration_log.erase(first_later, written);
      }
    uzawa_header_shown = false;
    if (!shows(Verbosity::normal))
      return;
    if (parameters.load_path.adaptive_steps)
      pcout << "Load step " << step.step << ", t = " << step.time << " (size "
            << step.step_size << ")\n";
    else
      pcout << "Load step " << step.step << " of "
            << parameters.load_path.n_steps_on_path() << ", t = " << step.time
            << '\n';
  }

  template <int dim>
  void
  Report<dim>::cut_step(const StepRecord  &failed,
                        const std::string &why,
                        const double       retry_time)
  {
    // the failed try's iterations: the last ones, not yet written
    iteration_log.resize(iterations_written);
    const std::string  reason = Utilities::trim(why.substr(0, why.find('\n')));
    std::ostringstream label;
    label << "step " << std::setw(4) << failed.step << ": ";
    pcout
      << wrap(label.str(),
              {"t = " + significant(failed.time, 6) + " failed (" + reason +
                 ")",
               "cut: again at t = " + significant(retry_time, 6) + " (size " +
                 significant(retry_time - (failed.time - failed.step_size), 6) +
                 ")"},
              ", ",
              "            ")
      << std::flush;
  }

  template <int dim>
  const CycleResult &
  Report<dim>::end_step(const CycleResult &measured)
  {
    CycleResult result = measured;
    if (result.step.step > 1)
      complete_times(result);
    else
      pcout << "Load path: " << result.step.n_steps
            << " steps to t = " << parameters.load_path.step_times().back()
            << "; "
            << (loops_of(parameters, scene).friction ?
                  "friction acts on the slip of each step, so each starts "
                  "from the state the one before reached (history)" :
                  "without friction each step is the static problem at its "
                  "loads (no history), started from the step before")
            << '\n';
    step_results.push_back(result);

    // the step's line, at every verbosity
    const CycleResult       &r     = result;
    std::vector<std::string> items = {"t = " + significant(r.step.time, 6)};
    // a mesh adapted for the step
    if (parameters.load_path.adapt_at_every_step && r.step.step > 1)
      items.push_back(std::to_string(r.mesh.n_dofs) + " DoFs");
    items.insert(items.end(),
                 {"Uzawa " + std::to_string(r.solve.uzawa_steps) +
                    (r.solve.predictor > 0. ? " (extrapolated)" : ""),
                  "Newton " + std::to_string(r.solve.newton_steps),
                  "CG " + std::to_string(r.solve.cg_iterations)});
    if (scene.effects().contact)
      items.push_back("contact force " + significant(r.zone.contact_force, 6));
    if (loops_of(parameters, scene).friction)
      {
        items.push_back("tangential " +
                        significant(r.zone.tangential_force, 6));
        items.push_back("stick/slip " + std::to_string(r.solve.n_stick) + "/" +
                        std::to_string(r.solve.n_slip));
        items.push_back("dissipated " + scientific(r.step.dissipation) +
                        " (total " + scientific(r.step.dissipation_total) +
                        ")");
      }
    items.back() += seconds(r.time.cycle);
    std::ostringstream label;
    label << "step " << std::setw(4) << r.step.step << ": ";
    pcout << wrap(label.str(), items, ", ", "            ") << std::flush;

    // the step's row of steps.csv and its iterations appended, the loop's
    // script updated: a step costs the same however many came before
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      {
        TableEntries csv;
        for (const auto &quantity : quantities)
          quantity->csv_entries(result, csv);
        if (result.step.step == 1)
          steps_file.open(parameters.output.directory + "/steps.csv");
        steps_file.add_rows({csv.csv_row()});
        if (scene.effects().contact)
          {
            loop_figure->add(result);
            loop_figure->write(parameters.output.directory,
                               scene.obstacle_moves());
          }
      }
    append_iterations_csv();
    return step_results.back();
  }

  template <int dim>
  void
  Report<dim>::resume(const unsigned int last_step,
                      const double       time,
                      const double       total_time)
  {
    steps_before  = last_step;
    cycles_before = parameters.refinement.n_cycles;
    total_before  = total_time;
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      {
        const std::string &directory = parameters.output.directory;
        steps_file.resume(directory + "/steps.csv", last_step);
        if (scene.effects().contact)
          iterations_file.resume(directory + "/iterations.csv", last_step);
      }
    iterations_file_started = true;
    // the first step's times from here: not the time the loading took
    previous_totals = timer.get_summary_data(TimerOutput::total_wall_time);
    resumed_time    = time;
  }

  template <int dim>
  void
  Report<dim>::print_resume() const
  {
    pcout << "Resumed from the checkpoint at load step " << steps_before
          << ", t = " << resumed_time
          << " (the files of the steps up to it are kept, later ones written "
             "again)\n";
  }

  template void
  Report<2>::start_step(const StepRecord &step);
  template void
  Report<2>::cut_step(const StepRecord  &failed,
                      const std::string &why,
                      const double       retry_time);
  template const CycleResult &
  Report<2>::end_step(const CycleResult &measured);
  template void
  Report<2>::resume(const unsigned int last_step,
                    const double       time,
                    const double       total_time);
  template void
  Report<2>::print_resume() const;
  template void
  Report<3>::start_step(const StepRecord &step);
  template void
  Report<3>::cut_step(const StepRecord  &failed,
                      const std::string &why,
                      const double       retry_time);
  template const CycleResult &
  Report<3>::end_step(const CycleResult &measured);
  template void
  Report<3>::resume(const unsigned int last_step,
                    const double       time,
                    const double       total_time);
  template void
  Report<3>::print_resume() const;
} // namespace dualcontact
