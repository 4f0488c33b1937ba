// The quantities of the report (report_quantity.h), declared together so
// that report_quantities() can list them; the ones of the contact problem
// are defined in contact_quantities.cc, the others in run_quantities.cc.
// Each comment names the columns of cycles.csv the quantity writes.
#ifndef dualcontact_report_quantities_h
#define dualcontact_report_quantities_h

#include <dualcontact/report_quantity.h>

namespace dualcontact
{
  namespace report_quantities_impl
  {
    /** Every scene: cycle, cells, dofs. */
    template <int dim>
    class MeshSize : public ReportQuantity<dim>
    {
    public:
      using ReportQuantity<dim>::ReportQuantity;
      static bool
      has(const Parameters &parameters, const Scene<dim> &scene);
      void
      csv_entries(const CycleResult &r, TableEntries &csv) const override;
      void
      summary_entries(const CycleResult &r, TableEntries &s) const override;
      void
      row_columns(std::vector<RowColumn> &columns) const override;
    };

    /**
     * <Refinement/Nested iteration>: warm_start, and with contact
     * carried_min_l1, carried_max_excess.
     */
    template <int dim>
    class NestedIteration : public ReportQuantity<dim>
    {
    public:
      using ReportQuantity<dim>::ReportQuantity;
      static bool
      has(const Parameters &parameters, const Scene<dim> &scene);
      void
      csv_entries(const CycleResult &r, TableEntries &csv) const override;
    };

    /** Every scene: linear_iterations, amg_setups. */
    template <int dim>
    class LinearSolves : public ReportQuantity<dim>
    {
    public:
      using ReportQuantity<dim>::ReportQuantity;
      static bool
      has(const Parameters &parameters, const Scene<dim> &scene);
      void
      csv_entries(const CycleResult &r, TableEntries &csv) const override;
      void
      summary_entries(const CycleResult &r, TableEntries &s) const override;
      void
      row_columns(std::vector<RowColumn> &columns) const override;
      void
      print(const CycleResult &r, ScreenLines &lines) const override;
    };

    /**
     * Contact: contact_nodes, hanging_contact_nodes, active_nodes, r, chi,
     * uzawa_steps, newton_steps, uzawa_rate, l1_error_estimate,
     * normal_load, contact_force, max_pressure, contact_half_width,
     * contact_edge_half_width.
     */
    template <int dim>
    class ContactSolve : public ReportQuantity<dim>
    {
    public:
      using ReportQuantity<dim>::ReportQuantity;
      static bool
      has(const Parameters &parameters, const Scene<dim> &scene);
      void
      csv_entries(const CycleResult &r, TableEntries &csv) const override;
      void
      summary_entries(const CycleResult &r, TableEntries &s) const override;
      void
      row_columns(std::vector<RowColumn> &columns) const override;
      void
      print(const CycleResult &r, ScreenLines &lines) const override;
    };

    /**
     * Contact: time_newton_matrix, time_amg_setup, time_cg, time_gradient,
     * time_multipliers.
     */
    template <int dim>
    class ContactSolveTimes : public ReportQuantity<dim>
    {
    public:
      using ReportQuantity<dim>::ReportQuantity;
      static bool
      has(const Parameters &parameters, const Scene<dim> &scene);
      void
      csv_entries(const CycleResult &r, TableEntries &csv) const override;
      void
      print(const CycleResult &r, ScreenLines &lines) const override;
    };

    /**
     * A friction law other than 'none': stick_nodes, slip_nodes,
     * tangential_force, stick_half_width.
     */
    template <int dim>
    class Friction : public ReportQuantity<dim>
    {
    public:
      using ReportQuantity<dim>::ReportQuantity;
      static bool
      has(const Parameters &parameters, const Scene<dim> &scene);
      void
      csv_entries(const CycleResult &r, TableEntries &csv) const override;
      void
      row_columns(std::vector<RowColumn> &columns) const override;
      void
      print(const CycleResult &r, ScreenLines &lines) const override;
    };

    /** Friction bounded by F l1 (Coulomb): threshold_steps. */
    template <int dim>
    class ThresholdSteps : public ReportQuantity<dim>
    {
    public:
      using ReportQuantity<dim>::ReportQuantity;
      static bool
      has(const Parameters &parameters, const Scene<dim> &scene);
      void
      csv_entries(const CycleResult &r, TableEntries &csv) const override;
      void
      summary_entries(const CycleResult &r, TableEntries &s) const override;
      void
      row_columns(std::vector<RowColumn> &columns) const override;
    };

