#include <deal.II/base/quadrature_lib.h>

#include <deal.II/lac/full_matrix.h>

#include <dualcontact/mortar.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace dualcontact
{
  namespace mortar
  {
    double
    Coupling::coverage(const unsigned int s) const
    {
      double sum = 0.;
      for (const auto &[j, m] : master[s])
        sum += m;
      return weight[s] > 0. ? sum / weight[s] : 0.;
    }

    double
    facing_tolerance(const double slave_size, const double master_size)
    {
      return std::max(slave_size, master_size);
    }

    namespace
    {
      // The nodes of a segment in the order of its basis: the end points
      // at xi = 0 and 1, then the inner nodes.
      std::vector<double>
      node_coordinates(const Segment &s)
      {
        std::vector<double> xi = {0., 1.};
        xi.insert(xi.end(), s.inner_xi.begin(), s.inner_xi.end());
        return xi;
      }

      std::vector<unsigned int>
      node_numbers(const Segment &s)
      {
        std::vector<unsigned int> n = {s.node[0], s.node[1]};
        n.insert(n.end(), s.inner_node.begin(), s.inner_node.end());
        return n;
      }

      /**
       * Whether a master point x_m and the slave point x_s it faces (the
       * two ends of a line along the slave's normal) lie on each other's
       * front side, each up to `tolerance`: n_s . (x_m - x_s) and
       * n_m . (x_s - x_m) at least -tolerance. Faces without normals
       * (zero) are taken as facing.
       */
      bool
      in_front(const Tensor<1, 2> &n_s,
               const Tensor<1, 2> &n_m,
               const Point<2>     &x_s,
               const Point<2>     &x_m,
               const double        tolerance)
      {
        if (!(n_s.norm() > 0. && n_m.norm() > 0.))
          return true;
        return n_s * (x_m - x_s) >= -tolerance &&
               n_m * (x_s - x_m) >= -tolerance;
      }

      // the Lagrange polynomials through the nodes `xi`, at `x`
      std::vector<double>
      lagrange(const std::vector<double> &xi, const double x)
      {
        std::vector<double> phi(xi.size(), 1.);
        for (std::size_t a = 0; a < xi.size(); ++a)
          for (std::size_t b = 0; b < xi.size(); ++b)
            if (b != a)
              phi[a] *= (x - xi[b]) / (xi[a] - xi[b]);
        return phi;
      }

      /**
       * The dual coefficients A = D M^-1 of a slave segment with the nodes
       * at `xi_s` (D = diag(int phi_t), M the mass matrix, on [0, 1]:
       * scale-free, both grow with the length), and int phi_t on [0, 1].
       */
      FullMatrix<double>
      segment_dual_coefficients(const std::vector<double> &xi_s,
                                std::vector<double>       &integral)
      {
        const unsigned int n = xi_s.size();
        const unsigned int k = n - 1; // the degree
        // Gauss points on [0, 1] exact for degree 2k
        const QGauss<1>    gauss(k + 1);
        FullMatrix<double> mass(n, n), inverse(n, n), dual(n, n);
        integral.assign(n, 0.);
        for (unsigned int q = 0; q < gauss.size(); ++q)
          {
            const auto phi = lagrange(xi_s, gauss.point(q)[0]);
            for (unsigned int a = 0; a < n; ++a)
              {
                integral[a] += gauss.weight(q) * phi[a];
                for (unsigned int b = 0; b < n; ++b)
                  mass(a, b) += gauss.weight(q) * phi[a] * phi[b];
              }
          }
        inverse.invert(mass);
        for (unsigned int a = 0; a < n; ++a)
          for (unsigned int b = 0; b < n; ++b)
            dual(a, b) = integral[a] * inverse(a, b);
        return dual;
      }

      /**
       * The entries M_sj of the slave segment s (its nodes at xi_s,
       * numbered n_s, its dual coefficients `dual`) against the master
       * segment m, added to `entries`: none unless they face each other
       * and overlap along the slave's chord.
       */
      void
      couple_segments(const Segment                               &s,
                      const Segment                               &m,
                      const std::vector<double>                   &xi_s,
                      const std::vector<unsigned int>             &n_s,
                      const FullMatrix<double>                    &dual,
                      std::vector<std::map<unsigned int, double>> &entries)
      {
        const Tensor<1, 2> along  = s.x[1] - s.x[0];
        const double       length = along.norm();
        const unsigned int n      = xi_s.size();
        const unsigned int k      = n - 1;
        // the slave coordinate of a point projected along the normal
        const auto coordinate = [&](const Point<2> &p) {
          return (p - s.x[0]) * along / (length * length);
        };
        if (s.normal.norm() > 0. && m.normal.norm() > 0. &&
            s.normal * m.normal >= -0.5)
          return;
        const double xi0 = coordinate(m.x[0]);
        const double xi1 = coordinate(m.x[1]);
        // a master segment at a right angle to the slave projects
        // onto a point: no overlap of positive length
        if (std::abs(xi1 - xi0) <= 1e-14)
          return;
        const double lo = std::max(0., std::min(xi0, xi1));
        const double hi = std::min(1., std::max(xi0, xi1));
        if (hi <= lo)
          return;
        // the two segments face each other where they overlap: at
        // both ends of the overlap (the distance between the chords
        // is affine in between), each lies in front of the other
        // up to the longer one's length (facing_tolerance())
        const double tolerance =
          facing_tolerance(length, (m.x[1] - m.x[0]).norm());
        const auto on_master = [&](const double xi) {
          return m.x[0] + (xi - xi0) / (xi1 - xi0) * (m.x[1] - m.x[0]);
        };
        if (!in_front(s.normal,
                      m.normal,
                      s.x[0] + lo * along,
                      on_master(lo),
                      tolerance) ||
            !in_front(s.normal,
                      m.normal,
                      s.x[0] + hi * along,
                      on_master(hi),
                      tolerance))
          return;
        const std::vector<double>       xi_m = node_coordinates(m);
        const std::vector<unsigned int> n_m  = node_numbers(m);
        // psi_a phi_b has degree k + k_master: Gauss points enough
        const QGauss<1> overlap((k + xi_m.size()) / 2 + 1);
        for (unsigned int q = 0; q < overlap.size(); ++q)
          {
            const double xi    = lo + (hi - lo) * overlap.point(q)[0];
            const double w     = (hi - lo) * length * overlap.weight(q);
            const auto   phi_s = lagrange(xi_s, xi);
            // the master's functions at the same point: in its own
            // coordinate eta, which is affine in xi
            const auto phi_m = lagrange(xi_m, (xi - xi0) / (xi1 - xi0));
            for (unsigned int a = 0; a < n; ++a)
              {
                double psi = 0.;
                for (unsigned int b = 0; b < n; ++b)
                  psi += dual(a, b) * phi_s[b];
                for (unsigned int b = 0; b < phi_m.size(); ++b)
                  entries[n_s[a]][n_m[b]] += w * psi * phi_m[b];
              }
          }
      }
    } // namespace

    Coupling
    couple(const std::vector<Segment> &slave,
           const unsigned int          n_slave_nodes,
           const std::vector<Segment> &master)
    {
      Coupling coupling;
      coupling.weight.assign(n_slave_nodes, 0.);
      std::vector<std::map<unsigned int, double>> entries(n_slave_nodes);

      for (const Segment &s : slave)
        {
          const double length = (s.x[1] - s.x[0]).norm();
          if (length == 0.)
            continue;
          const std::vector<double>       xi_s = node_coordinates(s);
          const std::vector<unsigned int> n_s  = node_numbers(s);
          std::vector<double>             integral;
          const FullMatrix<double>        dual =
            segment_dual_coefficients(xi_s, integral);
          for (unsigned int a = 0; a < xi_s.size(); ++a)
            coupling.weight[n_s[a]] += integral[a] * length;
          for (const Segment &m : master)
            couple_segments(s, m, xi_s, n_s, dual, entries);
        }
      coupling.master.resize(n_slave_nodes);
      for (unsigned int s = 0; s < n_slave_nodes; ++s)
        coupling.master[s].assign(entries[s].begin(), entries[s].end());
      return coupling;
    }

    Coupling
    couple_node_to_segment(const std::vector<Segment> &slave,
                           const unsigned int          n_slave_nodes,
                           const std::vector<Segment> &master)
    {
      Coupling coupling;
      coupling.weight.assign(n_slave_nodes, 0.);
      coupling.master.resize(n_slave_nodes);
      std::vector<Point<2>>     position(n_slave_nodes);
      std::vector<Tensor<1, 2>> normal(n_slave_nodes);
      // the longest of a node's segments, for facing_tolerance()
      std::vector<double> longest(n_slave_nodes, 0.);
      for (const Segment &s : slave)
        for (const unsigned int k : {0u, 1u})
          {
            const double length = (s.x[1] - s.x[0]).norm();
            coupling.weight[s.node[k]] += 0.5 * length;
            position[s.node[k]] = s.x[k];
            normal[s.node[k]] += s.normal;
            longest[s.node[k]] = std::max(longest[s.node[k]], length);
          }
      for (unsigned int i = 0; i < n_slave_nodes; ++i)
        {
          if (!(normal[i].norm() > 0.))
            continue;
          const Tensor<1, 2> n = normal[i] / normal[i].norm();
          // the nearest facing master segment that the line x_s + t n
          // crosses, at eta in [0, 1] of it
          double best = std::numeric_limits<double>::max();
          for (const Segment &m : master)
            {
              if (m.normal.norm() > 0. && n * m.normal >= -0.5)
                continue;
              const Tensor<1, 2> along = m.x[1] - m.x[0];
              // x_s + t n = x_0 + eta along: two equations in t, eta
              const double det = n[1] * along[0] - n[0] * along[1];
              if (std::abs(det) <= 1e-14 * along.norm())
                continue;
              const Tensor<1, 2> d = m.x[0] - position[i];
              const double       t = (d[1] * along[0] - d[0] * along[1]) / det;
              const double       eta = (n[0] * d[1] - n[1] * d[0]) / det;
              if (eta < -1e-12 || eta > 1. + 1e-12 || std::abs(t) >= best)
                continue;
              // the met point and the node face each other, as the dual
              // mortar's segments do
              if (!in_front(n,
                            m.normal,
                            position[i],
                            position[i] + t * n,
                            facing_tolerance(longest[i], along.norm())))
                continue;
              best           = std::abs(t);
              const double e = std::clamp(eta, 0., 1.);
              coupling.master[i].clear();
              coupling.master[i].emplace_back(m.node[0],
                                              coupling.weight[i] * (1. - e));
              coupling.master[i].emplace_back(m.node[1],
                                              coupling.weight[i] * e);
            }
        }
      return coupling;
    }
  } // namespace mortar
} // namespace dualcontact
