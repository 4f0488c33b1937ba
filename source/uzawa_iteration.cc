#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <dualcontact/contact_functions.h>
#include <dualcontact/input_error.h>
#include <dualcontact/parameters.h>
#include <dualcontact/uzawa_iteration.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace dualcontact
{
  namespace
  {
    // sqrt(sum_s g_s^2) over the contact nodes of all ranks
    template <int dim>
    double
    threshold_norm(const ContactSet<dim> &contact, const MPI_Comm comm)
    {
      double sum = 0.;
      for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
        sum += contact.threshold[s] * contact.threshold[s];
      return std::sqrt(Utilities::MPI::sum(sum, comm));
    }
  } // namespace

  template <int dim>
  UzawaIteration<dim>::UzawaIteration(const SolverParameters &parameters,
                                      NewtonSolver<dim>      &newton)
      : parameters(parameters)
      , newton(newton)
  {}

  template <int dim>
  NewtonStatistics
  UzawaIteration<dim>::proximal_step(
    const ContactSystem                 &system,
    const ContactSet<dim>               &contact,
    const TrilinosWrappers::MPI::Vector &v_previous,
    TrilinosWrappers::MPI::Vector       &v,
    const unsigned int                   k,
    IterationObserver                   *observer)
  {
    return newton.minimise(system,
                           contact,
                           v_previous,
                           v,
                           newton_envelope(k),
                           final_newton_tolerance(),
                           k,
                           observer);
  }

  template <int dim>
  IterationRecord
  UzawaIteration<dim>::update_multipliers(
    const ContactSystem                 &system,
    ContactSet<dim>                     &contact,
    const TrilinosWrappers::MPI::Vector &v_previous,
    const TrilinosWrappers::MPI::Vector &v,
    const bool                           update_threshold) const
  {
    const MPI_Comm                  comm = v.get_mpi_communicator();
    std::vector<double>             z;
    std::vector<Tensor<1, dim - 1>> y;
    contact.augmented_state(v, system.r, system.r_t, z, y);

    // sums: |dl1|^2, |l1|^2, |dl2|^2, |l2|^2, |dg|^2, |g|^2
    double                  sums[6] = {0, 0, 0, 0, 0, 0};
    double                  l1_max = 0, violation = 0, complementarity = 0;
    types::global_dof_index counts[3]      = {0, 0, 0}; // active, stick, slip
    const TrilinosWrappers::MPI::Vector &w = contact.with_masters(v);
    for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
      {
        const double l1_new = positive_part(z[s]);
        const double gap =
          contact.nodes[s].gap0 - contact.normal_displacement(w, s);
        sums[0] += std::pow(l1_new - contact.l1[s], 2);
        sums[1] += l1_new * l1_new;
        l1_max          = std::max(l1_max, l1_new);
        violation       = std::max(violation, positive_part(-gap));
        complementarity = std::max(complementarity, l1_new * std::abs(gap));
        contact.l1[s]   = l1_new;
        if (contact.friction)
          {
            // merged threshold iteration: g from the new pressure first, so
            // that |l2| <= g holds
            if (update_threshold)
              {
                const double g_new = contact.threshold_from_pressure(s);
                sums[4] += std::pow(g_new - contact.threshold[s], 2);
                sums[5] += g_new * g_new;
                contact.threshold[s] = g_new;
              }
            const Tensor<1, dim - 1> l2_new =
              project_onto_disc(y[s], contact.threshold[s]);
            sums[2] += (l2_new - contact.l2[s]).norm_square();
            sums[3] += l2_new.norm_square();
            contact.l2[s] = l2_new;
          }
        contact.statuses[s] =
          node_status(l1_new, y[s], contact.threshold[s], contact.friction);
        counts[0] += (contact.statuses[s] != separated);
        if (contact.friction && contact.statuses[s] != separated)
          ++counts[contact.statuses[s]]; // stick 1, slip 2
      }
    Utilities::MPI::sum(ArrayView<const double>(sums, 6),
                        comm,
                        ArrayView<double>(sums, 6));
    Utilities::MPI::sum(ArrayView<const types::global_dof_index>(counts, 3),
                        comm,
                        ArrayView<types::global_dof_index>(counts, 3));
    l1_max          = Utilities::MPI::max(l1_max, comm);
    violation       = Utilities::MPI::max(violation, comm);
    complementarity = Utilities::MPI::max(complementarity, comm);

    IterationRecord record;
    record.loop     = Loop::uzawa;
    record.n_active = counts[0];
    record.n_stick  = counts[1];
    record.n_slip   = counts[2];
    const double l1_norm =
      std::max(std::sqrt(sums[1]), system.previous.l1_norm);
    record.change_l1 = relative_change(std::sqrt(sums[0]), l1_norm);
    // l2 relative to the contact forces, not to itself: where the exact l2
    // is zero (no tangential load, nu = 0) |l2| is round-off, and a change
    // relative to it never falls below the tolerance (doc/theory.md §6)
    record.change_l2 = relative_change(std::sqrt(sums[2]),
                                       std::max(std::sqrt(sums[3]), l1_norm));
    record.change_g  = relative_change(std::sqrt(sums[4]), std::sqrt(sums[5]));
    TrilinosWrappers::MPI::Vector change(v);
    change -= v_previous;
    // without the rigid motions that nothing holds: the problem does not
    // determine v along them, and a change there is no change of the
    // solution (doc/theory.md §6)
    if (system.free_motions != nullptr)
      for (const TrilinosWrappers::MPI::Vector &w : *system.free_motions)
        change.add(-(w * change), w);
    const double v_norm_inf = std::max(v.linfty_norm(), system.previous.v_max);
    record.norm_v           = v.l2_norm();
    record.change_v =
      relative_change(change.l2_norm(),
                      std::max(record.norm_v, system.previous.v_norm));
    record.violation = relative_change(violation, v_norm_inf);
    record.complementarity =
      relative_change(complementarity,
                      std::max(l1_max, system.previous.l1_max) * v_norm_inf);
    return record;
  }

  template <int dim>
  bool
  UzawaIteration<dim>::converged(const IterationRecord &record,
                                 const bool             friction,
                                 const bool             update_threshold,
                                 const double threshold_tolerance) const
  {
    const double tolerance = parameters.uzawa_tolerance;
    return record.change_l1 <= tolerance && record.change_v <= tolerance &&
           record.violation <= tolerance &&
           (!friction || record.change_l2 <= tolerance) &&
           (!update_threshold || record.change_g <= threshold_tolerance);
  }

  namespace
  {
    // The largest of the changes the stopping test looks at.
    double
    largest_change(const IterationRecord &record, const bool friction)
    {
      return std::max(
        {record.change_l1, record.change_v, friction ? record.change_l2 : 0.});
    }

    // The mean contraction rate of the largest change over the last (up
    // to) n steps of `history`; 0 if there are fewer than two steps.
    double
    mean_rate(const std::vector<IterationRecord> &history,
              const bool                          friction,
              const unsigned int                  n)
    {
      if (history.size() < 2)
        return 0.;
      const std::size_t steps = std::min<std::size_t>(n, history.size() - 1);
      const double      last  = largest_change(history.back(), friction);
      const double      first =
        largest_change(history[history.size() - 1 - steps], friction);
      if (!(first > 0.) || !(last > 0.))
        return 0.;
      return std::pow(last / first, 1. / steps);
    }

    /**
     * Whether the second half of the history (at least 20 steps) shows a
     * drift: v grows at each of its last 10 steps, and the steps
     * |v_new - v| have not shrunk by a fifth since its start. A load that
     * nothing balances moves the body by about the same amount at each
     * proximal step (chi M (v_new - v) carries the unbalanced force), so v
     * grows without bound and its changes relative to v fall only like
     * 1/k; a converging iteration shrinks its steps geometrically.
     */
    bool
    drifts(const std::vector<IterationRecord> &history)
    {
      const std::size_t n = history.size();
      if (n < 20)
        return false;
      const IterationRecord &first = history[n / 2], &last = history[n - 1];
      for (std::size_t i = n - 10; i < n; ++i)
        if (!(history[i].norm_v > history[i - 1].norm_v))
          return false;
      return last.norm_v > first.norm_v &&
             last.change_v * last.norm_v >= 0.8 * first.change_v * first.norm_v;
    }

    const std::string drift_cause =
      "v drifts: it grows at every Uzawa step by steps that do not shrink, "
      "which is what a load "
      "that nothing balances does: check that the contact can carry the "
      "loads (their resultant pushes the body onto the obstacle, and their "
      "moment does not tip or roll it off), or hold the body by a "
      "prescribed displacement (<Boundary conditions/Conditions>); more "
      "steps or another <Solver/Augmentation parameter> cannot help";

    /** Pass `text` to the observer, if there is one. */
    void
    note(IterationObserver *observer, const std::string &text)
    {
      if (observer != nullptr)
        observer->note(text);
    }

    /**
     * Some free motions keep the start's value: along them the proximal
     * term pulls toward v_start, not toward the last v. The force along
     * them that a weak hold leaves (between two bodies, the normals'
     * discretisation error) then moves them once by F / chi, not by F / chi
     * in every step; and a body's motion relative to another is not left
     * where the first, inexact Newton solve put it (doc/theory.md §6).
     * Against the obstacle alone, along the motions held by nothing at
     * all, the last v is the anchor.
     */
    void
    anchor_at_start(const ContactSystem                 &system,
                    const TrilinosWrappers::MPI::Vector &v_start,
                    TrilinosWrappers::MPI::Vector       &v_previous)
    {
      if (system.free_motions != nullptr && system.anchored_at_start != nullptr)
        for (unsigned int i = 0; i < system.free_motions->size(); ++i)
          if ((*system.anchored_at_start)[i])
            {
              const TrilinosWrappers::MPI::Vector &w =
                (*system.free_motions)[i];
              v_previous.add(w * v_start - w * v_previous, w);
            }
    }

    /**
     * The relative change of g from `threshold_before`, against the largest
     * of the new g and `threshold_scale`, over the contact nodes of all
     * ranks.
     */
    template <int dim>
    double
    threshold_change_on_path(const ContactSet<dim>     &contact,
                             const std::vector<double> &threshold_before,
                             const double               threshold_scale,
                             const MPI_Comm             comm)
    {
      double sums[2] = {0., 0.};
      for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
        {
          sums[0] += std::pow(contact.threshold[s] - threshold_before[s], 2);
          sums[1] += contact.threshold[s] * contact.threshold[s];
        }
      Utilities::MPI::sum(ArrayView<const double>(sums, 2),
                          comm,
                          ArrayView<double>(sums, 2));
      return relative_change(std::sqrt(sums[0]),
                             std::max(std::sqrt(sums[1]), threshold_scale));
    }

    /** The Newton figures and the time of Uzawa step k into `record`. */
    void
    record_step(IterationRecord        &record,
                const unsigned int      k,
                const NewtonStatistics &newton_statistics,
                const double            time)
    {
      record.uzawa_step      = k;
      record.newton_steps    = newton_statistics.newton_steps;
      record.newton_at_floor = newton_statistics.at_floor;
      record.cg_iterations   = newton_statistics.cg_iterations;
      record.amg_setups      = newton_statistics.amg_setups;
      record.time            = time;
    }

    /**
     * The last step of `history` into the solve's statistics: the counts,
     * the active set, the observed contraction rate and the error it
     * implies.
     */
    void
    add_step(ContactStatistics                  &statistics,
             const std::vector<IterationRecord> &history)
    {
      const std::size_t      k      = history.size();
      const IterationRecord &record = history.back();
      statistics.uzawa_steps        = k;
      statistics.newton_steps += record.newton_steps;
      statistics.cg_iterations += record.cg_iterations;
      statistics.amg_setups += record.amg_setups;
      statistics.n_active = record.n_active;
      statistics.n_stick  = record.n_stick;
      statistics.n_slip   = record.n_slip;
      statistics.change_g = record.change_g;
      if (k > 1 && history[k - 2].change_l1 > 0.)
        statistics.rate =
          std::min(record.change_l1 / history[k - 2].change_l1, 0.999);
      statistics.estimated_l1_error =
        record.change_l1 * statistics.rate / (1. - statistics.rate);
    }
  } // namespace

  template <int dim>
  bool
  UzawaIteration<dim>::at_roundoff_floor(
    const std::vector<IterationRecord> &history,
    const bool                          friction) const
  {
    // The proximal steps no longer improve v (twice in a row the Newton
    // iteration is at its final tolerance and takes no step, or it stops
    // at the round-off floor of its matrix, whose gradient moves the
    // multipliers by round-off at every update), the constraint holds, and
    // the changes of the multipliers do not shrink, within 10^3 of the
    // tolerance or below 1e-8 (a tolerance far below the floor): the rest
    // of them is what the inner solves leave (doc/theory.md §6), and no
    // further Uzawa step can remove it.
    const std::size_t n = history.size();
    if (n < 3 || newton_envelope(n) > final_newton_tolerance())
      return false;
    const IterationRecord &last = history[n - 1], &before = history[n - 2];
    const double           tolerance = parameters.uzawa_tolerance;
    const auto             still     = [](const IterationRecord &record) {
      return record.newton_steps == 0 || record.newton_at_floor;
    };
    return still(last) && still(before) && last.violation <= tolerance &&
           last.complementarity <= tolerance &&
           largest_change(last, friction) <= std::max(1e3 * tolerance, 1e-8) &&
           largest_change(last, friction) >=
             0.5 * largest_change(before, friction);
  }

  template <int dim>
  bool
  UzawaIteration<dim>::contracts_slowly(
    const std::vector<IterationRecord> &history,
    const bool                          friction) const
  {
    // Three steps in a row that each took Newton steps (v moves) and
    // reduced the changes by less than 30 %: a mode of v that hardly any
    // contact term resists converges at about chi / (chi + its stiffness)
    // per step (doc/theory.md §3.2).
    const std::size_t n = history.size();
    if (n < 5)
      return false;
    for (std::size_t i = n - 3; i < n; ++i)
      {
        const double rate = largest_change(history[i], friction) /
                            largest_change(history[i - 1], friction);
        if (history[i].newton_steps == 0 || !(rate > 0.7) || !(rate < 1.05))
          return false;
      }
    return true;
  }

  template <int dim>
  double
  UzawaIteration<dim>::final_newton_tolerance() const
  {
    return parameters.newton_tolerance_factor * parameters.uzawa_tolerance;
  }

  template <int dim>
  double
  UzawaIteration<dim>::newton_envelope(const unsigned int k) const
  {
    return std::max(final_newton_tolerance(),
                    parameters.newton_initial_tolerance *
                      std::pow(parameters.newton_tolerance_reduction, k - 1.));
  }

  template <int dim>
  std::string
  UzawaIteration<dim>::non_convergence_message(
    const std::vector<IterationRecord> &history,
    const bool                          friction,
    const double                        chi_scale) const
  {
    const IterationRecord &last      = history.back();
    const double           tolerance = parameters.uzawa_tolerance;
    const double           rate      = mean_rate(history, friction, 10);
    const double           change    = largest_change(last, friction);
    std::ostringstream     text;
    text << "The Uzawa iteration (loop 2) did not converge in "
         << history.size() << " steps (<Solver/Maximum Uzawa steps>). Last "
         << "step: d(l1) " << format_number(last.change_l1);
    if (friction)
      text << ", d(l2) " << format_number(last.change_l2);
    text << ", d(v) " << format_number(last.change_v) << ", violation "
         << format_number(last.violation) << ", complementarity "
         << format_number(last.complementarity) << " (tolerance "
         << format_number(tolerance) << "); contraction rate "
         << format_number(rate) << " per step over the last 10 steps. Likely "
         << "causes, most likely first: ";

    // whether the active set or the stick/slip split still changes
    bool switching = false;
    for (std::size_t i = history.size() > 10 ? history.size() - 10 : 1;
         i < history.size();
         ++i)
      switching |= history[i].n_active != history[i - 1].n_active ||
                   history[i].n_stick != history[i - 1].n_stick;
    // the violation ten steps ago: if it has not fallen by 10 % since, the
    // constraint is not being met, as opposed to being met slowly
    const IterationRecord &earlier =
      history[history.size() > 10 ? history.size() - 11 : 0];
    std::vector<std::string> causes;
    const bool               drift = drifts(history);
    if (drift)
      causes.push_back(drift_cause);
    if (last.violation > 1e2 * tolerance &&
        last.violation > 0.9 * earlier.violation)
      causes.emplace_back(
        "the contact condition cannot be met (violation " +
        format_number(last.violation) +
        "): check that the foundation can hold the load (its <Foundation/"
        "Point> and <Foundation/Normal>, and the loads)");
    if (rate >= 0.999 || switching)
      causes.emplace_back(
        "the contact or stick/slip status of some nodes keeps switching: "
        "lower <Solver/Augmentation parameter>");
    if (rate > 0.5 && rate < 0.999 && !drift)
      {
        std::ostringstream slow;
        slow << "slow but steady convergence, about "
             << static_cast<long>(
                  std::ceil(std::log(tolerance / change) / std::log(rate)))
             << " more steps needed: raise <Solver/Maximum Uzawa steps>, or "
                "<Solver/Augmentation parameter> (a larger r contracts "
                "faster)";
        if (friction && last.n_stick == 0)
          slow << " (every contact node slips: the tangential load is close "
                  "to what friction can hold, and only the proximal term, "
                  "already lowered to "
               << format_number(chi_scale)
               << " of <Solver/Proximal parameter>, holds the body along the "
                  "foundation)";
        causes.push_back(slow.str());
      }
    if (last.newton_steps == 0 && change <= 1e3 * tolerance)
      causes.emplace_back(
        "the changes are at the round-off floor of the inner solves: raise "
        "<Solver/Uzawa tolerance> or lower <Solver/Newton tolerance factor>");
    if (causes.empty())
      causes.emplace_back("too few steps allowed: raise <Solver/Maximum Uzawa "
                          "steps>, or <Solver/Augmentation parameter>");
    for (std::size_t i = 0; i < causes.size(); ++i)
      text << (i > 0 ? "; " : "") << "(" << i + 1 << ") " << causes[i];
    text << ".";
    return text.str();
  }

  template <int dim>
  NewtonStatistics
  UzawaIteration<dim>::proximal_step_unless_drifting(
    const ContactSystem                 &system,
    const ContactSet<dim>               &contact,
    const TrilinosWrappers::MPI::Vector &v_previous,
    TrilinosWrappers::MPI::Vector       &v,
    const unsigned int                   k,
    IterationObserver                   *observer,
    const std::vector<IterationRecord>  &history)
  {
    try
      {
        return proximal_step(system, contact, v_previous, v, k, observer);
      }
    catch (const ExceptionBase &exception)
      {
        // a Newton failure while v drifts: the drift is the cause
        if (!drifts(history))
          throw;
        std::ostringstream message;
        exception.print_info(message);
        std::string failure = Utilities::trim(message.str());
        failure             = failure.substr(0, failure.find(" Likely causes"));
        AssertThrow(false,
                    ExcMessage("The contact solve cannot converge: " +
                               drift_cause + ". It stopped here: " + failure));
      }
    return NewtonStatistics();
  }

  template <int dim>
  IterationRecord
  UzawaIteration<dim>::update_multipliers_on_path(
    const ContactSystem                 &system,
    ContactSet<dim>                     &contact,
    const TrilinosWrappers::MPI::Vector &v_previous,
    const TrilinosWrappers::MPI::Vector &v,
    const bool                           update_threshold,
    const double                         threshold_scale)
  {
    std::vector<double> threshold_before;
    if (threshold_scale > 0.)
      threshold_before = contact.threshold;
    IterationRecord record =
      update_multipliers(system, contact, v_previous, v, update_threshold);
    // along a path, the change of g against the previous step's g too
    if (threshold_scale > 0.)
      record.change_g = threshold_change_on_path(contact,
                                                 threshold_before,
                                                 threshold_scale,
                                                 v.get_mpi_communicator());
    return record;
  }

  template <int dim>
  bool
  UzawaIteration<dim>::stop_at_roundoff_floor(
    const std::vector<IterationRecord> &history,
    const bool                          friction,
    const bool                          update_threshold,
    const double                        threshold_tolerance,
    ContactStatistics                  &statistics,
    IterationObserver                  *observer) const
  {
    const IterationRecord &record = history.back();
    if (!at_roundoff_floor(history, friction) ||
        (update_threshold &&
         !(record.change_g <=
           std::max(threshold_tolerance, 1e3 * parameters.uzawa_tolerance))))
      return false;
    statistics.at_roundoff_floor = true;
    note(observer,
         "Uzawa: stopped at the round-off floor of the inner "
         "solves, accuracy reached " +
           format_number(largest_change(record, friction)) +
           " (the multipliers' and v's relative changes; <Solver/Uzawa "
           "tolerance> asks " +
           format_number(parameters.uzawa_tolerance) +
           "): the Newton steps no longer improve v, and the violation "
           "(" +
           format_number(record.violation) + ") and complementarity (" +
           format_number(record.complementarity) + ") are below the tolerance");
    return true;
  }

  template <int dim>
  void
  UzawaIteration<dim>::lower_proximal_weight(
    ContactSystem                      &step_system,
    const std::vector<IterationRecord> &history,
    const bool                          friction,
    IterationObserver                  *observer)
  {
    const double rate = mean_rate(history, friction, 3);
    step_system.chi_scale /= 10.;
    newton.reset(); // a new matrix
    note(observer,
         "Uzawa: contraction rate " + format_number(rate) +
           " per step, a mode that hardly any contact term holds: the "
           "proximal weight is lowered to " +
           format_number(step_system.chi_scale) + " chi");
  }

  template <int dim>
  ContactStatistics
  UzawaIteration<dim>::solve(const ContactSystem           &system,
                             ContactSet<dim>               &contact,
                             TrilinosWrappers::MPI::Vector &v,
                             IterationObserver             *observer,
                             const bool                     update_threshold,
                             const double                   threshold_tolerance)
  {
    // a new system: the preconditioner is built afresh unless K is the
    // previous solve's
    newton.reset(system.same_stiffness);
    // this solve's copy of the system: its proximal weight may be lowered
    ContactSystem                       step_system = system;
    ContactStatistics                   statistics;
    TrilinosWrappers::MPI::Vector       v_previous(v);
    const TrilinosWrappers::MPI::Vector v_start(v);
    std::vector<IterationRecord>        history;
    unsigned int                        lowered_at = 0;
    // Merged with the threshold iteration on a later step of a load path:
    // the change of g is measured against the largest of the new g, the
    // step's first one and the previous step's (doc/theory.md §11). Where
    // the path brings the body back to its start, g is round-off, and a
    // change relative to it alone never falls below the tolerance; the
    // step's first g is the predictor's, round-off as well on a path that
    // unloads to zero.
    const double threshold_scale =
      update_threshold && system.previous.l1_norm > 0. ?
        std::max(threshold_norm(contact, v.get_mpi_communicator()),
                 system.previous.g_norm) :
        0.;
    for (unsigned int k = 1; k <= parameters.max_uzawa_steps; ++k)
      {
        Timer timer(v.get_mpi_communicator(), true);
        v_previous = v;
        anchor_at_start(system, v_start, v_previous);
        const NewtonStatistics newton_statistics =
          proximal_step_unless_drifting(
            step_system, contact, v_previous, v, k, observer, history);
        const auto      update_start = std::chrono::steady_clock::now();
        IterationRecord record       = update_multipliers_on_path(step_system,
                                                            contact,
                                                            v_previous,
                                                            v,
                                                            update_threshold,
                                                            threshold_scale);
        statistics.times += newton_statistics.times;
        statistics.times.multipliers +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                        update_start)
            .count();
        timer.stop();
        record_step(record, k, newton_statistics, timer.wall_time());
        if (observer != nullptr)
          observer->uzawa_step(record, contact.friction, update_threshold);
        history.push_back(record);
        add_step(statistics, history);

        if (converged(
              record, contact.friction, update_threshold, threshold_tolerance))
          return statistics;
        if (stop_at_roundoff_floor(history,
                                   contact.friction,
                                   update_threshold,
                                   threshold_tolerance,
                                   statistics,
                                   observer))
          return statistics;
        // A slow, steady contraction: a mode of v that only the proximal
        // term holds. Lower its weight (doc/theory.md §3.2).
        if (contracts_slowly(history, contact.friction) &&
            k >= lowered_at + 4 &&
            step_system.chi_scale > 1.5 * minimum_chi_scale)
          {
            lower_proximal_weight(step_system,
                                  history,
                                  contact.friction,
                                  observer);
            statistics.chi_scale = step_system.chi_scale;
            lowered_at           = k;
          }
      }

    AssertThrow(false,
                ExcMessage(non_convergence_message(history,
                                                   contact.friction,
                                                   step_system.chi_scale)));
    return statistics;
  }

  template class UzawaIteration<2>;
  template class UzawaIteration<3>;
} // namespace dualcontact
