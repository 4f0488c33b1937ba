// ContactProblem: the later steps of a load path. A step starts from the
// state the step before reached, moves the loads to its time, solves (with
// step control's retries), and is recorded and written; a failure names
// the step and its time.
#include <deal.II/base/utilities.h>

#include <dualcontact/contact_problem.h>
#include <dualcontact/input_error.h>
#include <dualcontact/parameter_helpers.h>
#include <dualcontact/postprocess.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <set>
#include <sstream>
#include <string>

namespace dualcontact
{
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
    make_constraints(/*contact_set_built=*/scene.effects().contact);
    if (scene.effects().contact)
      contact_set.place_obstacle(scene.obstacle(), mpi_communicator);
  }

  template <int dim>
  void
  ContactProblem<dim>::solve_step(StepControl &control, CycleResult &result)
  {
    // the state the step starts from, kept for a retry: the step's first
    // guess and the multipliers, threshold, predictor and (in the mixed
    // formulation) pressure it starts from
    const bool adaptive = parameters.load_path.adaptive_steps;
    TrilinosWrappers::MPI::Vector       start_solution, start_v, start_p;
    std::unique_ptr<ContactSet<dim>>    start_contact;
    std::unique_ptr<StepPredictor<dim>> start_predictor;
    const bool                          start_carried = carried;
    if (adaptive)
      {
        start_solution  = solution;
        start_v         = carried_v;
        start_contact   = std::make_unique<ContactSet<dim>>(contact_set);
        start_predictor = std::make_unique<StepPredictor<dim>>(predictor);
        if (mixed)
          start_p = mixed->pressure;
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
          solution    = start_solution;
          carried_v   = start_v;
          carried     = start_carried;
          contact_set = *start_contact;
          predictor   = *start_predictor;
          if (mixed)
            mixed->pressure = start_p;
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
                         parameters.material,
                         mixed.get());
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

  template std::string
  ContactProblem<2>::step_failure(const unsigned int step,
                                  const double       t) const;
  template StepRecord
  ContactProblem<2>::start_step(const unsigned int step,
                                const StepControl &control,
                                CycleResult       &result);
  template void
  ContactProblem<2>::set_slip_origins(const StepRecord &step);
  template void
  ContactProblem<2>::move_to_step_time();
  template void
  ContactProblem<2>::solve_step(StepControl &control, CycleResult &result);
  template StepRecord
  ContactProblem<2>::step_record(const unsigned int step,
                                 const StepControl *control) const;
  template void
  ContactProblem<2>::finish_step(CycleResult &result);
  template std::string
  ContactProblem<3>::step_failure(const unsigned int step,
                                  const double       t) const;
  template StepRecord
  ContactProblem<3>::start_step(const unsigned int step,
                                const StepControl &control,
                                CycleResult       &result);
  template void
  ContactProblem<3>::set_slip_origins(const StepRecord &step);
  template void
  ContactProblem<3>::move_to_step_time();
  template void
  ContactProblem<3>::solve_step(StepControl &control, CycleResult &result);
  template StepRecord
  ContactProblem<3>::step_record(const unsigned int step,
                                 const StepControl *control) const;
  template void
  ContactProblem<3>::finish_step(CycleResult &result);
} // namespace dualcontact
