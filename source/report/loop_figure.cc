#include "loop_figure.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace dualcontact
{
  template <int dim>
  void
  LoopFigure<dim>::Range::add(const double value)
  {
    lowest  = std::min(lowest, value);
    highest = std::max(highest, value);
  }

  template <int dim>
  void
  LoopFigure<dim>::add(const CycleResult &step)
  {
    if (empty)
      {
        // the normal: the axis of the largest contact force at the first
        // step; the loaded parts: those the first step has
        for (unsigned int c = 1; c < dim; ++c)
          if (std::abs(step.zone.resultant[c]) >
              std::abs(step.zone.resultant[normal]))
            normal = c;
        for (const auto &[id, u] : step.step.boundary_displacement)
          boundary[id] = {};
        empty = false;
      }
    for (unsigned int c = 0; c < dim; ++c)
      {
        force[c].add(step.zone.resultant[c]);
        obstacle[c].add(step.step.obstacle_displacement[c]);
      }
    for (auto &[id, ranges] : boundary)
      {
        const auto found = step.step.boundary_displacement.find(id);
        for (unsigned int c = 0; c < dim; ++c)
          ranges[c].add(found == step.step.boundary_displacement.end() ?
                          0. :
                          found->second[c]);
      }
  }

  template <int dim>
  std::string
  LoopFigure<dim>::state() const
  {
    std::ostringstream out;
    out << std::setprecision(17) << empty << ' ' << normal;
    for (unsigned int c = 0; c < dim; ++c)
      out << ' ' << force[c].lowest << ' ' << force[c].highest << ' '
          << obstacle[c].lowest << ' ' << obstacle[c].highest;
    out << ' ' << boundary.size();
    for (const auto &[id, ranges] : boundary)
      {
        out << ' ' << id;
        for (const Range &range : ranges)
          out << ' ' << range.lowest << ' ' << range.highest;
      }
    return out.str();
  }

  template <int dim>
  bool
  LoopFigure<dim>::load(const std::string &state)
  {
    // read into a copy: a state that state() does not write changes nothing
    LoopFigure<dim>    read;
    std::istringstream in(state);
    in >> read.empty >> read.normal;
    for (unsigned int c = 0; c < dim; ++c)
      in >> read.force[c].lowest >> read.force[c].highest >>
        read.obstacle[c].lowest >> read.obstacle[c].highest;
    std::size_t n_boundaries = 0;
    in >> n_boundaries;
    for (std::size_t b = 0; b < n_boundaries && in; ++b)
      {
        types::boundary_id id = 0;
        in >> id;
        for (Range &range : read.boundary[id])
          in >> range.lowest >> range.highest;
      }
    // every range spans 0 (Range::add() starts from it)
    const auto spans_zero = [](const std::array<Range, dim> &ranges) {
      for (const Range &range : ranges)
        if (!(range.lowest <= 0. && 0. <= range.highest))
          return false;
      return true;
    };
    bool whole = in && (in >> std::ws).eof() && read.normal < dim &&
                 read.boundary.size() == n_boundaries &&
                 spans_zero(read.force) && spans_zero(read.obstacle);
    for (const auto &[id, ranges] : read.boundary)
      whole = whole && spans_zero(ranges);
    if (whole)
      *this = read;
    return whole;
  }

  template <int dim>
  void
  LoopFigure<dim>::write(const std::string &directory,
                         const bool         obstacle_moves) const
  {
    if (empty)
      return;
    static const char axes[] = "xyz";

    // the tangential axis along which the force varies most
    unsigned int axis       = normal == 0 ? 1 : 0;
    double       force_span = -1.;
    for (unsigned int c = 0; c < dim; ++c)
      if (c != normal && force[c].spread() > force_span)
        {
          force_span = force[c].spread();
          axis       = c;
        }
    // the displacement that moves most along it
    const std::string component(1, axes[axis]);
    std::string       column, label;
    double            span = -1.;
    if (obstacle_moves)
      {
        span   = obstacle[axis].spread();
        column = "obstacle_displacement_" + component;
        label  = component + "-displacement of the obstacle";
      }
    for (const auto &[id, ranges] : boundary)
      if (ranges[axis].spread() > span)
        {
          span   = ranges[axis].spread();
          column = "displacement_" + std::to_string(id) + "_" + component;
          label  = "mean " + component + "-displacement of boundary " +
                  std::to_string(id);
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

  template class LoopFigure<2>;
  template class LoopFigure<3>;
} // namespace dualcontact
