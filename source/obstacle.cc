#include <deal.II/base/utilities.h>

#include <dualcontact/obstacle.h>
#include <dualcontact/parameter_helpers.h>
#include <dualcontact/parameters.h>
#include <dualcontact/registry.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace dualcontact
{
  bool
  register_obstacle(const std::string &name, ObstacleKind kind)
  {
    Registry<ObstacleKind>::instance().add(name, std::move(kind));
    return true;
  }

  std::vector<std::string>
  obstacle_names()
  {
    return Registry<ObstacleKind>::instance().names();
  }

  const ObstacleKind &
  obstacle_kind(const std::string &name)
  {
    return Registry<ObstacleKind>::instance().get(name,
                                                  "obstacle",
                                                  "Obstacle/Type");
  }

  std::map<std::string, std::vector<std::string>>
  obstacle_entry_readers(const unsigned int dim)
  {
    std::map<std::string, std::vector<std::string>> readers;
    for (const std::string &name : obstacle_names())
      if (obstacle_kind(name).entries != nullptr)
        for (const std::string &entry : obstacle_kind(name).entries(dim))
          readers[entry].push_back(name);
    return readers;
  }

  void
  declare_obstacle_parameters(EntryDeclarer &declarer)
  {
    std::string names, help;
    for (const std::string &name : obstacle_names())
      {
        names += (names.empty() ? "" : "|") + name;
        help += " '" + name + "': " + obstacle_kind(name).help;
      }
    declarer.enter_subsection("Obstacle");
    declarer.declare_entry(
      "Type",
      "plane",
      EntryPattern::selection(names),
      "The rigid obstacle on Gamma_C." + help +
        " Gap and normal are taken at each contact node's "
        "position before deformation (small displacements).");
    declarer.declare_entry(
      "Displacement",
      "",
      EntryPattern::text(),
      "A rigid translation U of the obstacle, prescribed (e.g. an "
      "indentation depth: U = 0, -0.01 moves it down by 0.01) [length], one "
      "value per dimension, separated by ',' or, when the expressions hold "
      "commas, by ';'. Each may be an expression in the time t of the load "
      "path (0; -0.01 * if(t <= 1, t, 2 - t)). Empty: it stays where it is. "
      "The force on the obstacle is reported.");
    declarer.leave_subsection();

    // each kind's entries, once per declaring function (kinds of one file
    // may share one)
    std::vector<void (*)(EntryDeclarer &)> declared;
    for (const std::string &name : obstacle_names())
      {
        const auto declare = obstacle_kind(name).declare_parameters;
        if (declare != nullptr &&
            std::find(declared.begin(), declared.end(), declare) ==
              declared.end())
          {
            declare(declarer);
            declared.push_back(declare);
          }
      }
  }

  void
  ObstacleParameters::declare_parameters(EntryDeclarer &declarer)
  {
    declare_obstacle_parameters(declarer);
  }

  void
  ObstacleParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    const unsigned int dim = prm.get_integer("Dimension");
    prm.leave_subsection();
    prm.enter_subsection("Obstacle");
    type         = prm.get("Type");
    displacement = prm.get("Displacement");
    prm.leave_subsection();
    obstacle_kind(type); // InputError for a name nobody registered
    // every kind's entries, so that a program may change the kind
    std::vector<std::string> entries;
    for (const auto &[entry, kinds] : obstacle_entry_readers(dim))
      entries.push_back(entry);
    values = read_entry_values(prm, entries);
  }

  template <int dim>
  std::unique_ptr<Obstacle<dim>>
  create_obstacle(const std::string        &type,
                  const EntryValues        &values,
                  const MaterialParameters &material,
                  const double              length)
  {
    const ObstacleKind &kind = obstacle_kind(type);
    if constexpr (dim == 2)
      return kind.create_2d(values, material, length);
    else
      return kind.create_3d(values, material, length);
  }

  std::string
  obstacle_entries_text(const std::string &type, const unsigned int dim)
  {
    const ObstacleKind      &kind = obstacle_kind(type);
    std::vector<std::string> entries;
    if (kind.entries != nullptr)
      entries = kind.entries(dim);
    return listed(entries, "<", ">");
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
  create_obstacle(const std::string &,
                  const EntryValues &,
                  const MaterialParameters &,
                  double);
  template std::unique_ptr<Obstacle<3>>
  create_obstacle(const std::string &,
                  const EntryValues &,
                  const MaterialParameters &,
                  double);
  template std::array<Tensor<1, 2>, 1>
  tangent_basis(const Tensor<1, 2> &);
  template std::array<Tensor<1, 3>, 2>
  tangent_basis(const Tensor<1, 3> &);
} // namespace dualcontact
