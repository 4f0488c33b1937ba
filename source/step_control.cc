// The times of a load path's later steps (step_control.h).
#include <dualcontact/parameters.h>
#include <dualcontact/step_control.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace dualcontact
{
  StepControl::StepControl(const std::vector<double> &listed_times,
                           const LoadPathParameters  &parameters)
      : times(listed_times)
      , adaptive(parameters.adaptive_steps)
      , min_step(minimum_step(listed_times, parameters))
      , time(listed_times.front())
  {}

  double
  StepControl::minimum_step(const std::vector<double> &listed_times,
                            const LoadPathParameters  &parameters)
  {
    if (parameters.minimum_step > 0.)
      return parameters.minimum_step;
    double shortest = std::numeric_limits<double>::max();
    for (std::size_t i = 1; i < listed_times.size(); ++i)
      shortest = std::min(shortest, listed_times[i] - listed_times[i - 1]);
    return listed_times.size() > 1 ? shortest / 1024. : 0.;
  }

  bool
  StepControl::finished() const
  {
    return next >= times.size();
  }

  double
  StepControl::interval() const
  {
    return times[next] - times[next - 1];
  }

  double
  StepControl::target_time() const
  {
    return times[next];
  }

  double
  StepControl::next_time() const
  {
    const double size = std::ldexp(interval(), -static_cast<int>(level));
    // a step that would end at (or within round-off of) the listed time, or
    // beyond it, ends there: the listed times are reached exactly
    if (time + size >= times[next] - 1e-12 * interval())
      return times[next];
    return time + size;
  }

  double
  StepControl::next_step_size() const
  {
    return next_time() - time;
  }

  unsigned int
  StepControl::next_listed() const
  {
    return next_time() == times[next] ? next + 1 : 0;
  }

  void
  StepControl::accept()
  {
    const double reached = next_time();
    if (reached == times[next])
      ++next;
    time   = reached;
    n_cuts = 0;
    if (adaptive && ++converged == 2 && level > 0)
      {
        --level;
        converged = 0;
      }
    if (converged >= 2)
      converged = 0;
  }

  bool
  StepControl::cut()
  {
    // half the size that failed, also where it was the rest of an interval
    const double half = next_step_size() / 2.;
    if (!adaptive || half < min_step)
      return false;
    while (std::ldexp(interval(), -static_cast<int>(level)) > half)
      ++level;
    ++n_cuts;
    converged = 0;
    return true;
  }
  std::string
  StepControl::state() const
  {
    std::ostringstream out;
    out << std::setprecision(17) << next << ' ' << time << ' ' << level << ' '
        << converged;
    return out.str();
  }

  bool
  StepControl::load(const std::string &state,
                    const unsigned int step,
                    const double       step_time)
  {
    std::istringstream in(state);
    std::size_t        next_read      = 0;
    double             time_read      = 0.;
    unsigned int       level_read     = 0;
    unsigned int       converged_read = 0;
    in >> next_read >> time_read >> level_read >> converged_read;
    if (!in || !(in >> std::ws).eof())
      return false;
    // a state that accept() leaves: a time from the listed time it left
    // (included) to the one it heads for, the step's own; at least as many
    // steps as listed times passed (as many without sub-steps); a count of
    // converged steps below 2; and a level that a cut can reach (one
    // beyond it would take steps that do not move the path on)
    if (next_read < 1 || next_read >= times.size() ||
        !(times[next_read - 1] <= time_read && time_read < times[next_read]) ||
        time_read != step_time || step < next_read ||
        (!adaptive && step != next_read) || converged_read > 1)
      return false;
    double longest = 0.;
    for (std::size_t i = 1; i < times.size(); ++i)
      longest = std::max(longest, times[i] - times[i - 1]);
    if ((!adaptive && level_read > 0) ||
        std::ldexp(longest, -static_cast<int>(std::min(level_read, 2000u))) <
          min_step / 2.)
      return false;
    next      = next_read;
    time      = time_read;
    level     = level_read;
    converged = converged_read;
    n_cuts    = 0;
    return true;
  }
} // namespace dualcontact
