// The dual mortar coupling of two surfaces in 3D (mortar_3d.h): on matching
// faces it is the lumped weight alone; on non-matching flat grids of
// quadrilaterals, triangles or both, tilted or not, touching or a little
// apart, every slave node the master covers sees the master's functions sum
// to its weight and reproduces linear fields, and a uniform multiplier on
// the slave gives the master exactly the nodal forces of a uniform pressure
// (the contact patch test at the interface); a slave node beyond the master
// sees the covered part of its dual function; the dual basis of a
// quadrilateral that is not a parallelogram is still biorthogonal;
// between a ball and a spherical socket the coverage is near one; and only
// faces that face each other couple.

#include <deal.II/base/quadrature_lib.h>

#include <dualcontact/mortar_3d.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <tuple>
#include <vector>

using namespace dualcontact;

namespace
{
  /** The faces of a surface and the positions of its nodes. */
  struct Surface
  {
    std::vector<mortar::Face> faces;
    std::vector<Point<3>>     nodes;
  };

  /**
   * An n x n grid of the square [lo, hi]^2 at height z with the normal
   * (0, 0, normal_z): quadrilaterals (split 0), or each square cut into two
   * triangles along its diagonal from vertex 0 to 3 (split 1) or from 1 to 2
   * (split 2). Node (i, j) is number j (n + 1) + i.
   */
  Surface
  grid(const double       lo,
       const double       hi,
       const double       z,
       const unsigned int n,
       const double       normal_z,
       const unsigned int split = 0)
  {
    Surface s;
    for (unsigned int j = 0; j <= n; ++j)
      for (unsigned int i = 0; i <= n; ++i)
        s.nodes.emplace_back(lo + (hi - lo) * i / n, lo + (hi - lo) * j / n, z);
    Tensor<1, 3> normal;
    normal[2]      = normal_z;
    const auto add = [&](const std::vector<unsigned int> &v) {
      mortar::Face f;
      f.node   = v;
      f.normal = normal;
      for (const unsigned int k : v)
        f.x.push_back(s.nodes[k]);
      s.faces.push_back(f);
    };
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int i = 0; i < n; ++i)
        {
          const unsigned int v0 = j * (n + 1) + i, v1 = v0 + 1, v2 = v0 + n + 1,
                             v3 = v2 + 1;
          if (split == 0)
            add({v0, v1, v2, v3});
          else if (split == 1)
            {
              add({v0, v1, v3});
              add({v0, v3, v2});
            }
          else
            {
              add({v0, v1, v2});
              add({v1, v3, v2});
            }
        }
    return s;
  }

  /**
   * The surface moved by x -> R x + b for the rotation R of the angle 0.7
   * about the axis (1, 2, 3) and b = (0.3, -0.2, 0.5).
   */
  Surface
  rotated(Surface s)
  {
    Tensor<1, 3> axis;
    axis[0] = 1.;
    axis[1] = 2.;
    axis[2] = 3.;
    axis /= axis.norm();
    const double angle = 0.7;
    const auto   turn  = [&](const Tensor<1, 3> &v) {
      // Rodrigues' formula
      return std::cos(angle) * v + std::sin(angle) * cross_product_3d(axis, v) +
             (1. - std::cos(angle)) * (axis * v) * axis;
    };
    const Point<3> b(0.3, -0.2, 0.5);
    for (Point<3> &p : s.nodes)
      p = b + turn(p);
    for (mortar::Face &f : s.faces)
      {
        for (Point<3> &p : f.x)
          p = b + turn(p);
        f.normal = turn(f.normal);
      }
    return s;
  }

  /**
   * The area of a flat face that is a triangle or a parallelogram.
   */
  double
  area(const mortar::Face &f)
  {
    return (f.x.size() == 3 ? 0.5 : 1.) *
           cross_product_3d(f.x[1] - f.x[0], f.x[2] - f.x[0]).norm();
  }

  /**
   * int phi_k dA for every node of a surface of flat triangles and
   * parallelograms: each face gives each of its vertices its area divided
   * by the number of its vertices.
   */
  std::vector<double>
  lumped(const Surface &s)
  {
    std::vector<double> m(s.nodes.size(), 0.);
    for (const mortar::Face &f : s.faces)
      for (const unsigned int k : f.node)
        m[k] += area(f) / f.node.size();
    return m;
  }

  /** The largest deviations of the three properties of the patch test. */
  struct Deviations
  {
    // |sum_j M_sj / m_s - 1| over the chosen slave nodes
    double coverage = 0.;
    // |sum_j M_sj x_j / m_s - x_s| over the chosen slave nodes
    double reproduction = 0.;
    // |sum_s M_sj - int phi_j dA| / int phi_j dA over the master nodes
    double patch = 0.;
    // |m_s - int phi_s dA| / int phi_s dA over the slave nodes
    double weight = 0.;
  };

  /**
   * The deviations of the coupling c of `slave` with `master` from the
   * patch test's figures, coverage and reproduction over the slave nodes
   * `chosen` says the master covers, the patch test over all master nodes
   * (for a slave that covers the master), the weights for slave faces that
   * are triangles or parallelograms.
   */
  Deviations
  deviations(const mortar::Coupling                 &c,
             const Surface                          &slave,
             const Surface                          &master,
             const std::function<bool(unsigned int)> chosen = {})
  {
    Deviations          d;
    const auto          ms = lumped(slave);
    const auto          mm = lumped(master);
    std::vector<double> force(master.nodes.size(), 0.);
    for (unsigned int s = 0; s < slave.nodes.size(); ++s)
      {
        d.weight = std::max(d.weight, std::abs(c.weight[s] - ms[s]) / ms[s]);
        Tensor<1, 3> x;
        for (const auto &[j, m] : c.master[s])
          {
            x += m / c.weight[s] * master.nodes[j];
            force[j] += m; // the multiplier 1 at every slave node
          }
        if (chosen && !chosen(s))
          continue;
        d.coverage     = std::max(d.coverage, std::abs(c.coverage(s) - 1.));
        d.reproduction = std::max(d.reproduction, (x - slave.nodes[s]).norm());
      }
    for (unsigned int j = 0; j < master.nodes.size(); ++j)
      d.patch = std::max(d.patch, std::abs(force[j] - mm[j]) / mm[j]);
    return d;
  }

  /**
   * The part of int psi dx / int phi dx of a 1D dual function on
   * [lo, hi]: node i of the n equal intervals of [x0, x1], with
   * psi = 2 - 3 xi on the interval right of it and 3 xi - 1 on the one left
   * of it (xi the interval's coordinate from its left end), int phi = h on
   * an inner node and h / 2 at an end.
   */
  double
  covered_1d(const unsigned int i,
             const double       x0,
             const double       x1,
             const unsigned int n,
             const double       lo,
             const double       hi)
  {
    const double h        = (x1 - x0) / n;
    double       integral = 0., weight = 0.;
    // the antiderivatives of 2 - 3 xi and of 3 xi - 1
    const auto left_end  = [](const double t) { return 2. * t - 1.5 * t * t; };
    const auto right_end = [](const double t) { return 1.5 * t * t - t; };
    for (const unsigned int e : {i - 1, i})
      if (e < n) // i - 1 wraps around for i = 0
        {
          weight += h / 2.;
          const double a = std::clamp((lo - (x0 + e * h)) / h, 0., 1.);
          const double b = std::clamp((hi - (x0 + e * h)) / h, 0., 1.);
          if (b > a)
            integral += h * (e == i ? left_end(b) - left_end(a) :
                                      right_end(b) - right_end(a));
        }
    return integral / weight;
  }
} // namespace

