// A scene: what every geometry shares (the geometry itself is a plugin,
// geometry.h): the loads and prescribed displacements as functions, the
// obstacle and its path, the friction, the effects the solver composes,
// and the coarse mesh with the check of its size against the memory.
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>

#include <deal.II/grid/tria.h>

#include <dualcontact/expressions.h>
#include <dualcontact/input_error.h>
#include <dualcontact/parameter_helpers.h>
#include <dualcontact/scene.h>

#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

namespace dualcontact
{
  std::string
  Effects::describe() const
  {
    std::ostringstream out;
    out << "  contact with the obstacle   : "
        << (obstacle_contact ? "yes: Uzawa on the modified Lagrangian" :
            contact          ? "no" :
                               "no: one linear elasticity solve per mesh")
        << '\n';
    if (obstacle_contact)
      out << "  obstacle                    : " << obstacle << '\n';
    if (!pairs.empty())
      out << "  contact between bodies      : slave on master " << pairs << ": "
          << pair_coupling << ", Uzawa on the modified Lagrangian\n";
    out << "  friction                    : "
        << (!contact      ? "no (no contact)" :
            zero_friction ? "no: the coefficient/threshold is zero, the "
                            "frictionless path runs" :
                            friction->description())
        << '\n'
        << "  body force                  : "
        << (body_force ? "yes" : "no (not assembled)") << '\n'
        << "  boundary tractions          : "
        << (tractions ? "yes" : "no (not assembled)") << '\n';
    return out.str();
  }

  template <int dim>
  Scene<dim>::Scene(const Parameters                  &parameters,
                    const std::function<void(double)> &before_building)
      : parameters(parameters)
  {
    AssertThrow(parameters.geometry.dimension == dim,
                ExcMessage("Scene<dim> built for the wrong dimension."));
    // The geometry first: a mesh file's coarse mesh is read here, on every
    // rank (it is small): its size is the scene's length, and its boundary
    // ids are what the conditions must name.
    geometry_ = create_geometry<dim>(parameters, before_building);
    discretization_ =
      std::make_unique<Discretization<dim>>(geometry_->cell_kind(),
                                            parameters.discretization.degree);
    const double length = characteristic_length();
    // the loads follow the load path (doc/theory.md §11)
    const std::vector<double> times = parameters.load_path.step_times();
    make_loads(length, times);
    const std::string path = make_obstacle(length, times);
    find_effects(length, times, path);
  }

  template <int dim>
  void
  Scene<dim>::make_loads(const double length, const std::vector<double> &times)
  {
    const MaterialParameters &material = parameters.material;
    const BoundaryParameters &boundary = parameters.boundary;

    // A load or a prescribed displacement: its function, or none where it
    // is zero (nothing to assemble or to interpolate), with the count of
    // its components checked in either case.
    const auto load = [&](const std::string &expression,
                          const std::string &entry) {
      auto function =
        make_function<dim>(expression, dim, material, entry, length, times);
      return is_zero_expression(expression) ? nullptr : std::move(function);
    };
    for (const types::boundary_id id : ids_with(BoundaryCondition::fixed))
      {
        const auto it = boundary.displacements.find(id);
        if (it != boundary.displacements.end())
          if (auto function =
                load(it->second, "Boundary conditions/Displacements"))
            displacements[id] = std::move(function);
      }
    for (const types::boundary_id id : ids_with(BoundaryCondition::traction))
      if (auto function =
            load(boundary.tractions.at(id), "Boundary conditions/Tractions"))
        tractions[id] = std::move(function);
    body_force_ = load(parameters.loads.body_force, "Loads/Body force");
    if (!parameters.exact.displacement.empty())
      exact_ = make_function<dim>(parameters.exact.displacement,
                                  dim,
                                  material,
                                  "Exact solution/Displacement",
                                  length);

    if (!parameters.exact.contact_pressure.empty())
      exact_pressure_ = make_function<dim>(parameters.exact.contact_pressure,
                                           1,
                                           material,
                                           "Exact solution/Contact pressure",
                                           length);
  }

  template <int dim>
  std::string
  Scene<dim>::make_obstacle(const double               length,
                            const std::vector<double> &times)
  {
    // the obstacle is needed only with contact, but a plane is always
    // there (its entries have defaults), so that gaps are defined; its
    // translation U(t) is a function of the time alone
    std::string path;
    for (const std::string &component :
         parameters.obstacle.displacement_components())
      path += (path.empty() ? "" : "; ") + component;
    if (!path.empty())
      obstacle_path = make_obstacle_path<dim>(path, times, length);
    obstacle_ = std::make_unique<PlacedObstacle<dim>>(
      create_obstacle<dim>(parameters.obstacle.type,
                           parameters.obstacle.values,
                           parameters.material,
                           length),
      Tensor<1, dim>(),
      obstacle_entries_text(parameters.obstacle.type,
                            parameters.geometry.dimension));
    set_time(times.front());

    return path;
  }

