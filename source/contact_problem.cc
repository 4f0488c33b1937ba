// ContactProblem: run() and its phases, from the assembly to the refinement.
// The mesh and system set-up, the load path's later steps, the equilibrium
// checks, the measurements, the output, the checkpoints and the rigid
// motions nothing holds are in contact_problem_*.cc.
#include <deal.II/base/utilities.h>

#include <deal.II/dofs/dof_accessor.h>
#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>

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
#include <dualcontact/parameter_helpers.h>
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
#include <memory>

namespace dualcontact
{
  template <int dim>
  ContactProblem<dim>::ContactProblem(const Parameters &given_parameters,
                                      MPI_Comm          mpi_communicator,
                                      std::ostream     &out)
      : mpi_communicator(mpi_communicator)
      , pcout(out, Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      , parameters(given_parameters)
      // the scene reads the coarse mesh of a mesh file: its size is
      // checked against the memory before it is built, as in make_grid()
      , scene(parameters,
              [this](const double n_cells) {
                RunSizeCheck(parameters,
                             this->mpi_communicator,
                             parameters.geometry.cell_kind)
                  .check(n_cells, false);
              })
      , step_times(parameters.load_path.step_times())
      , computing_timer(mpi_communicator,
                        pcout,
                        TimerOutput::never,
                        TimerOutput::wall_times)
      , report(parameters, scene, computing_timer, mpi_communicator, out)
      , triangulation_ptr(
          scene.discretization().make_triangulation(mpi_communicator))
      , mapping_ptr(scene.discretization().make_mapping())
      , fe_ptr(scene.discretization().make_element())
      , triangulation(*triangulation_ptr)
      , mapping(*mapping_ptr)
      , fe(*fe_ptr)
      , dof_handler(triangulation)
      , elastic_solver(parameters.solver, parameters.material.poissons_ratio)
      , newton(parameters.solver, elastic_solver)
      , uzawa(parameters.solver, newton)
      , threshold_iteration(parameters.friction, uzawa)
      , probes(parameters.output.probe_points,
               parameters.material.formulation == Formulation::mixed)
  {
    if (parameters.material.formulation == Formulation::mixed)
      mixed =
        std::make_unique<MixedBulk<dim>>(triangulation,
                                         scene.discretization().cell_kind(),
                                         scene.discretization().degree(),
                                         this->parameters.material);
  }

  // The algorithm: on each mesh of a nested sequence, set up, carry the
  // previous mesh's fields over, assemble, solve, measure, write; then
  // refine. A load path of several steps then solves each later step on the
  // finest mesh, from the state the step before reached. Each phase times
  // itself and returns its record; the report prints them and writes the
  // tables.
  template <int dim>
  void
  ContactProblem<dim>::run()
  {
    // The output folder first: one that cannot be made is bad input, found
    // before the mesh is built. A run that fails before it wrote anything
    // removes it again.
    const OutputDirectory output(parameters.output.directory, mpi_communicator);
    try
      {
        CycleResult  result;
        StepControl  control(step_times, parameters.load_path);
        unsigned int step = 2;
        if (resume)
          {
            // the path from where a checkpoint left it (checked first:
            // nothing is printed before)
            step = load_checkpoint(control) + 1;
            report.print_scene();
            report.print_resume();
          }
        else
          {
            make_grid(); // checks the input first: nothing is written before
            report.print_scene();

            // the first step of the load path, on every mesh
            for (unsigned int cycle = 0; cycle < parameters.refinement.n_cycles;
                 ++cycle)
              {
                if (cycle > 0)
                  refine_mesh();

                result          = CycleResult();
                result.step     = step_record(1, nullptr);
                result.mesh     = setup_system(cycle);
                result.transfer = transfer_fields();
                report.start_cycle(result.mesh, result.transfer);

                solve_and_measure(result);
                if (scene.effects().contact)
                  result.cold = compare_with_cold_start();

                output_results(cycle);
                result = report.end_cycle(result); // with its times
              }
            path_mesh = result.mesh;
            if (step_times.size() > 1)
              finish_step(result);
          }

        // the later steps, each from the state the step before reached
        // (doc/theory.md §11), at the times step control gives
        const unsigned int checkpoints = parameters.output.checkpoint_interval;
        for (; !control.finished(); ++step)
          {
            result      = CycleResult();
            result.step = start_step(step, control, result);
            solve_step(control, result);
            finish_step(result);
            control.accept();
            if (checkpoints > 0 && step % checkpoints == 0 &&
                !control.finished())
              write_checkpoint(result.step, control);
          }
        report.finish();
      }
    catch (...)
      {
        output.remove_if_unused();
        throw;
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::solve_and_measure(CycleResult &result)
  {
    assemble_system();
    result.solve    = solve();
    result.position = check_position();
    if (scene.effects().contact)
      result.zone = measure_contact_zone();
    result.errors           = postprocess();
    result.potential_energy = potential_energy();
    result.reactions        = compute_reactions(result.zone);
    check_balance(result.reactions);
    // the energy friction dissipated in this step (on each mesh of the
    // first step: from the undeformed state)
    if (scene.effects().contact)
      result.step.dissipation = dissipation();
    result.step.dissipation_total = dissipated + result.step.dissipation;
  }

  template <int dim>
  TransferRecord
  ContactProblem<dim>::transfer_fields()
  {
    TransferRecord record;
    carried           = false;
    carried_from_step = false;
    same_stiffness    = false;
    if (!transfer)
      return record;
    TimerOutput::Scope t(computing_timer, "refine mesh");
    carried_v.reinit(locally_owned_dofs, mpi_communicator);
    std::vector<TrilinosWrappers::MPI::Vector *> fields = {&carried_v};
    if (scene.effects().contact)
      {
        carried_multipliers.reinit(locally_owned_dofs, mpi_communicator);
        carried_threshold.reinit(locally_owned_dofs, mpi_communicator);
        fields.push_back(&carried_multipliers);
        fields.push_back(&carried_threshold);
      }
    transfer->interpolate(fields);
    transfer.reset();
    if (mixed)
      mixed->finish_transfer();
    constraints.distribute(carried_v);
    carried           = true;
    record.warm_start = true;
    if (scene.effects().contact)
      {
        // the multipliers onto the contact nodes, projected onto the
        // admissible set; how far they were from it (doc/theory.md §7)
        const auto [smallest_l1, excess] =
          contact_set.read_fields(carried_multipliers, carried_threshold);
        const double l1_max = std::max(carried_multipliers.linfty_norm(),
                                       std::numeric_limits<double>::min());
        const double g_max  = std::max(carried_threshold.linfty_norm(),
                                      std::numeric_limits<double>::min());
        record.carried_min_l1 =
          Utilities::MPI::min(smallest_l1, mpi_communicator) / l1_max;
        // without friction there is no l2 and no excess
        if (contact_set.friction)
          record.carried_max_excess =
            Utilities::MPI::max(excess, mpi_communicator) / g_max;
      }
    return record;
  }

  template <int dim>
  void
  ContactProblem<dim>::assemble_system()
  {
    TimerOutput::Scope t(computing_timer, "assemble system");
    const bool         contact = scene.effects().contact;
    assemble_elasticity(mapping,
                        dof_handler,
                        scene,
                        constraints,
                        system_matrix,
                        system_rhs,
                        contact ? &mass : nullptr,
                        &applied_load);
    if (mixed)
      mixed->assemble(mapping, dof_handler, constraints);
    // An expression may evaluate to NaN or infinity somewhere (sqrt of a
    // negative number, log of zero): stop here, naming the suspects, rather
    // than solve with it.
    if (!std::isfinite(system_rhs.l2_norm()))
      throw InputError(
        "The loads are not finite numbers at some point of the body or its "
        "boundary (NaN or infinity): check the expressions of <Loads/Body "
        "force>, <Boundary conditions/Tractions> and <Boundary "
        "conditions/Displacements> over the whole body (e.g. sqrt or log of "
        "a negative number).",
        exit_invalid_value);
    if (contact)
      {
        // The Uzawa steps minimise with the proximal term (chi/2)|v - v^k|^2
        // (doc/theory.md §3.2), so their matrix is K = A + chi M. chi is
        // relative to E / L^2 so that the scene's units do not matter
        // (doc/theory.md §5).
        // (of the stiffest body where there are several materials)
        chi = parameters.solver.proximal *
              parameters.material.stiffest().youngs_modulus /
              std::pow(scene.characteristic_length(), 2);
        mass.add_to(system_matrix, chi);
      }
    // the rigid-body modes of this mesh, for the algebraic multigrid
    elastic_solver.set_near_null_space(mapping,
                                       dof_handler,
                                       system_matrix,
                                       scene.center(),
                                       scene.characteristic_length());
  }

  template <int dim>
  SolveRecord
  ContactProblem<dim>::solve()
  {
    TimerOutput::Scope t(computing_timer, "solve");
    indicator_valid = false; // a new solution
    TrilinosWrappers::MPI::Vector v(locally_owned_dofs, mpi_communicator);
    SolveRecord                   record =
      scene.effects().contact ? solve_contact(v) : solve_linear_elasticity(v);
    solution = v;
    t.stop();

    // What the contact solve is compared with, timed apart from it
    if (scene.effects().contact && parameters.solver.time_reference_solve)
      {
        TimerOutput::Scope r(computing_timer, "reference linear solve");
        // with a solver of its own: the contact solver's preconditioner
        // serves the next step of a load path
        ElasticSolver<dim> reference(parameters.solver,
                                     parameters.material.poissons_ratio);
        reference.set_near_null_space(mapping,
                                      dof_handler,
                                      system_matrix,
                                      scene.center(),
                                      scene.characteristic_length());
        record.time_reference =
          newton.time_reference_solve(contact_system(),
                                      contact_set,
                                      v,
                                      reference,
                                      record.reference_iterations);
      }
    return record;
  }

  template <int dim>
  SolveRecord
  ContactProblem<dim>::solve_linear_elasticity(TrilinosWrappers::MPI::Vector &v)
  {
    SolveRecord record;
    if (carried) // nested iteration: the coarse solution is a first guess
      v = carried_v;
    elastic_solver.initialize(system_matrix);
    if (mixed)
      record.cg_iterations = solve_mixed_elasticity(v);
    else
      record.cg_iterations = elastic_solver.solve(system_matrix, v, system_rhs);
    constraints.distribute(v);
    return record;
  }

  template <int dim>
  unsigned int
  ContactProblem<dim>::solve_mixed_elasticity(TrilinosWrappers::MPI::Vector &v)
  {
    // one step from (v, p) to the solution: the saddle-point system for the
    // correction, with the residual b - K v - B^T p and the constraint's
    constraints.distribute(v);
    TrilinosWrappers::MPI::Vector residual(system_rhs), correction(system_rhs);
    system_matrix.vmult(residual, v);
    mixed->add_pressure_forces(residual);
    residual.sadd(-1., 1., system_rhs);
    homogeneous_constraints.set_zero(residual);
    const auto [converged, iterations] =
      mixed->solve(system_matrix,
                   elastic_solver.amg(),
                   v,
                   residual,
                   correction,
                   parameters.solver.linear_tolerance,
                   parameters.solver.max_linear_iterations);
    AssertThrow(converged,
                ExcMessage("MINRES did not solve the mixed saddle-point "
                           "system in " +
                           std::to_string(iterations) +
                           " iterations: raise <Solver/Maximum linear "
                           "iterations>, or check that the scene holds the "
                           "body and, at nu = 0.5, that some boundary is free "
                           "to move (otherwise nothing determines the "
                           "pressure's constant)."));
    homogeneous_constraints.distribute(correction);
    v += correction;
    mixed->update_pressure(correction);
    return iterations;
  }

  template <int dim>
  SolveRecord
  ContactProblem<dim>::prepare_contact_solve()
  {
    SolveRecord record;
    held_by_friction_pressure = check_equilibrium();

    // r is relative to M / h_k, so that the Uzawa steps do not depend on
    // the units, the mesh size or the degree; M is the contact modulus of
    // material_parameters.h: the P-wave modulus lambda + 2 mu rather than
    // E in displacements, because it follows the stiffness of a nearly
    // incompressible (locked) material, for which r_rel E / h_k is far too
    // small, and 4 mu in the mixed formulation, which does not lock. h_k = h_C
    // / k is the spacing of the contact nodes: at degree k the slowest
    // multiplier mode lives on one node spacing, and r scaled with the faces
    // alone slows the Uzawa rate with k (doc/theory.md §5). The friction terms
    // have their own r_t, scaled alike: by default r in 2D and r / 4 in 3D,
    // where friction terms as large as r make the Newton matrices hard
    // (doc/theory.md §5).
    const double r_t_rel =
      parameters.solver.tangential_augmentation > 0. ?
        parameters.solver.tangential_augmentation :
        (dim == 2 ? 1. : 0.25) * parameters.solver.augmentation;
    const double modulus = parameters.material.stiffest().contact_modulus();
    const double h_k =
      contact_set.min_face_diameter() / parameters.discretization.degree;
    r                        = parameters.solver.augmentation * modulus / h_k;
    r_t                      = r_t_rel * modulus / h_k;
    record.r                 = r;
    record.r_t               = contact_set.friction ? r_t : 0.;
    record.chi               = chi;
    record.n_contact_nodes   = contact_set.n_global_nodes();
    record.n_hanging_contact = contact_set.n_hanging_nodes();
    record.n_corner_contact  = contact_set.n_corner_nodes();
    record.n_uncovered       = contact_set.n_uncovered_nodes();
    record.pairing_time      = contact_set.pairing_wall_time();
    // the applied load toward the obstacle, which the contact force
    // balances when nothing else holds the body in that direction (not
    // b . n: b also holds the lifting of prescribed displacements)
    for (unsigned int c = 0; c < dim; ++c)
      record.normal_load += applied_load[c] * contact_set.normal[c];
    find_free_motions();
    return record;
  }

  template <int dim>
  ContactSystem
  ContactProblem<dim>::contact_system()
  {
    ContactSystem system{system_matrix,
                         mass,
                         system_rhs,
                         homogeneous_constraints,
                         r,
                         r_t,
                         chi,
                         1.,
                         &free_motions,
                         previous_size,
                         same_stiffness};
    system.anchored_at_start = &anchored_at_start;
    system.pressure          = mixed.get();
    return system;
  }

  template <int dim>
  SolutionSize
  ContactProblem<dim>::solution_size() const
  {
    SolutionSize size;
    double       sums[4] = {0., 0., 0., 0.};
    for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
      {
        const double m = contact_set.nodes[s].weight;
        sums[2] += m * contact_set.l1[s];
        sums[3] += contact_set.threshold[s] * contact_set.threshold[s];
        sums[0] += contact_set.l1[s] * contact_set.l1[s];
        sums[1] +=
          m * m *
          (contact_set.l1[s] * contact_set.l1[s] +
           (contact_set.friction ? contact_set.l2[s].norm_square() : 0.));
        size.l1_max = std::max(size.l1_max, contact_set.l1[s]);
      }
    Utilities::MPI::sum(ArrayView<const double>(sums, 4),
                        mpi_communicator,
                        ArrayView<double>(sums, 4));
    size.contact_force = sums[2];
    size.g_norm        = std::sqrt(sums[3]);
    size.l1_norm       = std::sqrt(sums[0]);
    size.force_norm    = std::sqrt(sums[1]);
    size.l1_max        = Utilities::MPI::max(size.l1_max, mpi_communicator);
    // norms of the owned entries (a ghosted vector has none of its own)
    TrilinosWrappers::MPI::Vector owned(locally_owned_dofs, mpi_communicator);
    owned       = solution;
    size.v_norm = owned.l2_norm();
    size.v_max  = owned.linfty_norm();
    return size;
  }

  template <int dim>
  TrilinosWrappers::MPI::Vector
  ContactProblem<dim>::initial_displacement() const
  {
    TrilinosWrappers::MPI::Vector v(locally_owned_dofs, mpi_communicator);
    if (carried)
      v = carried_v;
    constraints.distribute(v);
    return v;
  }

  template <int dim>
  void
  ContactProblem<dim>::set_displacement(const TrilinosWrappers::MPI::Vector &v)
  {
    solution        = v;
    indicator_valid = false;
  }

  template <int dim>
  SolveRecord
  ContactProblem<dim>::solve_contact(TrilinosWrappers::MPI::Vector &v)
  {
    SolveRecord record = prepare_contact_solve();
    report.start_contact_solve(record);

    // from the previous mesh's solution (nested iteration), or from v = 0
    // with the prescribed boundary values and l1 = l2 = 0; a later load
    // step from the last one's state, or its extrapolation from the last
    // two (step_predictor.h)
    v = initial_displacement();
    if (carried_from_step && parameters.load_path.predictor)
      {
        record.predictor = predictor.predict(system_rhs,
                                             scene.obstacle().displacement(),
                                             v,
                                             contact_set);
        if (record.predictor > 0.)
          constraints.distribute(v);
      }
    static_cast<ContactStatistics &>(record) =
      threshold_iteration.solve(contact_system(),
                                contact_set,
                                v,
                                &report,
                                held_by_friction_pressure,
                                !carried          ? WarmStart::cold :
                                carried_from_step ? WarmStart::previous_step :
                                                    WarmStart::previous_mesh);
    return record;
  }

  template <int dim>
  PositionRecord
  ContactProblem<dim>::check_position()
  {
    TimerOutput::Scope   t(computing_timer, "postprocess");
    const PositionRecord record =
      check_deformed_position(mapping, dof_handler, solution, scene);
    for (const std::string &warning : record.warnings)
      report.warning(warning);
    return record;
  }

  template <int dim>
  ErrorNorms
  ContactProblem<dim>::postprocess() const
  {
    TimerOutput::Scope t(computing_timer, "postprocess");
    const ErrorNorms   norms = compute_error_norms(mapping,
                                                 dof_handler,
                                                 solution,
                                                 scene.exact_displacement());
    if (!std::isfinite(norms.error_L2) || !std::isfinite(norms.error_H1_semi))
      throw InputError("The entry <Exact solution/Displacement> is not a "
                       "finite number (NaN or infinity) at some point of "
                       "the body: '" +
                         parameters.exact.displacement + "'.",
                       exit_invalid_value);
    return norms;
  }

  template <int dim>
  const Vector<float> &
  ContactProblem<dim>::refinement_indicator()
  {
    // computed once per solution: the output and the marking both use it
    if (indicator_valid)
      return indicator;
    indicator_valid = true;
    const std::set<types::boundary_id> contact_ids =
      scene.effects().contact ? scene.contact_ids() :
                                std::set<types::boundary_id>();
    indicator = compute_indicator<dim>(
      {mapping,
       dof_handler,
       solution,
       contact_set,
       contact_ids,
       parameters,
       parameters.refinement.values,
       [this] {
         TrilinosWrappers::MPI::Vector multipliers, threshold;
         multiplier_fields(multipliers, threshold);
         return multipliers;
       },
       mixed ? mixed->pressure_at(mapping) : PressureAt<dim>()});
    return indicator;
  }

  template <int dim>
  void
  ContactProblem<dim>::refine_mesh()
  {
    TimerOutput::Scope          t(computing_timer, "refine mesh");
    const RefinementParameters &refinement = parameters.refinement;
    const bool simplex = scene.discretization().mesh_is_replicated();
    if (refinement_indicator_kind(refinement.strategy).refines_every_cell())
      {
        // (a replicated mesh of simplices refines the cells that every
        // rank flags alike: all of them are flagged)
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() || simplex)
            cell->set_refine_flag();
      }
    else // the same cells on any number of ranks
      mark_fixed_number(triangulation,
                        refinement_indicator(),
                        indicator_scale(mapping, dof_handler, solution),
                        refinement.refine_fraction,
                        refinement.coarsen_fraction);

    // Nested iteration: v and the multiplier fields go with the cells.
    // The inputs must live until the refinement is executed.
    TrilinosWrappers::MPI::Vector multipliers, threshold;
    if (refinement.nested_iteration)
      {
        std::vector<const TrilinosWrappers::MPI::Vector *> fields = {&solution};
        if (scene.effects().contact)
          {
            multiplier_fields(multipliers, threshold);
            fields.push_back(&multipliers);
            fields.push_back(&threshold);
          }
        transfer = std::make_unique<FieldTransfer<dim>>(dof_handler);
        triangulation.prepare_coarsening_and_refinement();
        transfer->prepare(fields);
        if (mixed)
          mixed->prepare_transfer();
      }
    triangulation.execute_coarsening_and_refinement();
  }

  template class ContactProblem<2>;
  template class ContactProblem<3>;
} // namespace dualcontact
