// The pre-refinement band around the surfaces of the contact pairs.
#include <deal.II/base/mpi.h>

#include <dualcontact/pair_band.h>

#include <cmath>
#include <limits>
#include <set>

namespace dualcontact
{
  template <int dim>
  PairBand<dim>::PairBand(
    const Triangulation<dim>                               &triangulation,
    const std::map<types::boundary_id, types::boundary_id> &pairs,
    const double                                            width)
      : width(std::max(width, std::numeric_limits<double>::min()))
      , bodies(triangulation)
  {
    std::set<types::boundary_id> ids;
    for (const auto &[slave, master] : pairs)
      {
        ids.insert(slave);
        ids.insert(master);
      }
    std::vector<double> local;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && ids.count(face->boundary_id()))
            for (const unsigned int v : face->vertex_indices())
              {
                for (unsigned int d = 0; d < dim; ++d)
                  local.push_back(face->vertex(v)[d]);
                local.push_back(bodies.of(cell));
              }
    for (const auto &part :
         Utilities::MPI::all_gather(triangulation.get_communicator(), local))
      for (std::size_t i = 0; i + dim < part.size(); i += dim + 1)
        {
          Point<dim> x;
          for (unsigned int d = 0; d < dim; ++d)
            x[d] = part[i + d];
          bins[bin_of(x)].emplace_back(
            x, static_cast<unsigned int>(part[i + dim]));
        }
  }

  template <int dim>
  bool
  PairBand<dim>::near(
    const typename Triangulation<dim>::active_cell_iterator &cell,
    const unsigned int                                       v) const
  {
    const Point<dim>   x    = cell->vertex(v);
    const unsigned int body = bodies.of(cell);
    const auto         home = bin_of(x);
    for (unsigned int k = 0; k < std::pow(3, dim); ++k)
      {
        auto         key  = home;
        unsigned int rest = k;
        for (unsigned int d = 0; d < dim; ++d, rest /= 3)
          key[d] += static_cast<long>(rest % 3) - 1;
        const auto it = bins.find(key);
        if (it != bins.end())
          for (const auto &[p, other] : it->second)
            if (other != body && x.distance(p) <= width)
              return true;
      }
    return false;
  }

  template <int dim>
  std::array<long, dim>
  PairBand<dim>::bin_of(const Point<dim> &x) const
  {
    std::array<long, dim> key;
    for (unsigned int d = 0; d < dim; ++d)
      key[d] = static_cast<long>(std::floor(x[d] / width));
    return key;
  }

  template class PairBand<2>;
  template class PairBand<3>;
} // namespace dualcontact
