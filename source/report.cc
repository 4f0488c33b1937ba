#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <dualcontact/report.h>

#include <algorithm>
#include <fstream>
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

  void
  ContactStatistics::add(const ContactStatistics &part)
  {
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
    pcout << "Boundary parts:\n";
    for (const auto &[id, condition] : parameters.boundary.conditions)
      pcout << "  id " << static_cast<unsigned int>(id) << ": "
            << to_string(condition) << '\n';
    pcout << "Effects composed for this scene:\n" << scene.effects().describe();
  }

  template <int dim>
  void
  Report<dim>::start_cycle(const MeshFigures     &mesh,
                           const TransferFigures &transfer)
  {
    pcout << "Cycle " << mesh.cycle << ": " << mesh.n_cells << " cells, "
          << mesh.n_dofs << " DoFs" << seconds(phase_time("setup system"));
    if (mesh.cycle > 0)
      pcout << ", refined (" << to_string(parameters.refinement.strategy)
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
    pcout << "   contact: " << solve.n_contact_nodes
          << " nodes, r = " << solve.r << ", chi = " << solve.chi << '\n';
  }

  template <int dim>
  void
  Report<dim>::start_cold_start() const
  {
    pcout << "   cold start, for comparison with nested iteration:\n";
  }

  template <int dim>
  void
  Report<dim>::end_cold_start() const
  {
    pcout << "   nested start from the previous mesh:\n";
  }

  template <int dim>
  void
  Report<dim>::newton_step(const IterationRecord &record)
  {
    iteration_log.push_back(record);
    iteration_log.back().cycle = cycle_results.size();
  }

  template <int dim>
  void
  Report<dim>::uzawa_step(const IterationRecord &record,
                          const bool             friction,
                          const bool             merged)
  {
    iteration_log.push_back(record);
    iteration_log.back().cycle = cycle_results.size();
    std::ostringstream line;
    line << "   Uzawa " << std::setw(4) << record.uzawa_step << ": Newton "
         << std::setw(2) << record.newton_steps << ", CG " << std::setw(4)
         << record.cg_iterations << ", active " << std::setw(6)
         << record.n_active << std::scientific << std::setprecision(2)
         << ", d(l1) " << record.change_l1 << ", d(v) " << record.change_v
         << ", violation " << record.violation << ", compl. "
         << record.complementarity;
    if (friction)
      line << ", d(l2) " << record.change_l2 << ", stick/slip "
           << record.n_stick << "/" << record.n_slip;
    if (merged)
      line << ", d(g) " << record.change_g;
    pcout << line.str() << seconds(record.time) << std::endl;
  }

  template <int dim>
  void
  Report<dim>::threshold_step(const IterationRecord &record)
  {
    iteration_log.push_back(record);
    iteration_log.back().cycle = cycle_results.size();
    std::ostringstream line;
    line << "   threshold step " << std::setw(3) << record.index << ": "
         << record.uzawa_steps << " Uzawa steps, stick/slip " << record.n_stick
         << "/" << record.n_slip << ", d(g) " << std::scientific
         << std::setprecision(2) << record.change_g;
    pcout << line.str() << std::endl;
  }

  template <int dim>
  void
  Report<dim>::warn(const std::string &text) const
  {
    if (pcout.is_active())
      std::cerr << "dualcontact: warning: " << text << std::endl;
  }

  template <int dim>
  void
  Report<dim>::note(const std::string &text)
  {
    pcout << "   " << text << std::endl;
  }

  template <int dim>
  void
  Report<dim>::print_cycle(const CycleResult &r) const
  {
    const Effects      &effects = scene.effects();
    const SolveFigures &solve   = r.solve;
    if (!effects.contact)
      {
        pcout << "   one linear elasticity solve: " << solve.cg_iterations
              << " CG iterations" << seconds(r.time.solve) << '\n';
      }
    else
      {
        const ContactZoneFigures &zone = r.zone;
        pcout << "   contact solved: " << solve.uzawa_steps << " Uzawa steps, "
              << solve.newton_steps << " Newton steps, " << solve.cg_iterations
              << " CG iterations, " << solve.amg_setups << " AMG set-ups, "
              << solve.n_active << " of " << solve.n_contact_nodes
              << " nodes in contact" << seconds(r.time.solve) << '\n'
              << std::setprecision(8) << "   total contact force "
              << zone.contact_force << " (applied load toward the foundation "
              << solve.normal_load << "), peak pressure " << zone.max_pressure
              << ", contact half-width " << zone.half_width << " (nodes), "
              << zone.edge_half_width << " (edges extrapolated)";
        if (scene.exact_pressure() != nullptr)
          pcout << ", pressure error (rel. L2) " << zone.pressure_error;
        if (parameters.exact.contact_half_width > 0.)
          pcout << ", half-width error " << zone.half_width_error;
        if (parameters.exact.peak_pressure > 0.)
          pcout << ", peak error " << zone.peak_pressure_error;
        if (solve.n_hanging_contact > 0)
          pcout << "\n   " << solve.n_hanging_contact
                << " hanging nodes on Gamma_C (no contact condition of their "
                   "own)";
        if (r.cold.uzawa_steps > 0)
          pcout << "\n   nested iteration against a cold start: Uzawa "
                << solve.uzawa_steps << " vs " << r.cold.uzawa_steps
                << ", Newton " << solve.newton_steps << " vs "
                << r.cold.newton_steps << ", threshold steps "
                << solve.threshold_steps << " vs " << r.cold.threshold_steps
                << ", time " << r.time.solve << " s vs " << r.cold.time
                << " s; solutions differ by " << r.cold.difference_v
                << " (v, energy norm), " << r.cold.difference_l1 << " (l1)";
        if (effects.friction_law().has_friction())
          {
            pcout << "\n   friction: " << solve.n_stick << " stick, "
                  << solve.n_slip << " slip nodes, total tangential force "
                  << zone.tangential_force;
            if (solve.threshold_steps > 0)
              pcout << ", " << solve.threshold_steps << " threshold steps";
          }
        pcout << std::scientific << std::setprecision(2)
              << "\n   Uzawa contraction rate " << solve.rate
              << ", remaining error of l1 estimated from it (d rho/(1 - rho), "
                 "doc/theory.md §6) "
              << solve.estimated_l1_error << std::defaultfloat << '\n';
        if (parameters.solver.time_reference_solve)
          pcout << "   reference: one linear solve on this mesh "
                << solve.reference_iterations << " CG iterations"
                << seconds(solve.time_reference)
                << ", contact / linear = " << std::fixed << std::setprecision(2)
                << (r.time.assembly + r.time.solve) /
                     (r.time.assembly + solve.time_reference)
                << std::defaultfloat << " (assembly included)\n";
      }
    // the supports' reactions and the loads: with the contact force they
    // balance
    if (!r.reactions.on_id.empty())
      {
        const auto vector = [](const std::array<double, 3> &f) {
          std::ostringstream s;
          s << std::setprecision(8) << "(" << f[0];
          for (unsigned int c = 1; c < dim; ++c)
            s << ", " << f[c];
          s << ")";
          return s.str();
        };
        pcout << "   reactions on the body:";
        for (const auto &[id, f] : r.reactions.on_id)
          pcout << " id " << static_cast<unsigned int>(id) << " " << vector(f)
                << ";";
        pcout << " applied loads " << vector(r.reactions.applied_load)
              << "; imbalance " << std::scientific << std::setprecision(1)
              << r.reactions.imbalance << " (relative)" << std::defaultfloat
              << '\n';
      }
    pcout << std::scientific << std::setprecision(6)
          << "   ||u||_L2 = " << r.errors.u_l2;
    if (scene.exact_displacement() != nullptr)
      pcout << ", error L2 = " << r.errors.l2 << ", H1 = " << r.errors.h1_semi;
    pcout << std::defaultfloat << '\n';
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
    t.add_value("half_width_error", r.zone.half_width_error);
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
    t.add_value("time_refine", r.time.refine);
    t.add_value("time_setup", r.time.setup);
    t.add_value("time_assembly", r.time.assembly);
    t.add_value("time_solve", r.time.solve);
    t.add_value("time_output", r.time.output);
    t.add_value("time_total", r.time.total);
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
        s.add_value("Gamma_C nodes",
                    static_cast<std::uint64_t>(r.solve.n_contact_nodes));
        if (dim == 3)
          s.add_value("hanging",
                      static_cast<std::uint64_t>(r.solve.n_hanging_contact));
        // relative errors, where the scene gives something to compare with
        if (scene.exact_pressure() != nullptr)
          add_error("p L2 err", r.zone.pressure_error);
        if (parameters.exact.contact_half_width > 0.)
          add_error("a err", r.zone.half_width_error);
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
    result.time.total =
      (cycle_results.empty() ? 0. : cycle_results.back().time.total) +
      result.time.refine + result.time.setup + result.time.assembly +
      result.time.solve + result.time.output + phase_time("postprocess") +
      phase_time("measure contact zone");
    Utilities::System::MemoryStats stats;
    Utilities::System::get_memory_stats(stats);
    result.memory_mb =
      Utilities::MPI::sum(static_cast<double>(stats.VmHWM), mpi_communicator) /
      1024.;
    previous_totals = timer.get_summary_data(TimerOutput::total_wall_time);

    print_cycle(result);
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
    pcout << "\nSummary (" << to_string(parameters.refinement.strategy)
          << " refinement"
          << (parameters.refinement.nested_iteration ? ", nested iteration" :
                                                       ", cold starts")
          << "; contact errors relative; an error's rate per DoF, "
             "dim log(e_{k-1}/e_k) / log(N_k/N_{k-1}), beside it";
    if (parameters.output.print_timing)
      pcout << "; times in s";
    pcout << "):\n";
    if (pcout.is_active())
      table.write_text(pcout.get_stream(), TableHandler::table_with_headers);
    pcout << "Output written to " << parameters.output.directory << "/\n";
    if (parameters.output.print_timing)
      timer.print_summary();
  }

  template class Report<2>;
  template class Report<3>;
} // namespace dualcontact
