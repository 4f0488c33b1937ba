// Checkpoint and restart of a load path (doc/theory.md §11, "Restart"): a
// cycle stopped after its checkpoint and resumed gives the numbers of the
// run that was not stopped, on a fixed mesh and on one adapted at every
// step, and in the mixed formulation with its pressure field; a checkpoint
// of another scene (of the other formulation included), of another number
// of ranks, or none, is refused, and a damaged one too, naming the file
// and what is wrong. Tagged [path]: ctest runs them on 1 and 2 ranks.

#include <deal.II/base/mpi.h>

#include <dualcontact/checkpoint.h>
#include <dualcontact/contact_problem.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <limits>
#include <sstream>

#include "scene_run.h"
#include "test_tools.h"

using namespace dualcontact;
using namespace dualcontact_test;

namespace
{
  // the cylinder of prm/cattaneo_mindlin.prm pressed to t = 1, sheared to
  // t = 2 and back to t = 3 in twelve steps, on its first mesh, with a
  // checkpoint after every sixth step: the one after step 6 stays (none is
  // written after the last step)
  const std::string cycle =
    "subsection Refinement\n  set Number of cycles = 1\nend\n"
    "subsection Load path\n  set Times = 0.25, 0.5, 0.75, 1, 1.25, 1.5, "
    "1.75, 2, 2.25, 2.5, 2.75, 3\nend\n"
    "subsection Output\n  set Checkpoint interval = 6\nend\n";

  // the same with the mesh adapted before every later step
  const std::string adapted =
    cycle +
    "subsection Refinement\n  set Strategy = contact\n  set Refine fraction "
    "= 0.1\n  set Coarsen fraction = 0.4\nend\n"
    "subsection Load path\n  set Adapt at every step = true\nend\n";

  // The cylinder at degree 2 on a coarser mesh, pressed to t = 1 and
  // sheared to t = 2 in four steps, each from the state the step before
  // reached (no predictor); at nu = 1/2 in the mixed formulation (Q2/Q1),
  // and with a checkpoint after every second step (the one after step 2
  // stays).
  const std::string four_steps =
    "subsection Discretization\n  set Polynomial degree = 2\nend\n"
    "subsection Geometry\n  set Pre-refinement steps = 2\nend\n"
    "subsection Refinement\n  set Initial global refinement = 3\n  set "
    "Number of cycles = 1\nend\n"
    "subsection Load path\n  set Times = 0.5, 1, 1.5, 2\n  set Predictor = "
    "false\nend\n";
  const std::string incompressible =
    "subsection Material\n  set Poisson's ratio = 0.5\n  set Formulation = "
    "mixed\nend\n";
  const std::string every_second =
    "subsection Output\n  set Checkpoint interval = 2\nend\n";

  /** `text` split at every `separator`. */
  std::vector<std::string>
  split(const std::string &text, const char separator)
  {
    std::vector<std::string> parts;
    std::istringstream       in(text);
    for (std::string part; std::getline(in, part, separator);)
      parts.push_back(part);
    return parts;
  }

  /**
   * The gradient of the first Newton step of load step `step` in the text
   * of iterations.csv; NaN if it has none.
   */
  double
  first_gradient(const std::string &iterations, const unsigned int step)
  {
    const std::vector<std::string> lines  = split(iterations, '\n');
    const std::vector<std::string> header = split(lines.at(0), ',');
    const auto                     column = [&header](const std::string &name) {
      return std::find(header.begin(), header.end(), name) - header.begin();
    };
    for (const std::string &line : lines)
      {
        const std::vector<std::string> fields = split(line, ',');
        if (fields.size() == header.size() &&
            fields[column("step")] == std::to_string(step) &&
            fields[column("loop")] == "newton")
          return std::stod(fields[column("gradient")]);
      }
    return std::numeric_limits<double>::quiet_NaN();
  }