TEST_CASE("Dual mortar in 3D on matching quadrilaterals gives the lumped "
          "weight alone",
          "[functions][mortar]")
{
  // the same 3 x 3 unit squares on both sides, facing each other
  const Surface slave  = grid(0., 3., 0., 3, -1.);
  const Surface master = grid(0., 3., 0., 3, 1.);
  const auto    c      = mortar::couple(slave.faces, 16, master.faces);
  double        worst  = 0.;
  for (unsigned int s = 0; s < 16; ++s)
    {
      const unsigned int i = s % 4, j = s / 4;
      // a corner node 1/4, an edge node 1/2, an inner node 1
      CHECK(c.weight[s] == Approx(0.25 * ((i == 0 || i == 3) ? 1 : 2) *
                                  ((j == 0 || j == 3) ? 1 : 2))
                             .epsilon(1e-14));
      for (const auto &[k, m] : c.master[s])
        worst =
          std::max(worst,
                   std::abs(m - (k == s ? c.weight[s] : 0.)) / c.weight[s]);
      CHECK(std::abs(c.coverage(s) - 1.) <= 1e-14);
    }
  CHECK(worst <= 1e-14);
}

TEST_CASE("Dual mortar in 3D on non-matching flat grids, 5 x 5 over 7 x 7 "
          "quadrilaterals, passes the patch test at the interface",
          "[functions][mortar]")
{
  const Surface slave  = grid(0., 1., 0., 5, -1.);
  const Surface master = grid(0., 1., 0., 7, 1.);
  const auto    c      = mortar::couple(slave.faces, 36, master.faces);
  const auto    d      = deviations(c, slave, master);
  CHECK(d.weight <= 1e-14);
  CHECK(d.coverage <= 1e-13);
  CHECK(d.reproduction <= 1e-13);
  CHECK(d.patch <= 1e-13);
}

