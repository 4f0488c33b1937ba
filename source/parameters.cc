#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <dualcontact/friction_law.h>
#include <dualcontact/input_error.h>
#include <dualcontact/obstacle.h>
#include <dualcontact/parameter_reader.h>
#include <dualcontact/parameters.h>
#include <dualcontact/refinement_indicator.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace dualcontact
{
  using namespace dealii;

  namespace
  {
    const char *const condition_names =
      "free|fixed|normal fixed|traction|contact";

    BoundaryCondition
    parse_condition(const std::string &name)
    {
      if (name == "free")
        return BoundaryCondition::free;
      if (name == "fixed")
        return BoundaryCondition::fixed;
      if (name == "normal fixed")
        return BoundaryCondition::normal_fixed;
      if (name == "traction")
        return BoundaryCondition::traction;
      if (name == "contact")
        return BoundaryCondition::contact;
      AssertThrow(false, ExcInternalError());
      return BoundaryCondition::free;
    }

    /**
     * Split "k1: v1, k2: v2" into (key, value) pairs, keeping the order and
     * any repeated key (repeats are an error the caller reports).
     */
    std::vector<std::pair<boundary_id, std::string>>
    split_id_map(const std::string &text)
    {
      std::vector<std::pair<boundary_id, std::string>> result;
      for (const std::string &item : Utilities::split_string_list(text, ','))
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

    std::vector<double>
    parse_doubles(const std::string &text)
    {
      return Utilities::string_to_double(
        Utilities::split_string_list(text, ','));
    }

    // The pattern of an "id: value" list (ids 0..255).
    Patterns::Map
    id_map_pattern(const Patterns::PatternBase &value_pattern)
    {
      return Patterns::Map(Patterns::Integer(0, 255),
                           value_pattern,
                           0,
                           Patterns::Map::max_int_value,
                           ",",
                           ":");
    }

    // a number as the user would write it (0, -1, 2.5)
    std::string
    number_text(const double x)
    {
      std::ostringstream out;
      out << x;
      return out.str();
    }

    /**
     * <Geometry/Manifolds>: "id: kind center x, y[, z] radius R [axis a, b,
     * c]; ...". The counts of coordinates are checked against the dimension
     * in check_consistency().
     */
    std::vector<BoundaryManifold>
    parse_manifolds(const std::string &text)
    {
      const std::string entry = "<Geometry/Manifolds>";
      const std::string form =
        " (expected 'id: circle center x, y radius R', 'id: sphere center x, "
        "y, z radius R' or 'id: cylinder center x, y, z axis a, b, c radius "
        "R', separated by ';')";
      std::vector<BoundaryManifold> result;
      for (const std::string &item : Utilities::split_string_list(text, ';'))
        {
          if (item.empty())
            continue;
          const auto colon = item.find(':');
          const auto bad   = [&](const std::string &what) {
            return InputError("The entry " + entry + " has '" + item +
                                "': " + what + form + ".",
                              exit_invalid_value);
          };
          if (colon == std::string::npos)
            throw bad("no 'id:' in front");
          BoundaryManifold  manifold;
          const std::string id_text = Utilities::trim(item.substr(0, colon));
          if (id_text.empty() ||
              id_text.find_first_not_of("0123456789") != std::string::npos ||
              id_text.size() > 3 || std::stoi(id_text) > 255)
            throw bad("'" + id_text + "' is not a boundary id (0 to 255)");
          manifold.id = static_cast<boundary_id>(std::stoi(id_text));

          std::string words = item.substr(colon + 1);
          std::replace(words.begin(), words.end(), ',', ' ');
          std::istringstream in(words);
          std::string        kind;
          in >> kind;
          if (kind == "circle")
            manifold.kind = BoundaryManifold::Kind::circle;
          else if (kind == "sphere")
            manifold.kind = BoundaryManifold::Kind::sphere;
          else if (kind == "cylinder")
            manifold.kind = BoundaryManifold::Kind::cylinder;
          else
            throw bad("'" + kind +
                      "' is not a kind of manifold (circle, sphere, cylinder)");

          // keyword, then its numbers up to the next keyword
          std::map<std::string, std::vector<double>> values;
          std::string                                word, key;
          while (in >> word)
            {
              if (word == "center" || word == "radius" || word == "axis")
                {
                  key = word;
                  if (!values.emplace(key, std::vector<double>()).second)
                    throw bad("'" + key + "' is given twice");
                  continue;
                }
              std::size_t used  = 0;
              double      value = 0.;
              try
                {
                  value = std::stod(word, &used);
                }
              catch (const std::exception &)
                {
                  used = 0;
                }
              if (key.empty() || used != word.size() || !std::isfinite(value))
                throw bad("'" + word +
                          "' is neither a number nor one of "
                          "center, radius, axis");
              values[key].push_back(value);
            }
          if (values.count("center") == 0 || values.count("radius") == 0)
            throw bad("a manifold needs its center and its radius");
          manifold.center = values["center"];
          if (values["radius"].size() != 1 || !(values["radius"][0] > 0.))
            throw bad("the radius must be one positive number");
          manifold.radius = values["radius"][0];
          if (manifold.kind == BoundaryManifold::Kind::cylinder)
            {
              if (values.count("axis") == 0)
                throw bad("a cylinder needs its axis");
              manifold.axis = values["axis"];
            }
          else if (values.count("axis") > 0)
            throw bad("only a cylinder has an axis");
          for (const BoundaryManifold &earlier : result)
            if (earlier.id == manifold.id)
              throw bad("boundary id " + id_text + " is given twice");
          result.push_back(manifold);
        }
      return result;
    }

    /**
     * The friction law takes its parameter from one entry of its own.
     * Giving only another law's entry is a mix-up of the laws: the run
     * would be frictionless, which is never what was meant.
     */
    void
    check_friction_entries(const FrictionParameters                 &friction,
                           const std::map<std::string, std::string> &given)
    {
      const std::string used =
        create_friction_law(friction.law)->parameter_entry();
      if (used.empty() || given.count("Friction/" + used) > 0)
        return;
      for (const auto &[other, laws] : friction_law_entries())
        if (other != used && given.count("Friction/" + other) > 0)
          {
            std::string names;
            for (std::size_t i = 0; i < laws.size(); ++i)
              names += (i == 0 ? "'" : ", '") + laws[i] + "'";
            throw InputError("The friction law '" + friction.law +
                               "' needs <Friction/" + used +
                               ">, which is not given (0 by default: no "
                               "friction); <Friction/" +
                               other + "> (" + given.at("Friction/" + other) +
                               ") is for the law" +
                               (laws.size() > 1 ? "s " : " ") + names + ".",
                             exit_inconsistent);
          }
    }
  } // namespace

  std::string
  to_string(const BoundaryCondition condition)
  {
    switch (condition)
      {
        case BoundaryCondition::free:
          return "free";
        case BoundaryCondition::fixed:
          return "fixed";
        case BoundaryCondition::normal_fixed:
          return "normal fixed";
        case BoundaryCondition::traction:
          return "traction";
        case BoundaryCondition::contact:
          return "contact";
      }
    return "";
  }

  std::string
  to_string(const GeometryType type)
  {
    switch (type)
      {
        case GeometryType::rectangle:
          return "rectangle";
        case GeometryType::half_disc:
          return "half disc";
        case GeometryType::quarter_disc:
          return "quarter disc";
        case GeometryType::mesh_file:
          return "mesh file";
      }
    return "";
  }

  std::string
  BoundaryManifold::kind_name() const
  {
    switch (kind)
      {
        case Kind::circle:
          return "circle";
        case Kind::sphere:
          return "sphere";
        case Kind::cylinder:
          return "cylinder";
      }
    return "";
  }

  bool
  is_zero_expression(const std::string &expression)
  {
    for (const std::string &component :
         Utilities::split_string_list(expression, ';'))
      {
        try
          {
            std::size_t  used  = 0;
            const double value = std::stod(component, &used);
            if (used != component.size() || value != 0.)
              return false;
          }
        catch (const std::exception &)
          {
            return false;
          }
      }
    return true;
  }

  bool
  uses_coordinates(const std::string &expression, const unsigned int dim)
  {
    // the identifiers of the expression: a letter or '_', then letters,
    // digits and '_' (a number's exponent, as in 1e-3, is not one)
    std::string word;
    bool        in_number = false;
    for (const char c : expression + " ")
      {
        const bool letter =
          std::isalpha(static_cast<unsigned char>(c)) || c == '_';
        const bool digit =
          std::isdigit(static_cast<unsigned char>(c)) || c == '.';
        if (word.empty() && !in_number && letter)
          word += c;
        else if (!word.empty() && (letter || digit))
          word += c;
        else if (word.empty() && (digit || (in_number && letter)))
          in_number = true;
        else
          {
            if (word == "x" || word == "y" || (dim == 3 && word == "z"))
              return true;
            word.clear();
            in_number = digit;
          }
      }
    return false;
  }

  // ------------------------------------------------------------ Geometry

  void
  GeometryParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    prm.declare_entry("Dimension",
                      "2",
                      Patterns::Integer(2, 3),
                      "Space dimension of the body. 2 means plane strain.");
    prm.declare_entry(
      "Type",
      "rectangle",
      Patterns::Selection("rectangle|half disc|quarter disc|mesh file"),
      "Shape of the body. 'rectangle': an axis-parallel box with boundary ids "
      "0 (x = x_min), 1 (x = x_max), 2 (y = y_min), 3 (y = y_max) (and 4, 5 "
      "for z in 3D). 'half disc': the lower half of a disc (ball in 3D) of "
      "the given radius and centre, with boundary ids 0 (the curved part) "
      "and 1 (the flat top); refinement follows the circle. 'quarter disc' "
      "(2D): the lower right quarter (x >= x_c, y <= y_c) with ids 0 (curved), "
      "1 (flat top) and 2 (the symmetry line x = x_c). 'mesh file': the "
      "coarse mesh of <Geometry/Mesh file> (Gmsh, quadrilaterals in 2D, "
      "hexahedra in 3D), whose physical groups are the boundary ids; "
      "<Geometry/Manifolds> makes curved parts stay curved under refinement "
      "(doc/meshes.md).");
    prm.declare_entry(
      "Mesh file",
      "",
      Patterns::FileName(Patterns::FileName::input),
      "Type 'mesh file': the Gmsh mesh (.msh, ASCII, format 2.2 or 4.1), a "
      "path relative to the folder of the .prm file that sets it (given by "
      "--set: relative to the working directory). It must hold only "
      "quadrilaterals (2D) or hexahedra (3D), the coarse mesh that the "
      "refinement starts from. Physical groups of curves (2D) or surfaces "
      "(3D) become boundary ids, the numbers of <Boundary conditions/"
      "Conditions>; every boundary face must be in one (Gmsh's 'Physical "
      "Curve(0) = {...};' gives id 0). Coordinates are in [length].");
    prm.declare_entry(
      "Manifolds",
      "",
      Patterns::Anything(),
      "Type 'mesh file': the curved parts of the boundary, so that refinement "
      "puts new vertices on the curve instead of on the straight line "
      "between old ones. A list separated by ';' of 'id: circle center x, y "
      "radius R' (2D), 'id: sphere center x, y, z radius R' or 'id: cylinder "
      "center x, y, z axis a, b, c radius R' (3D: the cylinder's axis passes "
      "through the center in direction (a, b, c)), e.g. '0: circle center 0, "
      "0 radius 1'. Center and radius in [length]. Every vertex of a "
      "boundary face with that id must lie on the curve (within 1e-5 R). The "
      "interior then follows a transfinite interpolation of the boundary, "
      "so that refined cells stay well shaped. Empty: every face stays "
      "straight.");
    prm.declare_entry("Lower left corner",
                      "0, 0",
                      Patterns::List(Patterns::Double(), 2, 3),
                      "Rectangle: the corner with the smallest coordinates "
                      "[length], one value per dimension (3D default: 0, 0, "
                      "0).");
    prm.declare_entry("Upper right corner",
                      "1, 1",
                      Patterns::List(Patterns::Double(), 2, 3),
                      "Rectangle: the corner with the largest coordinates "
                      "[length], one value per dimension (3D default: 1, 1, "
                      "1).");
    prm.declare_entry("Subdivisions",
                      "1, 1",
                      Patterns::List(Patterns::Integer(1), 2, 3),
                      "Rectangle: number of cells of the coarse mesh in each "
                      "direction [-] (3D default: 1, 1, 1).");
    prm.declare_entry("Center",
                      "0, 0",
                      Patterns::List(Patterns::Double(), 2, 3),
                      "Half disc (3D: half ball): centre of the disc, i.e. "
                      "the middle of the flat top; the curved part lies below "
                      "it, toward -y (3D: -z) [length] (3D default: 0, 0, "
                      "0).");
    prm.declare_entry("Radius",
                      "1",
                      Patterns::Double(0., Patterns::Double::max_double_value),
                      "Half disc: radius R [length]. Must be positive.");
    prm.declare_entry(
      "Pre-refinement steps",
      "0",
      Patterns::Integer(0, 30),
      "Number of times the cells near the obstacle (the foundation plane, or "
      "the surface of subsection Obstacle) are refined before the first cycle "
      "(after the initial global refinement) [-]. A cell counts as near if "
      "one of its vertices lies within 'Pre-refinement distance' of the "
      "obstacle in its prescribed position (after <Obstacle/Displacement>).");
    prm.declare_entry("Pre-refinement distance",
                      "0",
                      Patterns::Double(0.),
                      "Distance from the obstacle within which cells are "
                      "pre-refined in the first step [length].");
    prm.declare_entry(
      "Pre-refinement grading",
      "1",
      Patterns::Double(0., 1.),
      "Factor in (0, 1] by which the pre-refinement distance shrinks from one "
      "step to the next [-]: 1 refines the same band every step (a sharp "
      "jump in cell size at its edge), 0.5 gives a graded mesh whose cells "
      "grow with the distance from the obstacle.");
    prm.leave_subsection();
  }

  void
  GeometryParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    dimension               = prm.get_integer("Dimension");
    const std::string shape = prm.get("Type");
    type                    = shape == "rectangle" ? GeometryType::rectangle :
                              shape == "half disc" ? GeometryType::half_disc :
                              shape == "quarter disc" ? GeometryType::quarter_disc :
                                                        GeometryType::mesh_file;
    lower_left              = parse_doubles(prm.get("Lower left corner"));
    upper_right             = parse_doubles(prm.get("Upper right corner"));
    subdivisions.clear();
    for (const int n : Utilities::string_to_int(
           Utilities::split_string_list(prm.get("Subdivisions"), ',')))
      subdivisions.push_back(n);
    center                  = parse_doubles(prm.get("Center"));
    radius                  = prm.get_double("Radius");
    pre_refinement_steps    = prm.get_integer("Pre-refinement steps");
    pre_refinement_distance = prm.get_double("Pre-refinement distance");
    pre_refinement_grading  = prm.get_double("Pre-refinement grading");
    mesh_file               = prm.get("Mesh file");
    mesh_file_given         = mesh_file;
    manifolds               = parse_manifolds(prm.get("Manifolds"));
    prm.leave_subsection();
    // the patterns allow 0 (Patterns::Double has closed bounds), which
    // would fail late, inside deal.II's mesh or manifold code
    if ((type == GeometryType::half_disc ||
         type == GeometryType::quarter_disc) &&
        !(radius > 0.))
      throw InputError("The entry <Geometry/Radius> must be positive: a " +
                         to_string(type) + " of radius " + number_text(radius) +
                         " has no area.",
                       exit_invalid_value);
    if (pre_refinement_steps > 1 && !(pre_refinement_grading > 0.))
      throw InputError("The entry <Geometry/Pre-refinement grading> must be "
                       "positive: 0 shrinks the pre-refinement band to "
                       "nothing after the first step.",
                       exit_invalid_value);
  }

  // ------------------------------------------------------------ Material

  double
  MaterialParameters::lambda() const
  {
    return youngs_modulus * poissons_ratio /
           ((1. + poissons_ratio) * (1. - 2. * poissons_ratio));
  }

  double
  MaterialParameters::mu() const
  {
    return youngs_modulus / (2. * (1. + poissons_ratio));
  }

  void
  MaterialParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    prm.declare_entry("Young's modulus",
                      "1",
                      Patterns::Double(0., Patterns::Double::max_double_value),
                      "Young's modulus E [stress = force/length^2, e.g. Pa "
                      "in N-m-Pa or MPa in N-mm-MPa]. Must be positive.");
    prm.declare_entry("Poisson's ratio",
                      "0.3",
                      Patterns::Double(-1., 0.5),
                      "Poisson's ratio nu [-], in (-1, 0.5). 2D is plane "
                      "strain.");
    prm.leave_subsection();
  }

  void
  MaterialParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    youngs_modulus = prm.get_double("Young's modulus");
    poissons_ratio = prm.get_double("Poisson's ratio");
    prm.leave_subsection();
    // Patterns::Double has closed bounds; the open ends are checked here.
    if (!(youngs_modulus > 0.))
      throw InputError("The entry <Material/Young's modulus> must be positive.",
                       exit_invalid_value);
    if (!(poissons_ratio > -1. && poissons_ratio < 0.5))
      throw InputError("The entry <Material/Poisson's ratio> must lie in the "
                       "open interval (-1, 0.5).",
                       exit_invalid_value);
  }

  // ------------------------------------------------------------ Boundary

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

  void
  BoundaryParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    prm.declare_entry(
      "Conditions",
      "",
      id_map_pattern(Patterns::Selection(condition_names)),
      "The condition on each boundary id, as a list 'id: condition, id: "
      "condition'. Conditions: 'free' (zero traction), 'fixed' (all "
      "displacement components prescribed, see 'Displacements'), 'normal "
      "fixed' (zero normal displacement, tangential one free: a frictionless "
      "slider), 'traction' (prescribed traction, see 'Tractions'), 'contact' "
      "(unilateral contact with the rigid foundation, with the friction law "
      "of subsection Friction). Ids not listed are free. An id may appear "
      "only once.");
    prm.declare_entry(
      "Displacements",
      "",
      id_map_pattern(Patterns::Anything()),
      "Prescribed displacement on 'fixed' ids, as 'id: u_x; u_y' [length]; "
      "each component an expression in x, y (z) with the constants pi, E, "
      "nu, lambda, mu (no commas or colons inside). Fixed ids not listed "
      "here are clamped (zero displacement).");
    prm.declare_entry(
      "Tractions",
      "",
      id_map_pattern(Patterns::Anything()),
      "Prescribed traction on 'traction' ids, as 'id: T_x; T_y' [stress = "
      "force/length^2]; each component an expression in x, y (z) with the "
      "constants pi, E, nu, lambda, mu (no commas or colons inside). A "
      "pressure p on a face with outer normal n is the traction -p n. Every "
      "'traction' id must be listed.");
    prm.leave_subsection();
  }

  void
  BoundaryParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    conditions.clear();
    for (const auto &[id, name] :
         parse_id_map(prm.get("Conditions"), "Boundary conditions/Conditions"))
      conditions[id] = parse_condition(name);
    displacements = parse_id_map(prm.get("Displacements"),
                                 "Boundary conditions/Displacements");
    tractions =
      parse_id_map(prm.get("Tractions"), "Boundary conditions/Tractions");
    prm.leave_subsection();
  }

  // ------------------------------------------------------------ Loads

  void
  LoadParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loads");
    prm.declare_entry(
      "Body force",
      "0; 0",
      Patterns::Anything(),
      "Body force f per unit volume, 'f_x; f_y' (one component per "
      "dimension) [force/length^3]; each an expression in x, y (z) with the "
      "constants pi, E, nu, lambda, mu. All zero: no body force is "
      "assembled.");
    prm.leave_subsection();
  }

  void
  LoadParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loads");
    body_force = prm.get("Body force");
    prm.leave_subsection();
  }

  // ------------------------------------------------------------ Friction

  void
  FrictionParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Friction");
    // the laws registered in source/friction_laws/ (friction_law.h)
    std::string names;
    for (const std::string &name : friction_law_names())
      names += (names.empty() ? "" : "|") + name;
    std::string help;
    for (const std::string &name : friction_law_names())
      help += std::string(help.empty() ? "" : ", ") + "'" + name + "' (" +
              create_friction_law(name)->help() + ")";
    prm.declare_entry("Law",
                      "none",
                      Patterns::Selection(names),
                      "Friction on the contact boundary, one of " + help + ".");
    prm.leave_subsection();
    // each law's own entry, once
    std::set<std::string> declared;
    for (const std::string &name : friction_law_names())
      {
        const auto        law   = create_friction_law(name);
        const std::string entry = law->parameter_entry();
        if (!entry.empty() && declared.insert(entry).second)
          law->declare_parameters(prm);
      }
    prm.enter_subsection("Friction");
    prm.declare_entry(
      "Threshold iteration",
      "merged",
      Patterns::Selection("nested|merged"),
      "Coulomb only, the threshold iteration: 'nested' solves the "
      "given-friction problem with the threshold g fixed, then sets g = F "
      "l1, until g settles (successive approximations); 'merged' sets g = F "
      "l1 after every Uzawa step (one loop). Both give the same solution "
      "within the tolerances.");
    prm.declare_entry("Initial threshold",
                      "zero",
                      Patterns::Selection("zero|frictionless"),
                      "Coulomb only: g^0 = 0, or g^0 = F times the contact "
                      "pressure of the frictionless problem (solved first).");
    prm.declare_entry(
      "Threshold tolerance",
      "1e-6",
      Patterns::Double(1e-14, 1.),
      "Coulomb only: the threshold iteration stops when |g_new - g| <= tol "
      "|g_new| (nodal Euclidean norms) [-].");
    prm.declare_entry(
      "Maximum threshold steps",
      "100",
      Patterns::Integer(1),
      "Coulomb only: the threshold iteration gives up (with an error naming "
      "the cause) after this many steps [-].");
    prm.leave_subsection();
  }

  void
  FrictionParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Friction");
    law                     = prm.get("Law");
    const std::string entry = create_friction_law(law)->parameter_entry();
    parameter               = entry.empty() ? "" : prm.get(entry);
    strategy                = prm.get("Threshold iteration") == "nested" ?
                                FrictionStrategy::nested :
                                FrictionStrategy::merged;
    initial_threshold       = prm.get("Initial threshold") == "zero" ?
                                InitialThreshold::zero :
                                InitialThreshold::frictionless;
    tolerance               = prm.get_double("Threshold tolerance");
    max_steps               = prm.get_integer("Maximum threshold steps");
    prm.leave_subsection();
  }

  // ------------------------------------------------------------ Solver

  void
  SolverParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    prm.declare_entry("Linear solver tolerance",
                      "1e-10",
                      Patterns::Double(1e-16, 1.),
                      "Relative tolerance of CG: stop when |residual| <= tol "
                      "|right-hand side| [-].");
    prm.declare_entry("Maximum linear iterations",
                      "2000",
                      Patterns::Integer(1),
                      "Maximum number of CG iterations per linear solve [-].");
    prm.declare_entry(
      "AMG with rotation modes",
      "true",
      Patterns::Bool(),
      "Give the algebraic multigrid all rigid-body modes (translations and "
      "rotations) as near-null space; false gives it the translations only.");

    prm.declare_entry(
      "Augmentation parameter",
      "10",
      Patterns::Double(1e-3, 1e12),
      "r_rel [-], > 0: the augmentation parameter of the modified Lagrangian "
      "is r = r_rel (lambda + 2 mu) / h_C [stress/length], with h_C the "
      "smallest face diameter on the contact boundary and lambda + 2 mu the "
      "P-wave modulus (E (1 - nu) / ((1 + nu) (1 - 2 nu)); 1.35 E at nu = "
      "0.3), which follows the stiffness of nearly incompressible materials. "
      "Any r > 0 converges; larger r means fewer Uzawa steps and harder "
      "Newton problems (more Newton steps where many nodes slip), smaller r "
      "more Uzawa steps (below 0.1, more than the default <Solver/Maximum "
      "Uzawa steps>). From 1e-3 to 1e12: below, the contact terms vanish "
      "beside the proximal term and the body drifts for thousands of "
      "steps.");
    prm.declare_entry(
      "Tangential augmentation parameter",
      "auto",
      Patterns::Anything(),
      "r_t,rel [-]: 'auto' or a number > 0. The friction terms use their own "
      "augmentation r_t = r_t,rel (lambda + 2 mu) / h_C [stress/length] (as "
      "r, with r_t,rel for r_rel), in the update l2 <- proj_g(l2 + r_t v_t) "
      "and in the Newton terms of l2. 'auto' is r_rel in 2D and r_rel / 4 in "
      "3D: in 3D, friction terms as large as the normal ones make the "
      "Newton matrices hard for CG and need 3-4 Newton steps per Uzawa "
      "step (the projection onto the friction disc), and r_rel / 4 halves "
      "the Coulomb solves; in 2D (an interval, no disc) a smaller r_t only "
      "costs Uzawa steps (doc/theory.md §5). Ignored without friction.");
    prm.declare_entry(
      "Proximal parameter",
      "1e-3",
      Patterns::Double(0., 1e3),
      "chi_rel [-], > 0: the proximal weight is chi = chi_rel E / L^2 "
      "[stress/length^2], with L the body's size (longest side, or radius). "
      "It makes each Uzawa step strongly convex, also when only contact "
      "holds the body. At most 1e3: a proximal term that outweighs the "
      "stiffness of coarse meshes (chi_rel 1e6 on 8 x 4 cells) holds v "
      "where it is, and the Newton and Uzawa iterations stall; from 1 on "
      "the Uzawa steps already stop before the solution is reached to the "
      "tolerance (doc/robustness.md).");
    prm.declare_entry(
      "Uzawa tolerance",
      "1e-8",
      Patterns::Double(1e-15, 1.),
      "The Uzawa iteration stops when the relative changes of l1 and of v "
      "and the relative constraint violation are all below "
      "this [-].");
    prm.declare_entry(
      "Maximum Uzawa steps",
      "500",
      Patterns::Integer(1),
      "The Uzawa iteration gives up (with an error) after this many steps "
      "[-].");
    prm.declare_entry(
      "Newton tolerance factor",
      "1e-2",
      Patterns::Double(1e-8, 1.),
      "The Newton iteration's final tolerance on the relative gradient is this factor "
      "times the Uzawa tolerance [-] (at most 0.01 is advised).");
    prm.declare_entry(
      "Initial inner tolerance",
      "1e-2",
      Patterns::Double(0., 1.),
      "The Newton iteration's relative gradient tolerance in the first Uzawa step [-]; it "
      "shrinks geometrically from step to step (summable errors, as the "
      "convergence theorem needs) down to the final tolerance.");
    prm.declare_entry(
      "Inner tolerance reduction",
      "0.5",
      Patterns::Double(0., 1.),
      "The Newton iteration's tolerance stays below initial tolerance times "
      "this factor to the power (Uzawa step - 1) [-], in "
      "(0, 1): a geometric envelope that keeps the errors "
      "summable.");
    prm.declare_entry(
      "Inner tolerance factor",
      "1e-2",
      Patterns::Double(0., 1.),
      "The Newton iteration stops once its gradient fell by this factor "
      "within the Uzawa step (and is below the envelope), or "
      "is below the final tolerance [-]: no Uzawa step is "
      "solved much more accurately than the iteration can "
      "use.");
    prm.declare_entry(
      "Maximum Newton steps",
      "50",
      Patterns::Integer(1),
      "The Newton iteration gives up (with an error) after this many steps "
      "in one Uzawa step [-], unless the line search is cutting its steps "
      "short at changes of the node statuses (gross slip with a large r): "
      "then it goes on, at most one more step per contact node.");
    prm.declare_entry(
      "Line search",
      "true",
      Patterns::Bool(),
      "Exact line search on the Uzawa step's functional (a convex "
      "piecewise quadratic along each Newton direction); makes "
      "Newton globally convergent. false: full steps.");
    prm.declare_entry(
      "AMG rebuild fraction",
      "0.05",
      Patterns::Double(0., 1.),
      "Rebuild the AMG preconditioner of the Newton matrix only when the "
      "number of contact nodes that changed status since it was built "
      "exceeds this fraction of the active set [-], or when the last CG "
      "solve needed more than 1.5 times (plus 10) the iterations of the "
      "first one after the set-up; 0 rebuilds it at every Newton step.");
    prm.declare_entry(
      "Time a reference linear solve",
      "false",
      Patterns::Bool(),
      "After each contact solve, also time one linear elasticity solve on "
      "the same mesh (AMG set-up and CG to the linear tolerance on the final "
      "Newton matrix, i.e. with the contact nodes held) and report the ratio "
      "of the times (assembly included in both). For benchmarks.");
    prm.leave_subsection();
  }

  void
  SolverParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    linear_tolerance      = prm.get_double("Linear solver tolerance");
    max_linear_iterations = prm.get_integer("Maximum linear iterations");
    amg_rotation_modes    = prm.get_bool("AMG with rotation modes");
    augmentation          = prm.get_double("Augmentation parameter");
    {
      const std::string value =
        Utilities::trim(prm.get("Tangential augmentation parameter"));
      char *end               = nullptr;
      tangential_augmentation = std::strtod(value.c_str(), &end);
      const bool number       = !value.empty() && *end == '\0' &&
                          std::isfinite(tangential_augmentation) &&
                          tangential_augmentation > 0.;
      if (value == "auto")
        tangential_augmentation = 0.; // resolved per dimension
      else if (!number)
        throw InputError("The entry <Solver/Tangential augmentation "
                         "parameter> must be 'auto' or a positive number, "
                         "not '" +
                           value + "'.",
                         exit_invalid_value);
    }
    proximal                  = prm.get_double("Proximal parameter");
    uzawa_tolerance           = prm.get_double("Uzawa tolerance");
    max_uzawa_steps           = prm.get_integer("Maximum Uzawa steps");
    newton_tolerance_factor   = prm.get_double("Newton tolerance factor");
    initial_inner_tolerance   = prm.get_double("Initial inner tolerance");
    inner_tolerance_reduction = prm.get_double("Inner tolerance reduction");
    inner_tolerance_factor    = prm.get_double("Inner tolerance factor");
    max_newton_steps          = prm.get_integer("Maximum Newton steps");
    line_search               = prm.get_bool("Line search");
    amg_rebuild_fraction      = prm.get_double("AMG rebuild fraction");
    time_reference_solve      = prm.get_bool("Time a reference linear solve");
    prm.leave_subsection();
    if (!(augmentation > 0.))
      throw InputError("The entry <Solver/Augmentation parameter> must be "
                       "positive.",
                       exit_invalid_value);
    if (!(proximal > 0.))
      throw InputError("The entry <Solver/Proximal parameter> must be "
                       "positive (chi = 0 leaves semi-coercive scenes "
                       "singular).",
                       exit_invalid_value);
    if (!(inner_tolerance_reduction > 0. && inner_tolerance_reduction < 1.))
      throw InputError("The entry <Solver/Inner tolerance reduction> must lie "
                       "in (0, 1).",
                       exit_invalid_value);
  }

  // ------------------------------------------------------------ Refinement

  void
  RefinementParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Refinement");
    prm.declare_entry("Initial global refinement",
                      "0",
                      Patterns::Integer(0, 20),
                      "Number of global refinements of the coarse mesh before "
                      "the first cycle [-].");
    prm.declare_entry("Number of cycles",
                      "1",
                      Patterns::Integer(1, 30),
                      "Number of meshes solved on; each after the first is "
                      "the previous one refined [-].");
    std::string names, help;
    for (const std::string &name : refinement_indicator_names())
      {
        names += (names.empty() ? "" : "|") + name;
        help += " '" + name + "' " + refinement_indicator_kind(name).help;
      }
    prm.declare_entry("Strategy",
                      "global",
                      Patterns::Selection(names),
                      "How the mesh is refined between cycles; every mesh "
                      "is the previous one refined (nested meshes)." +
                        help);
    prm.declare_entry(
      "Refine fraction",
      "0.3",
      Patterns::Double(0., 1.),
      "Adaptive strategies (not 'global'): the fraction of the cells, "
      "those with the largest indicators, refined per cycle "
      "[-].");
    prm.declare_entry(
      "Coarsen fraction",
      "0",
      Patterns::Double(0., 1.),
      "Adaptive strategies (not 'global'): the fraction of the cells, "
      "those with the smallest indicators, coarsened per "
      "cycle [-]. Refine + coarsen fractions must not exceed "
      "1.");
    prm.declare_entry(
      "Nested iteration",
      "true",
      Patterns::Bool(),
      "Carry the displacement v (by interpolation) and the multipliers l1, "
      "l2 and the threshold g (by interpolation of their nodal values, then "
      "projected so that l1 >= 0 and |l2| <= g) from each mesh to the next, "
      "and start the solver there. false: every mesh starts cold, from v = 0 "
      "and l1 = l2 = 0.");
    prm.declare_entry(
      "Compare with cold start",
      "false",
      Patterns::Bool(),
      "With nested iteration: also solve each refined mesh from a cold "
      "start, before the nested solve, and report the Uzawa, loop-1 and "
      "Newton steps and the time saved, and the difference of the two "
      "solutions (columns cold_* of cycles.csv). Doubles the cost.");
    prm.leave_subsection();
    // the indicators' own entries
    for (const std::string &name : refinement_indicator_names())
      if (refinement_indicator_kind(name).declare_parameters != nullptr)
        refinement_indicator_kind(name).declare_parameters(prm);
  }

  void
  RefinementParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Refinement");
    initial_global_refinement = prm.get_integer("Initial global refinement");
    n_cycles                  = prm.get_integer("Number of cycles");
    strategy                  = prm.get("Strategy");
    refine_fraction           = prm.get_double("Refine fraction");
    coarsen_fraction          = prm.get_double("Coarsen fraction");
    nested_iteration          = prm.get_bool("Nested iteration");
    compare_cold_start        = prm.get_bool("Compare with cold start");
    prm.leave_subsection();
    // every indicator's entries, so that a program may change the strategy
    std::vector<std::string> entries;
    for (const std::string &name : refinement_indicator_names())
      for (const std::string &entry : refinement_indicator_kind(name).entries)
        entries.push_back(entry);
    values = read_entry_values(prm, entries);
    if (refine_fraction + coarsen_fraction > 1.)
      throw InputError("The entries <Refinement/Refine fraction> and "
                       "<Refinement/Coarsen fraction> add up to more than 1.",
                       exit_invalid_value);
  }

  // ------------------------------------------------------------ Output

  void
  OutputParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Directory",
                      "output",
                      Patterns::DirectoryName(),
                      "Folder for all output files; created if missing.");
    prm.declare_entry("Write vtu",
                      "true",
                      Patterns::Bool(),
                      "Write .pvtu/.vtu files (one set per cycle) for "
                      "ParaView.");
    prm.declare_entry("Print timing",
                      "true",
                      Patterns::Bool(),
                      "Print wall times on screen. Tests switch this off so "
                      "that the screen output is deterministic.");
    prm.declare_entry(
      "Verbosity",
      "normal",
      Patterns::Selection("quiet|normal|detailed"),
      "How much the screen shows (no unit). quiet: the scene and one line "
      "per refinement cycle, then the summary table; normal: also a legend, "
      "one line per Uzawa step and per threshold step, and each cycle's "
      "results; detailed: also one line per Newton step with its CG "
      "iterations. Warnings and errors are always shown; cycles.csv and "
      "iterations.csv hold everything at every level.");
    prm.declare_entry(
      "Probe points",
      "",
      Patterns::List(Patterns::List(Patterns::Double(), 2, 3, ","),
                     0,
                     Patterns::List::max_int_value,
                     ";"),
      "Points of the body [length] at which the displacement [length] and "
      "the stress [stress] are written to probes.csv for every cycle, as "
      "'x, y; x, y' (3D: 'x, y, z; ...'): one row per cycle and point, with "
      "the columns cycle, probe (the point's number in this list, from 1), "
      "x, y, (z), u_x, u_y, (u_z), sigma_xx, sigma_yy, sigma_zz, sigma_xy, "
      "(sigma_xz, sigma_yz) and von_mises (in 2D sigma_zz is plane strain's "
      "lambda tr(eps), and von_mises includes it). Each must lie in the body, "
      "its boundary included: a point outside the mesh by at most the "
      "distance of the nearest boundary face from the curved boundary at the "
      "face's middle, plus 1e-6 of the face's size, counts as on the "
      "boundary and is evaluated at the nearest point of the mesh; a point "
      "farther outside is an input error, found on the first mesh. Empty: no "
      "probes.");
    prm.leave_subsection();
  }

  void
  OutputParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    directory               = prm.get("Directory");
    write_vtu               = prm.get_bool("Write vtu");
    print_timing            = prm.get_bool("Print timing");
    const std::string level = prm.get("Verbosity");
    verbosity               = level == "quiet"    ? Verbosity::quiet :
                              level == "detailed" ? Verbosity::detailed :
                                                    Verbosity::normal;
    probe_points.clear();
    for (const std::string &point :
         Utilities::split_string_list(prm.get("Probe points"), ';'))
      if (!point.empty())
        probe_points.push_back(parse_doubles(point));
    prm.leave_subsection();
    if (directory.empty())
      throw InputError("The entry <Output/Directory> must not be empty.",
                       exit_invalid_value);
  }

  // ------------------------------------------------------------ Exact

  void
  ExactSolutionParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Exact solution");
    prm.declare_entry(
      "Displacement",
      "",
      Patterns::Anything(),
      "If known, the exact displacement 'u_x; u_y' [length] as expressions "
      "in x, y (z) with the constants pi, E, nu, lambda, mu; the L2 and H1 "
      "errors are then reported per cycle. Empty: none is known.");
    prm.declare_entry(
      "Contact pressure",
      "",
      Patterns::Anything(),
      "If known, the exact contact pressure p = -sigma_n on the contact "
      "boundary [stress], an expression in x, y (z) with the constants pi, "
      "E, nu, lambda, mu (functions such as sqrt, max may be used); the "
      "relative L2 error on Gamma_C of l1 (interpolated between the contact nodes) is then reported per cycle. "
      "Empty: none is known.");
    prm.declare_entry(
      "Contact half-width",
      "0",
      Patterns::Double(0.),
      "If known, the exact half-width a of the contact zone [length] in 2D, "
      "its radius in 3D; the relative error of the computed one (edges "
      "extrapolated; in 3D along two lines through the zone's centre, where "
      "the contact begins) is then reported per cycle. The zone is measured "
      "whole: a model cut by symmetry planes through that centre (a half or "
      "quarter ball) is measured as mirrored across them; a zone cut "
      "anywhere else is measured as the part in the model. 0: not known.");
    prm.declare_entry(
      "Stick half-width",
      "0",
      Patterns::Double(0.),
      "If known, the exact half-width c of the stick zone [length] in 2D, "
      "its radius in 3D (e.g. Cattaneo-Mindlin); the relative error of the "
      "computed one (each end half-way between the last sticking and the "
      "first slipping node) is then reported per cycle. Needs friction. 0: "
      "not known.");
    prm.declare_entry("Peak pressure",
                      "0",
                      Patterns::Double(0.),
                      "If known, the exact largest contact pressure p0 "
                      "[stress]; the relative error of max l1 is then "
                      "reported per cycle. 0: not known.");
    prm.leave_subsection();
  }

  void
  ExactSolutionParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Exact solution");
    displacement       = Utilities::trim(prm.get("Displacement"));
    contact_pressure   = Utilities::trim(prm.get("Contact pressure"));
    contact_half_width = prm.get_double("Contact half-width");
    stick_half_width   = prm.get_double("Stick half-width");
    peak_pressure      = prm.get_double("Peak pressure");
    prm.leave_subsection();
  }

  // ------------------------------------------------------------ Parameters

  void
  Parameters::declare_parameters(ParameterHandler &prm)
  {
    GeometryParameters::declare_parameters(prm);
    MaterialParameters::declare_parameters(prm);
    BoundaryParameters::declare_parameters(prm);
    LoadParameters::declare_parameters(prm);
    ObstacleParameters::declare_parameters(prm);
    FrictionParameters::declare_parameters(prm);
    SolverParameters::declare_parameters(prm);
    RefinementParameters::declare_parameters(prm);
    OutputParameters::declare_parameters(prm);
    ExactSolutionParameters::declare_parameters(prm);
  }

  void
  Parameters::parse_parameters(ParameterHandler &prm)
  {
    geometry.parse_parameters(prm);
    material.parse_parameters(prm);
    boundary.parse_parameters(prm);
    loads.parse_parameters(prm);
    obstacle.parse_parameters(prm);
    friction.parse_parameters(prm);
    solver.parse_parameters(prm);
    refinement.parse_parameters(prm);
    output.parse_parameters(prm);
    exact.parse_parameters(prm);
    check_consistency();
  }

  void
  Parameters::read_file(const std::string              &filename,
                        const std::vector<std::string> &overrides)
  {
    ParameterHandler prm;
    declare_parameters(prm);
    ParameterReader reader(prm);
    reader.read_file(filename);
    // A file without a single 'set' line (in it or in a file it includes)
    // is empty, or only comments: every entry would keep its default, which
    // is never meant.
    if (!reader.scene_has_entries())
      throw InputError("The parameter file <" + filename +
                         "> has no entries (no 'set' line): it is empty or "
                         "holds only comments.",
                       exit_cannot_read_file);
    std::string source = filename;
    for (const std::string &assignment : overrides)
      {
        reader.set_override(assignment);
        source += " --set \"" + assignment + "\"";
      }
    use(prm, reader);
    parameter_file = "# The parameters of a dualcontact run: " + source + "\n" +
                     parameter_file;
  }

  void
  Parameters::read_string(const std::string &text, const std::string &overlay)
  {
    ParameterHandler prm;
    declare_parameters(prm);
    ParameterReader reader(prm);
    reader.read_text(text, "parameters");
    if (!overlay.empty())
      reader.read_overlay(overlay, "overlay");
    use(prm, reader);
  }

  namespace
  {
    // The points and vectors whose declared defaults are 2D, with their 3D
    // defaults: in a 3D scene an entry it does not give takes these, so
    // that a 3D scene states only what differs (a foundation z = 0 with
    // the normal +z, the unit cube, shapes about the origin). Set into the
    // handler, so that the listing (parameters.prm) repeats the run. An
    // entry the scene sets keeps its value, even one equal to the 2D
    // default: its count of values is then checked like any other's.
    void
    apply_3d_defaults(ParameterHandler &prm, const std::set<std::string> &set)
    {
      prm.enter_subsection("Geometry");
      const bool three = prm.get_integer("Dimension") == 3;
      prm.leave_subsection();
      if (!three)
        return;
      const std::vector<std::array<std::string, 3>> defaults = {
        {{"Geometry", "Lower left corner", "0, 0, 0"}},
        {{"Geometry", "Upper right corner", "1, 1, 1"}},
        {{"Geometry", "Subdivisions", "1, 1, 1"}},
        {{"Geometry", "Center", "0, 0, 0"}}};
      std::vector<std::array<std::string, 3>> all = defaults;
      for (const std::string &name : obstacle_names())
        for (const auto &entry : obstacle_kind(name).defaults_3d)
          if (std::find(all.begin(), all.end(), entry) == all.end())
            all.push_back(entry);
      for (const auto &[subsection, entry, value] : all)
        if (set.count(subsection + "/" + entry) == 0)
          {
            prm.enter_subsection(subsection);
            prm.set(entry, value);
            prm.leave_subsection();
          }
    }
  } // namespace

  void
  Parameters::use(ParameterHandler &prm, const ParameterReader &reader)
  {
    given = reader.given_entries();
    // <Geometry/Mesh file> is relative to the folder of the file that set
    // it (an override: the working directory). The listing (parameters.prm
    // in the output folder) gets the absolute path, so that it repeats the
    // run from wherever it is.
    prm.enter_subsection("Geometry");
    const std::string mesh_file_given = prm.get("Mesh file");
    if (!mesh_file_given.empty())
      {
        std::filesystem::path file(mesh_file_given);
        if (file.is_relative())
          file = reader.folder_of("Geometry/Mesh file") / file;
        prm.set("Mesh file",
                std::filesystem::absolute(file).lexically_normal().string());
      }
    prm.leave_subsection();
    apply_3d_defaults(prm, reader.set_entries());
    std::ostringstream out;
    prm.print_parameters(out, ParameterHandler::PRM);
    parameter_file = out.str();
    parse_parameters(prm);
    geometry.mesh_file_given = mesh_file_given;
  }

  void
  Parameters::check_magnitudes() const
  {
    // The solver scales E and the lengths out (r, chi and the tolerances
    // are relative to them), so the units do not matter, within the range
    // where their squares and products stay normal doubles.
    const auto magnitude = [](const double       x,
                              const std::string &entry,
                              const std::string &unit,
                              const std::string &example) {
      if (!(std::abs(x) >= 1e-100 && std::abs(x) <= 1e100))
        throw InputError("The entry <" + entry + "> = " + format_number(x) +
                           " is outside the magnitudes 1e-100 to 1e100 " +
                           unit +
                           " that the solver's products of it can "
                           "represent: use other units (" +
                           example + ").",
                         exit_invalid_value);
    };
    magnitude(material.youngs_modulus,
              "Material/Young's modulus",
              "[stress]",
              "e.g. MPa or GPa instead of Pa");
    const std::string lengths = "e.g. mm or km instead of m";
    if (geometry.type == GeometryType::rectangle &&
        geometry.lower_left.size() == geometry.upper_right.size())
      for (std::size_t d = 0; d < geometry.lower_left.size(); ++d)
        {
          magnitude(geometry.upper_right[d] - geometry.lower_left[d],
                    "Geometry/Upper right corner",
                    "[length] (a side of the box)",
                    lengths);
          if (std::abs(geometry.lower_left[d]) > 1e100)
            magnitude(geometry.lower_left[d],
                      "Geometry/Lower left corner",
                      "[length]",
                      lengths);
          if (std::abs(geometry.upper_right[d]) > 1e100)
            magnitude(geometry.upper_right[d],
                      "Geometry/Upper right corner",
                      "[length]",
                      lengths);
        }

    // deal.II's manifolds (the curved boundaries and the cells next to
    // them) work with absolute tolerances of about 1e-10, and its
    // transfinite interpolation in 3D loses its accuracy far from the
    // origin against the cell size: radii below 1e-6 and, in 3D, centres
    // farther than 100 radii from the origin fail inside deal.II while the
    // mesh is refined.
    const unsigned int dim    = geometry.dimension;
    const auto         curved = [dim](const double               radius,
                              const std::vector<double> &center,
                              const std::string         &entry) {
      if (radius < 1e-6)
        throw InputError("The entry <" + entry +
                           "> gives a curved boundary "
                                   "the radius " +
                           format_number(radius) +
                           ", below 1e-6 [length]: deal.II's manifolds, "
                                   "which refine curved boundaries, use absolute "
                                   "tolerances of about 1e-10 and fail for such "
                                   "small cells. Use smaller units (e.g. "
                                   "micrometres instead of metres); the results do "
                                   "not depend on them.",
                         exit_invalid_value);
      double distance = 0.;
      for (const double c : center)
        distance += c * c;
      distance = std::sqrt(distance);
      if (dim == 3 && distance > 100. * radius)
        throw InputError("The entry <" + entry +
                           "> puts the centre of a "
                                   "curved boundary " +
                           format_number(distance) +
                           " from the origin, more than 100 times its "
                                   "radius " +
                           format_number(radius) +
                           ": in 3D, deal.II's transfinite interpolation of "
                                   "the cells next to it fails that far from the "
                                   "origin. Move the origin near the body (shift the "
                                   "centre, the foundation or obstacle, and the "
                                   "expressions that use x, y, z).",
                         exit_invalid_value);
    };
    if (geometry.type == GeometryType::half_disc ||
        geometry.type == GeometryType::quarter_disc)
      {
        magnitude(geometry.radius, "Geometry/Radius", "[length]", lengths);
        curved(geometry.radius, geometry.center, "Geometry/Radius");
      }
    if (geometry.type == GeometryType::mesh_file)
      for (const BoundaryManifold &manifold : geometry.manifolds)
        curved(manifold.radius, manifold.center, "Geometry/Manifolds");
  }

  void
  Parameters::check_consistency() const
  {
    const unsigned int dim      = geometry.dimension;
    const auto         need_dim = [dim](const std::vector<double> &values,
                                const std::string         &entry) {
      if (values.size() != dim)
        throw InputError("The entry <" + entry + "> needs " +
                           std::to_string(dim) +
                           " values (one per dimension), "
                                   "not " +
                           std::to_string(values.size()) + ".",
                         exit_inconsistent);
    };

    for (unsigned int i = 0; i < output.probe_points.size(); ++i)
      if (output.probe_points[i].size() != dim)
        throw InputError("The point " + std::to_string(i + 1) +
                           " of <Output/Probe points> has " +
                           std::to_string(output.probe_points[i].size()) +
                           " coordinates, not " + std::to_string(dim) +
                           " (one per dimension).",
                         exit_inconsistent);

    if (geometry.type == GeometryType::rectangle)
      {
        need_dim(geometry.lower_left, "Geometry/Lower left corner");
        need_dim(geometry.upper_right, "Geometry/Upper right corner");
        if (geometry.subdivisions.size() != dim)
          throw InputError("The entry <Geometry/Subdivisions> needs " +
                             std::to_string(dim) + " values.",
                           exit_inconsistent);
        for (unsigned int d = 0; d < dim; ++d)
          if (!(geometry.upper_right[d] > geometry.lower_left[d]))
            throw InputError("The entry <Geometry/Upper right corner> must be "
                             "larger than <Geometry/Lower left corner> in "
                             "every coordinate.",
                             exit_inconsistent);
      }
    else if (geometry.type != GeometryType::mesh_file)
      need_dim(geometry.center, "Geometry/Center");

    check_magnitudes();

    if (geometry.type == GeometryType::mesh_file &&
        geometry.mesh_file.find_first_not_of(" \t") == std::string::npos)
      throw InputError("The entry <Geometry/Type> is 'mesh file' but "
                       "<Geometry/Mesh file> names no file.",
                       exit_inconsistent);
    for (const BoundaryManifold &manifold : geometry.manifolds)
      {
        const std::string kind = manifold.kind_name();
        const std::string what = "The entry <Geometry/Manifolds> gives "
                                 "boundary id " +
                                 std::to_string(manifold.id) + " a " + kind;
        if ((manifold.kind == BoundaryManifold::Kind::circle) != (dim == 2))
          throw InputError(what + ", which is for " +
                             (dim == 2 ? "3D; in 2D use 'circle'." :
                                         "2D; in 3D use 'sphere' or "
                                         "'cylinder'."),
                           exit_inconsistent);
        if (manifold.center.size() != dim)
          throw InputError(what + " whose center has " +
                             std::to_string(manifold.center.size()) +
                             " coordinates, not " + std::to_string(dim) + ".",
                           exit_inconsistent);
        if (manifold.kind == BoundaryManifold::Kind::cylinder)
          {
            double norm = 0;
            for (const double c : manifold.axis)
              norm += c * c;
            if (manifold.axis.size() != dim || !(std::sqrt(norm) > 0.))
              throw InputError(what + " whose axis is not a nonzero vector "
                                      "of 3 components.",
                               exit_inconsistent);
          }
      }

    if (geometry.type == GeometryType::quarter_disc && dim != 2)
      throw InputError("The entry <Geometry/Type> 'quarter disc' exists in 2D "
                       "only.",
                       exit_inconsistent);
    const unsigned int n_ids = geometry.type == GeometryType::rectangle ?
                                 2 * dim :
                               geometry.type == GeometryType::quarter_disc ? 3 :
                                                                             2;
    const std::string  shape = to_string(geometry.type);
    // a mesh file's ids are checked once it is read (Scene)
    for (const auto &[id, condition] : boundary.conditions)
      if (geometry.type != GeometryType::mesh_file && id >= n_ids)
        throw InputError("The entry <Boundary conditions/Conditions> names "
                         "boundary id " +
                           std::to_string(id) + ", which the geometry '" +
                           shape + "' does not have (its ids are 0 to " +
                           std::to_string(n_ids - 1) + ").",
                         exit_inconsistent);

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

    if (!boundary.ids_with(BoundaryCondition::contact).empty())
      {
        const ObstacleKind &kind = obstacle_kind(obstacle.type);
        if (kind.check != nullptr)
          kind.check(obstacle.values, dim);
        if (!obstacle.displacement.empty())
          need_dim(obstacle.displacement, "Obstacle/Displacement");
      }
    else if (create_friction_law(friction.law)->has_friction())
      throw InputError("The entry <Friction/Law> asks for friction, but no "
                       "boundary id has the condition 'contact'.",
                       exit_inconsistent);

    check_friction_entries(friction, given);

    if (geometry.pre_refinement_steps > 0 &&
        boundary.ids_with(BoundaryCondition::contact).empty())
      throw InputError("The entry <Geometry/Pre-refinement steps> refines "
                       "toward the foundation, but the scene has no contact "
                       "boundary.",
                       exit_inconsistent);
  }

  EntryValues
  read_entry_values(ParameterHandler               &prm,
                    const std::vector<std::string> &entries)
  {
    EntryValues values;
    for (const std::string &entry : entries)
      {
        const auto slash = entry.find('/');
        prm.enter_subsection(entry.substr(0, slash));
        values[entry] = prm.get(entry.substr(slash + 1));
        prm.leave_subsection();
      }
    return values;
  }

  std::vector<double>
  numbers_of(const EntryValues &values, const std::string &entry)
  {
    const auto it = values.find(entry);
    AssertThrow(it != values.end(),
                ExcMessage("A plugin reads <" + entry +
                           ">, which it does not list among its entries."));
    return Utilities::string_to_double(
      Utilities::split_string_list(it->second, ','));
  }

  std::vector<double>
  vector_of(const EntryValues &values,
            const std::string &entry,
            const unsigned int n,
            const bool         nonzero)
  {
    const std::vector<double> v = numbers_of(values, entry);
    if (v.size() != n)
      throw InputError("The entry <" + entry + "> needs " + std::to_string(n) +
                         " values (one per dimension), not " +
                         std::to_string(v.size()) + ".",
                       exit_inconsistent);
    double norm = 0.;
    for (const double c : v)
      norm += c * c;
    if (nonzero && !(std::sqrt(norm) > 1e-12))
      throw InputError("The entry <" + entry + "> must not be the zero vector.",
                       exit_invalid_value);
    return v;
  }

  std::string
  default_parameter_file()
  {
    ParameterHandler prm;
    Parameters::declare_parameters(prm);
    std::ostringstream out;
    prm.print_parameters(out, ParameterHandler::PRM);
    return out.str();
  }
} // namespace dualcontact
