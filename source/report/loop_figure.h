// The force-displacement loop of a load path: a gnuplot script beside
// steps.csv that plots it.
#ifndef dualcontact_report_loop_figure_h
#define dualcontact_report_loop_figure_h

#include <deal.II/base/types.h>

#include <dualcontact/records.h>

#include <array>
#include <map>
#include <string>

namespace dualcontact
{
  /**
   * The script steps.gp, which `gnuplot steps.gp` (run in the output
   * folder) turns into steps_loop.svg: the tangential force of the body on
   * the obstacle (steps.csv's obstacle_force_c) against the displacement
   * that drives it (displacement_i_c of a loaded boundary part i, or
   * obstacle_displacement_c). The normal is the axis of the largest
   * contact force at the first step; c is the other axis along which that
   * force varies most over the steps, and the displacement is the column
   * of the loaded boundary part (or the obstacle) that moves most along c.
   * Each step updates the ranges of these figures, so that a step costs
   * the same however many came before.
   */
  template <int dim>
  class LoopFigure
  {
  public:
    /** The figures of one more step. */
    void
    add(const CycleResult &step);

    /** Write `directory`/steps.gp for the steps so far. Call on one rank. */
    void
    write(const std::string &directory, const bool obstacle_moves) const;

    /**
     * The figures' ranges as one line of text, which load() reads back
     * exactly (a checkpoint's record: a resumed run's steps.gp spans the
     * steps before it too).
     */
    std::string
    state() const;

    /** False, and nothing changed, if `state` is not one state() writes. */
    bool
    load(const std::string &state);

  private:
    /** The span of a figure over the steps, 0 included. */
    struct Range
    {
      double lowest  = 0.;
      double highest = 0.;
      void
      add(const double value);
      double
      spread() const
      {
        return highest - lowest;
      }
    };

    bool                                                 empty  = true;
    unsigned int                                         normal = 0;
    std::array<Range, dim>                               force;
    std::array<Range, dim>                               obstacle;
    std::map<types::boundary_id, std::array<Range, dim>> boundary;
  };
} // namespace dualcontact

#endif