TEST_CASE("Dual mortar in 3D with the slave beyond the master sees the "
          "covered part of each dual function",
          "[functions][mortar]")
{
  // the slave [-0.2, 1.2]^2 in 5 x 5 squares (every node faces part of the
  // master), then [-0.5, 1.5]^2 in 10 x 10 (the outer two rings face
  // nothing), over the master [0, 1]^2 in 7 x 7
  for (const auto &[lo, hi, n] :
       {std::tuple<double, double, unsigned int>{-0.2, 1.2, 5},
        {-0.5, 1.5, 10}})
    {
      INFO("slave [" << lo << ", " << hi << "]^2 in " << n << " x " << n);
      const Surface slave  = grid(lo, hi, 0., n, -1.);
      const Surface master = grid(0., 1., 0., 7, 1.);
      const auto    c =
        mortar::couple(slave.faces, (n + 1) * (n + 1), master.faces);
      // the dual functions of a grid of parallelograms are products of 1D
      // ones, and the master's functions sum to one on [0, 1]^2: the
      // coverage is the product of the 1D dual functions' covered parts
      const auto expected = [&](const unsigned int s) {
        return covered_1d(s % (n + 1), lo, hi, n, 0., 1.) *
               covered_1d(s / (n + 1), lo, hi, n, 0., 1.);
      };
      const auto inner = [&](const unsigned int s) {
        return expected(s) == 1.;
      };
      const auto d = deviations(c, slave, master, inner);
      CHECK(d.coverage <= 1e-13);
      CHECK(d.reproduction <= 1e-13);
      // the slave covers the master: the uniform pressure still crosses
      CHECK(d.patch <= 1e-13);
      unsigned int n_inner = 0, n_partly = 0, n_none = 0;
      double       worst = 0.;
      for (unsigned int s = 0; s < (n + 1) * (n + 1); ++s)
        {
          INFO("slave node " << s << " at " << slave.nodes[s] << ", coverage "
                             << c.coverage(s) << ", expected " << expected(s));
          worst = std::max(worst, std::abs(c.coverage(s) - expected(s)));
          if (expected(s) == 1.)
            ++n_inner;
          else if (expected(s) == 0.)
            {
              ++n_none;
              CHECK(c.master[s].empty());
            }
          else
            {
              ++n_partly;
              CHECK(c.coverage(s) != Approx(1.).epsilon(1e-3));
            }
        }
      CHECK(worst <= 1e-13);
      if (n == 5)
        {
          // 2 x 2 inner nodes at 0.36 and 0.64, no node facing nothing
          CHECK(n_inner == 4);
          CHECK(n_none == 0);
          // at 0.08 the dual function's covered part is 93/98 per
          // direction; at the slave's edge, -0.2, it is -16/49: the
          // negative part of psi there is the covered one
          CHECK(c.coverage(1 * 6 + 2) == Approx(93. / 98.).epsilon(1e-13));
          CHECK(c.coverage(1 * 6 + 1) ==
                Approx(93. / 98. * 93. / 98.).epsilon(1e-13));
          CHECK(c.coverage(0 * 6 + 2) == Approx(-16. / 49.).epsilon(1e-13));
          CHECK(c.coverage(0) == Approx(16. / 49. * 16. / 49.).epsilon(1e-13));
        }
      else
        {
          // per direction, the nodes at 0.3, 0.5, 0.7 inner, at -0.1, 0.1,
          // 0.9, 1.1 partly covered, the outer two on each side none
          CHECK(n_inner == 3 * 3);
          CHECK(n_partly == 7 * 7 - 3 * 3);
          CHECK(n_none == 11 * 11 - 7 * 7);
        }
      CHECK(n_partly > 0);
    }
}

