// Expressions of the scene's entries as functions: loads, prescribed
// displacements, exact solutions, friction, and the obstacle's path, parsed
// by muparser with the material's constants, checked as they are read.
#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <dualcontact/expressions.h>
#include <dualcontact/input_error.h>
#include <dualcontact/parameter_helpers.h>

#include <cmath>
#include <iostream>
#include <map>
#include <sstream>

namespace dualcontact
{
  namespace
  {
    /**
     * A FunctionParser of `expression` in `variables` (the time t last if
     * `of_time`), or nullptr if muparser refuses it. deal.II prints
     * muparser's diagnostics on std::cerr before it throws; the user gets
     * our one-line message instead.
     */
    template <int dim>
    std::unique_ptr<FunctionParser<dim>>
    try_parse(const std::string                   &expression,
              const unsigned int                   n_components,
              const std::string                   &variables,
              const std::map<std::string, double> &constants,
              const bool                           of_time,
              const double                         length)
    {
      // Gradients (for H1 errors) by fourth-order differences with a step
      // relative to the body's size.
      auto function =
        std::make_unique<FunctionParser<dim>>(n_components, 0., 1e-4 * length);
      function->set_formula(AutoDerivativeFunction<dim>::FourthOrder);
      std::ostringstream    muparser_diagnostics;
      std::streambuf *const cerr_buffer =
        std::cerr.rdbuf(muparser_diagnostics.rdbuf());
      try
        {
          function->initialize(variables, expression, constants, of_time);
          // muparser may defer some errors to the first evaluation
          Vector<double> values(n_components);
          function->vector_value(Point<dim>(), values);
        }
      catch (const std::exception &)
        {
          function.reset();
        }
      std::cerr.rdbuf(cerr_buffer);
      return function;
    }
  } // namespace

  /**
   * <Obstacle/Displacement>, "U_x; U_y" (U_z), as dim functions of the
   * one variable t (evaluated at the point t); checked finite at the
   * steps' times.
   */
  template <int dim>
  std::unique_ptr<FunctionParser<1>>
  make_obstacle_path(const std::string         &expression,
                     const std::vector<double> &times,
                     const double               length)
  {
    auto path =
      try_parse<1>(expression, dim, "t", {{"pi", numbers::PI}}, false, length);
    if (path == nullptr)
      throw InputError("The entry <Obstacle/Displacement> is not a valid "
                       "expression in t: '" +
                         expression + "'.",
                       exit_invalid_value);
    for (const double t : times)
      for (unsigned int c = 0; c < dim; ++c)
        if (!std::isfinite(path->value(Point<1>(t), c)))
          throw InputError("The entry <Obstacle/Displacement> is not a "
                           "finite number (NaN or infinity) at t = " +
                             number_text(t) + ": '" + expression + "'.",
                           exit_invalid_value);
    return path;
  }

  template <int dim>
  std::unique_ptr<Function<dim>>
  make_function(const std::string         &expression,
                const unsigned int         n_components,
                const MaterialParameters  &material,
                const std::string         &entry,
                const double               length,
                const std::vector<double> &times)
  {
    const std::map<std::string, double> constants = {
      {"pi", numbers::PI},
      {"E", material.youngs_modulus},
      {"nu", material.poissons_ratio},
      {"lambda", material.lambda()},
      {"mu", material.mu()}};
    const bool        of_time   = !times.empty();
    const std::string space     = dim == 2 ? "x,y" : "x,y,z";
    const std::string variables = space + (of_time ? ",t" : "");

    // the count is checked whatever the values: '0' or '0; 0' for a 3D
    // vector is as wrong as '1; 2' (a 3D scene's default body force is
    // '0; 0; 0', Parameters::use)
    const auto n_given = Utilities::split_string_list(expression, ';').size();
    if (n_given != n_components)
      throw InputError("The entry <" + entry + "> needs " +
                         std::to_string(n_components) +
                         " expression(s) separated by ';', not " +
                         std::to_string(n_given) + ": '" + expression + "'.",
                       exit_invalid_value);

    auto function = try_parse<dim>(
      expression, n_components, variables, constants, of_time, length);
    if (function == nullptr)
      {
        if (!of_time && try_parse<dim>(expression,
                                       n_components,
                                       space + ",t",
                                       constants,
                                       true,
                                       length) != nullptr)
          throw InputError(
            "The entry <" + entry + "> may not depend on the time t: '" +
              expression +
              "'. Only the loads (<Boundary conditions/Tractions>, <Boundary "
              "conditions/Displacements>, <Loads/Body force>) and "
              "<Obstacle/Displacement> follow the load path.",
            exit_invalid_value);
        throw InputError("The entry <" + entry +
                           "> is not a valid expression in " + variables +
                           ": '" + expression + "'.",
                         exit_invalid_value);
      }
    // An expression without x, y, z is one number at each time: NaN or
    // infinity (0/0, 1/0) is refused here. One that depends on the position
    // is checked where it is used (loads, friction at the contact nodes,
    // errors).
    const bool follows_path = of_time && uses_time(expression);
    if (!uses_coordinates(expression, dim))
      for (const double t : follows_path ? times : std::vector<double>{0.})
        {
          function->set_time(t);
          Vector<double> values(n_components);
          function->vector_value(Point<dim>(), values);
          for (const double value : values)
            if (!std::isfinite(value))
              throw InputError("The entry <" + entry +
                                 "> is not a finite number (NaN or infinity)" +
                                 (follows_path ? " at t = " + number_text(t) :
                                                 std::string()) +
                                 ": '" + expression + "'.",
                               exit_invalid_value);
        }
    return function;
  }


  template std::unique_ptr<Function<2>>
  make_function(const std::string &,
                unsigned int,
                const MaterialParameters &,
                const std::string &,
                double,
                const std::vector<double> &);
  template std::unique_ptr<Function<3>>
  make_function(const std::string &,
                unsigned int,
                const MaterialParameters &,
                const std::string &,
                double,
                const std::vector<double> &);
  template std::unique_ptr<FunctionParser<1>>
  make_obstacle_path<2>(const std::string &,
                        const std::vector<double> &,
                        double);
  template std::unique_ptr<FunctionParser<1>>
  make_obstacle_path<3>(const std::string &,
                        const std::vector<double> &,
                        double);
} // namespace dualcontact
