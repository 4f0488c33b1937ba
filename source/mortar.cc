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

    Coupling
    couple(const std::vector<Segment> &slave,
           const unsigned int          n_slave_nodes,
           const std::vector<Segment> &master)
    {
      Coupling coupling;
      coupling.weight.assign(n_slave_nodes, 0.);
      std::vector<std::map<unsigned int, double>> entries(n_slave_nodes);
      // the two Gauss points of [0, 1] and their weights
      const double gauss[2] = {0.5 - 0.5 / std::sqrt(3.),
                               0.5 + 0.5 / std::sqrt(3.)};

      for (const Segment &s : slave)
        {
          const Tensor<1, 2> along  = s.x[1] - s.x[0];
          const double       length = along.norm();
          if (length == 0.)
            continue;
          // phi_0 = 1 - xi, phi_1 = xi on the segment, xi in [0, 1], and
          // int phi_k = length / 2
          for (const unsigned int k : {0u, 1u})
            coupling.weight[s.node[k]] += 0.5 * length;
          // the slave coordinate of a point projected along the normal
          const auto coordinate = [&](const Point<2> &p) {
            return (p - s.x[0]) * along / (length * length);
          };
          for (const Segment &m : master)
            {
              if (s.normal.norm() > 0. && m.normal.norm() > 0. &&
                  s.normal * m.normal >= -0.5)
                continue;
              const double xi0 = coordinate(m.x[0]);
              const double xi1 = coordinate(m.x[1]);
              // a master segment at a right angle to the slave projects
              // onto a point: no overlap of positive length
              if (std::abs(xi1 - xi0) <= 1e-14)
                continue;
              const double lo = std::max(0., std::min(xi0, xi1));
              const double hi = std::min(1., std::max(xi0, xi1));
              if (hi <= lo)
                continue;
              for (const double g : gauss)
                {
                  const double xi = lo + (hi - lo) * g;
                  const double w  = 0.5 * (hi - lo) * length;
                  // the dual functions of the slave segment:
                  // psi_0 = 2 phi_0 - phi_1, psi_1 = 2 phi_1 - phi_0
                  const double psi[2] = {2. - 3. * xi, 3. * xi - 1.};
                  // the master's functions at the same point: linear in
                  // its own coordinate eta, which is affine in xi
                  const double eta    = (xi - xi0) / (xi1 - xi0);
                  const double phi[2] = {1. - eta, eta};
                  for (const unsigned int a : {0u, 1u})
                    for (const unsigned int b : {0u, 1u})
                      entries[s.node[a]][m.node[b]] += w * psi[a] * phi[b];
                }
            }
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
      for (const Segment &s : slave)
        for (const unsigned int k : {0u, 1u})
          {
            coupling.weight[s.node[k]] += 0.5 * (s.x[1] - s.x[0]).norm();
            position[s.node[k]] = s.x[k];
            normal[s.node[k]] += s.normal;
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