TEST_CASE("Dual mortar in 3D on triangles, and on triangles against "
          "quadrilaterals, passes the patch test at the interface",
          "[functions][mortar]")
{
  const Surface  quads_5     = grid(0., 1., 0., 5, -1.);
  const Surface  tri_5       = grid(0., 1., 0., 5, -1., 1);
  const Surface  quads_7     = grid(0., 1., 0., 7, 1.);
  const Surface  tri_7       = grid(0., 1., 0., 7, 1., 2);
  const Surface *pairs[3][2] = {{&tri_5, &tri_7},
                                {&tri_5, &quads_7},
                                {&quads_5, &tri_7}};
  for (const auto &[slave, master] : pairs)
    {
      INFO("slave " << slave->faces[0].x.size() << " vertices, master "
                    << master->faces[0].x.size());
      const auto c = mortar::couple(slave->faces, 36, master->faces);
      const auto d = deviations(c, *slave, *master);
      CHECK(d.weight <= 1e-14);
      CHECK(d.coverage <= 1e-13);
      CHECK(d.reproduction <= 1e-13);
      CHECK(d.patch <= 1e-13);
    }
}

TEST_CASE("Dual mortar in 3D on a tilted, rotated interface passes the patch "
          "test at the interface",
          "[functions][mortar]")
{
  for (const unsigned int split : {0u, 1u})
    {
      INFO((split == 0 ? "quadrilaterals" : "triangles"));
      const Surface slave  = rotated(grid(0., 1., 0., 5, -1., split));
      const Surface master = rotated(grid(0., 1., 0., 7, 1., 2 * split));
      const auto    c      = mortar::couple(slave.faces, 36, master.faces);
      const auto    d      = deviations(c, slave, master);
      CHECK(d.weight <= 1e-13);
      CHECK(d.coverage <= 1e-12);
      CHECK(d.reproduction <= 1e-12);
      CHECK(d.patch <= 1e-12);
    }
}