  template <int dim>
  void
  Scene<dim>::find_effects(const double               length,
                           const std::vector<double> &times,
                           const std::string         &path)
  {
    const MaterialParameters &material = parameters.material;
    effects_.contact                   = parameters.boundary.has_contact();
    effects_.obstacle_contact = !ids_with(BoundaryCondition::contact).empty();
    effects_.pairs            = parameters.boundary.pairs_in_words();
    effects_.pair_coupling    = parameters.boundary.node_to_segment ?
                                  "node to segment (one pass)" :
                                  "dual mortar";
    effects_.obstacle         = (*obstacle_)->description();
    obstacle_moves_           = obstacle_->displacement().norm() > 0;
    if (obstacle_path != nullptr && times.size() > 1 && uses_time(path))
      {
        obstacle_moves_ = true;
        effects_.obstacle += ", moved by U(t) = (" + path + ")";
      }
    else if (obstacle_->displacement().norm() > 0)
      {
        std::ostringstream moved;
        moved << ", moved by (" << obstacle_->displacement() << ")";
        effects_.obstacle += moved.str();
      }
    effects_.friction           = create_friction_law(parameters.friction.law);
    const std::string parameter = effects_.friction->parameter_entry();
    if (effects_.contact && !parameter.empty())
      {
        const std::string &expression = parameters.friction.parameter;
        const std::string  entry      = "Friction/" + parameter;
        friction_ = make_function<dim>(expression, 1, material, entry, length);
        if (is_zero_expression(expression))
          {
            effects_.zero_friction = true;
            effects_.friction      = create_friction_law("none");
            friction_.reset();
          }
        else if (friction_->value(center()) < 0. &&
                 expression.find_first_of("xyz") == std::string::npos)
          throw InputError("The entry <" + entry + "> must not be negative.",
                           exit_invalid_value);
      }
    effects_.body_force = body_force_ != nullptr;
    effects_.tractions  = !tractions.empty();
  }

  template <int dim>
  void
  Scene<dim>::set_time(const double t)
  {
    time_ = t;
    for (auto &[id, function] : displacements)
      function->set_time(t);
    for (auto &[id, function] : tractions)
      function->set_time(t);
    if (body_force_ != nullptr)
      body_force_->set_time(t);
    Tensor<1, dim> U;
    if (obstacle_path != nullptr)
      {
        for (unsigned int c = 0; c < dim; ++c)
          U[c] = obstacle_path->value(Point<1>(t), c);
      }
    obstacle_->move_to(U);
  }

  template <int dim>
  std::set<types::boundary_id>
  Scene<dim>::ids_with(const BoundaryCondition condition) const
  {
    const auto ids = parameters.boundary.ids_with(condition);
    return {ids.begin(), ids.end()};
  }

  template <int dim>
  const Function<dim> &
  Scene<dim>::displacement(const types::boundary_id id) const
  {
    const auto it = displacements.find(id);
    return it == displacements.end() ?
             static_cast<const Function<dim> &>(zero) :
             *it->second;
  }

  template <int dim>
  const Function<dim> *
  Scene<dim>::traction(const types::boundary_id id) const
  {
    const auto it = tractions.find(id);
    return it == tractions.end() ? nullptr : it->second.get();
  }

  template <int dim>
  double
  Scene<dim>::characteristic_length() const
  {
    return geometry_->characteristic_length();
  }

  template <int dim>
  Point<dim>
  Scene<dim>::center() const
  {
    return geometry_->center();
  }

  template <int dim>
  void
  Scene<dim>::create_mesh(
    parallel::TriangulationBase<dim>  &triangulation,
    const std::function<void(double)> &before_refining) const
  {
    create_coarse_mesh(triangulation, before_refining);
    refine_initial_mesh(triangulation, before_refining);
  }

  template <int dim>
  void
  Scene<dim>::create_coarse_mesh(
    parallel::TriangulationBase<dim>  &triangulation,
    const std::function<void(double)> &before_refining) const
  {
    // A coarse mesh whose cells are known before it is built (a box) is
    // checked against the memory first: each refinement makes 2^dim
    // children of a cell (a triangle 4, a tetrahedron 8).
    const double n_cells = geometry_->n_coarse_cells();
    if (before_refining && n_cells > 0)
      before_refining(
        n_cells * std::pow(std::pow(2., dim),
                           parameters.refinement.initial_global_refinement));
    geometry_->create_coarse_mesh(triangulation);
  }

  template class Scene<2>;
  template class Scene<3>;
} // namespace dualcontact
