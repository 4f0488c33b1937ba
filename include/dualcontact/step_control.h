// The times of a load path's later steps: the listed times one after the
// other (fixed control), or, with <Load path/Step control> = adaptive,
// sub-steps toward each listed time that halve when a solve fails and grow
// again after easy steps (doc/theory.md §11).
#ifndef dualcontact_step_control_h
#define dualcontact_step_control_h

#include <cstddef>
#include <string>
#include <vector>

namespace dualcontact
{
  struct LoadPathParameters; // parameters.h

  /**
   * Where a load path goes next. The listed times t_1 < ... < t_N (<Load
   * path/Times>, or the uniform ones) are reached exactly, in turn; t_1 is
   * the first step, solved on every mesh of the refinement cycles.
   *
   * Fixed control takes each listed interval in one step. Adaptive control
   * takes it in steps of (t_i - t_{i-1}) / 2^level: a step whose solve fails
   * is tried again at the next level (half the size), down to the minimum
   * step; after two steps in a row that converged the level goes down by one
   * (twice the size), never below 0, so that a step never spans more than a
   * listed interval, and never beyond the next listed time: a step that would
   * pass it ends there. The level carries over to the next listed interval.
   */
  class StepControl
  {
  public:
    StepControl(const std::vector<double> &listed_times,
                const LoadPathParameters  &parameters);

    /** Every listed time reached. */
    bool
    finished() const;

    /** The time the next step (or its retry) solves at. */
    double
    next_time() const;

    /** The size of the next step, next_time() - the time reached. */
    double
    next_step_size() const;

    /**
     * Which listed time the next step reaches, 2 .. N, or 0 where it ends
     * short of it (a sub-step).
     */
    unsigned int
    next_listed() const;

    /** The time the next step's listed interval ends at. */
    double
    target_time() const;

    /** The next step converged: the path is at next_time(). */
    void
    accept();

    /**
     * The next step failed. Adaptive control halves it and returns true,
     * unless half of it would be smaller than the minimum step; fixed
     * control returns false.
     */
    bool
    cut();

    /** The times the next step has been cut before it converged. */
    unsigned int
    cuts() const
    {
      return n_cuts;
    }

    /** The smallest step that adaptive control tries [time]. */
    double
    minimum_step() const
    {
      return min_step;
    }

    /**
     * <Load path/Minimum step> as the path uses it: the entry, or with
     * 'auto' (0) the shortest listed interval after the first step / 1024.
     */
    static double
    minimum_step(const std::vector<double> &listed_times,
                 const LoadPathParameters  &parameters);

    /**
     * Where the path stands (the listed time it heads for, the time
     * reached, the level and the count of converged steps), as one line of
     * text that load() reads back exactly: a checkpoint's record.
     */
    std::string
    state() const;

    /**
     * Go on from `state`, which the path reached at load step `step`, time
     * `step_time` (a checkpoint's record). False, and nothing changed, if
     * it is not a state that state() writes on this path at that step and
     * time (a damaged record).
     */
    bool
    load(const std::string &state,
         const unsigned int step,
         const double       step_time);

  private:
    double
    interval() const;

    std::vector<double> times;
    bool                adaptive;
    double              min_step;
    std::size_t         next      = 1; // the index of the next listed time
    double              time      = 0.;
    unsigned int        level     = 0;
    unsigned int        converged = 0; // steps in a row since the last cut
    unsigned int        n_cuts    = 0; // of the next step
  };
} // namespace dualcontact

#endif
