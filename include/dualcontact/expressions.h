// Expressions of the scene's entries as functions of x, y (z) and the time
// t: loads, prescribed displacements, exact solutions, friction, and the
// obstacle's path.
#ifndef dualcontact_expressions_h
#define dualcontact_expressions_h

#include <deal.II/base/function.h>
#include <deal.II/base/function_parser.h>

#include <dualcontact/material_parameters.h>

#include <memory>
#include <string>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  /**
   * An expression of <entry> ("a; b" for a vector) as a function of x, y
   * (z) with the constants pi, E, nu, lambda, mu; gradients by fourth-order
   * differences with a step 1e-4 `length`. With `times` (the steps of the
   * load path), also of the time t, set by Function::set_time(). Throws
   * InputError naming the entry if it does not parse, has the wrong number
   * of components, or uses t without `times`.
   */
  template <int dim>
  std::unique_ptr<Function<dim>>
  make_function(const std::string         &expression,
                const unsigned int         n_components,
                const MaterialParameters  &material,
                const std::string         &entry,
                const double               length,
                const std::vector<double> &times = {});

  /**
   * <Obstacle/Displacement>, "U_x; U_y" (U_z), as dim functions of the
   * one variable t (evaluated at the point t); checked finite at the
   * steps' times.
   */
  template <int dim>
  std::unique_ptr<FunctionParser<1>>
  make_obstacle_path(const std::string         &expression,
                     const std::vector<double> &times,
                     double                     length);
} // namespace dualcontact

#endif
