// Round indenters: a rigid cylinder (a disc in 2D; in 3D infinite along its
// axis) or a sphere (a disc in 2D), of centre c and radius R, the body
// outside it: d(x) = |x - c|_perp - R, with |.|_perp the distance from the
// axis (cylinder) or the centre (sphere), and m(x) the unit vector from the
// axis or centre toward x.
#include <deal.II/base/parameter_handler.h>

#include <dualcontact/input_error.h>
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
      Round(const EntryValues &values, const bool cylinder)
          : kind(cylinder ? "cylinder" : "sphere")
          , radius(numbers_of(values, "Obstacle/Radius").at(0))
      {
        center = to_point<dim>(numbers_of(values, "Obstacle/Center"));
        if (cylinder && dim == 3)
          {
            axis = to_point<dim>(numbers_of(values, "Obstacle/Axis"));
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

    // the entries of both kinds, declared once
    void
    declare(EntryDeclarer &declarer)
    {
      declarer.enter_subsection("Obstacle");
      declarer.declare_entry(
        "Center",
        "0, 0",
        EntryPattern::list(EntryPattern::number(), 2, 3),
        "Cylinder, sphere: the centre c (for a 3D cylinder, "
        "a point on its axis) [length] (3D default: 0, 0, "
        "0).");
      declarer.declare_entry("Radius",
                             "1",
                             EntryPattern::number(0.),
                             "Cylinder, sphere: the radius R [length]. Must be "
                             "positive.");
      declarer.declare_entry("Axis",
                             "0, 0, 1",
                             EntryPattern::list(EntryPattern::number(), 3, 3),
                             "Cylinder in 3D: the direction of its axis [-]. "
                             "Normalised on input; must not be zero.");
      declarer.leave_subsection();
    }

    template <bool cylinder>
    std::vector<std::string>
    entries(const unsigned int dim)
    {
      if (cylinder && dim == 3)
        return {"Obstacle/Center", "Obstacle/Radius", "Obstacle/Axis"};
      return {"Obstacle/Center", "Obstacle/Radius"};
    }

    template <bool cylinder>
    void
    check(const EntryValues &values, const unsigned int dim)
    {
      vector_of(values, "Obstacle/Center", dim);
      if (!(numbers_of(values, "Obstacle/Radius").at(0) > 0.))
        throw InputError("The entry <Obstacle/Radius> must be positive.",
                         exit_invalid_value);
      if (cylinder && dim == 3)
        vector_of(values, "Obstacle/Axis", 3, true);
    }

    template <int dim, bool cylinder>
    std::unique_ptr<Obstacle<dim>>
    make(const EntryValues &values, const MaterialParameters &, const double)
    {
      return std::make_unique<Round<dim>>(values, cylinder);
    }

    const std::vector<std::array<std::string, 3>> defaults_3d = {
      {{"Obstacle", "Center", "0, 0, 0"}}};

    const bool registered_cylinder = register_obstacle(
      "cylinder",
      {"a disc in 2D, a circular cylinder along <Obstacle/Axis> in 3D, of "
       "the given centre and radius, the body outside it (an indenter).",
       declare,
       entries<true>,
       defaults_3d,
       check<true>,
       make<2, true>,
       make<3, true>});
    const bool registered_sphere =
      register_obstacle("sphere",
                        {"a ball in 3D, a disc in 2D, of the given centre "
                         "and radius, the body outside it.",
                         declare,
                         entries<false>,
                         defaults_3d,
                         check<false>,
                         make<2, false>,
                         make<3, false>});
  } // namespace
} // namespace dualcontact
