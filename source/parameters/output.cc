// <Output>: what is written where, and how much the screen shows.
#include <deal.II/base/utilities.h>

#include <dualcontact/input_error.h>
#include <dualcontact/parameter_helpers.h>
#include <dualcontact/parameters.h>

namespace dualcontact
{
  using namespace dealii;

  const NameTable<Verbosity> &
  verbosity_names()
  {
    static const NameTable<Verbosity> table = {{Verbosity::quiet, "quiet"},
                                               {Verbosity::normal, "normal"},
                                               {Verbosity::detailed,
                                                "detailed"}};
    return table;
  }

  void
  OutputParameters::declare_parameters(EntryDeclarer &declarer)
  {
    declarer.enter_subsection("Output");
    declarer.declare_entry("Directory",
                           "output",
                           EntryPattern::folder_name(),
                           "Folder for all output files; created if missing.");
    declarer.declare_entry("Write vtu",
                           "true",
                           EntryPattern::boolean(),
                           "Write .pvtu/.vtu files (one set per cycle) for "
                           "ParaView.");
    declarer.declare_entry(
      "Print timing",
      "true",
      EntryPattern::boolean(),
      "Print wall times on screen, and in the summary the peak memory of "
      "all ranks [MB] and per DoF [kB]. Tests switch this off so that the "
      "screen output is deterministic.");
    declarer.declare_entry(
      "Verbosity",
      "normal",
      EntryPattern::selection(verbosity_names().names()),
      "How much the screen shows (no unit). quiet: the scene and one line "
      "per refinement cycle, then the summary table; normal: also a legend, "
      "one line per Uzawa step and per threshold step, and each cycle's "
      "results; detailed: also one line per Newton step with its CG "
      "iterations. Warnings and errors are always shown; cycles.csv and "
      "iterations.csv hold everything at every level.");
    declarer.declare_entry(
      "Probe points",
      "",
      EntryPattern::list(EntryPattern::list(EntryPattern::number(), 2, 3),
                         0,
                         Patterns::List::max_int_value,
                         ";"),
      "Points of the body [length] at which the displacement [length] and "
      "the stress [stress] are written to probes.csv for every cycle, as "
      "'x, y; x, y' (3D: 'x, y, z; ...'): one row per cycle and point, with "
      "the columns cycle, probe (the point's number in this list, from 1), "
      "x, y, (z), u_x, u_y, (u_z), sigma_xx, sigma_yy, sigma_zz, sigma_xy, "
      "(sigma_xz, sigma_yz) and von_mises (in 2D sigma_zz is plane strain's "
      "lambda tr(eps), and von_mises includes it). With <Material/"
      "Formulation> = mixed the stress is 2 mu dev eps(u) - p I, p the "
      "pressure field at the point, and a last column pressure [stress] "
      "holds p. Each must lie in the body, "
      "its boundary included: a point outside the mesh by at most the "
      "distance of the nearest boundary face from the curved boundary at the "
      "face's middle, plus 1e-6 of the face's size, counts as on the "
      "boundary and is evaluated at the nearest point of the mesh; a point "
      "farther outside is an input error, found on the first mesh. Empty: no "
      "probes.");
    declarer.declare_entry(
      "Checkpoint interval",
      "0",
      EntryPattern::whole_number(0),
      "Write a checkpoint after every n-th later step of the load path (each "
      "row of steps.csv counts) [-]: the folder checkpoint/ in the output "
      "folder, which each checkpoint replaces, holds the mesh, the "
      "displacement (with <Material/Formulation> = mixed the pressure "
      "field too), the multipliers, the threshold, the slip origins' "
      "state and the path's place. 'dualcontact scene.prm --resume folder/' "
      "goes on from it with the same parameters on the same number of MPI "
      "ranks, and appends to steps.csv and the .pvd files. The step after a "
      "checkpoint starts from the last step's state, as a resumed run does "
      "(no extrapolation, a new preconditioner): a resumed run gives the "
      "same numbers as one that was not stopped. 0: none. Meshes of "
      "quadrilaterals and hexahedra only.");
    declarer.leave_subsection();
  }

  std::vector<IneffectiveRule>
  OutputParameters::ineffective_rules(const Parameters &parameters) const
  {
    return {{parameters.load_path.n_steps_on_path() == 1,
             "Output",
             {"Checkpoint interval"},
             "the path has one step"}};
  }

  void
  OutputParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    directory           = prm.get("Directory");
    write_vtu           = prm.get_bool("Write vtu");
    print_timing        = prm.get_bool("Print timing");
    verbosity           = verbosity_names().value(prm.get("Verbosity"));
    checkpoint_interval = prm.get_integer("Checkpoint interval");
    probe_points.clear();
    for (const std::string &point :
         Utilities::split_string_list(prm.get("Probe points"), ';'))
      if (!point.empty())
        probe_points.push_back(parse_doubles(point));
    prm.leave_subsection();
    if (directory.empty())
      throw InputError("The entry <Output/Directory> must not be empty.",
                       exit_invalid_value);
  }

  void
  OutputParameters::check(const Parameters &parameters) const
  {
    const unsigned int dim = parameters.geometry.dimension;
    for (unsigned int i = 0; i < probe_points.size(); ++i)
      if (probe_points[i].size() != dim)
        throw InputError("The point " + std::to_string(i + 1) +
                           " of <Output/Probe points> has " +
                           std::to_string(probe_points[i].size()) +
                           " coordinates, not " + std::to_string(dim) +
                           " (one per dimension).",
                         exit_inconsistent);
  }
} // namespace dualcontact
