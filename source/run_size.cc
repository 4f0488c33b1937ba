#include <dualcontact/geometry.h>
#include <dualcontact/input_error.h>
#include <dualcontact/parameter_helpers.h>
#include <dualcontact/parameters.h>
#include <dualcontact/refinement_indicator_kind.h>
#include <dualcontact/run_size.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <sys/resource.h>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  namespace
  {
    // Bounds of the peak resident memory (column memory_mb of cycles.csv,
    // VmHWM summed over the ranks) per DoF and per rank, from the
    // measurements of doc/performance.md (section Memory; the peak is the
    // AMG set-up), rounded up: the check is to refuse what cannot fit, not
    // to predict the peak to the megabyte. The 3D bound was measured with an
    // assembled mass matrix and is an upper bound.
    constexpr double bytes_per_dof_2d = 1700.;
    constexpr double bytes_per_dof_3d = 7300.;
    constexpr double bytes_per_rank   = 180. * 1024. * 1024.;
    // the replicated mesh of simplices (triangulation and DoF indices of
    // every cell on every rank), per cell and rank
    constexpr double bytes_per_replicated_cell_2d = 1000.;
    constexpr double bytes_per_replicated_cell_3d = 1500.;
    constexpr double gigabyte                     = 1024. * 1024. * 1024.;

    std::string
    number(const double x)
    {
      std::ostringstream out;
      out.precision(x < 1e6 ? 6 : 2);
      if (x >= 1e6)
        out << std::scientific;
      out << (x < 1e6 ? std::round(x) : x);
      return out.str();
    }

    std::string
    gigabytes(const double bytes)
    {
      std::ostringstream out;
      out.precision(bytes < 1e3 * gigabyte ? 3 : 2);
      if (bytes >= 1e3 * gigabyte)
        out << std::scientific;
      out << bytes / gigabyte << " GB";
      return out.str();
    }

    // The first number of `file` after `key` (0 if there is none).
    double
    read_number(const std::string &file, const std::string &key = "")
    {
      std::ifstream in(file);
      std::string   line;
      while (std::getline(in, line))
        if (line.compare(0, key.size(), key) == 0)
          {
            std::istringstream values(line.substr(key.size()));
            double             value = 0;
            values >> value;
            return values ? value : 0.;
          }
      return 0.;
    }

    // MemTotal, or the container's limit (cgroup v2 or v1) if it is lower.
    double
    node_memory()
    {
      double memory = read_number("/proc/meminfo", "MemTotal:") * 1024.;
      if (memory <= 0.)
        memory = static_cast<double>(sysconf(_SC_PHYS_PAGES)) *
                 static_cast<double>(sysconf(_SC_PAGESIZE));
      for (const char *limit : {"/sys/fs/cgroup/memory.max",
                                "/sys/fs/cgroup/memory/memory.limit_in_bytes"})
        {
          const double value = read_number(limit);
          if (value > 0. && value < memory)
            memory = value;
        }
      return memory;
    }

    std::string
    setting(const std::string &entry, const std::string &value)
    {
      return "<" + entry + "> (" + value + ")";
    }

    // the entries that set the size of the finest mesh, with their values
    std::string
    entries_driving_size(const Parameters &parameters)
    {
      const GeometryParameters   &g = parameters.geometry;
      const RefinementParameters &r = parameters.refinement;
      std::vector<std::string>    entries;
      const auto size_entries = geometry_kind(g.type).size_entries;
      if (size_entries != nullptr)
        for (const auto &[entry, value] : size_entries(g))
          entries.push_back(setting(entry, value));
      if (r.initial_global_refinement > 0)
        entries.push_back(setting("Refinement/Initial global refinement",
                                  std::to_string(r.initial_global_refinement)));
      if (g.pre_refinement_steps > 0)
        entries.push_back(setting("Geometry/Pre-refinement steps",
                                  std::to_string(g.pre_refinement_steps)));
      if (r.n_cycles > 1)
        entries.push_back(
          setting("Refinement/Number of cycles", std::to_string(r.n_cycles)));
      const LoadPathParameters &path    = parameters.load_path;
      const std::size_t         n_steps = path.step_times().size();
      const bool adapts = path.adapt_at_every_step && n_steps > 1;
      if ((r.n_cycles > 1 || adapts) &&
          !refinement_indicator_kind(r.strategy).refines_every_cell())
        entries.push_back(setting("Refinement/Refine fraction",
                                  number_text(r.refine_fraction)));
      if (adapts)
        {
          entries.push_back(setting("Refinement/Coarsen fraction",
                                    number_text(r.coarsen_fraction)));
          entries.push_back(setting("Load path/Adapt at every step", "true"));
          entries.push_back(
            path.times.empty() ?
              setting("Load path/Number of steps", std::to_string(n_steps)) :
              setting("Load path/Times", std::to_string(n_steps) + " times"));
        }
      std::string text;
      for (const std::string &entry : entries)
        text += (text.empty() ? "" : ", ") + entry;
      return text;
    }
  } // namespace

  RunSize
  estimate_run_size(const Parameters  &parameters,
                    const double       initial_cells,
                    const unsigned int n_ranks,
                    const CellKind     kind)
  {
    const unsigned int          dim        = parameters.geometry.dimension;
    const double                children   = std::pow(2., dim);
    const RefinementParameters &refinement = parameters.refinement;
    const double                growth =
      refinement_indicator_kind(refinement.strategy).refines_every_cell() ?
                       children :
                       1. + (children - 1.) * refinement.refine_fraction;

    // the load steps that adapt the mesh once each, refining and
    // coarsening: the mesh grows unless the coarsened cells make up for
    // the refined ones
    const LoadPathParameters &path    = parameters.load_path;
    const std::size_t         n_steps = path.step_times().size();
    const double              step_growth =
      std::max(1.,
               1. + (children - 1.) * refinement.refine_fraction -
                 (1. - 1. / children) * refinement.coarsen_fraction);

    RunSize size;
    size.cycle       = refinement.n_cycles - 1;
    size.adapts      = path.adapt_at_every_step ? n_steps - 1 : 0;
    size.step_growth = step_growth;
    size.cells       = initial_cells * std::pow(growth, size.cycle) *
                 std::pow(step_growth, size.adapts);
    // FE_Q(k): k intervals of nodes along each cell edge; a square is 2
    // triangles, a cube about 6 tetrahedra
    const bool   simplex = kind == CellKind::simplex;
    const double boxes =
      simplex ? size.cells / (dim == 2 ? 2. : 6.) : size.cells;
    const double k     = parameters.discretization.degree;
    const double nodes = std::pow(k * std::pow(boxes, 1. / dim) + 1., dim);
    size.dofs          = dim * nodes;
    size.memory        = n_ranks * bytes_per_rank +
                  (dim == 2 ? bytes_per_dof_2d : bytes_per_dof_3d) * size.dofs;
    if (simplex)
      size.memory += n_ranks * size.cells *
                     (dim == 2 ? bytes_per_replicated_cell_2d :
                                 bytes_per_replicated_cell_3d);
    return size;
  }

  MemoryLimit
  memory_limit(const MPI_Comm comm)
  {
    MemoryLimit limit;
    if (const char *gigabytes = std::getenv("DUALCONTACT_MEMORY_GB"))
      {
        limit.bytes  = std::atof(gigabytes) * gigabyte;
        limit.source = MemoryLimit::Source::environment;
        return limit;
      }
    // this rank's address-space limit, less what it has mapped and does
    // not use (infinite without a limit)
    constexpr double unlimited     = std::numeric_limits<double>::infinity();
    double           address_space = unlimited, usable = unlimited;
    rlimit           rank_limit{};
    if (getrlimit(RLIMIT_AS, &rank_limit) == 0 &&
        rank_limit.rlim_cur != RLIM_INFINITY)
      {
        address_space       = static_cast<double>(rank_limit.rlim_cur);
        const double unused = (read_number("/proc/self/status", "VmSize:") -
                               read_number("/proc/self/status", "VmRSS:")) *
                              1024.;
        usable = std::max(0., address_space - std::max(0., unused));
      }

    // one rank per node counts its node's memory
    MPI_Comm node;
    MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
    const bool   first_on_node = Utilities::MPI::this_mpi_process(node) == 0;
    const double on_node =
      Utilities::MPI::n_mpi_processes(node) * Utilities::MPI::min(usable, node);
    MPI_Comm_free(&node);
    const double machine     = first_on_node ? node_memory() : 0.;
    const double usable_here = first_on_node ? std::min(machine, on_node) : 0.;
    limit.bytes              = Utilities::MPI::sum(usable_here, comm);
    if (limit.bytes < Utilities::MPI::sum(machine, comm))
      {
        limit.source                 = MemoryLimit::Source::address_space;
        limit.address_space_per_rank = Utilities::MPI::min(address_space, comm);
      }
    return limit;
  }

  RunSizeCheck::RunSizeCheck(const Parameters &parameters,
                             const MPI_Comm    comm,
                             const CellKind    kind)
      : parameters(parameters)
      , comm(comm)
      , n_ranks(Utilities::MPI::n_mpi_processes(comm))
      , kind(kind)
      , limit(memory_limit(comm))
      , memory(limit.bytes)
  {}

  void
  RunSizeCheck::check(const double initial_cells, const bool exact) const
  {
    const RunSize size =
      estimate_run_size(parameters, initial_cells, n_ranks, kind);
    if (size.memory > memory)
      throw InputError("The scene is too large for the memory of this "
                       "machine: " +
                         describe(size, exact) + "; make the mesh coarser (" +
                         entries_driving_size(parameters) + ").",
                       exit_inconsistent);
  }

  void
  RunSizeCheck::warn(const double initial_cells) const
  {
    const RunSize size =
      estimate_run_size(parameters, initial_cells, n_ranks, kind);
    if (size.memory > 0.5 * memory &&
        Utilities::MPI::this_mpi_process(comm) == 0)
      std::cerr << "dualcontact: warning: the run needs more than half of "
                   "the memory of this machine: "
                << describe(size, true) << "." << std::endl;
    // refining a fraction r of the cells adds (2^dim - 1) r of them,
    // coarsening c removes (1 - 2^-dim) c: c = (2^dim - 1) / (1 - 2^-dim) r
    // = 2^dim r keeps the mesh's size
    const unsigned int children = 1u << parameters.geometry.dimension;
    if (size.adapts > 0 && size.step_growth > 1.05 &&
        Utilities::MPI::this_mpi_process(comm) == 0)
      std::cerr << "dualcontact: warning: <Load path/Adapt at every step> "
                   "grows the mesh by a factor of about "
                << number_text(size.step_growth) << " per step, to about "
                << number(size.cells)
                << " cells at the last step; a <Refinement/Coarsen fraction> "
                   "of "
                << children
                << " times <Refinement/Refine fraction> keeps it near its size "
                   "(e.g. "
                << number_text(0.4 / children) << " and 0.4)." << std::endl;
  }

  std::string
  RunSizeCheck::describe(const RunSize &size, const bool exact) const
  {
    return "its finest mesh (cycle " + std::to_string(size.cycle) +
           (size.adapts > 0 ?
              ", then adapted at each of " + std::to_string(size.adapts) +
                " later load steps" :
              "") +
           ") would have " + (exact ? "about " : "at least ") +
           number(size.cells) + " cells and " + number(size.dofs) +
           " DoFs and need " + (exact ? "about " : "at least ") +
           gigabytes(size.memory) + " of the " + gigabytes(memory) +
           (limit.source == MemoryLimit::Source::environment ?
              " that DUALCONTACT_MEMORY_GB allows" :
            limit.source == MemoryLimit::Source::address_space ?
              " that the address-space limit (ulimit -v) of " +
                gigabytes(limit.address_space_per_rank) +
                (n_ranks == 1 ? "" : " per rank") + " leaves" :
              " the machine has") +
           " (" + std::to_string(n_ranks) +
           (n_ranks == 1 ? " rank" : " ranks") +
           (kind == CellKind::simplex ?
              "; every rank holds the whole mesh of simplices)" :
              ")");
  }
} // namespace dualcontact
