// An obstacle of any shape, given by the signed distance d(x) from its
// surface (<Obstacle/Distance>, > 0 where the body is). The normal is the
// gradient of d by central differences, normalised; where the gradient
// vanishes or is not finite the normal is returned as zero and the contact
// set reports the node as unusable.
#include <deal.II/base/parameter_handler.h>

#include <dualcontact/expressions.h>
#include <dualcontact/input_error.h>
#include <dualcontact/obstacle.h>

#include <cmath>

namespace dualcontact
{
  namespace
  {
    template <int dim>
    class SignedDistance : public Obstacle<dim>
    {
    public:
      SignedDistance(const EntryValues        &values,
                     const MaterialParameters &material,
                     const double              length)
          : expression(values.at("Obstacle/Distance"))
          , function(make_function<dim>(expression,
                                        1,
                                        material,
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

      bool
      has_corner_near(const Point<dim> &x) const override
      {
        // The nearest surface point p = x - d(x) m(x), and the normals at
        // points around it on the body's side (a circle, or two cones in
        // 3D, of radius rho about p, up to 80 degrees from m): on a smooth
        // surface they stay within rho/R of m, at a corner or an edge they
        // turn by its angle. 100 times the difference step keeps the
        // normals accurate; 20 degrees flags corners of the obstacle but no
        // curvature of radius above about 3 rho.
        const Tensor<1, dim> m = normal(x);
        if (!(m.norm() > 0.5))
          return false;
        const Point<dim>   p         = x - distance(x) * m;
        const double       rho       = 100. * step;
        const auto         t         = tangent_basis(-m);
        const double       cos_limit = std::cos(20. * numbers::PI / 180.);
        const unsigned int n_around  = dim == 2 ? 1 : 8;
        for (const double degrees : {-80., -40., 40., 80.})
          for (unsigned int k = 0; k < n_around; ++k)
            {
              const double   theta = degrees * numbers::PI / 180.;
              const double   phi   = 2. * numbers::PI * k / n_around;
              Tensor<1, dim> side  = t[0];
              if (dim == 3)
                side = std::cos(phi) * t[0] + std::sin(phi) * t[dim - 2];
              const Tensor<1, dim> e =
                std::cos(theta) * m + std::sin(theta) * side;
              const Tensor<1, dim> there = normal(p + rho * e);
              if (there.norm() > 0.5 && there * m < cos_limit)
                return true;
            }
        return false;
      }

    private:
      std::string                    expression;
      std::unique_ptr<Function<dim>> function;
      double                         step;
    };

    void
    declare(EntryDeclarer &declarer)
    {
      declarer.enter_subsection("Obstacle");
      declarer.declare_entry(
        "Distance",
        "",
        EntryPattern::text(),
        "Distance: the signed distance d(x, y) (2D) or d(x, y, z) (3D) from "
        "the obstacle's surface [length], > 0 where the body is, in the "
        "function parser's syntax (constants E, nu, L as elsewhere). Its "
        "gradient should have length 1 near the surface; it is computed by "
        "central differences and normalised. Example: a flat punch of "
        "half-width 0.1 whose face lies on y = 1, above the body: "
        "'max(1 - y, abs(x) - 0.1)'.");
      declarer.leave_subsection();
    }

    std::vector<std::string>
    entries(const unsigned int)
    {
      return {"Obstacle/Distance"};
    }

    void
    check(const EntryValues &values, const unsigned int)
    {
      if (values.at("Obstacle/Distance").find_first_not_of(" \t") ==
          std::string::npos)
        throw InputError("The entry <Obstacle/Type> is 'distance' but "
                         "<Obstacle/Distance> gives no expression.",
                         exit_inconsistent);
    }

    template <int dim>
    std::unique_ptr<Obstacle<dim>>
    make(const EntryValues        &values,
         const MaterialParameters &material,
         const double              length)
    {
      return std::make_unique<SignedDistance<dim>>(values, material, length);
    }

    const bool registered = register_obstacle(
      "distance",
      {"the surface d(x) = 0 of the signed-distance expression "
       "<Obstacle/Distance>, d > 0 where the body is; the normal is its "
       "gradient, normalised.",
       declare,
       entries,
       {},
       check,
       make<2>,
       make<3>});
  } // namespace
} // namespace dualcontact
