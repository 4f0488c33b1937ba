// The report's CSV writers: a table as CSV (cycles.csv, steps.csv), and
// the rows of iterations.csv, appended as the loops run.
#include <deal.II/base/mpi.h>

#include <dualcontact/report.h>

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

  template <int dim>
  void
  Report<dim>::write_cycles_csv() const
  {
    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return;
    std::ofstream csv(parameters.output.directory + "/cycles.csv");
    cycle_table.write_csv(csv);
  }

  template <int dim>
  void
  Report<dim>::append_iterations_csv()
  {
    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0 ||
        !scene.effects().contact)
      {
        iterations_written = iteration_log.size(); // by rank 0
        return;
      }
    if (!iterations_file_started)
      iterations_file.open(parameters.output.directory + "/iterations.csv");
    iterations_file_started = true;
    const bool path         = parameters.load_path.n_steps_on_path() > 1;
    std::vector<AppendedCsvFile::Row> rows;
    for (; iterations_written < iteration_log.size(); ++iterations_written)
      {
        const IterationRecord &r    = iteration_log[iterations_written];
        const auto             text = [](const auto value) {
          std::ostringstream out;
          out << std::scientific << std::setprecision(10) << value;
          return out.str();
        };
        AppendedCsvFile::Row row = {{"cycle", text(r.cycle)}};
        if (path)
          row.emplace_back("step", text(r.step));
        row.insert(row.end(),
                   {{"loop", to_string(r.loop)},
                    {"uzawa_step", text(r.uzawa_step)},
                    {"index", text(r.index)},
                    {"uzawa_steps", text(r.uzawa_steps)},
                    {"newton_steps", text(r.newton_steps)},
                    {"cg_iterations", text(r.cg_iterations)},
                    {"amg_setups", text(r.amg_setups)},
                    {"n_active", text(r.n_active)},
                    {"n_stick", text(r.n_stick)},
                    {"n_slip", text(r.n_slip)},
                    {"gradient", text(r.gradient)},
                    {"step_length", text(r.step_length)},
                    {"change_l1", text(r.change_l1)},
                    {"change_l2", text(r.change_l2)},
                    {"change_g", text(r.change_g)},
                    {"change_v", text(r.change_v)},
                    {"violation", text(r.violation)},
                    {"complementarity", text(r.complementarity)},
                    {"time", text(r.time)}});
        rows.push_back(std::move(row));
      }
    iterations_file.add_rows(rows);
  }

  template void
  Report<2>::write_cycles_csv() const;
  template void
  Report<2>::append_iterations_csv();
  template void
  Report<3>::write_cycles_csv() const;
  template void
  Report<3>::append_iterations_csv();
} // namespace dualcontact