TEST_CASE("Dual mortar in 3D with the master 1e-3 apart gives the same "
          "coupling as touching",
          "[functions][mortar]")
{
  for (const bool turn : {false, true})
    {
      INFO((turn ? "rotated" : "horizontal"));
      const auto surface = [&](const Surface &s) {
        return turn ? rotated(s) : s;
      };
      const Surface slave    = surface(grid(0., 1., 0., 5, -1.));
      const Surface touching = surface(grid(0., 1., 0., 7, 1.));
      const Surface apart    = surface(grid(0., 1., -1e-3, 7, 1.));
      const auto    c0       = mortar::couple(slave.faces, 36, touching.faces);
      const auto    c1       = mortar::couple(slave.faces, 36, apart.faces);
      double        worst    = 0.;
      for (unsigned int s = 0; s < 36; ++s)
        {
          REQUIRE(c0.master[s].size() == c1.master[s].size());
          for (unsigned int k = 0; k < c0.master[s].size(); ++k)
            {
              CHECK(c0.master[s][k].first == c1.master[s][k].first);
              worst = std::max(worst,
                               std::abs(c0.master[s][k].second -
                                        c1.master[s][k].second) /
                                 c0.weight[s]);
            }
        }
      CHECK(worst <= 1e-13);
      CHECK(deviations(c1, slave, apart).coverage <= 1e-13);
    }
}

TEST_CASE("Dual mortar in 3D on quadrilaterals that are not "
          "parallelograms, biorthogonal per face, with coverage and "
          "reproduction to the rule's accuracy and the patch test exact",
          "[functions][mortar]")
{
  // the 5 x 5 slave grid with its inner vertices moved in the plane by up
  // to 0.2 of a cell (a fixed scatter of directions and lengths)
  Surface      slave = grid(0., 1., 0., 5, -1.);
  const double h     = 0.2;
  for (unsigned int j = 1; j < 5; ++j)
    for (unsigned int i = 1; i < 5; ++i)
      {
        const unsigned int k     = j * 6 + i;
        const double       angle = 2.4 * k + 0.3;
        const double       r     = 0.2 * h * (0.55 + 0.45 * std::sin(1.3 * k));
        slave.nodes[k][0] += r * std::cos(angle);
        slave.nodes[k][1] += r * std::sin(angle);
      }
  for (mortar::Face &f : slave.faces)
    for (unsigned int v = 0; v < 4; ++v)
      f.x[v] = slave.nodes[f.node[v]];
  const Surface master = grid(0., 1., 0., 7, 1.);

  // biorthogonality on each face, int psi_s phi_t dA = delta_st
  // int phi_s dA, by the 3-point Gauss rule in each direction (exact: on a
  // flat quadrilateral the surface element is affine)
  const double        g[3] = {0.5 - 0.5 * std::sqrt(0.6),
                              0.5,
                              0.5 + 0.5 * std::sqrt(0.6)};
  const double        w[3] = {5. / 18., 8. / 18., 5. / 18.};
  std::vector<double> weight(36, 0.);
  double              worst = 0., column_sum = 0.;
  for (const mortar::Face &f : slave.faces)
    {
      const auto a             = mortar::dual_coefficients(f);
      double     psi_phi[4][4] = {}, phi[4] = {};
      for (unsigned int p = 0; p < 3; ++p)
        for (unsigned int q = 0; q < 3; ++q)
          {
            const double       xi = g[p], eta = g[q];
            const double       v[4] = {(1. - xi) * (1. - eta),
                                       xi * (1. - eta),
                                       (1. - xi) * eta,
                                       xi * eta};
            const Tensor<1, 3> t0 =
              (1. - eta) * (f.x[1] - f.x[0]) + eta * (f.x[3] - f.x[2]);
            const Tensor<1, 3> t1 =
              (1. - xi) * (f.x[2] - f.x[0]) + xi * (f.x[3] - f.x[1]);
            const double dA = w[p] * w[q] * cross_product_3d(t0, t1).norm();
            for (unsigned int s = 0; s < 4; ++s)
              {
                phi[s] += dA * v[s];
                for (unsigned int t = 0; t < 4; ++t)
                  for (unsigned int k = 0; k < 4; ++k)
                    psi_phi[s][t] += dA * a[s][k] * v[k] * v[t];
              }
          }
      for (unsigned int s = 0; s < 4; ++s)
        {
          weight[f.node[s]] += phi[s];
          // sum_s psi_s = 1: the columns of A sum to one
          column_sum =
            std::max(column_sum,
                     std::abs(a[0][s] + a[1][s] + a[2][s] + a[3][s] - 1.));
          for (unsigned int t = 0; t < 4; ++t)
            worst = std::max(worst,
                             std::abs(psi_phi[s][t] - (s == t ? phi[s] : 0.)) /
                               phi[s]);
        }
    }
  CHECK(worst <= 1e-12);
  CHECK(column_sum <= 1e-12);

  const auto c            = mortar::couple(slave.faces, 36, master.faces);
  double     weight_error = 0.;
  for (unsigned int s = 0; s < 36; ++s)
    weight_error =
      std::max(weight_error, std::abs(c.weight[s] - weight[s]) / weight[s]);
  CHECK(weight_error <= 1e-13);
  const auto d = deviations(c, slave, master);
  // psi_s is not a polynomial of the plane's coordinates on such a face:
  // the 36-point rule the coupling takes for a pair that is not affine
  // approximates its integral (3e-13 here, 5e-7 with the 7-point rule)
  CHECK(d.coverage <= 1e-11);
  CHECK(d.reproduction <= 1e-11);
  // sum_s psi_s = 1 and the master's phi_j are polynomials: exact
  CHECK(d.patch <= 1e-13);
}

