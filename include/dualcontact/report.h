// Everything a run tells: the screen output (rank 0 only), the tables of
// cycles and iterations, and their CSV files. The Problem class hands it
// the records each phase returns; the three loops report their steps to it
// as an IterationObserver. Nothing else prints. A cycle's columns and
// result lines come from the measured quantities the scene has
// (report_quantity.h): cycles.csv has their columns and no others.
//
// <Output/Verbosity> sets how much of it the screen shows: quiet, the scene
// and one table row per cycle; normal, also a legend, the Uzawa and
// threshold steps and each cycle's results; detailed, also the Newton steps.
// No screen line is longer than 120 characters; warnings are always shown;
// the CSV files hold everything at every level.
#ifndef dualcontact_report_h
#define dualcontact_report_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/convergence_table.h>
#include <deal.II/base/table_handler.h>
#include <deal.II/base/timer.h>

#include <dualcontact/contact_system.h>
#include <dualcontact/parameters.h>
#include <dualcontact/records.h>
#include <dualcontact/report_quantity.h>
#include <dualcontact/scene.h>

#include <chrono>
#include <fstream>
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  /** A TableHandler that can also write itself as CSV. */
  class CsvTable : public TableHandler
  {
  public:
    /** One header line of the column keys, then one line per row. */
    void
    write_csv(std::ostream &out) const;
  };

  /**
   * A CSV file that grows a row at a time, for the tables of a load path:
   * each row is appended, so that its cost does not depend on how many
   * rows came before (a path of many thousand steps). The columns are
   * those of the first row. A row with a column the header lacks rewrites
   * the file once, read back from the disk, with the new column added at
   * the end and left empty in the rows before; a row that lacks a column
   * leaves it empty. Nothing is kept in memory but the header. Use on one
   * rank.
   */
  class AppendedCsvFile
  {
  public:
    using Row = std::vector<std::pair<std::string, std::string>>;

    /** Start `filename` afresh: it is emptied at the first row. */
    void
    open(const std::string &filename);

    /**
     * Go on with `filename` as a checkpoint left it: its rows up to the
     * step `last_step` (column "step") stay, later ones go, and new rows
     * are appended under its header.
     */
    void
    resume(const std::string &filename, const unsigned int last_step);

    /** Append `rows` (flushed, so that the file is whole after each call). */
    void
    add_rows(const std::vector<Row> &rows);

  private:
    /** The file again, its rows padded to the columns now in `columns`. */
    void
    rewrite_with_columns(const std::size_t old_size);

    std::string              name_of_file;
    std::vector<std::string> columns;
    std::ofstream            file;
  };

  /**
   * Keep of the CSV file `filename` its header and the rows whose column
   * `column` is at most `last` (rank 0; a file without the column, or no
   * file, is left as it is): a run resumed from a checkpoint drops the
   * rows that the stopped run wrote after it.
   */
  void
  keep_rows_up_to(const std::string &filename,
                  const std::string &column,
                  const double       last);

  template <int dim>
  class LoopFigure;

  template <int dim>
  class Report : public IterationObserver
  {
  public:
    Report(const Parameters  &parameters,
           const Scene<dim>  &scene,
           const TimerOutput &timer,
           MPI_Comm           mpi_communicator,
           std::ostream      &out);

    ~Report();

    /** The scene and the effects composed for it. */
    void
    print_scene() const;

    /**
     * A new mesh: its size, and how it was made (after set-up). Before the
     * first, the legend.
     */
    void
    start_cycle(const MeshRecord &mesh, const TransferRecord &transfer);

    /** The contact problem about to be solved on this mesh. */
    void
    start_contact_solve(const SolveRecord &solve);

    /** The comparison run from a cold start begins / ends. */
    void
    start_cold_start() const;
    void
    end_cold_start() const;

    // The loops' steps (IterationObserver), all logged for iterations.csv.
    // Printed: Uzawa and threshold steps and notes from normal on, Newton
    // steps at detailed, warnings always.
    void
    newton_step(const IterationRecord &record) override;
    void
    uzawa_step(const IterationRecord &record,
               const bool             friction,
               const bool             merged) override;
    void
    threshold_step(const IterationRecord &record) override;
    void
    note(const std::string &text) override;
    void
    warning(const std::string &text) override;


    /**
     * The cycle is done: fill its times from the timer and the peak memory,
     * print its results, add it to the tables and (re)write cycles.csv and
     * iterations.csv in the output directory. Returns the completed record.
     */
    const CycleResult &
    end_cycle(const CycleResult &result);

    /**
     * A later step of the load path begins (or begins again, smaller): at
     * normal verbosity its line, above its Uzawa steps.
     */
    void
    start_step(const StepRecord &step);

    /**
     * A later step's solve failed and adaptive step control tries it again
     * at t = `retry_time`: a line at every verbosity with the reason (the
     * first line of `why`); the failed try's iterations are dropped.
     */
    void
    cut_step(const StepRecord  &failed,
             const std::string &why,
             const double       retry_time);

    /**
     * A step of the load path is done (the first one: the last cycle's
     * result, times and all): fill the times of a later step, print its
     * line, append its row to steps.csv. Returns the
     * completed record.
     */
    const CycleResult &
    end_step(const CycleResult &result);

    const std::vector<CycleResult> &
    steps() const
    {
      return step_results;
    }

    /**
     * A run resumed from the checkpoint at step `last_step` (time `time`)
     * goes on with the stopped run's tables: steps.csv and iterations.csv
     * keep their rows up to it, and the step numbers and the total time go
     * on from it.
     */
    void
    resume(const unsigned int last_step,
           const double       time,
           const double       total_time);

    /** After print_scene(): the line that says where a resumed run began. */
    void
    print_resume() const;

    /** The solver's time over all cycles and steps so far [s]. */
    double
    total_time() const;

    /** What a checkpoint keeps of steps.gp's ranges. */
    std::string
    loop_figure_state() const;

    /**
     * A resumed run's steps.gp spans the steps before it too: their ranges
     * from loop_figure_state(). False, and nothing changed, if `state` is
     * not one it writes (a damaged checkpoint). Every rank checks it alike.
     */
    bool
    load_loop_figure_state(const std::string &state);

    /** The convergence table, and the timing summary if asked for. */
    void
    finish() const;

    const std::vector<CycleResult> &
    cycles() const
    {
      return cycle_results;
    }

    /** The cycles' iterations, and those of a load path's last step. */
    const std::vector<IterationRecord> &
    iterations() const
    {
      return iteration_log;
    }

  private:
    /** Whether the screen shows what `level` adds. */
    bool
    shows(const Verbosity level) const;

    /** " (1.234 s)" if timing is printed, else nothing. */
    std::string
    seconds(const double t) const;

    /** The column header of the Uzawa rows, once per Uzawa solve. */
    void
    print_uzawa_header(const unsigned int uzawa_step);

    /** The abbreviations of this scene's log, once (normal, detailed). */
    void
    print_legend() const;

    /** Wall time of a TimerOutput section since the last end_cycle(). */
    double
    phase_time(const std::string &section) const;

    /**
     * The wall times of the phases since the last cycle or step, the total
     * so far and the peak memory, into `result`.
     */
    void
    complete_times(CycleResult &result);

    /** quiet: the cycle's row (the first under the table's header). */
    void
    print_cycle_row(const CycleResult &result) const;

    /** normal, detailed: the cycle's results, a few lines. */
    void
    print_cycle(const CycleResult &result) const;

    void
    add_table_rows(const CycleResult &result);

    /** cycles.csv, all of it (a cycle is a new mesh: there are few). */
    void
    write_cycles_csv() const;

    /** The iterations not yet in iterations.csv, appended to it. */
    void
    append_iterations_csv();

    const Parameters  &parameters;
    const Scene<dim>  &scene;
    const TimerOutput &timer;
    // when the run began (the report is made with the problem)
    const std::chrono::steady_clock::time_point start =
      std::chrono::steady_clock::now();
    MPI_Comm           mpi_communicator;
    ConditionalOStream pcout;

    // the timer's section totals at the end of the previous cycle
    std::map<std::string, double> previous_totals;

    // the Uzawa rows' column header: shown in this contact solve, and the
    // step of the last row printed under it
    bool         uzawa_header_shown = false;
    unsigned int last_uzawa_row     = 0;

    std::vector<CycleResult> cycle_results;
    std::vector<CycleResult> step_results; // a load path's steps
    // of a run resumed from a checkpoint: the steps and cycles before it,
    // and their total time
    unsigned int                 steps_before  = 0;
    unsigned int                 cycles_before = 0;
    double                       resumed_time  = 0.;
    double                       total_before  = 0.;
    std::vector<IterationRecord> iteration_log;
    // the quantities the scene has: their columns and lines
    std::vector<std::unique_ptr<ReportQuantity<dim>>> quantities;

    CsvTable        cycle_table;     // every quantity's columns: cycles.csv
    AppendedCsvFile steps_file;      // the same, one row per step: steps.csv
    AppendedCsvFile iterations_file; // iteration_log: iterations.csv
    std::size_t     iterations_written      = 0;     // of iteration_log, in it
    bool            iterations_file_started = false; // opened afresh
    std::unique_ptr<LoopFigure<dim>> loop_figure;    // steps.gp
    ConvergenceTable                 screen_table;   // the summary on screen
    bool summary_has_errors = false;                 // errors in screen_table
  };
} // namespace dualcontact

#endif
