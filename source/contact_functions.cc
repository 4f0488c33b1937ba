#include <dualcontact/contact_functions.h>
#include <dualcontact/input_error.h>

#include <algorithm>
#include <cmath>

namespace dualcontact
{
  double
  exact_line_search(
    const std::function<std::pair<double, double>(double)> &derivatives)
  {
    const double slope = derivatives(0.).first; // < 0
    double       lower = 0., upper = 1.;
    while (derivatives(upper).first < 0. && upper < 1e6)
      {
        lower = upper;
        upper *= 4.;
      }
    double alpha = upper;
    for (unsigned int it = 0; it < 50; ++it)
      {
        const auto [d1, d2] = derivatives(alpha);
        if (std::abs(d1) <= 1e-12 * std::abs(slope) ||
            upper - lower <= 1e-12 * upper)
          break;
        (d1 > 0. ? upper : lower) = alpha;
        const double next         = alpha - d1 / d2;
        alpha = (next > lower && next < upper) ? next : 0.5 * (lower + upper);
      }
    return alpha;
  }

  ContactZoneWidth
  contact_zone_half_width(const std::vector<std::pair<double, double>> &nodes)
  {
    ContactZoneWidth width;
    std::size_t      first = 0, last = nodes.size();
    while (first < nodes.size() && !(nodes[first].second > 0.))
      ++first;
    while (last > first && !(nodes[last - 1].second > 0.))
      --last;
    if (last == first)
      return width;
    width.nodes = 0.5 * (nodes[last - 1].first - nodes[first].first);
    if (last - first < 2)
      {
        width.extrapolated = width.nodes;
        return width;
      }
    // the edge beyond `outer` (active) toward `beyond` (separated), where
    // the line through (t, l1^2) of `inner` and `outer` reaches zero
    const auto edge = [](const std::pair<double, double> &outer,
                         const std::pair<double, double> &inner,
                         const std::pair<double, double> &beyond) {
      const double p2_outer = outer.second * outer.second;
      const double p2_inner = inner.second * inner.second;
      if (!(p2_inner > p2_outer))
        return outer.first;
      const double t = outer.first + (outer.first - inner.first) * p2_outer /
                                       (p2_inner - p2_outer);
      return std::clamp(t,
                        std::min(outer.first, beyond.first),
                        std::max(outer.first, beyond.first));
    };
    const double lower =
      first > 0 ? edge(nodes[first], nodes[first + 1], nodes[first - 1]) :
                  nodes[first].first;
    const double upper = last < nodes.size() ?
                           edge(nodes[last - 1], nodes[last - 2], nodes[last]) :
                           nodes[last - 1].first;
    width.extrapolated = 0.5 * (upper - lower);
    return width;
  }

  void
  check_equilibrium(const LoadBalance &balance,
                    const double       capacity,
                    const std::string &capacity_text)
  {
    // loads below round-off of the resultant count as zero
    const double scale = 1e-10 * balance.resultant;
    if (balance.normal_free && balance.load_away > scale)
      throw InputError(
        "No equilibrium: the net load pulls the body away from the obstacle "
        "(" +
          std::to_string(balance.load_away) +
          " along the obstacle's normal) and only the contact could hold it "
          "in that direction.",
        exit_no_equilibrium);
    if (capacity < 0.)
      return;
    for (const double tangential : balance.tangential_loads)
      if (tangential > capacity * (1. + 1e-10) + scale)
        throw InputError("No equilibrium: the net tangential load " +
                           std::to_string(tangential) +
                           " exceeds what friction can resist, " +
                           std::to_string(capacity) + " (" + capacity_text +
                           "), and only friction holds the body along the "
                           "obstacle.",
                         exit_no_equilibrium);
  }
} // namespace dualcontact
