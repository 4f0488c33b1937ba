// Everything a run tells: the screen output (rank 0 only), the tables of
// cycles and iterations, and their CSV files. The Problem class hands it
// the figures each phase returns; the three loops report their steps to it
// as an IterationObserver. Nothing else prints.
#ifndef dualcontact_report_h
#define dualcontact_report_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/convergence_table.h>
#include <deal.II/base/table_handler.h>
#include <deal.II/base/timer.h>

#include <dualcontact/contact_system.h>
#include <dualcontact/figures.h>
#include <dualcontact/parameters.h>
#include <dualcontact/scene.h>

#include <map>
#include <ostream>
#include <string>
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

  template <int dim>
  class Report : public IterationObserver
  {
  public:
    Report(const Parameters  &parameters,
           const Scene<dim>  &scene,
           const TimerOutput &timer,
           MPI_Comm           mpi_communicator,
           std::ostream      &out);

    /** The scene and the effects composed for it. */
    void
    print_scene() const;

    /** A new mesh: its size, and how it was made (after set-up). */
    void
    start_cycle(const MeshFigures &mesh, const TransferFigures &transfer);

    /** The contact problem about to be solved on this mesh. */
    void
    start_contact_solve(const SolveFigures &solve);

    /** The comparison run from a cold start begins / ends. */
    void
    start_cold_start() const;
    void
    end_cold_start() const;

    // The loops' steps (IterationObserver). Uzawa and threshold steps are
    // printed, Newton steps only logged; notes are printed.
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

    /** A warning: on rank 0, "dualcontact: warning: ..." on stderr. */
    void
    warn(const std::string &text) const;

    /**
     * The cycle is done: fill its times from the timer and the peak memory,
     * print its figures, add it to the tables and (re)write cycles.csv and
     * iterations.csv in the output directory. Returns the completed record.
     */
    const CycleResult &
    end_cycle(const CycleResult &result);

    /** The convergence table, and the timing summary if asked for. */
    void
    finish() const;

    const std::vector<CycleResult> &
    cycles() const
    {
      return cycle_results;
    }

    const std::vector<IterationRecord> &
    iterations() const
    {
      return iteration_log;
    }

  private:
    /** " (1.234 s)" if timing is printed, else nothing. */
    std::string
    seconds(const double t) const;

    /** Wall time of a TimerOutput section since the last end_cycle(). */
    double
    phase_time(const std::string &section) const;

    void
    print_cycle(const CycleResult &result) const;

    void
    add_table_rows(const CycleResult &result);

    void
    write_csv_files() const;

    const Parameters  &parameters;
    const Scene<dim>  &scene;
    const TimerOutput &timer;
    MPI_Comm           mpi_communicator;
    ConditionalOStream pcout;

    // the timer's section totals at the end of the previous cycle
    std::map<std::string, double> previous_totals;

    std::vector<CycleResult>     cycle_results;
    std::vector<IterationRecord> iteration_log;
    CsvTable                     cycle_table;   // every figure: cycles.csv
    ConvergenceTable             screen_table;  // the summary on screen
    std::vector<std::string>     error_columns; // of screen_table
  };
} // namespace dualcontact

#endif
