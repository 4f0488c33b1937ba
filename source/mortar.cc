#include <dualcontact/mortar.h>

#include <algorithm>
#include <cmath>
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
  } // namespace mortar
} // namespace dualcontact
