// ContactProblem, the output of a cycle or of a load step: the displacement,
// the stresses and the refinement indicator of the body, and the contact
// fields on Gamma_C, as .vtu/.pvtu files with one .pvd record each over the
// cycles (the steps).
#include <deal.II/base/utilities.h>

#include <deal.II/dofs/dof_accessor.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <dualcontact/contact_functions.h>
#include <dualcontact/contact_output.h>
#include <dualcontact/contact_problem.h>
#include <dualcontact/input_error.h>
#include <dualcontact/output_directory.h>
#include <dualcontact/pair_results.h>
#include <dualcontact/plausibility.h>
#include <dualcontact/postprocess.h>
#include <dualcontact/refinement.h>
#include <dualcontact/refinement_indicator.h>
#include <dualcontact/run_size.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>

namespace dualcontact
{
  template <int dim>
  void
  ContactProblem<dim>::output_results(const unsigned int cycle)
  {
    TimerOutput::Scope t(computing_timer, "output results");
    const std::string &directory = parameters.output.directory;
    const bool root = Utilities::MPI::this_mpi_process(mpi_communicator) == 0;

    // The first file is written only now: a run that fails on its first
    // mesh (bad input found late, no equilibrium) writes nothing. run()
    // made the folder; a program that calls the phases itself may not have.
    // The files of an earlier run go first: the last cycles of a longer run
    // must not stand next to this run's.
    if (cycle == 0)
      {
        if (root)
          {
            std::filesystem::create_directories(directory);
            OutputDirectory::remove_earlier_results(directory);
            if (!recorded_parameters.empty())
              std::ofstream(directory + "/parameters.prm")
                << recorded_parameters;
          }
        MPI_Barrier(mpi_communicator);
        pvd_records.clear();
      }

    // the probes: all cycles so far
    probes.evaluate(
      cycle, mapping, dof_handler, solution, parameters.material, mixed.get());
    if (root && !probes.empty())
      probes.write_csv(directory + "/probes.csv");

    write_fields("", cycle, 2, cycle);
  }

  template <int dim>
  void
  ContactProblem<dim>::output_step(const StepRecord &step)
  {
    TimerOutput::Scope t(computing_timer, "output results");
    write_fields("_step", step.step, 3, step.time);
  }

