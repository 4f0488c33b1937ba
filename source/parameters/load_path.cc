// <Load path>: the times at which the scene is solved, one after the other,
// each step from the state the previous one reached (doc/theory.md §11).
#include <dualcontact/input_error.h>
#include <dualcontact/parameter_helpers.h>
#include <dualcontact/parameters.h>

#include <cmath>

namespace dualcontact
{
  using namespace dealii;

  void
  LoadPathParameters::declare_parameters(EntryDeclarer &declarer)
  {
    declarer.enter_subsection("Load path");
    declarer.declare_entry(
      "Number of steps",
      "1",
      EntryPattern::whole_number(1, 100000),
      "Number of load steps, at the times t = T/n, 2T/n, ..., T with T = "
      "<Load path/End time> [-]. The tractions, the displacements, the body "
      "force and the obstacle's displacement may depend on t; each step "
      "starts from the state the previous one reached, and friction acts on "
      "the slip of the step. 1: one static solve at t = T.");
    declarer.declare_entry(
      "End time",
      "1",
      EntryPattern::number(0.),
      "The time T of the last step of a uniform path [time]: t is the "
      "parameter of the loading (no inertia, no rate in the friction law), "
      "in whatever unit the expressions use.");
    declarer.declare_entry(
      "Times",
      "",
      EntryPattern::list(EntryPattern::number(0.)),
      "The times of the steps, an increasing list (t_1, t_2, ...) [time]; "
      "when given, it replaces <Load path/Number of steps> and <Load "
      "path/End time>. A path that starts with a small step (0.001, 0.1, "
      "0.2, ..., 1) loads gradually from the undeformed state.");
    declarer.declare_entry(
      "Adapt at every step",
      "false",
      EntryPattern::boolean(),
      "false: the refinement cycles run at the first step and the finest "
      "mesh serves every later step. true: before every later step the mesh "
      "is adapted once (<Refinement/Strategy>, refine and coarsen fractions) "
      "from the solution of the previous step, which is carried across with "
      "the multipliers and the friction history. The mesh keeps about its "
      "size when <Refinement/Coarsen fraction> is 2^dim times <Refinement/"
      "Refine fraction> (e.g. 0.1 and 0.4 in 2D); with less coarsening it "
      "grows at every step, and a path whose last mesh would not fit in the "
      "memory is refused before it starts.");
    declarer.declare_entry(
      "Output interval",
      "1",
      EntryPattern::whole_number(1),
      "Write the fields of every n-th step and of the last (contact_step_*.csv "
      "and, with <Output/Write vtu>, the .vtu files) [-]; steps.csv gets "
      "every step.");
    declarer.declare_entry(
      "Predictor",
      "true",
      EntryPattern::boolean(),
      "true: a later step starts from the linear extrapolation of the last "
      "two steps (v, the multipliers and the threshold), where the loads "
      "keep their direction, and from the last step's state where they turn "
      "(and at the second step, and on a mesh adapted for the step). false: "
      "every later step starts from the last step's state. Only the cost "
      "differs: steps.csv's column predictor has the factor of the "
      "extrapolation (0: none), uzawa_steps what the step took.");
    declarer.declare_entry(
      "Step control",
      "fixed",
      EntryPattern::selection("fixed|adaptive"),
      "fixed: each later step goes from one listed time to the next, and a "
      "step whose solve fails (the Uzawa, Newton or threshold limit, CG, a "
      "non-finite value) ends the run. adaptive: such a step is tried again "
      "at half its size (or less), down to <Load path/Minimum step>, and "
      "after two steps in a row that converged the size doubles again, up "
      "to the listed step; no step goes past the next listed time, and the "
      "fields are written at the listed times (<Load path/Output interval> "
      "counts listed times). Each sub-step is a row of steps.csv (columns "
      "step_size, cuts and listed). A load the obstacle cannot hold ends "
      "the run with exit 7 either way: a smaller step cannot help.");
    declarer.declare_entry(
      "Minimum step",
      "auto",
      EntryPattern::text(),
      "The smallest step adaptive control tries [time]: 'auto' or a number "
      "> 0. 'auto' is the shortest listed step after the first / 1024 (ten "
      "halvings). A step that fails at this size ends the run. It must be "
      "smaller than every listed step after the first.");
    declarer.leave_subsection();
  }

  void
  LoadPathParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Load path");
    n_steps             = prm.get_integer("Number of steps");
    end_time            = prm.get_double("End time");
    times               = parse_doubles(prm.get("Times"));
    adapt_at_every_step = prm.get_bool("Adapt at every step");
    output_interval     = prm.get_integer("Output interval");
    predictor           = prm.get_bool("Predictor");
    adaptive_steps      = prm.get("Step control") == "adaptive";
    minimum_step =
      parse_auto_or_positive(prm.get("Minimum step"), "Load path/Minimum step");
    prm.leave_subsection();
  }

  std::vector<double>
  LoadPathParameters::step_times() const
  {
    if (!times.empty())
      return times;
    std::vector<double> uniform(n_steps);
    // the fraction first: T (n + 1) would overflow for T near the largest
    // double, while T ((n + 1) / N) <= T stays finite
    for (unsigned int n = 0; n < n_steps; ++n)
      uniform[n] = end_time * (static_cast<double>(n + 1) / n_steps);
    return uniform;
  }

  void
  LoadPathParameters::check(const Parameters &) const
  {
    for (std::size_t n = 1; n < times.size(); ++n)
      if (!(times[n] > times[n - 1]))
        throw InputError("The entry <Load path/Times> must increase: " +
                           number_text(times[n]) + " follows " +
                           number_text(times[n - 1]) + ".",
                         exit_invalid_value);
    if (times.empty() && !(end_time > 0.))
      throw InputError("The entry <Load path/End time> must be greater than "
                       "0.",
                       exit_invalid_value);
    // a minimum step that no listed step exceeds could never cut that step
    if (adaptive_steps && minimum_step > 0.)
      {
        const std::vector<double> t = step_times();
        for (std::size_t n = 1; n < t.size(); ++n)
          if (!(minimum_step < t[n] - t[n - 1]))
            throw InputError(
              "The entry <Load path/Minimum step> (" +
                number_text(minimum_step) +
                ") must be smaller than every listed step after the first, "
                "but the step from t = " +
                number_text(t[n - 1]) + " to " + number_text(t[n]) + " is " +
                number_text(t[n] - t[n - 1]) +
                ": adaptive <Load path/Step control> could not cut it. Set a "
                "smaller minimum step, or 'auto'.",
              exit_inconsistent);
      }
  }

  std::vector<IneffectiveRule>
  LoadPathParameters::ineffective_rules(const Parameters &) const
  {
    const bool one_step = step_times().size() == 1;
    return {{!times.empty(),
             "Load path",
             {"Number of steps", "End time"},
             "<Load path/Times> gives the times"},
            {one_step,
             "Load path",
             {"Adapt at every step",
              "Output interval",
              "Predictor",
              "Step control",
              "Minimum step"},
             "the path has one step"},
            {!one_step && !adaptive_steps,
             "Load path",
             {"Minimum step"},
             "<Load path/Step control> is fixed: no step is cut"},
            {!one_step && adapt_at_every_step,
             "Load path",
             {"Predictor"},
             "<Load path/Adapt at every step> gives each step a mesh of its "
             "own, on which no earlier step was solved"}};
  }
} // namespace dualcontact