TEST_CASE("Dual mortar in 3D between a ball and a spherical socket covers "
          "the slave nodes to near one",
          "[functions][mortar]")
{
  // the slave on the ball of radius 1 about (0, 0, 1), the master on the
  // socket of radius 1.05 about (0, 0, 1.05), touching at the origin (the
  // gap r^2 / 2 (1 - 1 / 1.05) stays below 0.005): the grids of
  // [-0.5, 0.5]^2 in 8 x 8 and of [-0.6, 0.6]^2 in 11 x 11 lifted onto the
  // spheres' lower caps, with the bodies' outward normals at the faces'
  // centres (the ball's away from its centre, the socket's towards it)
  const auto cap = [](const double       a,
                      const unsigned int n,
                      const double       radius,
                      const double       outward) {
    Surface        s = grid(-a, a, 0., n, 0.);
    const Point<3> centre(0., 0., radius);
    for (Point<3> &p : s.nodes)
      p[2] = radius - std::sqrt(radius * radius - p[0] * p[0] - p[1] * p[1]);
    for (mortar::Face &f : s.faces)
      {
        Point<3> middle;
        for (unsigned int v = 0; v < 4; ++v)
          {
            f.x[v] = s.nodes[f.node[v]];
            middle += 0.25 * f.x[v];
          }
        f.normal = outward * (middle - centre) / (middle - centre).norm();
      }
    return s;
  };
  const Surface slave  = cap(0.5, 8, 1., 1.);
  const Surface master = cap(0.6, 11, 1.05, -1.);
  const auto    c      = mortar::couple(slave.faces, 81, master.faces);
  double        worst  = 0.;
  for (unsigned int s = 0; s < 81; ++s)
    worst = std::max(worst, std::abs(c.coverage(s) - 1.));
  // the master covers every slave node's support, and the projected master
  // faces tile the plane: the coverage is int psi_s dA / m_s, the
  // integral's change of variables into the plane, to the rule's error on
  // the curved faces (2e-15 here)
  CHECK(worst <= 1e-12);
}

