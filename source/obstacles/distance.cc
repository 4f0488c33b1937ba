// An obstacle of any shape, given by the signed distance d(x) from its
// surface (<Obstacle/Distance>, > 0 where the body is). The normal is the
// gradient of d by central differences, normalised; where the gradient
// vanishes or is not finite the normal is returned as zero and the contact
// set reports the node as unusable.
#include <dualcontact/obstacle.h>
#include <dualcontact/scene.h>

#include <cmath>

namespace dualcontact
{
  namespace
  {
    template <int dim>
    class SignedDistance : public Obstacle<dim>
    {
    public:
      SignedDistance(const Parameters &parameters, const double length)
          : expression(parameters.obstacle.distance)
          , function(make_function<dim>(expression,
                                        1,
                                        parameters.material,
                                        "Obstacle/Distance",
                                        length))
          , step(1e-6 * length)
      {}

      std::string
      name() const override
      {
        return "distance";
      }

      std::string
      description() const override
      {
        return "the surface d(x) = 0 of d = " + expression;
      }

      double
      distance(const Point<dim> &x) const override
      {
        return function->value(x);
      }

      Tensor<1, dim>
      normal(const Point<dim> &x) const override
      {
        Tensor<1, dim> gradient;
        for (unsigned int d = 0; d < dim; ++d)
          {
            Point<dim> forward = x, backward = x;
            forward[d] += step;
            backward[d] -= step;
            gradient[d] =
              (function->value(forward) - function->value(backward)) /
              (2. * step);
          }
        const double norm = gradient.norm();
        if (!std::isfinite(norm) || !(norm > 1e-3))
          return Tensor<1, dim>();
        return gradient / norm;
      }

    private:
      std::string                    expression;
      std::unique_ptr<Function<dim>> function;
      double                         step;
    };

    template <int dim>
    std::unique_ptr<Obstacle<dim>>
    make(const Parameters &parameters, const double length)
    {
      return std::make_unique<SignedDistance<dim>>(parameters, length);
    }

    const bool registered = register_obstacle("distance", make<2>, make<3>);
  } // namespace
} // namespace dualcontact
