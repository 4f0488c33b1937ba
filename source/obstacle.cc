#include <dualcontact/input_error.h>
#include <dualcontact/obstacle.h>

#include <map>
#include <utility>

namespace dualcontact
{
  namespace
  {
    // A function-local static, so that it exists before the first kind
    // registers itself, whatever the order of static initialisation.
    std::map<std::string, std::pair<ObstacleFactory<2>, ObstacleFactory<3>>> &
    registry()
    {
      static std::map<std::string,
                      std::pair<ObstacleFactory<2>, ObstacleFactory<3>>>
        kinds;
      return kinds;
    }
  } // namespace

  bool
  register_obstacle(const std::string &name,
                    ObstacleFactory<2> factory_2d,
                    ObstacleFactory<3> factory_3d)
  {
    registry()[name] = {std::move(factory_2d), std::move(factory_3d)};
    return true;
  }

  std::vector<std::string>
  obstacle_names()
  {
    std::vector<std::string> names;
    for (const auto &[name, factories] : registry())
      names.push_back(name);
    return names;
  }

  template <int dim>
  std::unique_ptr<Obstacle<dim>>
  create_obstacle(const Parameters &parameters, const double length)
  {
    const auto it = registry().find(parameters.obstacle.type);
    if (it == registry().end())
      throw InputError("There is no obstacle called '" +
                         parameters.obstacle.type +
                         "' (<Obstacle/Type>).",
                       exit_invalid_value);
    if constexpr (dim == 2)
      return it->second.first(parameters, length);
    else
      return it->second.second(parameters, length);
  }

  template <int dim>
  std::array<Tensor<1, dim>, dim - 1>
  tangent_basis(const Tensor<1, dim> &n)
  {
    std::array<Tensor<1, dim>, dim - 1> t;
    if constexpr (dim == 2)
      {
        t[0][0] = -n[1];
        t[0][1] = n[0];
      }
    else
      {
        Tensor<1, dim> e;
        e[std::abs(n[0]) < 0.9 ? 0 : 1] = 1.;
        const Tensor<1, dim> t1         = e - (e * n) * n;
        t[0]                            = t1 / t1.norm();
        t[1]                            = cross_product_3d(n, t[0]);
      }
    return t;
  }

  template std::unique_ptr<Obstacle<2>>
  create_obstacle(const Parameters &, double);
  template std::unique_ptr<Obstacle<3>>
  create_obstacle(const Parameters &, double);
  template std::array<Tensor<1, 2>, 1>
  tangent_basis(const Tensor<1, 2> &);
  template std::array<Tensor<1, 3>, 2>
  tangent_basis(const Tensor<1, 3> &);
} // namespace dualcontact