namespace
{
  /**
   * An n x n grid of the square [lo, hi]^2 at height z with the normal
   * (0, 0, normal_z) and the trace of FE_Q(k) on each face: node (a, b) of
   * the (n k + 1)^2 lattice at the Gauss-Lobatto points of each cell is
   * number b (n k + 1) + a, and a face lists its (k + 1)^2 nodes in
   * lexicographic order.
   */
  Surface
  grid_of_degree(const double       lo,
                 const double       hi,
                 const double       z,
                 const unsigned int n,
                 const double       normal_z,
                 const unsigned int k)
  {
    const QGaussLobatto<1> rule(k + 1);
    std::vector<double>    p;
    for (const Point<1> &q : rule.get_points())
      p.push_back(q[0]);
    std::sort(p.begin(), p.end());
    const double       h = (hi - lo) / n;
    const unsigned int m = n * k + 1;
    // the lattice coordinate of index a
    const auto at = [&](const unsigned int a) {
      return lo + h * (a / k) + h * p[a % k];
    };
    Surface s;
    for (unsigned int b = 0; b < m; ++b)
      for (unsigned int a = 0; a < m; ++a)
        s.nodes.emplace_back(a + 1 == m ? hi : at(a),
                             b + 1 == m ? hi : at(b),
                             z);
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int i = 0; i < n; ++i)
        {
          mortar::Face f;
          f.degree    = k;
          f.normal[2] = normal_z;
          for (unsigned int b = 0; b <= k; ++b)
            for (unsigned int a = 0; a <= k; ++a)
              f.node.push_back((j * k + b) * m + i * k + a);
          for (const unsigned int corner :
               {0u, k, k * (k + 1), (k + 1) * (k + 1) - 1})
            f.x.push_back(s.nodes[f.node[corner]]);
          s.faces.push_back(f);
        }
    return s;
  }
} // namespace

TEST_CASE("Dual mortar in 3D at degrees 2 and 3 (FE_Q(k) on the faces), "
          "5 x 5 over 7 x 7 quadrilaterals: positive weights, the dual "
          "basis biorthogonal, the patch test at the interface, and "
          "polynomials of degree k reproduced",
          "[functions][mortar]")
{
  for (const unsigned int k : {2u, 3u})
    {
      INFO("degree " << k);
      const Surface slave  = grid_of_degree(0., 1., 0., 5, -1., k);
      const Surface master = grid_of_degree(-0.1, 1.1, 0., 7, 1., k);
      // biorthogonality on one face: int psi_s phi_t = delta_st m_s, from
      // the coupling of the face with itself (the master the same face)
      {
        mortar::Face self = slave.faces[7];
        mortar::Face other(self);
        other.normal *= -1.;
        std::vector<unsigned int> numbers(self.node.size());
        for (unsigned int i = 0; i < numbers.size(); ++i)
          self.node[i] = other.node[i] = numbers[i] = i;
        const auto c     = mortar::couple({self}, numbers.size(), {other});
        double     worst = 0.;
        for (unsigned int s = 0; s < numbers.size(); ++s)
          {
            CHECK(c.weight[s] > 0.);
            for (const auto &[t, m] : c.master[s])
              worst = std::max(worst,
                               std::abs(m - (t == s ? c.weight[s] : 0.)) /
                                 c.weight[s]);
          }
        CHECK(worst <= 1e-12);
      }
      const auto c =
        mortar::couple(slave.faces, slave.nodes.size(), master.faces);
      // the weights int phi_s dA: a Gauss-Lobatto weight's product, over the
      // faces at the node; they sum to the area
      double total = 0.;
      for (unsigned int s = 0; s < slave.nodes.size(); ++s)
        {
          CHECK(c.weight[s] > 0.);
          total += c.weight[s];
        }
      CHECK(total == Approx(1.).epsilon(1e-13));
      // every slave node sees the master whole (the master covers the
      // slave), and sum_j M_sj f(x_j) = m_s f(x_s) for f in Q_k, which both
      // traces hold exactly
      const auto f = [k](const Point<3> &x) {
        return 1. + std::pow(x[0], k) - 2. * std::pow(x[1], k) +
               x[0] * std::pow(x[1], k - 1) + 3. * std::pow(x[0] * x[1], k);
      };
      double coverage = 0., reproduction = 0.;
      for (unsigned int s = 0; s < slave.nodes.size(); ++s)
        {
          double sum = 0.;
          for (const auto &[j, m] : c.master[s])
            sum += m * f(master.nodes[j]);
          coverage = std::max(coverage, std::abs(c.coverage(s) - 1.));
          reproduction =
            std::max(reproduction,
                     std::abs(sum / c.weight[s] - f(slave.nodes[s])));
        }
      INFO("coverage " << coverage << ", reproduction " << reproduction);
      CHECK(coverage <= 1e-12);
      CHECK(reproduction <= 1e-11);
      // a uniform multiplier on the slave loads each master node under it
      // by the load int phi_j dA over the slave's square: the patch test
      // (the master nodes of the cells inside [0.1, 0.9]^2 lie under it
      // whole; the master's cells are 1.2 / 7 wide)
      const auto          reference = grid_of_degree(-0.1, 1.1, 0., 7, 1., k);
      std::vector<double> force(master.nodes.size(), 0.), weight(force);
      const auto          own =
        mortar::couple(reference.faces,
                       reference.nodes.size(),
                       grid_of_degree(-0.1, 1.1, 0., 7, -1., k).faces);
      for (unsigned int j = 0; j < master.nodes.size(); ++j)
        weight[j] = own.weight[j];
      for (unsigned int s = 0; s < slave.nodes.size(); ++s)
        for (const auto &[j, m] : c.master[s])
          force[j] += m;
      double patch = 0.;
      for (unsigned int j = 0; j < master.nodes.size(); ++j)
        {
          const Point<3> &x = master.nodes[j];
          // the support of phi_j: the cells at x, one master cell around it
          const double h = 1.2 / 7.;
          if (x[0] - h > 0. && x[0] + h < 1. && x[1] - h > 0. && x[1] + h < 1.)
            patch = std::max(patch, std::abs(force[j] - weight[j]) / weight[j]);
        }
      INFO("patch " << patch);
      CHECK(patch <= 1e-12);
    }
}