  /**
   * `run`'s scene with `overrides` on top, resumed on `comm` from the
   * checkpoint in its output folder; the InputError it throws, if any.
   */
  CaughtError
  resume(const Run         &run,
         const std::string &scene,
         const std::string &overrides,
         const MPI_Comm     comm)
  {
    return catch_input_error([&]() {
      Parameters parameters;
      parameters.read_string(
        read_text(test_file("../prm/cattaneo_mindlin.prm")),
        scene + overrides +
          "subsection Output\n  set Directory = " + run.directory +
          "\n  set Write vtu = false\n  set Print "
          "timing = false\nend\n");
      std::ostringstream screen;
      ContactProblem<2>  problem(parameters, comm, screen);
      problem.continue_from_checkpoint();
      problem.run();
    });
  }

  /** A file of the run's output folder, as rank 0 reads it. */
  std::string
  output_file(const Run &run, const std::string &name)
  {
    std::string text;
    if (Utilities::MPI::this_mpi_process(run.comm) == 0)
      text = read_text(run.directory + "/" + name);
    return Utilities::MPI::broadcast(run.comm, text, 0);
  }

  /**
   * The largest relative difference of two CSV texts with the same header,
   * over their rows and all columns but the wall times and the memory
   * (they differ from run to run); 1 if the rows or columns differ.
   */
  double
  csv_difference(const std::string &a, const std::string &b)
  {
    const std::vector<std::string> lines_a = split(a, '\n'),
                                   lines_b = split(b, '\n');
    if (lines_a.size() != lines_b.size() || lines_a.empty() ||
        lines_a.front() != lines_b.front())
      return 1.;
    const std::vector<std::string> header = split(lines_a.front(), ',');
    double                         worst  = 0.;
    for (std::size_t l = 1; l < lines_a.size(); ++l)
      {
        const auto fields_a = split(lines_a[l], ','),
                   fields_b = split(lines_b[l], ',');
        if (fields_a.size() != fields_b.size())
          return 1.;
        for (std::size_t c = 0; c < fields_a.size() && c < header.size(); ++c)
          {
            if (header[c].compare(0, 4, "time") == 0 ||
                header[c] == "memory_mb" || fields_a[c] == fields_b[c])
              continue;
            try
              {
                const double x = std::stod(fields_a[c]),
                             y = std::stod(fields_b[c]);
                worst =
                  std::max(worst,
                           std::abs(x - y) /
                             std::max({std::abs(x), std::abs(y), 1e-300}));
              }
            catch (const std::exception &)
              {
                return 1.; // a word that differs
              }
          }
      }
    return worst;
  }

  /**
   * A resumed run refused as one of another scene, naming
   * <Material/Formulation> with its value in the scene and in the
   * checkpoint.
   */
  void
  check_formulation_refused(const CaughtError &error,
                            const std::string &scene,
                            const std::string &checkpoint)
  {
    INFO(error.message);
    CHECK(error.code == exit_inconsistent);
    CHECK(contains(error.message,
                   "is of another scene: <Material/Formulation> is '" + scene +
                     "' in the scene and '" + checkpoint +
                     "' in the checkpoint"));
  }

