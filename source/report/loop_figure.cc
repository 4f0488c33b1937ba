#include "loop_figure.h"

#include <algorithm>
#include <cmath>
#include <fstream>

namespace dualcontact
{
  namespace
  {
    // the spread max - min of f(step) over the steps
    template <typename F>
    double
    spread(const std::vector<CycleResult> &steps, const F &f)
    {
      double lowest = 0., highest = 0.;
      for (const CycleResult &r : steps)
        {
          lowest  = std::min(lowest, f(r));
          highest = std::max(highest, f(r));
        }
      return highest - lowest;
    }
  } // namespace

  template <int dim>
  void
  write_loop_script(const std::string              &directory,
                    const std::vector<CycleResult> &steps,
                    const bool                      obstacle_moves)
  {
    if (steps.empty())
      return;
    static const char axes[] = "xyz";

    // the normal: the axis of the largest contact force at the first step
    unsigned int normal = 0;
    for (unsigned int c = 1; c < dim; ++c)
      if (std::abs(steps[0].zone.resultant[c]) >
          std::abs(steps[0].zone.resultant[normal]))
        normal = c;
    // the tangential axis along which the force varies most
    unsigned int axis       = normal == 0 ? 1 : 0;
    double       force_span = -1.;
    for (unsigned int c = 0; c < dim; ++c)
      if (c != normal)
        {
          const double s = spread(steps, [c](const CycleResult &r) {
            return r.zone.resultant[c];
          });
          if (s > force_span)
            {
              force_span = s;
              axis       = c;
            }
        }
    // the displacement that moves most along it
    const std::string component(1, axes[axis]);
    std::string       column, label;
    double            span = -1.;
    if (obstacle_moves)
      {
        span   = spread(steps, [axis](const CycleResult &r) {
          return r.step.obstacle_displacement[axis];
        });
        column = "obstacle_displacement_" + component;
        label  = component + "-displacement of the obstacle";
      }
    for (const auto &[id, u] : steps[0].step.boundary_displacement)
      {
        const types::boundary_id part = id;
        const double s = spread(steps, [axis, part](const CycleResult &r) {
          const auto found = r.step.boundary_displacement.find(part);
          return found == r.step.boundary_displacement.end() ?
                   0. :
                   found->second[axis];
        });
        if (s > span)
          {
            span   = s;
            column = "displacement_" + std::to_string(id) + "_" + component;
            label  = "mean " + component + "-displacement of boundary " +
                    std::to_string(id);
          }
      }
    if (column.empty()) // nothing loaded moves: the load against the time
      {
        column = "time";
        label  = "time t";
      }

    std::ofstream gp(directory + "/steps.gp");
    gp << "# The force-displacement loop of the load path in steps.csv (one\n"
       << "# point per step): run 'gnuplot steps.gp' in this folder, which\n"
       << "# writes steps_loop.svg. Any two columns of steps.csv plot the "
          "same way.\n"
       << "set datafile separator ','\n"
       << "set terminal svg size 720,480 dynamic font 'sans,12'\n"
       << "set output 'steps_loop.svg'\n"
       << "set xlabel '" << label << "'\n"
       << "set ylabel '" << component << "-force of the body on the obstacle'\n"
       << "set grid\n"
       << "set key off\n"
       << "plot 'steps.csv' using (column('" << column
       << "')):(column('obstacle_force_" << component
       << "')) with linespoints pointtype 7 pointsize 0.6\n";
  }

  template void
  write_loop_script<2>(const std::string &,
                       const std::vector<CycleResult> &,
                       const bool);
  template void
  write_loop_script<3>(const std::string &,
                       const std::vector<CycleResult> &,
                       const bool);
} // namespace dualcontact
