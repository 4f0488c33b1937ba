// ContactProblem: run() and its phases, from the mesh to the refinement.
// The equilibrium checks, the measurements, the output and the rigid
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
      , probes(parameters.output.probe_points)
  {}

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
  std::string
  ContactProblem<dim>::step_failure(const unsigned int step,
                                    const double       t) const
  {
    return "At load step " + std::to_string(step) +
           (parameters.load_path.adaptive_steps ?
              std::string() :
              " of " + std::to_string(step_times.size())) +
           " (t = " + number_text(t) +
           "; the steps before "
           "are written, steps.csv has them): ";
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
  StepRecord
  ContactProblem<dim>::start_step(const unsigned int step,
                                  const StepControl &control,
                                  CycleResult       &result)
  {
    // the state the step before reached: u^{n-1}, its size, and the
    // obstacle there. A size that the step before had next to none of (a
    // step without load, after the body left the contact) keeps the value
    // of the last step that had it: the relative tests of this step then
    // still have the path's scale, however many steps without load come in
    // a row (doc/theory.md §11).
    previous_obstacle_displacement = scene.obstacle().displacement();
    const SolutionSize now         = solution_size();
    if (step == 1)
      previous_size = SolutionSize();
    const auto carry = [](const double now, const double before) {
      return now > 1e-10 * before ? now : before;
    };
    previous_size.l1_norm    = carry(now.l1_norm, previous_size.l1_norm);
    previous_size.l1_max     = carry(now.l1_max, previous_size.l1_max);
    previous_size.g_norm     = carry(now.g_norm, previous_size.g_norm);
    previous_size.v_norm     = carry(now.v_norm, previous_size.v_norm);
    previous_size.v_max      = carry(now.v_max, previous_size.v_max);
    previous_size.force_norm = carry(now.force_norm, previous_size.force_norm);
    previous_size.contact_force =
      carry(now.contact_force, previous_size.contact_force);
    const StepRecord record = step_record(step, &control);
    scene.set_time(record.time);
    report.start_step(record);

    if (parameters.load_path.adapt_at_every_step)
      {
        predictor.clear(); // a new mesh: nothing to extrapolate on it
        // v, the multipliers and the threshold go with the cells; u^{n-1}
        // is the carried v
        refine_mesh();
        result.mesh     = setup_system(parameters.refinement.n_cycles);
        result.transfer = transfer_fields();
        path_mesh       = result.mesh;
        step_start_u.reinit(locally_owned_dofs,
                            locally_relevant_dofs,
                            mpi_communicator);
        step_start_u = carried_v;
        step_before_u.clear();
      }
    else
      {
        // the same mesh: the multipliers as they are
        result.mesh = path_mesh;
        move_to_step_time();
        carried_v.reinit(locally_owned_dofs, mpi_communicator);
        carried_v                  = solution;
        carried                    = true;
        result.transfer.warm_start = true;
        // u^{n-2}: the step before's start, or the undeformed body at t = 0
        if (step == 2 || step_start_u.size() != solution.size())
          {
            step_before_u.reinit(locally_owned_dofs,
                                 locally_relevant_dofs,
                                 mpi_communicator);
            step_before_time = 0.;
          }
        else
          {
            step_before_u    = step_start_u;
            step_before_time = last_step_start;
          }
        step_start_u.reinit(locally_owned_dofs,
                            locally_relevant_dofs,
                            mpi_communicator);
        step_start_u   = solution;
        same_stiffness = !at_a_checkpoint;
      }
    at_a_checkpoint   = false;
    carried_from_step = true;
    set_slip_origins(record);
    return record;
  }

  template <int dim>
  void
  ContactProblem<dim>::set_slip_origins(const StepRecord &step)
  {
    if (!scene.effects().contact)
      return;
    const Tensor<1, dim> obstacle_step =
      scene.obstacle().displacement() - previous_obstacle_displacement;
    contact_set.set_slip_origin(step_start_u, obstacle_step);
    // the free motion of the step, u^{n-1} + (t - t_{n-1}) (u^{n-1} -
    // u^{n-2}) / (t_{n-1} - t_{n-2}): where it closes a node's gap, the node
    // touches during the step, and its slip counts from there
    const double t_start = step.time - step.step_size;
    if (step_before_u.size() == 0 || obstacle_step.norm() > 0. ||
        !(t_start > step_before_time))
      return;
    const double factor = step.step_size / (t_start - step_before_time);
    TrilinosWrappers::MPI::Vector owned(locally_owned_dofs, mpi_communicator);
    TrilinosWrappers::MPI::Vector before(locally_owned_dofs, mpi_communicator);
    owned  = step_start_u;
    before = step_before_u;
    owned.sadd(1. + factor, -factor, before);
    TrilinosWrappers::MPI::Vector u_free(locally_owned_dofs,
                                         locally_relevant_dofs,
                                         mpi_communicator);
    u_free = owned;
    contact_set.set_touch_origin(step_start_u, u_free);
  }

  template <int dim>
  void
  ContactProblem<dim>::move_to_step_time()
  {
    make_constraints(scene.effects().contact && contact_set.has_pairs());
    if (scene.effects().contact)
      contact_set.place_obstacle(scene, mpi_communicator);
  }

  template <int dim>
  void
  ContactProblem<dim>::solve_step(StepControl &control, CycleResult &result)
  {
    // the state the step starts from, kept for a retry: the step's first
    // guess and the multipliers, threshold and predictor it starts from
    const bool adaptive = parameters.load_path.adaptive_steps;
    TrilinosWrappers::MPI::Vector       start_solution, start_v;
    std::unique_ptr<ContactSet<dim>>    start_contact;
    std::unique_ptr<StepPredictor<dim>> start_predictor;
    const bool                          start_carried = carried;
    if (adaptive)
      {
        start_solution  = solution;
        start_v         = carried_v;
        start_contact   = std::make_unique<ContactSet<dim>>(contact_set);
        start_predictor = std::make_unique<StepPredictor<dim>>(predictor);
      }
    const unsigned int step = result.step.step;
    for (;;)
      try
        {
          solve_and_measure(result);
          return;
        }
      catch (const InputError &error)
        {
          // input that fails at this time (a load the obstacle cannot hold,
          // an expression that is not finite), which no smaller step
          // helps: the steps before are written, and the message says
          // which step failed
          throw InputError(step_failure(step, result.step.time) + error.what(),
                           error.code);
        }
      catch (const std::exception &error)
        {
          std::string why = error.what();
          if (const auto *exception =
                dynamic_cast<const ExceptionBase *>(&error))
            {
              std::ostringstream info;
              exception->print_info(info);
              why = Utilities::trim(info.str());
            }
          if (!control.cut())
            {
              report.warning(
                step_failure(step, result.step.time) + "the solve failed" +
                (adaptive ? " at the minimum step (<Load path/Minimum "
                            "step> = " +
                              number_text(control.minimum_step()) + ")." :
                            " (<Load path/Step control> = adaptive tries a "
                            "failed step again in smaller steps)."));
              throw;
            }
          // the step again, smaller, from the state it started from
          report.cut_step(result.step,
                          why.substr(0, why.find(" Likely causes")),
                          control.next_time());
          solution        = start_solution;
          carried_v       = start_v;
          carried         = start_carried;
          contact_set     = *start_contact;
          predictor       = *start_predictor;
          indicator_valid = false;
          same_stiffness  = false; // a new AMG: the failed try's is no guide
          CycleResult retry;       // on the step's mesh, as carried to it
          retry.mesh              = result.mesh;
          retry.transfer          = result.transfer;
          const StepRecord record = step_record(step, &control);
          retry.step              = record;
          result                  = retry;
          scene.set_time(record.time);
          report.start_step(record);
          move_to_step_time();
          set_slip_origins(record);
        }
      catch (...)
        {
          report.warning(step_failure(step, result.step.time) +
                         "the solve failed.");
          throw;
        }
  }

  template <int dim>
  StepRecord
  ContactProblem<dim>::step_record(const unsigned int step,
                                   const StepControl *control) const
  {
    StepRecord record;
    record.step      = step;
    record.n_steps   = step_times.size();
    record.time      = control ? control->next_time() : step_times.front();
    record.listed    = control ? control->next_listed() : 1;
    record.step_size = control ? control->next_step_size() : step_times.front();
    record.cuts      = control ? control->cuts() : 0;
    return record;
  }

  template <int dim>
  void
  ContactProblem<dim>::finish_step(CycleResult &result)
  {
    if (scene.effects().contact && parameters.load_path.predictor)
      predictor.add_step(solution,
                         contact_set,
                         system_rhs,
                         scene.obstacle().displacement());
    dissipated             = result.step.dissipation_total;
    last_step_start        = result.step.time - result.step.step_size;
    const Tensor<1, dim> U = scene.obstacle().displacement();
    for (unsigned int c = 0; c < dim; ++c)
      result.step.obstacle_displacement[c] = U[c];
    // where the loaded boundaries went, and the probes, at every step
    std::set<types::boundary_id> loaded =
      scene.ids_with(BoundaryCondition::traction);
    for (const types::boundary_id id : scene.ids_with(BoundaryCondition::fixed))
      loaded.insert(id);
    result.step.boundary_displacement =
      mean_boundary_displacements(mapping, dof_handler, solution, loaded);
    const StepRecord &step = result.step;
    probes.evaluate_step(step.step,
                         step.time,
                         mapping,
                         dof_handler,
                         solution,
                         parameters.material);
    if (!probes.empty() &&
        Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      probes.append_step_csv(parameters.output.directory + "/probes_steps.csv");
    // the fields at the listed times: every <Output interval>-th and the
    // last (adaptive control's sub-steps in between have their rows only)
    if (step.listed > 0 &&
        ((step.listed - 1) % parameters.load_path.output_interval == 0 ||
         step.listed == step.n_steps))
      output_step(step);
    report.end_step(result);
  }

  template <int dim>
  void
  ContactProblem<dim>::make_grid()
  {
    TimerOutput::Scope t(computing_timer, "make grid");
    // The size of the finest mesh is checked against the memory before
    // the coarse mesh is built (a box here, a mesh file's mesh in the
    // constructor), before each refinement that builds the initial mesh,
    // and once it is built: a scene refined far too often, or a box of far
    // too many cells, stops at once, not with std::bad_alloc after minutes.
    const RunSizeCheck size(parameters, mpi_communicator, scene.cell_kind());
    scene.create_mesh(triangulation, [&size](const double n_cells) {
      size.check(n_cells, false);
    });
    size.check(triangulation.n_global_active_cells(), true);
    size.warn(triangulation.n_global_active_cells());
    // a mapping of degree k follows the manifolds: a mesh file without them
    // stays the polygon of its vertices
    const GeometryParameters &geometry = parameters.geometry;
    if (parameters.discretization.degree > 1 && geometry.type == "mesh file" &&
        geometry.manifolds.empty() &&
        Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      std::cerr << "dualcontact: warning: <Geometry/Manifolds> is empty: the "
                   "boundary of the mesh file stays the polygon of its "
                   "faces at <Discretization/Polynomial degree> "
                << parameters.discretization.degree
                << " as at 1; name its curved parts there for the mapping to "
                   "follow them."
                << std::endl;
    scene.check_rigid_motions(triangulation);
    check_initial_position(triangulation, scene);
    // a checkpoint keeps the mesh as p4est's forest
    if (parameters.output.checkpoint_interval > 0 && step_times.size() > 1 &&
        scene.discretization().mesh_is_replicated())
      throw InputError(
        "<Output/Checkpoint interval> needs a mesh of quadrilaterals or "
        "hexahedra (a checkpoint keeps p4est's forest); this scene's mesh is "
        "of triangles or tetrahedra: set it to 0.",
        exit_inconsistent);
    // every cell has a material: once <Material/Materials by id> lists
    // some, a cell of an id it does not name (and not 0) is bad input
    types::material_id missing = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() &&
          !parameters.material.has(cell->material_id()))
        missing = std::max<types::material_id>(missing, cell->material_id());
    missing = Utilities::MPI::max(missing, mpi_communicator);
    if (missing > 0)
      throw InputError("The mesh has cells of material id " +
                         std::to_string(missing) +
                         ", which <Material/Materials by id> does not list "
                         "(id 0 takes <Material/Young's modulus> and "
                         "<Poisson's ratio>): give it its 'E, nu'.",
                       exit_inconsistent);
    // a probe outside the body is bad input: found before the first solve
    probes.check_inside(mapping, triangulation);
  }

  template <int dim>
  MeshRecord
  ContactProblem<dim>::setup_system(const unsigned int cycle)
  {
    TimerOutput::Scope t(computing_timer, "setup system");
    dof_handler.distribute_dofs(fe);
    // the dim DoFs of each support point next to each other, as the AMG
    // takes them (elasticity.cc); FE_Q(1) numbers them so already, FE_Q(k)
    // numbers an edge's or face's inner DoFs component by component
    if (fe.degree > 1)
      DoFRenumbering::support_point_wise(dof_handler);
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);

    make_constraints();

    // the contact nodes, their weights and gaps (doc/theory.md §4), and on
    // a pair of bodies their master nodes (doc/two_bodies.md)
    if (scene.effects().contact)
      {
        contact_set.setup(
          mapping, dof_handler, hanging_node_constraints, constraints, scene);
        AssertThrow(contact_set.n_global_nodes() > 0,
                    ExcMessage("The contact boundary has no contact nodes."));
        if (contact_set.has_pairs())
          make_constraints(true);
      }

    // The elements' couplings, and on a pair those of each slave node with
    // its master nodes, rows of other ranks included: the Newton matrix
    // adds its contact terms there (newton_solver.cc).
    const bool pairs = scene.effects().contact && contact_set.has_pairs();
    IndexSet   rows  = locally_relevant_dofs;
    if (pairs)
      rows.add_indices(contact_set.coupled_rows(constraints));
    DynamicSparsityPattern dsp(rows);
    DoFTools::make_sparsity_pattern(dof_handler,
                                    dsp,
                                    constraints,
                                    /*keep_constrained_dofs=*/false);
    if (pairs)
      contact_set.add_pair_couplings(dsp, constraints);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               locally_owned_dofs,
                                               mpi_communicator,
                                               rows);
    system_matrix.reinit(locally_owned_dofs,
                         locally_owned_dofs,
                         dsp,
                         mpi_communicator);
    if (scene.effects().contact)
      mass.diagonal.reinit(locally_owned_dofs, mpi_communicator);
    system_rhs.reinit(locally_owned_dofs, mpi_communicator);
    solution.reinit(locally_owned_dofs,
                    locally_relevant_dofs,
                    mpi_communicator);
    return {cycle, triangulation.n_global_active_cells(), dof_handler.n_dofs()};
  }

  template <int dim>
  void
  ContactProblem<dim>::make_constraints(const bool couple_masters)
  {
    // A slave node's coupling adds its forces and its Newton terms at the
    // master DoFs through these constraints. A master DoF off this rank's
    // cells that a slider or a clamp holds (the master body's end on a
    // symmetry plane) must be known as constrained here too, or its force
    // goes into an equation that the solve does not have: the Newton
    // gradient then keeps a part that no step reduces. Its owner has the
    // constraint and sends it.
    IndexSet relevant = locally_relevant_dofs;
    if (couple_masters)
      relevant.add_indices(contact_set.master_dofs(dof_handler.n_dofs()));
    hanging_node_constraints.clear();
    hanging_node_constraints.reinit(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler,
                                            hanging_node_constraints);
    hanging_node_constraints.close();

    // Hanging nodes first, then Dirichlet, then sliders: later ones do not
    // overwrite earlier ones, which keeps the space conforming.
    const Functions::ZeroFunction<dim> zero(dim);
    const auto sliders = scene.ids_with(BoundaryCondition::normal_fixed);
    for (const bool homogeneous : {false, true})
      {
        AffineConstraints<double> &c =
          homogeneous ? homogeneous_constraints : constraints;
        c.clear();
        c.reinit(relevant);
        c.merge(hanging_node_constraints,
                AffineConstraints<double>::no_conflicts_allowed,
                /*allow_different_local_lines=*/couple_masters);
        for (const types::boundary_id id :
             scene.ids_with(BoundaryCondition::fixed))
          VectorTools::interpolate_boundary_values(
            mapping,
            dof_handler,
            id,
            homogeneous ? static_cast<const Function<dim> &>(zero) :
                          scene.displacement(id),
            c);
        if (!sliders.empty())
          VectorTools::compute_no_normal_flux_constraints(
            dof_handler, 0, sliders, c, mapping);
        if (couple_masters)
          c.make_consistent_in_parallel(locally_owned_dofs,
                                        relevant,
                                        mpi_communicator);
        c.close();
      }
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
    record.cg_iterations = elastic_solver.solve(system_matrix, v, system_rhs);
    constraints.distribute(v);
    return record;
  }

  template <int dim>
  SolveRecord
  ContactProblem<dim>::prepare_contact_solve()
  {
    SolveRecord record;
    held_by_friction_pressure = check_equilibrium();

    // r is relative to (lambda + 2 mu) / h_k, so that the Uzawa steps do
    // not depend on the units, the mesh size or the degree; the P-wave
    // modulus lambda + 2 mu rather than E, because it follows the stiffness
    // of a nearly incompressible (locked) material, for which r_rel E / h_k
    // is far too small. h_k = h_C / k is the spacing of the contact nodes:
    // at degree k the slowest multiplier mode lives on one node spacing, and
    // r scaled with the faces alone slows the Uzawa rate with k
    // (doc/theory.md §5).
    // The friction terms have their own r_t, scaled alike: by default r in
    // 2D and r / 4 in 3D, where friction terms as large as r make the Newton
    // matrices hard (doc/theory.md §5).
    const double r_t_rel =
      parameters.solver.tangential_augmentation > 0. ?
        parameters.solver.tangential_augmentation :
        (dim == 2 ? 1. : 0.25) * parameters.solver.augmentation;
    const double modulus = parameters.material.stiffest().p_wave_modulus();
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
    indicator =
      compute_indicator<dim>({mapping,
                              dof_handler,
                              solution,
                              contact_set,
                              contact_ids,
                              parameters,
                              parameters.refinement.values,
                              [this] {
                                TrilinosWrappers::MPI::Vector multipliers,
                                  threshold;
                                multiplier_fields(multipliers, threshold);
                                return multipliers;
                              }});
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
      }
    triangulation.execute_coarsening_and_refinement();
  }

  template class ContactProblem<2>;
  template class ContactProblem<3>;
} // namespace dualcontact