  /**
   * Resume `run`, a path of `n_steps` steps run through, from its
   * checkpoint (after step `checkpoint`, at time `time`) in the same
   * folder, with a line cut short at the end of steps.csv as a run stopped
   * while writing leaves it: steps.csv, iterations.csv and the last
   * contact table must come out as the first run wrote them, the resumed
   * steps must hold the same numbers, and in the mixed formulation the
   * last step's pressure field must be the same.
   */
  void
  check_resumed_run(const Run         &run,
                    const unsigned int n_steps,
                    const unsigned int checkpoint,
                    const std::string &time)
  {
    const std::vector<CycleResult> &full = run.problem->steps();
    REQUIRE(full.size() == n_steps);
    const std::string steps      = output_file(run, "steps.csv");
    const std::string iterations = output_file(run, "iterations.csv");
    const std::string last_table =
      "contact_step_" + Utilities::int_to_string(n_steps, 3) + ".csv";
    const std::string last = output_file(run, last_table);
    REQUIRE(!last.empty());

    if (Utilities::MPI::this_mpi_process(run.comm) == 0)
      std::ofstream(run.directory + "/steps.csv", std::ios::app) << "13,3.2";
    std::ostringstream screen;
    ContactProblem<2>  resumed(run.parameters, run.comm, screen);
    resumed.continue_from_checkpoint();
    resumed.run();
    // (the screen of rank 0)
    const std::string shown =
      Utilities::MPI::broadcast(run.comm, screen.str(), 0);
    INFO(shown);
    CHECK(contains(shown,
                   "Resumed from the checkpoint at load step " +
                     std::to_string(checkpoint) + ", t = " + time));

    // the steps after the checkpoint, record by record
    const std::vector<CycleResult> &later = resumed.steps();
    REQUIRE(later.size() == n_steps - checkpoint);
    for (unsigned int n = 0; n < later.size(); ++n)
      {
        const CycleResult &a = later[n], &b = full[n + checkpoint];
        INFO("step " << b.step.step);
        CHECK(a.step.step == b.step.step);
        CHECK(a.step.time == b.step.time);
        CHECK(a.mesh.n_dofs == b.mesh.n_dofs);
        CHECK(a.solve.uzawa_steps == b.solve.uzawa_steps);
        CHECK(a.solve.n_stick == b.solve.n_stick);
        CHECK(a.solve.n_slip == b.solve.n_slip);
        CHECK(a.zone.contact_force == b.zone.contact_force);
        CHECK(a.zone.tangential_force == b.zone.tangential_force);
        CHECK(a.step.dissipation_total == b.step.dissipation_total);
      }

    // the files: the resumed run's rows after the first run's, the same
    const double steps_difference =
      csv_difference(output_file(run, "steps.csv"), steps);
    const double iterations_difference =
      csv_difference(output_file(run, "iterations.csv"), iterations);
    const double last_difference =
      csv_difference(output_file(run, last_table), last);
    INFO("relative differences: steps.csv "
         << steps_difference << ", iterations.csv " << iterations_difference
         << ", " << last_table << " " << last_difference);
    CHECK(steps_difference <= 1e-12);
    CHECK(iterations_difference <= 1e-12);
    CHECK(last_difference <= 1e-12);

    // the mixed formulation's pressure field at the last step (the same
    // mesh and ranks: the same DoFs)
    if (const MixedBulk<2> *mixed = run.problem->mixed_bulk())
      {
        REQUIRE(resumed.mixed_bulk() != nullptr);
        TrilinosWrappers::MPI::Vector difference(
          resumed.mixed_bulk()->pressure);
        REQUIRE(difference.size() == mixed->pressure.size());
        difference -= mixed->pressure;
        const double size     = mixed->pressure.linfty_norm();
        const double relative = difference.linfty_norm() / size;
        INFO("the pressure field: largest |p| "
             << size << ", relative difference " << relative);
        CHECK(size > 0.);
        CHECK(relative <= 1e-12);
      }
  }
} // namespace

TEST_CASE("Restart: a Cattaneo-Mindlin cycle of twelve steps resumed from "
          "its checkpoint after step 6 gives the numbers of the run that "
          "was not stopped",
          "[path]")
{
  SECTION("the finest mesh of the cycles for every step")
  {
    check_resumed_run(Run("cattaneo_mindlin.prm", cycle), 12, 6, "1.5");
  }
  SECTION("a mesh adapted at every step")
  {
    check_resumed_run(Run("cattaneo_mindlin.prm", adapted), 12, 6, "1.5");
  }
}

