// <Boundary conditions>: which condition holds on which boundary id.
#include <deal.II/base/utilities.h>

#include <dualcontact/geometry.h>
#include <dualcontact/input_error.h>
#include <dualcontact/parameter_helpers.h>
#include <dualcontact/parameters.h>

#include <map>
#include <utility>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  namespace
  {
    /**
     * Split "k1: v1, k2: v2" into (key, value) pairs at the commas outside
     * parentheses, keeping the order and any repeated key (repeats are an
     * error the caller reports).
     */
    std::vector<std::pair<boundary_id, std::string>>
    split_id_map(const std::string &text)
    {
      std::vector<std::pair<boundary_id, std::string>> result;
      for (const std::string &item : split_outside_parentheses(text, ','))
        {
          if (item.empty())
            continue;
          const auto        colon = item.find(':');
          const std::string key   = Utilities::trim(item.substr(0, colon));
          const std::string value = Utilities::trim(item.substr(colon + 1));
          result.emplace_back(
            static_cast<boundary_id>(Utilities::string_to_int(key)), value);
        }
      return result;
    }

    std::map<boundary_id, std::string>
    parse_id_map(const std::string &text, const std::string &entry)
    {
      std::map<boundary_id, std::string> result;
      for (const auto &[id, value] : split_id_map(text))
        if (!result.emplace(id, value).second)
          throw InputError("The entry <" + entry + "> names boundary id " +
                             std::to_string(id) + " twice.",
                           exit_inconsistent);
      return result;
    }

    // The pattern of an "id: value" list (ids 0..255).
    EntryPattern
    id_map_pattern(const EntryPattern &value_pattern)
    {
      return EntryPattern::map(EntryPattern::whole_number(0, 255),
                               value_pattern);
    }
  } // namespace

  const NameTable<BoundaryCondition> &
  boundary_condition_names()
  {
    static const NameTable<BoundaryCondition> table = {
      {BoundaryCondition::free, "free"},
      {BoundaryCondition::fixed, "fixed"},
      {BoundaryCondition::normal_fixed, "normal fixed"},
      {BoundaryCondition::traction, "traction"},
      {BoundaryCondition::contact, "contact"}};
    return table;
  }

  std::string
  to_string(const BoundaryCondition condition)
  {
    return boundary_condition_names().name(condition);
  }

  BoundaryCondition
  BoundaryParameters::condition(const boundary_id id) const
  {
    const auto it = conditions.find(id);
    return it == conditions.end() ? BoundaryCondition::free : it->second;
  }

  std::vector<boundary_id>
  BoundaryParameters::ids_with(const BoundaryCondition wanted) const
  {
    std::vector<boundary_id> ids;
    for (const auto &[id, condition] : conditions)
      if (condition == wanted)
        ids.push_back(id);
    return ids;
  }

  std::set<boundary_id>
  BoundaryParameters::contact_ids() const
  {
    std::set<boundary_id> ids;
    for (const boundary_id id : ids_with(BoundaryCondition::contact))
      ids.insert(id);
    for (const auto &[slave, master] : contact_pairs)
      ids.insert(slave);
    return ids;
  }

  std::vector<std::string>
  BoundaryParameters::parts_in_words() const
  {
    std::vector<std::string> parts;
    for (const auto &[id, condition] : conditions)
      parts.push_back("id " + std::to_string(id) + " " + to_string(condition));
    for (const auto &[slave, master] : contact_pairs)
      parts.push_back("id " + std::to_string(slave) + " slave, id " +
                      std::to_string(master) + " master of a contact pair");
    return parts;
  }

  std::string
  BoundaryParameters::pairs_in_words() const
  {
    std::string words;
    for (const auto &[slave, master] : contact_pairs)
      words += (words.empty() ? "" : ", ") + std::to_string(slave) + " on " +
               std::to_string(master);
    return words;
  }

  void
  BoundaryParameters::declare_parameters(EntryDeclarer &declarer)
  {
    declarer.enter_subsection("Boundary conditions");
    declarer.declare_entry(
      "Conditions",
      "",
      id_map_pattern(
        EntryPattern::selection(boundary_condition_names().names())),
      "The condition on each boundary id, as a list 'id: condition, id: "
      "condition'. Conditions: 'free' (zero traction), 'fixed' (all "
      "displacement components prescribed, see 'Displacements'), 'normal "
      "fixed' (zero normal displacement, tangential one free: a frictionless "
      "slider), 'traction' (prescribed traction, see 'Tractions'), 'contact' "
      "(unilateral contact with the rigid foundation, with the friction law "
      "of subsection Friction). Ids not listed are free. An id may appear "
      "only once.");
    declarer.declare_entry(
      "Displacements",
      "",
      EntryPattern::expression_map(EntryPattern::whole_number(0, 255)),
      "Prescribed displacement on 'fixed' ids, as 'id: u_x; u_y' [length]; "
      "each component an expression in x, y (z) and the time t of the load "
      "path (<Load path>), with the constants pi, E, nu, lambda, mu; commas "
      "only inside parentheses (if(t <= 1, t, 1)). Fixed ids not listed here "
      "are clamped (zero displacement).");
    declarer.declare_entry(
      "Tractions",
      "",
      EntryPattern::expression_map(EntryPattern::whole_number(0, 255)),
      "Prescribed traction on 'traction' ids, as 'id: T_x; T_y' [stress = "
      "force/length^2]; each component an expression in x, y (z) and the "
      "time t of the load path (<Load path>), with the constants pi, E, nu, "
      "lambda, mu; commas only inside parentheses (if(t <= 1, t, 1)). A "
      "pressure p on a face with outer normal n is the traction -p n. Every "
      "'traction' id must be listed.");
    declarer.declare_entry(
      "Contact pairs",
      "",
      id_map_pattern(EntryPattern::whole_number(0, 255)),
      "Contact between two bodies of the mesh, as 'slave id: master id': the "
      "faces with the slave id carry the contact nodes and multipliers, the "
      "faces with the master id are the other body's surface they may touch "
      "(dual mortar, small sliding, paired in the reference configuration). "
      "Both ids keep the condition 'free' in 'Conditions' (or 'traction': a "
      "load on the faces the other body does not hold, such as a part of "
      "the slave beyond the master's end), lie on different "
      "bodies (parts of the mesh that share no vertex), and an id belongs to "
      "one pair only. The friction law of subsection Friction holds on every "
      "pair as on the obstacle's 'contact' ids. At degree 1-3 on "
      "quadrilaterals and hexahedra, at degree 1 on triangles and "
      "tetrahedra.");
    declarer.declare_entry(
      "Pair coupling",
      "dual mortar",
      EntryPattern::selection("dual mortar|node to segment"),
      "How a slave node of a contact pair sees the master surface: 'dual "
      "mortar' (its gap and slip weighted over the master segments it faces "
      "with the dual basis, integrated exactly; passes the contact patch "
      "test on non-matching meshes), or 'node to segment' (the gap to the "
      "master point its normal meets, one pass; fails that test, for "
      "comparison, in 2D at degree 1: doc/two_bodies.md). Dimensionless.");
    declarer.leave_subsection();
  }

  void
  BoundaryParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    conditions.clear();
    for (const auto &[id, name] :
         parse_id_map(prm.get("Conditions"), "Boundary conditions/Conditions"))
      conditions[id] = boundary_condition_names().value(name);
    displacements = parse_id_map(prm.get("Displacements"),
                                 "Boundary conditions/Displacements");
    tractions =
      parse_id_map(prm.get("Tractions"), "Boundary conditions/Tractions");
    contact_pairs.clear();
    for (const auto &[slave, master] :
         parse_id_map(prm.get("Contact pairs"),
                      "Boundary conditions/Contact pairs"))
      contact_pairs[slave] =
        static_cast<boundary_id>(Utilities::string_to_int(master));
    node_to_segment = prm.get("Pair coupling") == "node to segment";
    prm.leave_subsection();
  }

  // the stages of check(), after it
  static void
  check_contact_pairs(const BoundaryParameters &boundary,
                      const unsigned int        n_ids,
                      const std::string        &shape);
  static void
  check_boundary_data(const BoundaryParameters &boundary);

  void
  BoundaryParameters::check(const Parameters &parameters) const
  {
    const GeometryParameters &geometry = parameters.geometry;
    const unsigned int        dim      = geometry.dimension;
    const unsigned int        n_ids    = n_geometry_boundary_ids(geometry);
    const std::string         shape    = geometry.type;
    // a mesh file's ids are checked once it is read (Scene)
    for (const auto &[id, condition] : conditions)
      if (id >= n_ids)
        throw InputError("The entry <Boundary conditions/Conditions> names "
                         "boundary id " +
                           std::to_string(id) + ", which the geometry '" +
                           shape + "' does not have (its ids are 0 to " +
                           std::to_string(n_ids - 1) + ").",
                         exit_inconsistent);

    // the mortar segments: intervals in 2D, polygons in 3D, where at
    // degree 2-3 the nodes of a face are FE_Q(k)'s support points on it
    // (quadrilaterals, hexahedra), and the node-to-segment comparison takes
    // the vertices alone (2D, degree 1)
    const unsigned int degree = parameters.discretization.degree;
    if (!contact_pairs.empty() && dim == 3 && node_to_segment)
      throw InputError("The entry <Boundary conditions/Pair coupling> = node "
                       "to segment is a comparison in 2D: set it to dual "
                       "mortar in 3D.",
                       exit_inconsistent);
    if (!contact_pairs.empty() && degree > 1 &&
        geometry.cell_kind == CellKind::simplex)
      throw InputError("The entry <Boundary conditions/Contact pairs> couples "
                       "two bodies of simplices at degree 1 only: set "
                       "<Discretization/Polynomial degree> to 1, or <Geometry/"
                       "Cell type> to quadrilateral.",
                       exit_inconsistent);
    if (!contact_pairs.empty() && degree > 1 && node_to_segment)
      throw InputError("The entry <Boundary conditions/Pair coupling> = node "
                       "to segment couples the vertices of degree 1 only: set "
                       "<Discretization/Polynomial degree> to 1, or the "
                       "coupling to dual mortar.",
                       exit_inconsistent);
    check_contact_pairs(*this, n_ids, shape);
    check_boundary_data(*this);
  }

  /**
   * The contact pairs: two different ids of the geometry (of `n_ids`, the
   * geometry `shape`'s, unless a mesh file gives them), both free or loaded
   * by a traction, each in one pair only.
   */
  static void
  check_contact_pairs(const BoundaryParameters &boundary,
                      const unsigned int        n_ids,
                      const std::string        &shape)
  {
    // a pair: two different ids of the geometry, both free (the pair is
    // their condition) or loaded by a traction, each in one pair only
    std::map<boundary_id, unsigned int> in_pairs;
    for (const auto &[slave, master] : boundary.contact_pairs)
      {
        const std::string pair = "The entry <Boundary conditions/Contact "
                                 "pairs> pairs " +
                                 std::to_string(slave) + ": " +
                                 std::to_string(master);
        if (slave == master)
          throw InputError(pair + ", one id with itself: a pair couples the "
                                  "surfaces of two bodies.",
                           exit_inconsistent);
        for (const boundary_id id : {slave, master})
          {
            if (id >= n_ids)
              throw InputError(pair + ", but the geometry '" + shape +
                                 "' has no boundary id " + std::to_string(id) +
                                 " (its ids are 0 to " +
                                 std::to_string(n_ids - 1) + ").",
                               exit_inconsistent);
            if (boundary.condition(id) != BoundaryCondition::free &&
                boundary.condition(id) != BoundaryCondition::traction)
              throw InputError(pair +
                                 ", but <Boundary conditions/"
                                 "Conditions> gives id " +
                                 std::to_string(id) + " the condition '" +
                                 to_string(boundary.condition(id)) +
                                 "': a pair's ids are free there, or "
                                 "loaded by a traction.",
                               exit_inconsistent);
            if (++in_pairs[id] > 1)
              throw InputError("The entry <Boundary conditions/Contact "
                               "pairs> names boundary id " +
                                 std::to_string(id) +
                                 " in two pairs: an id belongs to one pair.",
                               exit_inconsistent);
          }
      }
  }

  /**
   * Displacements for 'fixed' ids only, tractions for 'traction' ids only,
   * and a traction for each of these.
   */
  static void
  check_boundary_data(const BoundaryParameters &boundary)
  {
    const auto check_data = [&](const std::map<boundary_id, std::string> &data,
                                const BoundaryCondition wanted,
                                const std::string      &entry) {
      for (const auto &[id, expression] : data)
        if (boundary.condition(id) != wanted)
          throw InputError("The entry <Boundary conditions/" + entry +
                             "> gives data for boundary id " +
                             std::to_string(id) + ", whose condition is '" +
                             to_string(boundary.condition(id)) + "', not '" +
                             to_string(wanted) + "'.",
                           exit_inconsistent);
    };
    check_data(boundary.displacements,
               BoundaryCondition::fixed,
               "Displacements");
    check_data(boundary.tractions, BoundaryCondition::traction, "Tractions");
    for (const boundary_id id : boundary.ids_with(BoundaryCondition::traction))
      if (boundary.tractions.count(id) == 0)
        throw InputError("Boundary id " + std::to_string(id) +
                           " has the condition 'traction' but the entry "
                           "<Boundary conditions/Tractions> gives no traction "
                           "for it.",
                         exit_inconsistent);
  }
} // namespace dualcontact
