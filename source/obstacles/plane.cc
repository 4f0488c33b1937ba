// The plane obstacle, the foundation of the older scenes: the half-space
// behind the plane through p with unit normal m (pointing into the body),
// d(x) = (x - p).m. Given in subsection Foundation.
#include <dualcontact/obstacle.h>

#include <sstream>

namespace dualcontact
{
  namespace
  {
    template <int dim>
    class Plane : public Obstacle<dim>
    {
    public:
      explicit Plane(const ObstacleParameters &parameters)
      {
        // without contact the entries are not checked: read what is there
        point = to_point<dim>(parameters.point);
        m     = to_point<dim>(parameters.normal);
        if (m.norm() > 0)
          m /= m.norm();
      }

      std::string
      name() const override
      {
        return "plane";
      }

      std::string
      description() const override
      {
        std::ostringstream out;
        out << "plane through (" << point << ") with normal (" << m << ")";
        return out.str();
      }

      double
      distance(const Point<dim> &x) const override
      {
        return (x - point) * m;
      }

      Tensor<1, dim>
      normal(const Point<dim> &) const override
      {
        return m;
      }

      bool
      is_plane() const override
      {
        return true;
      }

    private:
      Point<dim>     point;
      Tensor<1, dim> m;
    };

    template <int dim>
    std::unique_ptr<Obstacle<dim>>
    make(const Parameters &parameters, const double)
    {
      return std::make_unique<Plane<dim>>(parameters.obstacle);
    }

    const bool registered = register_obstacle("plane", make<2>, make<3>);
  } // namespace
} // namespace dualcontact
