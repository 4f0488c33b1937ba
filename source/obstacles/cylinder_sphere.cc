// Round indenters: a rigid cylinder (a disc in 2D; in 3D infinite along its
// axis) or a sphere (a disc in 2D), of centre c and radius R, the body
// outside it: d(x) = |x - c|_perp - R, with |.|_perp the distance from the
// axis (cylinder) or the centre (sphere), and m(x) the unit vector from the
// axis or centre toward x.
#include <dualcontact/obstacle.h>

#include <sstream>

namespace dualcontact
{
  namespace
  {
    template <int dim>
    class Round : public Obstacle<dim>
    {
    public:
      Round(const ObstacleParameters &parameters, const bool cylinder)
          : kind(parameters.type)
          , radius(parameters.radius)
      {
        center = to_point<dim>(parameters.center);
        if (cylinder && dim == 3)
          {
            axis = to_point<dim>(parameters.axis);
            if (axis.norm() > 0)
              axis /= axis.norm();
          }
      }

      std::string
      name() const override
      {
        return kind;
      }

      std::string
      description() const override
      {
        std::ostringstream out;
        out << kind << " of radius " << radius << " about (" << center << ")";
        if (axis.norm() > 0)
          out << ", axis (" << axis << ")";
        out << ", the body outside it";
        return out.str();
      }

      double
      distance(const Point<dim> &x) const override
      {
        return radial(x).norm() - radius;
      }

      Tensor<1, dim>
      normal(const Point<dim> &x) const override
      {
        const Tensor<1, dim> r = radial(x);
        // at the centre itself every direction is as good as another
        return r.norm() > 0 ? r / r.norm() : Tensor<1, dim>();
      }

      double
      radius_of_curvature() const override
      {
        return radius;
      }

    private:
      // x - c without its component along the axis (cylinder in 3D)
      Tensor<1, dim>
      radial(const Point<dim> &x) const
      {
        const Tensor<1, dim> r = x - center;
        return r - (r * axis) * axis;
      }

      std::string    kind;
      Point<dim>     center;
      double         radius;
      Tensor<1, dim> axis; // zero unless a 3D cylinder
    };

    template <int dim, bool cylinder>
    std::unique_ptr<Obstacle<dim>>
    make(const Parameters &parameters, const double)
    {
      return std::make_unique<Round<dim>>(parameters.obstacle, cylinder);
    }

    const bool registered_cylinder =
      register_obstacle("cylinder", make<2, true>, make<3, true>);
    const bool registered_sphere =
      register_obstacle("sphere", make<2, false>, make<3, false>);
  } // namespace
} // namespace dualcontact
