// Probe points (<Output/Probe points>): the displacement and the stress
// (and in the mixed formulation the pressure) at given points of the body,
// for every cycle, written to probes.csv, and for every step of a load
// path, written to probes_steps.csv.
#ifndef dualcontact_probes_h
#define dualcontact_probes_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/mapping.h>

#include <deal.II/grid/tria.h>

#include <deal.II/lac/trilinos_vector.h>

#include <dualcontact/material_parameters.h>

#include <string>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  template <int dim>
  class MixedBulk; // mixed_bulk.h

  /**
   * The probe points of a run and the values found at them. The points are
   * located in the distributed mesh with
   * Utilities::MPI::RemotePointEvaluation, so a point may lie in a cell of
   * any rank; every rank asks for every point and gets every value, so all
   * ranks hold the same values.
   */
  template <int dim>
  class Probes
  {
  public:
    /** What a probe found on one cycle, or at one step of a load path. */
    struct Value
    {
      unsigned int            cycle = 0;
      unsigned int            step  = 1; // of the load path, from 1
      double                  time  = 1.;
      unsigned int            probe = 0; // its index in the entry, from 0
      Point<dim>              point;
      Tensor<1, dim>          displacement;
      SymmetricTensor<2, dim> stress;
      double                  stress_zz = 0.; // 2D: plane strain lambda tr(eps)
      double                  von_mises = 0.;
      double                  pressure  = 0.; // the mixed formulation's p
    };

    /**
     * The points of <Output/Probe points> (each with dim coordinates);
     * `with_pressure` in the mixed formulation: the stress takes the
     * pressure field, and the files have its column.
     */
    explicit Probes(const std::vector<std::vector<double>> &coordinates,
                    bool with_pressure = false);

    bool
    empty() const
    {
      return points.empty();
    }

    const std::vector<Point<dim>> &
    get_points() const
    {
      return points;
    }

    /**
     * Throws InputError (exit_inconsistent), naming <Output/Probe points>,
     * the first point outside the body and how far outside it lies. A point
     * on the boundary is inside, and so is a point that no cell holds but
     * that lies within a tolerance of the mesh's boundary: the distance of
     * the nearest boundary face (a chord of a curved boundary) from the
     * boundary's manifold at the face's middle, plus 1e-6 of the face's
     * size. A point on a curved boundary between two vertices lies outside
     * the chord by less than that. Collective.
     */
    void
    check_inside(const Mapping<dim>       &mapping,
                 const Triangulation<dim> &triangulation) const;

    /**
     * The displacement and the stress sigma = lambda tr(eps) I + 2 mu eps at
     * every point (averaged over the cells that share a point on their
     * common face), added to values() as the rows of `cycle`; in the mixed
     * formulation (`mixed` not null, as `with_pressure`) the pressure p at
     * the point, averaged alike, and sigma = 2 mu dev eps - p I. A point
     * that no cell holds but that lies within the tolerance of
     * check_inside() is evaluated at the nearest point of the mesh, found
     * over all ranks; one farther outside (a mesh that lost the point) gets
     * NaN. `solution` is ghosted. Collective.
     */
    void
    evaluate(const unsigned int                   cycle,
             const Mapping<dim>                  &mapping,
             const DoFHandler<dim>               &dof_handler,
             const TrilinosWrappers::MPI::Vector &solution,
             const MaterialParameters            &material,
             const MixedBulk<dim>                *mixed = nullptr);

    /**
     * The same at a step of a load path (on the mesh of that step), added
     * to step_values() as the rows of `step` at `time`. Collective.
     */
    void
    evaluate_step(const unsigned int                   step,
                  const double                         time,
                  const Mapping<dim>                  &mapping,
                  const DoFHandler<dim>               &dof_handler,
                  const TrilinosWrappers::MPI::Vector &solution,
                  const MaterialParameters            &material,
                  const MixedBulk<dim>                *mixed = nullptr);

    /** Every value of every cycle so far, by cycle, then by probe. */
    const std::vector<Value> &
    values() const
    {
      return all_values;
    }

    /** Every value of every step so far, by step, then by probe. */
    const std::vector<Value> &
    step_values() const
    {
      return all_step_values;
    }

    /**
     * Write values() as CSV: one row per cycle and probe, the columns
     * cycle, probe, x, y, (z), u_x, u_y, (u_z), sigma_xx, sigma_yy,
     * sigma_zz, sigma_xy, (sigma_xz, sigma_yz), von_mises, and with the
     * pressure field pressure. Call on one rank.
     */
    void
    write_csv(const std::string &filename) const;

    /**
     * step_values() as CSV: one row per step and probe, the columns step,
     * time, then those of write_csv() from probe on. The first call writes
     * the file afresh, a later one appends the rows that came since (a
     * step's cost does not depend on the steps before it). Call on one
     * rank.
     */
    void
    append_step_csv(const std::string &filename);

    /**
     * Go on with the file of append_step_csv() as a checkpoint at step
     * `last_step` left it: its rows of later steps go, and the next call
     * appends (a resumed run; rank 0).
     */
    void
    resume_step_csv(const std::string &filename, const unsigned int last_step);

  private:
    /** The values at every point for `solution`. Collective. */
    std::vector<Value>
    measure(const Mapping<dim>                  &mapping,
            const DoFHandler<dim>               &dof_handler,
            const TrilinosWrappers::MPI::Vector &solution,
            const MaterialParameters            &material,
            const MixedBulk<dim>                *mixed) const;

    /** The columns from probe on: their header, or one value's row. */
    void
    write_header(std::ostream &csv) const;
    void
    write_row(std::ostream &csv, const Value &value) const;

    std::vector<Point<dim>> points;
    bool                    with_pressure;
    std::vector<Value>      all_values;
    std::vector<Value>      all_step_values;
    std::size_t             step_values_written = 0; // by append_step_csv
    bool                    step_csv_started    = false;
  };
} // namespace dualcontact

#endif
