// The force-displacement loop of a load path: a gnuplot script beside
// steps.csv that plots it.
#ifndef dualcontact_report_loop_figure_h
#define dualcontact_report_loop_figure_h

#include <dualcontact/records.h>

#include <string>
#include <vector>

namespace dualcontact
{
  /**
   * Write `directory`/steps.gp, which `gnuplot steps.gp` (run in that
   * folder) turns into steps_loop.svg: the tangential force of the body on
   * the obstacle (steps.csv's obstacle_force_c) against the displacement
   * that drives it (displacement_i_c of a loaded boundary part i, or
   * obstacle_displacement_c). The normal is the axis of the largest
   * contact force at the first step; c is the other axis along which that
   * force varies most over `steps`, and the displacement is the column of
   * the loaded boundary part (or the obstacle) that moves most along c.
   * Call on one rank.
   */
  template <int dim>
  void
  write_loop_script(const std::string              &directory,
                    const std::vector<CycleResult> &steps,
                    const bool                      obstacle_moves);
} // namespace dualcontact

#endif
