#include <dualcontact/input_error.h>
#include <dualcontact/obstacle.h>
#include <dualcontact/registry.h>

#include <utility>

namespace dualcontact
{
  namespace
  {
    using Factories = std::pair<ObstacleFactory<2>, ObstacleFactory<3>>;
  } // namespace

  bool
  register_obstacle(const std::string &name,
                    ObstacleFactory<2> factory_2d,
                    ObstacleFactory<3> factory_3d)
  {
    Registry<Factories>::instance().add(name,
                                        {std::move(factory_2d),
                                         std::move(factory_3d)});
    return true;
  }

  std::vector<std::string>
  obstacle_names()
  {
    return Registry<Factories>::instance().names();
  }

  template <int dim>
  std::unique_ptr<Obstacle<dim>>
  create_obstacle(const Parameters &parameters, const double length)
  {
    const Factories *factories =
      Registry<Factories>::instance().find(parameters.obstacle.type);
    if (factories == nullptr)
      throw InputError("There is no obstacle called '" +
                         parameters.obstacle.type + "' (<Obstacle/Type>).",
                       exit_invalid_value);
    if constexpr (dim == 2)
      return factories->first(parameters, length);
    else
      return factories->second(parameters, length);
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
