// How large a run's finest mesh will be, and whether it fits in the memory
// of the machine: checked before the mesh is built, so that a scene refined
// far too often fails in a moment with a message instead of after minutes
// with std::bad_alloc.
#ifndef dualcontact_run_size_h
#define dualcontact_run_size_h

#include <deal.II/base/mpi.h>

#include <dualcontact/cell_kind.h>

#include <string>

namespace dualcontact
{
  struct Parameters; // parameters.h

  /** The estimated size of the finest mesh of a run. */
  struct RunSize
  {
    unsigned int cycle       = 0;  // the cycle of the finest mesh (the last)
    unsigned int adapts      = 0;  // then adapted before each later load step
    double       step_growth = 1.; // the cells' growth per such adaption
    double       cells       = 0.; // active cells
    double       dofs        = 0.; // degrees of freedom (dim per node)
    double       memory      = 0.; // peak resident memory of all ranks [bytes]
  };

  /**
   * The size of the last cycle's mesh if the initial mesh (after the
   * initial global refinement and the pre-refinement) has `initial_cells`
   * cells: global refinement multiplies the cells by 2^dim per cycle,
   * adaptive refinement by about 1 + (2^dim - 1) * <Refinement/Refine
   * fraction> (coarsening ignored); with <Load path/Adapt at every step>
   * each later step adapts it once more, by 1 + (2^dim - 1) r - (1 -
   * 2^-dim) c with the refine and coarsen fractions r, c (at least 1:
   * p4est coarsens only whole families); a mesh of FE_Q(k) has about (k
   * cells^(1/dim) + 1)^dim nodes (exact for a cube of n^dim cells), a mesh
   * of simplices as many as one of a half (2D) or a sixth (3D) as many
   * quadrilaterals (hexahedra). The memory follows from measurements of Q1
   * runs per DoF (run_size.cc), and on simplices, whose mesh every rank
   * holds whole, from measurements per cell and rank.
   */
  RunSize
  estimate_run_size(const Parameters  &parameters,
                    const double       initial_cells,
                    const unsigned int n_ranks,
                    const CellKind     kind = CellKind::quadrilateral);

  /** The memory a run may use, and what sets it. */
  struct MemoryLimit
  {
    enum class Source
    {
      machine,       // the nodes' physical memory or container limit
      address_space, // the ranks' address-space limit (ulimit -v)
      environment    // DUALCONTACT_MEMORY_GB
    };
    double bytes  = 0.;
    Source source = Source::machine;
    // with Source::address_space: the smallest limit of a rank [bytes]
    double address_space_per_rank = 0.;
  };

  /**
   * The memory the run may use: on each node the ranks of `comm` run on,
   * its physical memory (MemTotal of /proc/meminfo, or a lower cgroup
   * limit), or, if lower, what the address-space limit (RLIMIT_AS, ulimit
   * -v) of its ranks leaves them, summed over the nodes. That limit is each
   * rank's own: a node's ranks may use the sum of theirs, taken as the
   * number of ranks times the smallest one, since the run spreads evenly
   * over its ranks and the rank with the smallest limit fails first. From
   * a rank's limit goes the address space it has mapped but does not use
   * (VmSize - VmRSS of /proc/self/status: shared libraries, reserved
   * stacks and heaps, about 0.5 GB), which the estimate, of resident
   * memory, does not count. The environment variable DUALCONTACT_MEMORY_GB,
   * if set, replaces it all (a share of a node, or a test).
   */
  MemoryLimit
  memory_limit(const MPI_Comm comm);

  /**
   * Refuses a run that would not fit: check() throws InputError
   * (exit_inconsistent) naming the entries that make the mesh large, the
   * estimate and the memory; warn() writes one line to std::cerr (rank 0)
   * when the estimate exceeds half of the memory.
   */
  class RunSizeCheck
  {
  public:
    RunSizeCheck(const Parameters &parameters,
                 const MPI_Comm    comm,
                 const CellKind    kind = CellKind::quadrilateral);

    /**
     * `initial_cells` is what the initial mesh will have at least (before
     * the pre-refinement, or before one of its steps), or exactly (built).
     */
    void
    check(const double initial_cells, const bool exact) const;

    /**
     * Warn if the run needs more than half of the memory, or if a load path
     * that adapts the mesh at every step makes it grow from step to step.
     */
    void
    warn(const double initial_cells) const;

  private:
    std::string
    describe(const RunSize &size, const bool exact) const;

    const Parameters  &parameters;
    const MPI_Comm     comm;
    const unsigned int n_ranks;
    const CellKind     kind;
    const MemoryLimit  limit;
    const double       memory;
  };
} // namespace dualcontact

#endif
