// ContactProblem, checkpoint and restart of a load path (doc/theory.md §11,
// "Restart"): the mesh with u, u^{n-1}, the multipliers and the threshold
// on its cells in p4est's files, and the path's scalars in state.txt
// (checkpoint.h).
#include <deal.II/base/utilities.h>

#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria_base.h>

#include <dualcontact/checkpoint.h>
#include <dualcontact/contact_problem.h>
#include <dualcontact/input_error.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace dualcontact
{
  namespace
  {
    // the entries a resumed run may set otherwise: where and how much it
    // tells, and how often it writes checkpoints
    const std::set<std::string> entries_free_on_resume = {
      "Output/Directory",
      "Output/Verbosity",
      "Output/Print timing",
      "Output/Checkpoint interval"};

    template <int dim>
    parallel::DistributedTriangulationBase<dim> &
    forest_of(parallel::TriangulationBase<dim> &triangulation)
    {
      auto *forest =
        dynamic_cast<parallel::DistributedTriangulationBase<dim> *>(
          &triangulation);
      if (forest == nullptr)
        throw InputError(
          "Checkpoints (<Output/Checkpoint interval>, --resume) need a mesh "
          "of quadrilaterals or hexahedra, kept as p4est's forest; this "
          "scene's mesh is of triangles or tetrahedra.",
          exit_inconsistent);
      return *forest;
    }
  } // namespace

  template <int dim>
  void
  ContactProblem<dim>::write_checkpoint(const StepRecord  &step,
                                        const StepControl &control)
  {
    TimerOutput::Scope t(computing_timer, "output results");
    namespace fs                = std::filesystem;
    const std::string directory = parameters.output.directory;
    const std::string folder    = checkpoint_folder(directory);
    const std::string building  = folder + ".new";
    const bool root = Utilities::MPI::this_mpi_process(mpi_communicator) == 0;
    if (root)
      {
        fs::remove_all(building);
        fs::create_directories(building);
      }
    MPI_Barrier(mpi_communicator);

    // the fields, ghosted, on the cells of the mesh: u^n, u^{n-1} (0 where
    // there is none), the multipliers and the threshold
    using Vector       = TrilinosWrappers::MPI::Vector;
    const auto ghosted = [this](const Vector &owned) {
      Vector v(locally_owned_dofs, locally_relevant_dofs, mpi_communicator);
      v = owned;
      return v;
    };
    Vector before(locally_owned_dofs, mpi_communicator);
    if (step_start_u.size() == solution.size())
      before = step_start_u;
    std::vector<Vector> fields = {solution, ghosted(before)};
    if (scene.effects().contact)
      {
        Vector multipliers(locally_owned_dofs, mpi_communicator);
        Vector threshold(locally_owned_dofs, mpi_communicator);
        contact_set.write_fields(multipliers, threshold);
        fields.push_back(ghosted(multipliers));
        fields.push_back(ghosted(threshold));
      }
    {
      std::vector<const Vector *> pointers;
      for (const Vector &field : fields)
        pointers.push_back(&field);
      parallel::distributed::SolutionTransfer<dim, Vector> transfer(
        dof_handler);
      transfer.prepare_for_serialization(pointers);
      forest_of(triangulation).save(building + "/mesh");
    }

    // the scalars of the path and of the report
    CheckpointRecord record;
    record.set("step", std::to_string(step.step));
    record.set("time", step.time);
    record.set("ranks",
               std::to_string(
                 Utilities::MPI::n_mpi_processes(mpi_communicator)));
    record.set("step_control", control.state());
    record.set("has_start_u",
               std::to_string(step_start_u.size() == solution.size()));
    record.set("last_step_start", last_step_start);
    record.set("dissipated", dissipated);
    record.set("size_l1_norm", previous_size.l1_norm);
    record.set("size_l1_max", previous_size.l1_max);
    record.set("size_v_norm", previous_size.v_norm);
    record.set("size_v_max", previous_size.v_max);
    record.set("size_force_norm", previous_size.force_norm);
    record.set("size_contact_force", previous_size.contact_force);
    record.set("mesh",
               std::to_string(path_mesh.cycle) + " " +
                 std::to_string(path_mesh.n_cells) + " " +
                 std::to_string(path_mesh.n_dofs));
    record.set("total_time", report.total_time());
    record.set("loop_figure", report.loop_figure_state());
    for (const auto &[name, records] : pvd_records)
      {
        std::ostringstream text;
        text << std::setprecision(17) << records.size();
        for (const auto &[time, file] : records)
          text << ' ' << time << ' ' << file;
        record.set("pvd_" + name, text.str());
      }
    if (root)
      {
        record.write(building + "/state.txt");
        std::ofstream(building + "/parameters.prm")
          << parameters.parameter_file;
        // the new checkpoint replaces the old one only now that it is whole
        fs::remove_all(folder);
        fs::rename(building, folder);
      }
    MPI_Barrier(mpi_communicator);

    // The run goes on from what it wrote, as a resumed run does: the mesh
    // read back numbers its cells, and so its DoFs, in the order of the
    // forest, which a mesh adapted at every step does not keep (its cells'
    // order depends on which were coarsened when), and the order changes
    // the AMG and CG's rounding. Both runs then give the same numbers.
    load_mesh_and_fields(folder, record);
  }

  template <int dim>
  void
  ContactProblem<dim>::load_mesh_and_fields(const std::string      &folder,
                                            const CheckpointRecord &record)
  {
    // the coarse mesh, refined as the checkpoint's forest, and set up at
    // the time the run set it up (the first step's, or the step's own on a
    // mesh adapted for it), then at the checkpoint's
    const double time = record.number("time");
    scene.set_time(
      parameters.load_path.adapt_at_every_step ? time : step_times.front());
    triangulation.clear();
    scene.create_coarse_mesh(triangulation);
    forest_of(triangulation).load(folder + "/mesh");
    std::istringstream mesh(record.text("mesh"));
    mesh >> path_mesh.cycle;
    setup_system(path_mesh.cycle);
    mesh >> path_mesh.n_cells >> path_mesh.n_dofs;
    AssertThrow(path_mesh.n_dofs == dof_handler.n_dofs() &&
                  path_mesh.n_cells == triangulation.n_global_active_cells(),
                ExcMessage("The checkpoint's mesh does not have the cells "
                           "and DoFs that its state.txt says."));
    scene.set_time(time);
    move_to_step_time();

    // the fields on it, the multipliers as they were (not projected: a
    // rounding error above the threshold stays)
    using Vector                = TrilinosWrappers::MPI::Vector;
    const bool          contact = scene.effects().contact;
    std::vector<Vector> fields(contact ? 4 : 2,
                               Vector(locally_owned_dofs, mpi_communicator));
    std::vector<Vector *> pointers;
    for (Vector &field : fields)
      pointers.push_back(&field);
    parallel::distributed::SolutionTransfer<dim, Vector> transfer(dof_handler);
    transfer.deserialize(pointers);
    solution = fields[0];
    step_start_u.clear();
    if (record.text("has_start_u") == "1")
      {
        step_start_u.reinit(locally_owned_dofs,
                            locally_relevant_dofs,
                            mpi_communicator);
        step_start_u = fields[1];
      }
    if (contact)
      contact_set.read_fields(fields[2], fields[3], false);
    carried         = false;
    indicator_valid = false;
    // the next step without the predictor, with a new preconditioner
    predictor.clear();
    at_a_checkpoint = true;
  }

  template <int dim>
  unsigned int
  ContactProblem<dim>::load_checkpoint(StepControl &control)
  {
    TimerOutput::Scope t(computing_timer, "load checkpoint");
    const std::string  directory = parameters.output.directory;
    const std::string  folder    = checkpoint_folder(directory);
    CheckpointRecord   record;
    if (!record.read(folder + "/state.txt"))
      throw InputError("There is no checkpoint to resume from in '" +
                         directory +
                         "' (its folder checkpoint/ with state.txt): a run "
                         "writes one after every <Output/Checkpoint "
                         "interval>-th step of its load path.",
                       exit_cannot_read_file);
    std::ostringstream saved;
    saved << std::ifstream(folder + "/parameters.prm").rdbuf();
    const std::string difference = first_difference(parameters.parameter_file,
                                                    saved.str(),
                                                    entries_free_on_resume);
    if (!difference.empty())
      throw InputError("The checkpoint in '" + directory +
                         "' is of another scene: " + difference +
                         ". Resume with the parameters it was written with.",
                       exit_inconsistent);
    const unsigned int ranks = std::stoul(record.text("ranks"));
    if (ranks != Utilities::MPI::n_mpi_processes(mpi_communicator))
      throw InputError(
        "The checkpoint in '" + directory + "' was written on " +
          std::to_string(ranks) + " MPI ranks, and this run has " +
          std::to_string(Utilities::MPI::n_mpi_processes(mpi_communicator)) +
          ": resume it on " + std::to_string(ranks) + " (mpirun -np " +
          std::to_string(ranks) +
          "), which gives the same numbers as a run that was not stopped.",
        exit_inconsistent);

    load_mesh_and_fields(folder, record);
    probes.check_inside(mapping, triangulation);

    // the path's state, and the report's
    const unsigned int step = std::stoul(record.text("step"));
    control.load(record.text("step_control"));
    last_step_start             = record.number("last_step_start");
    dissipated                  = record.number("dissipated");
    previous_size.l1_norm       = record.number("size_l1_norm");
    previous_size.l1_max        = record.number("size_l1_max");
    previous_size.v_norm        = record.number("size_v_norm");
    previous_size.v_max         = record.number("size_v_max");
    previous_size.force_norm    = record.number("size_force_norm");
    previous_size.contact_force = record.number("size_contact_force");
    pvd_records.clear();
    for (const auto &[key, value] : record.with_prefix("pvd_"))
      {
        std::istringstream in(value);
        std::size_t        n = 0;
        in >> n;
        auto &records = pvd_records[key.substr(4)];
        for (std::size_t i = 0; i < n; ++i)
          {
            double      pvd_time = 0.;
            std::string file;
            in >> pvd_time >> file;
            records.emplace_back(pvd_time, file);
          }
      }
    if (!probes.empty() &&
        Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      probes.resume_step_csv(directory + "/probes_steps.csv", step);
    report.resume(step,
                  record.number("time"),
                  record.number("total_time"),
                  record.text("loop_figure"));
    return step;
  }

  template void
  ContactProblem<2>::write_checkpoint(const StepRecord  &step,
                                      const StepControl &control);
  template void
  ContactProblem<3>::write_checkpoint(const StepRecord  &step,
                                      const StepControl &control);
  template unsigned int
  ContactProblem<2>::load_checkpoint(StepControl &control);
  template unsigned int
  ContactProblem<3>::load_checkpoint(StepControl &control);
} // namespace dualcontact
