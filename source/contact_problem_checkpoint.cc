// ContactProblem, checkpoint and restart of a load path (doc/theory.md §11,
// "Restart"): the mesh with u, u^{n-1}, the multipliers and the threshold
// (and in the mixed formulation p) on its cells in p4est's files, and the
// path's scalars in state.txt (checkpoint.h).
#include <deal.II/base/utilities.h>

#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria_base.h>

#include <dualcontact/checkpoint.h>
#include <dualcontact/contact_problem.h>
#include <dualcontact/input_error.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <vector>

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
    // the entries named first where they differ, whatever else does: the
    // formulation decides which fields a checkpoint holds (the mixed
    // formulation's pressure beside the displacement)
    const std::vector<std::string> entries_compared_first = {
      "Material/Formulation"};

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

    // The forest's files with their sizes and CRC-32, which a resumed run
    // checks before deal.II and p4est read them: p4est stops the whole
    // program on a file it cannot read, and deal.II takes what it reads for
    // the sizes of the fields, where a file cut short, or of zeros after a
    // crash, is a damaged checkpoint.
    std::string
    forest_files(const std::string &building)
    {
      namespace fs = std::filesystem;
      std::map<std::string, std::uintmax_t> sizes;
      for (const auto &entry : fs::directory_iterator(building))
        if (entry.path().filename().string().compare(0, 4, "mesh") == 0)
          sizes[entry.path().filename().string()] = entry.file_size();
      std::string files;
      for (const auto &[name, size] : sizes)
        files += (files.empty() ? "" : " ") + name + " " +
                 std::to_string(size) + " " +
                 file_checksum(building + "/" + name);
      return files;
    }

    /** The pvd files' records: a count, then as many times and files. */
    std::map<std::string, std::vector<std::pair<double, std::string>>>
    saved_pvd_records(const CheckpointRecord &record)
    {
      std::map<std::string, std::vector<std::pair<double, std::string>>>
        saved_pvd;
      for (const auto &[key, value] : record.with_prefix("pvd_"))
        {
          const std::vector<std::string> words = record.words(key);
          unsigned long long             n     = 0;
          if (!read_whole_number(words[0], n) || words.size() != 1 + 2 * n)
            throw record.damaged(key,
                                 "not a count and as many times and files");
          auto &records = saved_pvd[key.substr(4)];
          for (std::size_t i = 1; i < words.size(); i += 2)
            {
              double pvd_time = 0.;
              if (!read_number(words[i], pvd_time) || words[i + 1].empty())
                throw record.damaged(key,
                                     "not a count and as many times and files");
              records.emplace_back(pvd_time, words[i + 1]);
            }
        }
      return saved_pvd;
    }

    /**
     * The forest's files, each as it was written: its size and CRC-32
     * (p4est stops the program on a file it cannot read, deal.II trusts
     * the sizes it reads from the fields' file). Rank 0 reads them and
     * tells the others what it found, so that all throw together.
     */
    void
    check_forest_files(const CheckpointRecord &record,
                       const std::string      &folder,
                       const MPI_Comm          mpi_communicator)
    {
      namespace fs                         = std::filesystem;
      const std::vector<std::string> files = record.words("files");
      std::set<std::string>          names;
      for (std::size_t i = 0; i + 2 < files.size(); i += 3)
        {
          unsigned long long size = 0;
          if (files[i].compare(0, 4, "mesh") != 0 ||
              files[i].find('/') != std::string::npos ||
              !read_whole_number(files[i + 1], size) ||
              files[i + 2].size() != 8 ||
              files[i + 2].find_first_not_of("0123456789abcdef") !=
                std::string::npos)
            break;
          names.insert(files[i]);
        }
      if (files.size() % 3 != 0 || names.size() != files.size() / 3 ||
          names.count("mesh") == 0 || names.count("mesh.info") == 0)
        throw record.damaged("files",
                             "not the forest's files mesh, mesh.info, ... each "
                             "with its size and CRC-32");
      std::string file_damage;
      if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
        for (std::size_t i = 0; i < files.size() && file_damage.empty(); i += 3)
          {
            const std::string file = folder + "/" + files[i];
            std::error_code   error;
            const auto        size = fs::file_size(file, error);
            std::string       checksum;
            if (error || (checksum = file_checksum(file)).empty())
              file_damage = damaged_checkpoint(file,
                                               "it is missing or cannot be "
                                               "read")
                              .what();
            else if (std::to_string(size) != files[i + 1])
              file_damage =
                damaged_checkpoint(file,
                                   "it has " + std::to_string(size) +
                                     " bytes, and state.txt gives " +
                                     files[i + 1] + " (it was cut short)")
                  .what();
            else if (checksum != files[i + 2])
              file_damage =
                damaged_checkpoint(file,
                                   "its CRC-32 is " + checksum +
                                     ", and state.txt gives " + files[i + 2] +
                                     " (its bytes changed)")
                  .what();
          }
      file_damage = Utilities::MPI::broadcast(mpi_communicator, file_damage, 0);
      if (!file_damage.empty())
        throw InputError(file_damage, exit_cannot_read_file);
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
      // the mixed formulation's pressure, on its own DoFs, after them
      if (mixed)
        mixed->prepare_checkpoint();
      forest_of(triangulation).save(building + "/mesh");
    }
    MPI_Barrier(mpi_communicator); // (every rank's part written)

    // the scalars of the path and of the report
    CheckpointRecord record = checkpoint_record(step, control);
    if (root)
      {
        record.set("files", forest_files(building));
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
  CheckpointRecord
  ContactProblem<dim>::checkpoint_record(const StepRecord  &step,
                                         const StepControl &control) const
  {
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
    record.set("size_g_norm", previous_size.g_norm);
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
    return record;
  }

  template <int dim>
  void
  ContactProblem<dim>::load_mesh_and_fields(const std::string      &folder,
                                            const CheckpointRecord &record)
  {
    // the coarse mesh, refined as the checkpoint's forest, and set up at
    // the time the run set it up (the first step's, or the step's own on a
    // mesh adapted for it), then at the checkpoint's
    const double                          time = record.number("time");
    const std::vector<unsigned long long> mesh =
      record.whole_numbers("mesh", 3);
    if (mesh[0] > parameters.refinement.n_cycles)
      throw damaged_checkpoint(
        folder + "/state.txt",
        "its 'mesh' is of cycle " + std::to_string(mesh[0]) +
          ", beyond the scene's <Refinement/Number of cycles> = " +
          std::to_string(parameters.refinement.n_cycles));
    scene.set_time(
      parameters.load_path.adapt_at_every_step ? time : step_times.front());
    triangulation.clear();
    scene.create_coarse_mesh(triangulation);
    // (deal.II's checks of the files it reads, which load_checkpoint()
    // has compared with their sizes and checksums; a checkpoint being
    // written is read back unchecked)
    auto &forest = forest_of(triangulation);
    try
      {
        forest.load(folder + "/mesh");
      }
    catch (const std::exception &exception)
      {
        throw damaged_checkpoint(folder + "/mesh",
                                 "deal.II cannot read the mesh from it: " +
                                   exception_message(exception));
      }
    path_mesh.cycle = mesh[0];
    setup_system(path_mesh.cycle);
    path_mesh.n_cells = mesh[1];
    path_mesh.n_dofs  = mesh[2];
    if (path_mesh.n_dofs != dof_handler.n_dofs() ||
        path_mesh.n_cells != triangulation.n_global_active_cells())
      throw damaged_checkpoint(
        folder + "/state.txt",
        "its 'mesh' gives " + std::to_string(mesh[1]) + " cells and " +
          std::to_string(mesh[2]) + " DoFs, and the mesh in " + folder +
          "/mesh has " + std::to_string(triangulation.n_global_active_cells()) +
          " cells and " + std::to_string(dof_handler.n_dofs()) + " DoFs");
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
    try
      {
        transfer.deserialize(pointers);
        if (mixed)
          mixed->read_checkpoint();
      }
    catch (const std::exception &exception)
      {
        throw damaged_checkpoint(folder + "/mesh_fixed.data",
                                 "deal.II cannot read the fields from it: " +
                                   exception_message(exception));
      }
    solution = fields[0];
    step_start_u.clear();
    if (record.whole_number("has_start_u", 0, 1) == 1)
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

    // A damaged checkpoint (a disk that filled up, a copy cut short, an
    // edited state.txt) is bad input, exit 3, naming the file and what is
    // wrong: not an error inside deal.II or p4est, nor a run that goes on
    // from numbers that do not hold together. First every field of
    // state.txt and the forest's files (their sizes and checksums), then
    // whether it is this scene's checkpoint on as many ranks (exit 6),
    // then whether the fields fit the scene's load path and the mesh
    // read. Every rank reads the same state.txt and throws alike.
    const unsigned int n_max = std::numeric_limits<unsigned int>::max();
    const auto         step =
      static_cast<unsigned int>(record.whole_number("step", 1, n_max));
    const double time = record.number("time");
    const auto   ranks =
      static_cast<unsigned int>(record.whole_number("ranks", 1, n_max));
    const std::string &control_state = record.text("step_control");
    record.whole_number("has_start_u", 0, 1);
    record.whole_numbers("mesh", 3);
    const double saved_last_step_start = record.number("last_step_start");
    const double saved_dissipated      = record.number("dissipated");
    SolutionSize saved_size;
    saved_size.l1_norm             = record.number("size_l1_norm", 0.);
    saved_size.l1_max              = record.number("size_l1_max", 0.);
    saved_size.g_norm              = record.number("size_g_norm", 0.);
    saved_size.v_norm              = record.number("size_v_norm", 0.);
    saved_size.v_max               = record.number("size_v_max", 0.);
    saved_size.force_norm          = record.number("size_force_norm", 0.);
    saved_size.contact_force       = record.number("size_contact_force");
    const double       total_time  = record.number("total_time", 0.);
    const std::string &loop_figure = record.text("loop_figure");
    // the pvd files' records
    const auto saved_pvd = saved_pvd_records(record);
    // the forest's files, each as it was written
    check_forest_files(record, folder, mpi_communicator);
    record.check_all_taken();
    std::ifstream      saved_file(folder + "/parameters.prm");
    std::ostringstream saved;
    saved << saved_file.rdbuf();
    if (!saved_file || saved.str().empty())
      throw damaged_checkpoint(folder + "/parameters.prm",
                               "it is missing, empty or cannot be read");

    // this scene's checkpoint, on as many ranks
    const std::string difference = first_difference(parameters.parameter_file,
                                                    saved.str(),
                                                    entries_free_on_resume,
                                                    entries_compared_first);
    if (!difference.empty())
      throw InputError("The checkpoint in '" + directory +
                         "' is of another scene: " + difference +
                         ". Resume with the parameters it was written with.",
                       exit_inconsistent);
    if (ranks != Utilities::MPI::n_mpi_processes(mpi_communicator))
      throw InputError(
        "The checkpoint in '" + directory + "' was written on " +
          std::to_string(ranks) + " MPI ranks, and this run has " +
          std::to_string(Utilities::MPI::n_mpi_processes(mpi_communicator)) +
          ": resume it on " + std::to_string(ranks) + " (mpirun -np " +
          std::to_string(ranks) +
          "), which gives the same numbers as a run that was not stopped.",
        exit_inconsistent);

    // the fields against the scene's load path, and the mesh and fields
    // (their cells and DoFs against 'mesh')
    if (!control.load(control_state, step, time))
      throw record.damaged("step_control",
                           "which does not hold together with 'step' " +
                             std::to_string(step) + " and 'time' " +
                             record.text("time") + " on the scene's load path");
    if (!report.load_loop_figure_state(loop_figure))
      throw record.damaged("loop_figure", "not a state of steps.gp's ranges");
    load_mesh_and_fields(folder, record);
    probes.check_inside(mapping, triangulation);

    // the path's state, and the report's
    last_step_start = saved_last_step_start;
    dissipated      = saved_dissipated;
    previous_size   = saved_size;
    pvd_records     = saved_pvd;
    if (!probes.empty() &&
        Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      probes.resume_step_csv(directory + "/probes_steps.csv", step);
    report.resume(step, time, total_time);
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