TEST_CASE("Restart in the mixed formulation: a Coulomb path at nu = 1/2 "
          "resumed from its checkpoint after step 2 gives the numbers and "
          "the pressure field of the run that was not stopped; resumed in "
          "displacements it is refused, naming <Material/Formulation>",
          "[path][mixed]")
{
  const Run run("cattaneo_mindlin.prm",
                four_steps + incompressible + every_second);
  check_resumed_run(run, 4, 2, "1");

  // The checkpoint holds p: the step after it starts from the state of a
  // run that writes none, and the gradient of its first Newton step, which
  // B^T p is part of, is that run's to round-off. (The run that writes the
  // checkpoint goes on from what it reads back, as the resumed run does:
  // the comparison above would not see a p lost on the way; p = 0 there
  // changes this gradient by a fifth.)
  const Run    through("cattaneo_mindlin.prm", four_steps + incompressible);
  const double gradient = first_gradient(output_file(run, "iterations.csv"), 3);
  const double without =
    first_gradient(output_file(through, "iterations.csv"), 3);
  INFO("the first gradient of step 3: "
       << std::setprecision(12) << gradient << " after the "
       << "checkpoint, " << without << " without");
  CHECK(std::abs(gradient - without) <= 1e-8 * std::abs(without));

  // (nu = 1/2 needs the mixed formulation: 0.49 in displacements)
  check_formulation_refused(
    resume(run,
           four_steps + every_second,
           "subsection Material\n  set Formulation = displacement\n  set "
           "Poisson's ratio = 0.49\nend\n",
           run.comm),
    "displacement",
    "mixed");
}