    /**
     * Contact with something of <Exact solution> to compare with, each
     * column where its exact value is given: pressure_error,
     * half_width_error, stick_half_width_error, peak_pressure_error.
     */
    template <int dim>
    class ContactErrors : public ReportQuantity<dim>
    {
    public:
      using ReportQuantity<dim>::ReportQuantity;
      static bool
      has(const Parameters &parameters, const Scene<dim> &scene);
      void
      csv_entries(const CycleResult &r, TableEntries &csv) const override;
      void
      summary_entries(const CycleResult &r, TableEntries &s) const override;
      void
      format_summary(ConvergenceTable &table) const override;
      void
      row_columns(std::vector<RowColumn> &columns) const override;
      void
      print(const CycleResult &r, ScreenLines &lines) const override;
    };

    /** Contact in 3D: contact_area, contact_extent. */
    template <int dim>
    class ContactArea : public ReportQuantity<dim>
    {
    public:
      using ReportQuantity<dim>::ReportQuantity;
      static bool
      has(const Parameters &parameters, const Scene<dim> &scene);
      void
      csv_entries(const CycleResult &r, TableEntries &csv) const override;
      void
      summary_entries(const CycleResult &r, TableEntries &s) const override;
      void
      print(const CycleResult &r, ScreenLines &lines) const override;
    };

    /**
     * An obstacle moved by <Obstacle/Displacement>: obstacle_force_x, _y
     * (_z), the force of the body on the obstacle.
     */
    template <int dim>
    class ObstacleForce : public ReportQuantity<dim>
    {
    public:
      using ReportQuantity<dim>::ReportQuantity;
      static bool
      has(const Parameters &parameters, const Scene<dim> &scene);
      void
      csv_entries(const CycleResult &r, TableEntries &csv) const override;
    };

    /**
     * Every scene: u_l2; with <Exact solution/Displacement> also l2_error,
     * h1_error.
     */
    template <int dim>
    class Displacement : public ReportQuantity<dim>
    {
    public:
      using ReportQuantity<dim>::ReportQuantity;
      static bool
      has(const Parameters &parameters, const Scene<dim> &scene);
      void
      csv_entries(const CycleResult &r, TableEntries &csv) const override;
      void
      summary_entries(const CycleResult &r, TableEntries &s) const override;
      void
      format_summary(ConvergenceTable &table) const override;
      void
      row_columns(std::vector<RowColumn> &columns) const override;
      void
      print(const CycleResult &r, ScreenLines &lines) const override;
    };

    /**
     * <Refinement/Compare with cold start>: cold_uzawa_steps,
     * cold_newton_steps, cold_threshold_steps, cold_time_solve,
     * cold_difference_v, cold_difference_l1.
     */
    template <int dim>
    class ColdStart : public ReportQuantity<dim>
    {
    public:
      using ReportQuantity<dim>::ReportQuantity;
      static bool
      has(const Parameters &parameters, const Scene<dim> &scene);
      void
      csv_entries(const CycleResult &r, TableEntries &csv) const override;
      void
      print(const CycleResult &r, ScreenLines &lines) const override;
    };

    /**
     * Every scene: equilibrium_imbalance, applied_load_x, _y (_z), and
     * reaction_<id>_x, ... for each 'fixed' or 'normal fixed' id.
     */
    template <int dim>
    class Reactions : public ReportQuantity<dim>
    {
    public:
      using ReportQuantity<dim>::ReportQuantity;
      static bool
      has(const Parameters &parameters, const Scene<dim> &scene);
      void
      csv_entries(const CycleResult &r, TableEntries &csv) const override;
      void
      print(const CycleResult &r, ScreenLines &lines) const override;
    };

    /**
     * <Solver/Time a reference linear solve>: time_reference,
     * reference_iterations.
     */
    template <int dim>
    class ReferenceSolve : public ReportQuantity<dim>
    {
    public:
      using ReportQuantity<dim>::ReportQuantity;
      static bool
      has(const Parameters &parameters, const Scene<dim> &scene);
      void
      csv_entries(const CycleResult &r, TableEntries &csv) const override;
      void
      print(const CycleResult &r, ScreenLines &lines) const override;
    };

    /**
     * Every scene: time_refine, time_setup, time_assembly, time_solve,
     * time_output, time_total.
     */
    template <int dim>
    class WallTimes : public ReportQuantity<dim>
    {
    public:
      using ReportQuantity<dim>::ReportQuantity;
      static bool
      has(const Parameters &parameters, const Scene<dim> &scene);
      void
      csv_entries(const CycleResult &r, TableEntries &csv) const override;
      void
      summary_entries(const CycleResult &r, TableEntries &s) const override;
      void
      format_summary(ConvergenceTable &table) const override;
      void
      row_columns(std::vector<RowColumn> &columns) const override;
    };

    /** Every scene: memory_mb. */
    template <int dim>
    class Memory : public ReportQuantity<dim>
    {
    public:
      using ReportQuantity<dim>::ReportQuantity;
      static bool
      has(const Parameters &parameters, const Scene<dim> &scene);
      void
      csv_entries(const CycleResult &r, TableEntries &csv) const override;
    };
  } // namespace report_quantities_impl
} // namespace dualcontact

#endif
