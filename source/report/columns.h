// The column layouts of the report's tables (internal to source/report.cc
// and source/report/*.cc): the loops a scene runs, the columns of its
// Uzawa rows, and the quantities' columns of the row a quiet run prints
// per cycle.
#ifndef dualcontact_report_columns_h
#define dualcontact_report_columns_h

#include <dualcontact/parameters.h>
#include <dualcontact/records.h>
#include <dualcontact/report_quantity.h>
#include <dualcontact/scene.h>

#include <memory>
#include <vector>

#include "format.h"

namespace dualcontact
{
  namespace report_format
  {
    /** The loops a scene runs: what its columns and its legend show. */
    struct Loops
    {
      bool contact  = false;
      bool friction = false; // l2 and stick/slip
      bool coulomb  = false; // g = F l1: the threshold iteration
      bool nested   = false; // its steps around Uzawa solves
      bool merged   = false; // g updated in each Uzawa step
    };

    /** The loops of a scene with these parameters. */
    template <int dim>
    Loops
    loops_of(const Parameters &parameters, const Scene<dim> &scene);

    /** A Uzawa step, and whether it had friction and updated g. */
    struct UzawaRow
    {
      IterationRecord record;
      bool            friction;
      bool            merged;
    };

    /**
     * The columns of the Uzawa rows of a scene: what the step did, the node
     * counts, the relative changes and the two contact conditions (what the
     * stopping test looks at), and its wall time. A step without friction
     * (the frictionless start of the threshold iteration) or without an
     * update of g has '-' in those columns.
     */
    std::vector<Column<UzawaRow>>
    uzawa_columns(const Loops &loops, const bool timing);

    /** The same columns for every Uzawa solve of a scene. */
    template <int dim>
    std::vector<Column<UzawaRow>>
    uzawa_columns_of(const Parameters &parameters, const Scene<dim> &scene);

    /**
     * The quantities' columns of the row a quiet run prints per cycle, in
     * the order of their places, without those of the largest priority
     * while the row is wider than a screen line (the summary table has
     * them all).
     */
    template <int dim>
    std::vector<Column<CycleResult>>
    row_columns(
      const std::vector<std::unique_ptr<ReportQuantity<dim>>> &quantities);
  } // namespace report_format
} // namespace dualcontact

#endif