TEST_CASE("Restart: a folder without a checkpoint, a checkpoint of another "
          "scene or of another number of ranks, or a damaged one is "
          "refused, naming why",
          "[path]")
{
  const Run run("cattaneo_mindlin.prm", cycle);

  // another friction coefficient: the entry is named with both values
  const CaughtError other =
    resume(run,
           cycle,
           "subsection Friction\n  set Coefficient = 0.4\nend\n",
           run.comm);
  CHECK(other.code == exit_inconsistent);
  CHECK(contains(other.message,
                 "is of another scene: <Friction/Coefficient> is '0.4' in "
                 "the scene and '0.3' in the checkpoint"));
  // the mixed formulation (at degree 2): the formulation is named first,
  // whatever else differs
  check_formulation_refused(
    resume(run,
           cycle,
           "subsection Material\n  set Formulation = mixed\nend\n"
           "subsection Discretization\n  set Polynomial degree = 2\nend\n",
           run.comm),
    "mixed",
    "displacement");
  // what is shown and how often checkpoints are written may differ
  const std::string saved =
    read_text(checkpoint_folder(run.directory) + "/parameters.prm");
  CHECK(first_difference(run.parameters.parameter_file, saved, {}).empty());

  // written on 2 ranks, resumed on 1
  if (Utilities::MPI::n_mpi_processes(run.comm) == 2)
    {
      const CaughtError ranks = resume(run, cycle, "", MPI_COMM_SELF);
      CHECK(ranks.code == exit_inconsistent);
      CHECK(contains(ranks.message,
                     "was written on 2 MPI ranks, and this run has 1: "
                     "resume it on 2"));
    }

  // A damaged checkpoint (an edited state.txt, a copy cut short, a disk
  // that filled up) is bad input, exit 3, naming the file and what is
  // wrong with it, whatever part is damaged; each damage is made on the
  // checkpoint as the run wrote it.
  namespace fs             = std::filesystem;
  const std::string folder = checkpoint_folder(run.directory);
  const std::string state  = folder + "/state.txt";
  const bool        root   = Utilities::MPI::this_mpi_process(run.comm) == 0;
  if (root)
    fs::copy(folder, folder + ".whole", fs::copy_options::recursive);
  const auto damaged = [&](const std::function<void()> &damage) {
    MPI_Barrier(run.comm);
    if (root)
      {
        fs::remove_all(folder);
        fs::copy(folder + ".whole", folder, fs::copy_options::recursive);
        damage();
      }
    MPI_Barrier(run.comm);
    return resume(run, cycle, "", run.comm);
  };
  // state.txt with the line of `key` given the value `value`, or left
  // out if `value` is "-"
  const auto set_field = [&](const std::string &key, const std::string &value) {
    return [=]() {
      std::istringstream lines(read_text(state));
      std::ostringstream out;
      for (std::string line; std::getline(lines, line);)
        if (line.compare(0, key.size() + 1, key + " ") != 0)
          out << line << '\n';
        else if (value != "-")
          out << key << ' ' << value << '\n';
      std::ofstream(state) << out.str();
    };
  };
  const auto write_file = [](const std::string &file, const std::string &text) {
    return [=]() { std::ofstream(file) << text; };
  };
  const std::string whole_state = read_text(state);
  const auto        field       = [&whole_state](const std::string &key) {
    const std::size_t begin =
      whole_state.find("\n" + key + " ") + 2 + key.size();
    return whole_state.substr(begin, whole_state.find('\n', begin) - begin);
  };
  const std::string mesh = field("mesh"); // cycle, cells, DoFs
  const std::vector<std::pair<std::function<void()>, std::string>> damages = {
    // a field that does not parse, or is not finite
    {set_field("ranks", "x"),
     state + " is damaged: 'ranks' is 'x', not a whole number"},
    {set_field("step", field("step") + " 2"), state + " is damaged: 'step' is"},
    {set_field("time", "nan"),
     state + " is damaged: 'time' is 'nan', not a finite number"},
    {set_field("size_v_norm", "1e999"), state + " is damaged: 'size_v_norm'"},
    // out of its range
    {set_field("ranks", "0"),
     state + " is damaged: 'ranks' is '0', less than 1"},
    {set_field("size_l1_norm", "-1"),
     state + " is damaged: 'size_l1_norm' is '-1', less than 0"},
    // missing, or a field too many
    {set_field("dissipated", "-"),
     state + " is damaged: it has no 'dissipated'"},
    {write_file(state, ""), state + " is damaged: it has no"},
    {write_file(state, whole_state + "extra 1\n"),
     state + " is damaged: 'extra' is not a field of a checkpoint"},
    {write_file(state, whole_state.substr(0, whole_state.size() - 3)),
     state + " is damaged: its last line has no end"},
    // not holding together: the time with the step control's state, the
    // cells with the mesh
    {set_field("time", "1.4"), state + " is damaged: 'step_control' is"},
    {set_field("mesh", "0 7" + mesh.substr(mesh.rfind(' '))),
     state + " is damaged: its 'mesh' gives 7 cells and"},
    // the forest's files emptied, of zeros or missing, parameters.prm
    // emptied
    {[&]() {
       for (const auto &entry : fs::directory_iterator(folder))
         if (entry.path().filename().string().compare(0, 4, "mesh") == 0)
           std::ofstream(entry.path());
     },
     folder + "/mesh is damaged: it has 0 bytes"},
    {[&]() {
       const std::string fields = folder + "/mesh_fixed.data";
       const std::string zeros(fs::file_size(fields), '\0');
       std::ofstream(fields) << zeros;
     },
     folder + "/mesh_fixed.data is damaged: its CRC-32 is"},
    {[&]() { fs::remove(folder + "/mesh.info"); },
     folder + "/mesh.info is damaged: it is missing"},
    {write_file(folder + "/parameters.prm", ""),
     folder + "/parameters.prm is damaged"}};
  for (const auto &[damage, message] : damages)
    {
      const CaughtError error = damaged(damage);
      INFO(message);
      INFO(error.message);
      CHECK(error.code == exit_cannot_read_file);
      CHECK(contains(error.message, "The checkpoint file " + message));
    }

  // no checkpoint
  remove_directory(folder + ".whole", run.comm);
  remove_directory(checkpoint_folder(run.directory), run.comm);
  const CaughtError none = resume(run, cycle, "", run.comm);
  CHECK(none.code == exit_cannot_read_file);
  CHECK(contains(none.message, "There is no checkpoint to resume from in"));
}
