#include <deal.II/base/utilities.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <dualcontact/contact_problem.h>
#include <dualcontact/input_error.h>
#include <dualcontact/postprocess.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>

namespace dualcontact
{
  template <int dim>
  ContactProblem<dim>::ContactProblem(const Parameters &parameters,
                                      MPI_Comm          mpi_communicator,
                                      std::ostream     &out)
    : mpi_communicator(mpi_communicator)
    , pcout(out, Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
    , computing_timer(mpi_communicator,
                      pcout,
                      parameters.output.print_timing ? TimerOutput::summary :
                                                       TimerOutput::never,
                      TimerOutput::wall_times)
    , parameters(parameters)
    , scene(parameters)
    , triangulation(mpi_communicator,
                    typename Triangulation<dim>::MeshSmoothing(
                      Triangulation<dim>::smoothing_on_refinement |
                      Triangulation<dim>::smoothing_on_coarsening))
    , mapping(1)
    , fe(FE_Q<dim>(1), dim)
    , dof_handler(triangulation)
    , elastic_solver(parameters.solver)
  {
    if (scene.effects().contact)
      throw InputError("The scene has a contact boundary; contact is not "
                       "implemented in this version of dualcontact.",
                       exit_inconsistent);
  }

  template <int dim>
  void
  ContactProblem<dim>::print_header() const
  {
    pcout << "dualcontact: " << dim << "D, "
          << (parameters.geometry.type == GeometryType::rectangle ? "rectangle" :
                                                                     "half disc")
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
  ContactProblem<dim>::make_grid()
  {
    scene.create_mesh(triangulation);
    scene.check_rigid_motions(triangulation);
  }

  template <int dim>
  void
  ContactProblem<dim>::setup_system()
  {
    dof_handler.distribute_dofs(fe);
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);

    // Hanging nodes first, then Dirichlet, then sliders: later ones do not
    // overwrite earlier ones, which keeps the space conforming.
    constraints.clear();
    constraints.reinit(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    for (const types::boundary_id id : scene.ids_with(BoundaryCondition::fixed))
      VectorTools::interpolate_boundary_values(
        mapping, dof_handler, id, scene.displacement(id), constraints);
    const auto sliders = scene.ids_with(BoundaryCondition::normal_fixed);
    if (!sliders.empty())
      VectorTools::compute_no_normal_flux_constraints(
        dof_handler, 0, sliders, constraints, mapping);
    constraints.close();

    DynamicSparsityPattern dsp(locally_relevant_dofs);
    DoFTools::make_sparsity_pattern(dof_handler,
                                    dsp,
                                    constraints,
                                    /*keep_constrained_dofs=*/false);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               locally_owned_dofs,
                                               mpi_communicator,
                                               locally_relevant_dofs);
    system_matrix.reinit(locally_owned_dofs,
                         locally_owned_dofs,
                         dsp,
                         mpi_communicator);
    system_rhs.reinit(locally_owned_dofs, mpi_communicator);
    solution.reinit(locally_owned_dofs, locally_relevant_dofs, mpi_communicator);
  }

  template <int dim>
  void
  ContactProblem<dim>::assemble_system()
  {
    assemble_elasticity(
      mapping, dof_handler, scene, constraints, system_matrix, system_rhs);
  }

  template <int dim>
  void
  ContactProblem<dim>::solve()
  {
    elastic_solver.initialize(mapping,
                              dof_handler,
                              system_matrix,
                              scene.center(),
                              scene.characteristic_length());

    TrilinosWrappers::MPI::Vector owned(locally_owned_dofs, mpi_communicator);
    const unsigned int iterations =
      elastic_solver.solve(system_matrix, owned, system_rhs);
    constraints.distribute(owned);
    solution = owned;
    cycle_results.back().linear_iterations = iterations;
  }

  template <int dim>
  void
  ContactProblem<dim>::postprocess(CycleResult &result)
  {
    const ErrorNorms norms = compute_error_norms(mapping,
                                                 dof_handler,
                                                 solution,
                                                 scene.exact_displacement());
    result.u_l2     = norms.u_l2;
    result.l2_error = norms.l2;
    result.h1_error = norms.h1_semi;
    if (cycle_results.size() > 1 && scene.exact_displacement() != nullptr)
      {
        // meshes are halved between cycles: the rate is log2 of the ratio
        const CycleResult &previous = cycle_results[cycle_results.size() - 2];
        result.l2_rate = std::log2(previous.l2_error / result.l2_error);
        result.h1_rate = std::log2(previous.h1_error / result.h1_error);
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::output_results(const unsigned int cycle)
  {
    if (!parameters.output.write_vtu)
      return;

    StressPostprocessor<dim> stress(parameters.material);
    DataOut<dim>             data_out;
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(
      solution,
      std::vector<std::string>(dim, "displacement"),
      DataOut<dim>::type_dof_data,
      std::vector<DataComponentInterpretation::DataComponentInterpretation>(
        dim, DataComponentInterpretation::component_is_part_of_vector));
    data_out.add_data_vector(solution, stress);

    Vector<float> subdomain(triangulation.n_active_cells());
    subdomain = static_cast<float>(triangulation.locally_owned_subdomain());
    data_out.add_data_vector(subdomain, "subdomain");
    data_out.build_patches(mapping, fe.degree);

    const std::string pvtu = data_out.write_vtu_with_pvtu_record(
      parameters.output.directory + "/", "solution", cycle, mpi_communicator, 2);

    // a .pvd record over all cycles so ParaView shows them as a sequence
    pvtu_records.emplace_back(cycle, pvtu);
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      {
        std::ofstream pvd(parameters.output.directory + "/solution.pvd");
        DataOutBase::write_pvd_record(pvd, pvtu_records);
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::write_cycle_table() const
  {
    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return;
    std::ofstream csv(parameters.output.directory + "/cycles.csv");
    csv << "cycle,cells,dofs,linear_iterations,u_l2,l2_error,h1_error,"
           "l2_rate,h1_rate,time_setup,time_assembly,time_solve,time_output\n";
    csv << std::setprecision(10);
    for (const CycleResult &r : cycle_results)
      csv << r.cycle << ',' << r.n_cells << ',' << r.n_dofs << ','
          << r.linear_iterations << ',' << r.u_l2 << ',' << r.l2_error << ','
          << r.h1_error << ',' << r.l2_rate << ',' << r.h1_rate << ','
          << r.time_setup << ',' << r.time_assembly << ',' << r.time_solve
          << ',' << r.time_output << '\n';
  }

  template <int dim>
  void
  ContactProblem<dim>::refine_mesh()
  {
    triangulation.refine_global(1);
  }

  template <int dim>
  void
  ContactProblem<dim>::run()
  {
    // Everything about the input is checked before anything is written.
    {
      TimerOutput::Scope t(computing_timer, "make grid");
      make_grid();
    }
    print_header();
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      std::filesystem::create_directories(parameters.output.directory);
    MPI_Barrier(mpi_communicator);

    const bool timing = parameters.output.print_timing;
    const auto timed  = [&](const char *name, const auto &phase) {
      TimerOutput::Scope t(computing_timer, name);
      Timer              timer(mpi_communicator, /*sync_lap_times=*/true);
      phase();
      timer.stop();
      return timer.wall_time();
    };
    const auto seconds = [timing](const double t) {
      std::ostringstream s;
      if (timing)
        s << "  (" << std::fixed << std::setprecision(3) << t << " s)";
      return s.str();
    };

    for (unsigned int cycle = 0; cycle < parameters.refinement.n_cycles; ++cycle)
      {
        if (cycle > 0)
          timed("refine mesh", [&] { refine_mesh(); });

        cycle_results.emplace_back();
        CycleResult &result = cycle_results.back();
        result.cycle        = cycle;
        result.time_setup   = timed("setup system", [&] { setup_system(); });
        result.n_cells      = triangulation.n_global_active_cells();
        result.n_dofs       = dof_handler.n_dofs();
        pcout << "Cycle " << cycle << ": " << result.n_cells << " cells, "
              << result.n_dofs << " DoFs" << seconds(result.time_setup) << '\n';

        result.time_assembly = timed("assemble", [&] { assemble_system(); });
        pcout << "   assembled A and b" << seconds(result.time_assembly) << '\n';
        result.time_solve = timed("solve", [&] { solve(); });
        pcout << "   one linear elasticity solve: " << result.linear_iterations
              << " CG iterations" << seconds(result.time_solve) << '\n';

        timed("postprocess", [&] { postprocess(result); });
        pcout << std::scientific << std::setprecision(6)
              << "   ||u||_L2 = " << result.u_l2;
        if (scene.exact_displacement() != nullptr)
          pcout << ", error L2 = " << result.l2_error
                << ", H1 = " << result.h1_error;
        pcout << std::defaultfloat << '\n';

        result.time_output =
          timed("output", [&] { output_results(cycle); });
        write_cycle_table();
      }

    if (scene.exact_displacement() != nullptr)
      {
        pcout << "\nConvergence (rates for h halved per cycle):\n"
              << "cycle       DoFs     L2 error  rate     H1 error  rate\n";
        for (const CycleResult &r : cycle_results)
          pcout << std::setw(5) << r.cycle << std::setw(11) << r.n_dofs
                << std::scientific << std::setprecision(4) << std::setw(13)
                << r.l2_error << std::fixed << std::setprecision(2)
                << std::setw(6) << r.l2_rate << std::scientific
                << std::setprecision(4) << std::setw(13) << r.h1_error
                << std::fixed << std::setprecision(2) << std::setw(6)
                << r.h1_rate << std::defaultfloat << '\n';
      }
    pcout << "Output written to " << parameters.output.directory << "/\n";
  }

  template class ContactProblem<2>;
  template class ContactProblem<3>;
} // namespace dualcontact
