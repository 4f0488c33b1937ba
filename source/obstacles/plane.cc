// The plane obstacle, the foundation: the half-space behind the plane
// through p with unit normal m (pointing into the body), d(x) = (x - p).m.
// Its entries are in subsection Foundation.
#include <deal.II/base/parameter_handler.h>

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
      explicit Plane(const EntryValues &values)
      {
        // without contact the entries are not checked: read what is there
        point = to_point<dim>(numbers_of(values, "Foundation/Point"));
        m     = to_point<dim>(numbers_of(values, "Foundation/Normal"));
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

    void
    declare(EntryDeclarer &declarer)
    {
      declarer.enter_subsection("Foundation");
      declarer.declare_entry(
        "Point",
        "0, 0",
        EntryPattern::list(EntryPattern::number(), 2, 3),
        "Plane obstacle (the foundation, a half-space): a "
        "point p on its boundary [length] (3D default: 0, 0, "
        "0).");
      declarer.declare_entry(
        "Normal",
        "0, 1",
        EntryPattern::list(EntryPattern::number(), 2, 3),
        "Plane obstacle: the normal m of its boundary, pointing from the "
        "foundation into the body [-]. Normalised on input; must not be "
        "zero. The initial gap is g0(x) = (x - p).m. Default: +y in 2D, +z "
        "in 3D (0, 0, 1).");
      declarer.leave_subsection();
    }

    std::vector<std::string>
    entries(const unsigned int)
    {
      return {"Foundation/Point", "Foundation/Normal"};
    }

    void
    check(const EntryValues &values, const unsigned int dim)
    {
      vector_of(values, "Foundation/Point", dim);
      vector_of(values, "Foundation/Normal", dim, true);
    }

    template <int dim>
    std::unique_ptr<Obstacle<dim>>
    make(const EntryValues &values, const MaterialParameters &, const double)
    {
      return std::make_unique<Plane<dim>>(values);
    }

    const bool registered =
      register_obstacle("plane",
                        {"a half-space, given in subsection Foundation.",
                         declare,
                         entries,
                         {{{"Foundation", "Point", "0, 0, 0"}},
                          {{"Foundation", "Normal", "0, 0, 1"}}},
                         check,
                         make<2>,
                         make<3>});
  } // namespace
} // namespace dualcontact
