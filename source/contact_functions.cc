#include <dualcontact/contact_functions.h>
#include <dualcontact/input_error.h>

#include <algorithm>
#include <cmath>
#include <limits>

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

  namespace
  {
    /**
     * Half the extent of the longest run of sticking nodes in `line`
     * (sorted by position), each end half-way to the next node of the line.
     */
    double
    stick_half_width(const std::vector<std::pair<double, unsigned int>> &line)
    {
      double best = 0.;
      for (std::size_t first = 0; first < line.size();)
        {
          if (line[first].second != 1)
            {
              ++first;
              continue;
            }
          std::size_t last = first;
          while (last + 1 < line.size() && line[last + 1].second == 1)
            ++last;
          const double lower =
            first > 0 ? 0.5 * (line[first - 1].first + line[first].first) :
                        line[first].first;
          const double upper =
            last + 1 < line.size() ?
              0.5 * (line[last].first + line[last + 1].first) :
              line[last].first;
          best  = std::max(best, 0.5 * (upper - lower));
          first = last + 1;
        }
      return best;
    }
  } // namespace

  ContactZoneShape
  contact_zone_shape(const std::vector<ZoneNode> &nodes,
                     const unsigned int           tangent_dimensions,
                     const double                 band)
  {
    ContactZoneShape shape;
    double           smallest_gap = std::numeric_limits<double>::max();
    for (const ZoneNode &node : nodes)
      if (node.l1 > 0.)
        {
          shape.area += node.weight;
          smallest_gap = std::min(smallest_gap, node.gap0);
        }
    if (!(shape.area > 0.))
      return shape;

    // the centre: where the contact begins, i.e. among the active nodes
    // with the smallest initial gap (ties within round-off of the mesh
    // size: a flat face) the one nearest their pressure-weighted centroid
    const auto first_contact = [&](const ZoneNode &node) {
      return node.l1 > 0. && node.gap0 <= smallest_gap + 1e-10 * band;
    };
    double centroid[2] = {0., 0.}, force = 0.;
    for (const ZoneNode &node : nodes)
      if (first_contact(node))
        {
          force += node.weight * node.l1;
          for (unsigned int k = 0; k < 2; ++k)
            centroid[k] += node.weight * node.l1 * node.t[k];
        }
    double nearest = std::numeric_limits<double>::max();
    for (const ZoneNode &node : nodes)
      if (first_contact(node))
        {
          const double d = std::hypot(node.t[0] - centroid[0] / force,
                                      node.t[1] - centroid[1] / force);
          if (d < nearest)
            {
              nearest      = d;
              shape.centre = node.t;
            }
        }
    for (const ZoneNode &node : nodes)
      if (node.l1 > 0.)
        shape.extent = std::max(shape.extent,
                                std::hypot(node.t[0] - shape.centre[0],
                                           node.t[1] - shape.centre[1]));

    // one line per tangent axis: the nodes within `band` of it
    struct LineNode
    {
      double       position, l1;
      unsigned int status;
      bool
      operator<(const LineNode &other) const
      {
        return position < other.position;
      }
    };
    const unsigned int n_lines = tangent_dimensions;
    for (unsigned int axis = 0; axis < n_lines; ++axis)
      {
        const unsigned int    across = 1 - axis;
        const double          c      = shape.centre[axis];
        std::vector<LineNode> line;
        bool                  below = false, above = false;
        for (const ZoneNode &node : nodes)
          if (tangent_dimensions == 1 ||
              std::abs(node.t[across] - shape.centre[across]) <= band)
            {
              line.push_back({node.t[axis], node.l1, node.status});
              below = below || node.t[axis] < c - band;
              above = above || node.t[axis] > c + band;
            }
        // a line that stops at the centre: the model is cut there by a
        // plane of symmetry, and the line is completed by its mirror image
        if (below != above)
          {
            ++shape.mirrored;
            for (std::size_t i = 0, n = line.size(); i < n; ++i)
              if (std::abs(line[i].position - c) > band)
                line.push_back(
                  {2. * c - line[i].position, line[i].l1, line[i].status});
          }
        std::sort(line.begin(), line.end());
        std::vector<std::pair<double, double>>       pressures;
        std::vector<std::pair<double, unsigned int>> statuses;
        for (const LineNode &node : line)
          {
            pressures.emplace_back(node.position, node.l1);
            statuses.emplace_back(node.position, node.status);
          }
        const ContactZoneWidth width = contact_zone_half_width(pressures);
        shape.width.nodes += width.nodes / n_lines;
        shape.width.extrapolated += width.extrapolated / n_lines;
        shape.stick_width += stick_half_width(statuses) / n_lines;
      }
    // the whole zone's measure: twice the model's per cut
    shape.area *= std::pow(2., shape.mirrored);
    return shape;
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
    // friction resists a tangential force of at most `capacity` in any
    // direction (a disc, not a square of the tangent axes): the length of
    // the free tangential load counts
    double squares = 0.;
    for (const double tangential : balance.tangential_loads)
      squares += tangential * tangential;
    const double tangential = std::sqrt(squares);
    if (tangential > capacity * (1. + 1e-10) + scale)
      throw InputError("No equilibrium: the net tangential load " +
                         std::to_string(tangential) +
                         (balance.tangential_loads.size() > 1 ?
                            " (the length of its vector in the tangent "
                            "plane)" :
                            "") +
                         " exceeds what friction can resist, " +
                         std::to_string(capacity) + " (" + capacity_text +
                         "), and only friction holds the body along the "
                         "obstacle.",
                       exit_no_equilibrium);
  }

  namespace
  {
    // (b - a) x (c - a): > 0 if a, b, c turn counter-clockwise
    double
    turn(const std::array<double, 2> &a,
         const std::array<double, 2> &b,
         const std::array<double, 2> &c)
    {
      return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    }

    // distance of p from the segment [a, b]
    double
    segment_distance(const std::array<double, 2> &p,
                     const std::array<double, 2> &a,
                     const std::array<double, 2> &b)
    {
      const double dx = b[0] - a[0], dy = b[1] - a[1];
      const double length2 = dx * dx + dy * dy;
      double       t       = 0.;
      if (length2 > 0.)
        t = std::clamp(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length2,
                       0.,
                       1.);
      return std::hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
    }
  } // namespace

  std::vector<std::array<double, 2>>
  convex_hull(std::vector<std::array<double, 2>> points,
              const unsigned int                 dims)
  {
    if (points.empty())
      return points;
    if (dims == 1)
      {
        const auto [low, high] =
          std::minmax_element(points.begin(),
                              points.end(),
                              [](const auto &a, const auto &b) {
                                return a[0] < b[0];
                              });
        return {std::array<double, 2>{{(*low)[0], 0.}},
                std::array<double, 2>{{(*high)[0], 0.}}};
      }
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (points.size() < 3)
      return points;
    // lower hull left to right, then upper hull right to left
    std::vector<std::array<double, 2>> hull(2 * points.size());
    std::size_t                        k = 0;
    for (std::size_t i = 0; i < points.size(); ++i)
      {
        while (k >= 2 && turn(hull[k - 2], hull[k - 1], points[i]) <= 0.)
          --k;
        hull[k++] = points[i];
      }
    for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;)
      {
        while (k >= lower && turn(hull[k - 2], hull[k - 1], points[i]) <= 0.)
          --k;
        hull[k++] = points[i];
      }
    hull.resize(k - 1); // the last point is the first
    return hull;
  }

  double
  distance_outside_hull(const std::vector<std::array<double, 2>> &hull,
                        const std::array<double, 2>              &point,
                        const unsigned int                        dims)
  {
    if (hull.empty())
      return std::numeric_limits<double>::infinity();
    if (dims == 1)
      return std::max(
        {hull.front()[0] - point[0], point[0] - hull.back()[0], 0.});
    if (hull.size() < 3) // a point or a segment
      return segment_distance(point, hull.front(), hull.back());
    bool inside = true;
    for (std::size_t i = 0; i < hull.size(); ++i)
      inside =
        inside && turn(hull[i], hull[(i + 1) % hull.size()], point) >= 0.;
    if (inside)
      return 0.;
    double distance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < hull.size(); ++i)
      distance =
        std::min(distance,
                 segment_distance(point, hull[i], hull[(i + 1) % hull.size()]));
    return distance;
  }
} // namespace dualcontact