  template <int dim>
  void
  ContactProblem<dim>::write_fields(const std::string &tag,
                                    const unsigned int number,
                                    const unsigned int digits,
                                    const double       pvd_time)
  {
    const std::string &directory = parameters.output.directory;
    const bool root = Utilities::MPI::this_mpi_process(mpi_communicator) == 0;
    // one row per contact node, gathered on rank 0
    const bool contact = scene.effects().contact;
    if (contact)
      {
        const std::vector<ContactNodeRow<dim>> rows =
          gather_contact_rows(contact_set, solution, mpi_communicator);
        const std::string suffix =
          tag + "_" + Utilities::int_to_string(number, digits) + ".csv";
        if (root)
          write_contact_csvs(
            directory, suffix, rows, contact_set, scene.exact_pressure());
      }

    if (!parameters.output.write_vtu)
      return;
    // zlib's fastest level: best_compression (deal.II's default) took
    // most of the output's time for files a few percent smaller
    DataOutBase::VtkFlags flags;
    flags.compression_level = DataOutBase::VtkFlags::best_speed;

    // The volume: displacement, stress and von Mises stress (from one
    // evaluation of the gradient per point; in the mixed formulation with
    // the pressure field, also written), the owning rank, and the
    // refinement indicator with adaptive refinement. The contact fields
    // live on Gamma_C only, in the boundary output below.
    const TrilinosWrappers::MPI::Vector pressure =
      mixed ? mixed->ghosted_pressure() : TrilinosWrappers::MPI::Vector();
    StressPostprocessor<dim> stress(parameters.material,
                                    mixed ? mixed->pressure_at(mapping) :
                                            PressureAt<dim>());
    DataOut<dim>             data_out;
    data_out.set_flags(flags);
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(
      solution,
      std::vector<std::string>(dim, "displacement"),
      DataOut<dim>::type_dof_data,
      std::vector<DataComponentInterpretation::DataComponentInterpretation>(
        dim, DataComponentInterpretation::component_is_part_of_vector));
    data_out.add_data_vector(solution, stress);
    if (mixed)
      data_out.add_data_vector(mixed->dofs(), pressure, "pressure");

    Vector<float> subdomain(triangulation.n_active_cells());
    subdomain = static_cast<float>(triangulation.locally_owned_subdomain());
    data_out.add_data_vector(subdomain, "subdomain");

    // what the adaptive strategies rank the cells by (the cells refined
    // next are those with the largest values)
    if (!refinement_indicator_kind(parameters.refinement.strategy)
           .refines_every_cell())
      data_out.add_data_vector(refinement_indicator(), "refinement_indicator");
    data_out.build_patches(mapping, fe.degree);

    // a .pvd record over all cycles (steps) so that ParaView shows them as
    // a sequence, each at its cycle (time)
    const auto add_to_pvd = [&](const std::string &name,
                                const std::string &pvtu) {
      auto &records = pvd_records[name + tag];
      records.emplace_back(pvd_time, pvtu);
      if (root)
        {
          std::ofstream pvd(directory + "/" + name + tag + ".pvd");
          DataOutBase::write_pvd_record(pvd, records);
        }
    };
    add_to_pvd("solution",
               data_out.write_vtu_with_pvtu_record(directory + "/",
                                                   "solution" + tag,
                                                   number,
                                                   mpi_communicator,
                                                   digits));

    // Gamma_C: the contact fields on its faces (contact_output.h)
    if (contact)
      {
        ContactBoundaryOutput<dim> boundary;
        boundary.set_flags(flags);
        boundary.build_patches(mapping,
                               dof_handler,
                               scene.contact_ids(),
                               contact_set,
                               solution,
                               hanging_node_constraints,
                               locally_relevant_dofs);
        add_to_pvd("contact",
                   boundary.write_vtu_with_pvtu_record(directory + "/",
                                                       "contact" + tag,
                                                       number,
                                                       mpi_communicator,
                                                       digits));
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::multiplier_fields(
    TrilinosWrappers::MPI::Vector &multipliers,
    TrilinosWrappers::MPI::Vector &threshold) const
  {
    // nodal values at the contact nodes, then at the hanging nodes on
    // Gamma_C (interpolated from their masters, so l1 >= 0 and |l2| <= g
    // hold there too), then ghosted
    TrilinosWrappers::MPI::Vector owned_multipliers(locally_owned_dofs,
                                                    mpi_communicator);
    TrilinosWrappers::MPI::Vector owned_threshold(locally_owned_dofs,
                                                  mpi_communicator);
    contact_set.write_fields(owned_multipliers, owned_threshold);
    hanging_node_constraints.distribute(owned_multipliers);
    hanging_node_constraints.distribute(owned_threshold);
    multipliers.reinit(locally_owned_dofs,
                       locally_relevant_dofs,
                       mpi_communicator);
    threshold.reinit(locally_owned_dofs,
                     locally_relevant_dofs,
                     mpi_communicator);
    multipliers = owned_multipliers;
    threshold   = owned_threshold;
  }


  template void
  ContactProblem<2>::output_results(const unsigned int cycle);
  template void
  ContactProblem<3>::output_results(const unsigned int cycle);
  template void
  ContactProblem<2>::output_step(const StepRecord &step);
  template void
  ContactProblem<3>::output_step(const StepRecord &step);
  template void
  ContactProblem<2>::multiplier_fields(
    TrilinosWrappers::MPI::Vector &multipliers,
    TrilinosWrappers::MPI::Vector &threshold) const;
  template void
  ContactProblem<3>::multiplier_fields(
    TrilinosWrappers::MPI::Vector &multipliers,
    TrilinosWrappers::MPI::Vector &threshold) const;
} // namespace dualcontact
