// The dual mortar coupling of two surfaces in 2D (mortar.h): on matching
// segments it is the lumped weight alone; on non-matching ones every slave
// node the master covers sees the master's functions sum to its weight,
// reproduces linear fields, and a uniform multiplier on the slave gives the
// master exactly the nodal forces of a uniform pressure: the contact patch
// test at the interface. Only segments that face each other couple.

#include <dualcontact/mortar.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <tuple>
#include <vector>

using namespace dualcontact;

namespace
{
  /** n equal segments from (x0, y) to (x1, y), nodes 0 to n. */
  std::vector<mortar::Segment>
  line(const double x0, const double x1, const double y, const unsigned int n)
  {
    std::vector<mortar::Segment> segments;
    for (unsigned int i = 0; i < n; ++i)
      {
        mortar::Segment s;
        s.x    = {{Point<2>(x0 + (x1 - x0) * i / n, y),
                   Point<2>(x0 + (x1 - x0) * (i + 1) / n, y)}};
        s.node = {{i, i + 1}};
        segments.push_back(s);
      }
    return segments;
  }

  /** The x coordinate of every node of a line of segments. */
  std::vector<double>
  node_x(const std::vector<mortar::Segment> &segments)
  {
    std::vector<double> x(segments.size() + 1);
    for (const auto &s : segments)
      for (const unsigned int k : {0u, 1u})
        x[s.node[k]] = s.x[k][0];
    return x;
  }
} // namespace

TEST_CASE("Dual mortar on matching segments: the lumped weight alone",
          "[functions][mortar]")
{
  const auto slave  = line(0., 1., 0., 4);
  const auto master = line(0., 1., 0., 4);
  const auto c      = mortar::couple(slave, 5, master);
  for (unsigned int s = 0; s < 5; ++s)
    {
      CHECK(c.weight[s] == Approx((s == 0 || s == 4) ? 0.125 : 0.25));
      for (const auto &[j, m] : c.master[s])
        CHECK(std::abs(m - (j == s ? c.weight[s] : 0.)) <= 1e-15);
      CHECK(c.coverage(s) == Approx(1.).epsilon(1e-14));
    }
}

TEST_CASE("Dual mortar on non-matching segments, 7 over 10: the patch "
          "test at the interface",
          "[functions][mortar]")
{
  // the master 10 segments on [0, 1]; the slave 7 on the same line or, in
  // the second case, on [-0.2, 1.2], a gap of 0.01 apart
  for (const double overhang : {0., 0.2})
    {
      const auto slave    = line(-overhang, 1. + overhang, 0.01, 7);
      const auto master   = line(0., 1., 0., 10);
      const auto c        = mortar::couple(slave, 8, master);
      const auto xs       = node_x(slave);
      const auto xm       = node_x(master);
      const auto m_master = mortar::couple(master, 11, master).weight;
      INFO("overhang " << overhang);
      std::vector<double> force(11, 0.);
      for (unsigned int s = 0; s < 8; ++s)
        {
          double reproduced = 0.;
          for (const auto &[j, m] : c.master[s])
            {
              reproduced += m * xm[j];
              force[j] += m; // the multiplier 1 at every slave node
            }
          INFO("slave node " << s << " at x = " << xs[s] << ", coverage "
                             << c.coverage(s));
          if (overhang == 0.)
            {
              // every node covered: sum_j c_sj = 1, sum_j c_sj x_j = x_s
              CHECK(c.coverage(s) == Approx(1.).epsilon(1e-14));
              CHECK(reproduced == Approx(c.weight[s] * xs[s]).margin(1e-15));
            }
          else if (xs[s] < -1e-12 || xs[s] > 1. + 1e-12)
            {
              // beyond the master's ends: partly covered or not at all
              CHECK(c.coverage(s) < 1.);
            }
        }
      // the master's nodal forces are those of the pressure 1 on it,
      // int phi_j: the uniform pressure crosses the interface exactly
      for (unsigned int j = 0; j < 11; ++j)
        {
          INFO("master node " << j);
          CHECK(force[j] == Approx(m_master[j]).epsilon(1e-13));
        }
    }
}

TEST_CASE("Dual mortar and node to segment couple only segments that face "
          "each other: a master behind the slave, or facing away, adds "
          "nothing",
          "[functions][mortar]")
{
  // the slave: 2 segments on [0, 1] at y = 0, the upper side of a body
  // below (outward normal +y); each master: 3 segments on [0, 1] at height
  // y, the lower side of a body above (outward normal -y) or, facing away,
  // the upper side of one (+y)
  const auto with_normal = [](std::vector<mortar::Segment> segments,
                              const double                 normal_y) {
    for (mortar::Segment &s : segments)
      s.normal[1] = normal_y;
    return segments;
  };
  const auto slave = with_normal(line(0., 1., 0., 2), 1.);
  // (height, normal, whether it couples)
  const std::vector<std::tuple<double, double, bool>> cases = {
    // a gap of 0.01 in front of the slave
    {0.01, -1., true},
    // an overlap of 0.2, less than the segments' length 0.5: the bodies
    // overlap at the start, and the check of the pair must see it
    {-0.2, -1., true},
    // the far side of a body above, 3 behind the slave: it projects onto
    // the slave's line and faces it, but lies behind it
    {-3., -1., false},
    // in front, but the master's outward normal looks the slave's way
    {0.01, 1., false}};
  for (const auto &[y, normal_y, couples] : cases)
    {
      const auto master = with_normal(line(0., 1., y, 3), normal_y);
      INFO("master at y = " << y << " with the normal (0, " << normal_y << ")");
      for (const bool node_to_segment : {false, true})
        {
          INFO((node_to_segment ? "node to segment" : "dual mortar"));
          const auto c = node_to_segment ?
                           mortar::couple_node_to_segment(slave, 3, master) :
                           mortar::couple(slave, 3, master);
          for (unsigned int s = 0; s < 3; ++s)
            {
              INFO("slave node " << s << ", coverage " << c.coverage(s));
              if (couples)
                CHECK(c.coverage(s) == Approx(1.).epsilon(1e-13));
              else
                CHECK(c.master[s].empty());
            }
        }
    }
}