TEST_CASE("Dual mortar in 3D couples only faces that face each other: a "
          "master behind the slave, or facing away, adds nothing",
          "[functions][mortar]")
{
  // the slave: 2 x 2 quadrilaterals of [0, 1]^2 at z = 0, the top of a
  // body below (outward normal +z); each master: 3 x 3 of them (or the
  // squares cut into triangles) at height z, the bottom of a body above
  // (-z) or, facing away, the top of one (+z). The reach 5 lets the slave
  // see every master along its normal: only the faces' facing decides.
  const Surface slave = grid(0., 1., 0., 2, 1.);
  // (height, normal, whether it couples)
  const std::vector<std::tuple<double, double, bool>> cases = {
    // a gap of 0.01 in front of the slave
    {0.01, -1., true},
    // an overlap of 0.2, less than the faces' size: the bodies overlap at
    // the start, and the check of the pair must see it
    {-0.2, -1., true},
    // the far side of a body above, 3 behind the slave: it projects onto
    // the slave's plane and faces it, but lies behind it
    {-3., -1., false},
    // in front, but the master's outward normal looks the slave's way
    {0.01, 1., false}};
  for (const unsigned int split : {0u, 1u})
    for (const auto &[z, normal_z, couples] : cases)
      {
        const Surface master = grid(0., 1., z, 3, normal_z, split);
        INFO("master at z = " << z << " with the normal (0, 0, " << normal_z
                              << "), "
                              << (split ? "triangles" : "quadrilaterals"));
        const auto c = mortar::couple(slave.faces, 9, master.faces, 5.);
        for (unsigned int s = 0; s < 9; ++s)
          {
            INFO("slave node " << s << ", coverage " << c.coverage(s));
            if (couples)
              CHECK(c.coverage(s) == Approx(1.).epsilon(1e-12));
            else
              CHECK(c.master[s].empty());
          }
      }
}
