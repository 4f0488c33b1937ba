// <Geometry>: the shape of the body and its initial mesh.
#include <deal.II/base/utilities.h>

#include <dualcontact/input_error.h>
#include <dualcontact/parameter_helpers.h>
#include <dualcontact/parameters.h>
#include <dualcontact/refinement_indicator.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace dualcontact
{
  using namespace dealii;

  namespace
  {
    /**
     * <Geometry/Manifolds>: "id: kind center x, y[, z] radius R [axis a, b,
     * c]; ...". The counts of coordinates are checked against the dimension
     * in GeometryParameters::check().
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
          if (!manifold_kind_names().has(kind))
            throw bad("'" + kind + "' is not a kind of manifold (" +
                      manifold_kind_names().names(", ") + ")");
          manifold.kind = manifold_kind_names().value(kind);

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

  } // namespace

  const NameTable<GeometryType> &
  geometry_type_names()
  {
    static const NameTable<GeometryType> table = {
      {GeometryType::rectangle, "rectangle"},
      {GeometryType::half_disc, "half disc"},
      {GeometryType::quarter_disc, "quarter disc"},
      {GeometryType::two_blocks, "two blocks"},
      {GeometryType::two_half_discs, "two half discs"},
      {GeometryType::mesh_file, "mesh file"}};
    return table;
  }

  const NameTable<CellKind> &
  cell_kind_names()
  {
    static const NameTable<CellKind> table = {{CellKind::quadrilateral,
                                               "quadrilateral"},
                                              {CellKind::simplex, "simplex"}};
    return table;
  }

  const NameTable<BoundaryManifold::Kind> &
  manifold_kind_names()
  {
    static const NameTable<BoundaryManifold::Kind> table = {
      {BoundaryManifold::Kind::circle, "circle"},
      {BoundaryManifold::Kind::sphere, "sphere"},
      {BoundaryManifold::Kind::cylinder, "cylinder"}};
    return table;
  }

  std::string
  to_string(const GeometryType type)
  {
    return geometry_type_names().name(type);
  }

  std::string
  BoundaryManifold::kind_name() const
  {
    return manifold_kind_names().name(kind);
  }

  void
  GeometryParameters::declare_parameters(EntryDeclarer &declarer)
  {
    declarer.enter_subsection("Geometry");
    declarer.declare_entry(
      "Dimension",
      "2",
      EntryPattern::whole_number(2, 3),
      "Space dimension of the body. 2 means plane strain.");
    declarer.declare_entry(
      "Type",
      "rectangle",
      EntryPattern::selection(geometry_type_names().names()),
      "Shape of the body. 'rectangle': an axis-parallel box with boundary ids "
      "0 (x = x_min), 1 (x = x_max), 2 (y = y_min), 3 (y = y_max) (and 4, 5 "
      "for z in 3D). 'half disc': the lower half of a disc (ball in 3D) of "
      "the given radius and centre, with boundary ids 0 (the curved part) "
      "and 1 (the flat top); refinement follows the circle. 'quarter disc' "
      "(2D): the lower right quarter (x >= x_c, y <= y_c) with ids 0 (curved), "
      "1 (flat top) and 2 (the symmetry line x = x_c). 'two blocks': the "
      "rectangle's box cut at half its height (2D: y, 3D: z) into two bodies "
      "whose meshes need not match across the cut (<Geometry/Subdivisions> "
      "for the lower, <Geometry/Upper subdivisions> for the upper block), "
      "with the rectangle's ids on the outside (the lower block's bottom "
      "2 in 2D, 4 in 3D; the upper block's top 3, 5) and on the cut the ids "
      "4 (2D; 6 in 3D) for the lower block's top and 5 (7) for the upper "
      "block's bottom, material id 0 for the lower and 1 for the upper "
      "block: a pair for <Boundary conditions/Contact pairs>. 'two half "
      "discs': two bodies that touch at <Geometry/Center>, the lower half of "
      "a disc (ball) of <Geometry/Radius> above it (material id 1; ids 0 on "
      "its curved part, 1 on its flat top) and the upper half of one of "
      "<Geometry/Lower radius> below it (material id 0; ids 2 curved, 3 flat "
      "bottom): Hertz's problem of two cylinders (spheres) as a pair '0: "
      "2'. 'mesh file': the "
      "coarse mesh of <Geometry/Mesh file> (Gmsh: quadrilaterals or "
      "triangles in 2D, hexahedra or tetrahedra in 3D), whose physical "
      "groups are the boundary ids; "
      "<Geometry/Manifolds> makes curved parts stay curved under refinement "
      "(doc/meshes.md).");
    declarer.declare_entry(
      "Cell type",
      "quadrilateral",
      EntryPattern::selection(cell_kind_names().names()),
      "The cells of the mesh and their element. 'quadrilateral' "
      "(hexahedra in 3D): FE_Q(k) and MappingQ(k) on a mesh that p4est "
      "distributes over the ranks. 'simplex': triangles (tetrahedra in 3D) "
      "with FE_SimplexP(k), k = 1 or 2 (1 in 3D with contact), straight-"
      "sided, on a mesh every rank holds whole; the rectangle splits each "
      "cell into 2 triangles (5 tetrahedra), the discs and a mesh file of "
      "quadrilaterals (hexahedra) each cell into 8 triangles (24 "
      "tetrahedra), and refinement halves every cell, so the meshes are "
      "nested (doc/simplices.md). A mesh file of triangles or tetrahedra is "
      "read as simplices whatever this entry says.");
    declarer.declare_entry(
      "Mesh file",
      "",
      EntryPattern::file_name(),
      "Type 'mesh file': the Gmsh mesh (.msh, ASCII, format 2.2 or 4.1), a "
      "path relative to the folder of the .prm file that sets it (given by "
      "--set: relative to the working directory). It must hold one kind of "
      "cell, quadrilaterals or triangles (2D), hexahedra or tetrahedra (3D): "
      "the coarse mesh that the refinement starts from. Physical groups of curves (2D) or surfaces "
      "(3D) become boundary ids, the numbers of <Boundary conditions/"
      "Conditions>; every boundary face must be in one (Gmsh's 'Physical "
      "Curve(0) = {...};' gives id 0). Coordinates are in [length].");
    declarer.declare_entry(
      "Manifolds",
      "",
      EntryPattern::text(),
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
    declarer.declare_entry(
      "Lower left corner",
      "0, 0",
      EntryPattern::list(EntryPattern::number(), 2, 3),
      "Rectangle: the corner with the smallest coordinates "
      "[length], one value per dimension (3D default: 0, 0, "
      "0).");
    declarer.declare_entry(
      "Upper right corner",
      "1, 1",
      EntryPattern::list(EntryPattern::number(), 2, 3),
      "Rectangle: the corner with the largest coordinates "
      "[length], one value per dimension (3D default: 1, 1, "
      "1).");
    declarer.declare_entry(
      "Subdivisions",
      "1, 1",
      EntryPattern::list(EntryPattern::whole_number(1), 2, 3),
      "Rectangle: number of cells of the coarse mesh in each "
      "direction [-] (3D default: 1, 1, 1). Two blocks: those of the lower "
      "block.");
    declarer.declare_entry(
      "Upper subdivisions",
      "1, 1",
      EntryPattern::list(EntryPattern::whole_number(1), 2, 3),
      "Two blocks: number of cells of the upper block's coarse mesh in each "
      "direction [-] (3D default: 1, 1, 1); across the cut they need not "
      "match the lower block's.");
    declarer.declare_entry(
      "Upper overhang",
      "0",
      EntryPattern::number(0.),
      "Two blocks: how far the upper block reaches beyond the lower one on "
      "each side across the cut (along x, and y in 3D) [length]. 0: both "
      "blocks span the box. The upper block's bottom beyond the lower one "
      "keeps the bottom's id (5 in 2D, 7 in 3D): a slave surface that "
      "extends beyond its master.");
    declarer.declare_entry(
      "Center",
      "0, 0",
      EntryPattern::list(EntryPattern::number(), 2, 3),
      "Half disc (3D: half ball): centre of the disc, i.e. "
      "the middle of the flat top; the curved part lies below "
      "it, toward -y (3D: -z) [length] (3D default: 0, 0, "
      "0).");
    declarer.declare_entry("Radius",
                           "1",
                           EntryPattern::number(0.),
                           "Half disc: radius R [length]. Must be positive. "
                           "Two half discs: the upper body's radius.");
    declarer.declare_entry("Lower radius",
                           "1",
                           EntryPattern::number(0.),
                           "Two half discs: the lower body's radius "
                           "[length]. Must be positive.");
    declarer.declare_entry(
      "Pre-refinement steps",
      "0",
      EntryPattern::whole_number(0, 30),
      "Number of times the cells near the obstacle (the foundation plane, or "
      "the surface of subsection Obstacle) are refined before the first cycle "
      "(after the initial global refinement) [-]. A cell counts as near if "
      "one of its vertices lies within 'Pre-refinement distance' of the "
      "obstacle in its prescribed position (after <Obstacle/Displacement>). "
      "In a scene whose only contact is between bodies (<Boundary "
      "conditions/Contact pairs>), near means within that distance of a "
      "vertex of another body's paired surface.");
    declarer.declare_entry("Pre-refinement distance",
                           "0",
                           EntryPattern::number(0.),
                           "Distance from the obstacle within which cells are "
                           "pre-refined in the first step [length].");
    declarer.declare_entry(
      "Pre-refinement grading",
      "1",
      EntryPattern::number(0., 1.),
      "Factor in (0, 1] by which the pre-refinement distance shrinks from one "
      "step to the next [-]: 1 refines the same band every step (a sharp "
      "jump in cell size at its edge), 0.5 gives a graded mesh whose cells "
      "grow with the distance from the obstacle.");
    declarer.leave_subsection();
  }

  void
  GeometryParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    dimension               = prm.get_integer("Dimension");
    const std::string shape = prm.get("Type");
    type                    = geometry_type_names().value(shape);
    cell_kind               = cell_kind_names().value(prm.get("Cell type"));
    lower_left              = parse_doubles(prm.get("Lower left corner"));
    upper_right             = parse_doubles(prm.get("Upper right corner"));
    subdivisions.clear();
    for (const int n : Utilities::string_to_int(
           Utilities::split_string_list(prm.get("Subdivisions"), ',')))
      subdivisions.push_back(n);
    upper_subdivisions.clear();
    for (const int n : Utilities::string_to_int(
           Utilities::split_string_list(prm.get("Upper subdivisions"), ',')))
      upper_subdivisions.push_back(n);
    upper_overhang          = prm.get_double("Upper overhang");
    center                  = parse_doubles(prm.get("Center"));
    radius                  = prm.get_double("Radius");
    lower_radius            = prm.get_double("Lower radius");
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
         type == GeometryType::quarter_disc ||
         type == GeometryType::two_half_discs) &&
        !(radius > 0.))
      throw InputError("The entry <Geometry/Radius> must be positive: " +
                         std::string(type == GeometryType::two_half_discs ?
                                       "the upper half disc" :
                                       "a " + to_string(type)) +
                         " of radius " + number_text(radius) + " has no area.",
                       exit_invalid_value);
    if (type == GeometryType::two_half_discs && !(lower_radius > 0.))
      throw InputError("The entry <Geometry/Lower radius> must be positive: a "
                       "half disc of radius " +
                         number_text(lower_radius) + " has no area.",
                       exit_invalid_value);
    if (pre_refinement_steps > 1 && !(pre_refinement_grading > 0.))
      throw InputError("The entry <Geometry/Pre-refinement grading> must be "
                       "positive: 0 shrinks the pre-refinement band to "
                       "nothing after the first step.",
                       exit_invalid_value);
  }

  void
  GeometryParameters::check(const Parameters &parameters) const
  {
    const unsigned int dim = dimension;
    if (is_box(type))
      {
        need_values(lower_left, "Geometry/Lower left corner", dim);
        need_values(upper_right, "Geometry/Upper right corner", dim);
        if (subdivisions.size() != dim)
          throw InputError("The entry <Geometry/Subdivisions> needs " +
                             std::to_string(dim) + " values.",
                           exit_inconsistent);
        if (type == GeometryType::two_blocks &&
            upper_subdivisions.size() != dim)
          throw InputError("The entry <Geometry/Upper subdivisions> needs " +
                             std::to_string(dim) + " values.",
                           exit_inconsistent);
        for (unsigned int d = 0; d < dim; ++d)
          if (!(upper_right[d] > lower_left[d]))
            throw InputError("The entry <Geometry/Upper right corner> must be "
                             "larger than <Geometry/Lower left corner> in "
                             "every coordinate.",
                             exit_inconsistent);
      }
    else if (type != GeometryType::mesh_file)
      need_values(center, "Geometry/Center", dim);

    // E's magnitude, then the lengths' (the sizes are known to be right)
    parameters.check_magnitudes();

    if (type == GeometryType::mesh_file &&
        mesh_file.find_first_not_of(" \t") == std::string::npos)
      throw InputError("The entry <Geometry/Type> is 'mesh file' but "
                       "<Geometry/Mesh file> names no file.",
                       exit_inconsistent);
    for (const BoundaryManifold &manifold : manifolds)
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

    if (type == GeometryType::two_half_discs && cell_kind == CellKind::simplex)
      throw InputError("The entry <Geometry/Type> 'two half discs' is made "
                       "of quadrilaterals (hexahedra): set <Geometry/Cell "
                       "type> to 'quadrilateral', or read two bodies of "
                       "triangles from a mesh file.",
                       exit_inconsistent);
    if (type == GeometryType::quarter_disc && dim != 2)
      throw InputError("The entry <Geometry/Type> 'quarter disc' exists in 2D "
                       "only.",
                       exit_inconsistent);
  }

  void
  GeometryParameters::check_magnitudes() const
  {
    const std::string lengths = "e.g. mm or km instead of m";
    if (is_box(type) && lower_left.size() == upper_right.size())
      for (std::size_t d = 0; d < lower_left.size(); ++d)
        {
          check_magnitude(upper_right[d] - lower_left[d],
                          "Geometry/Upper right corner",
                          "[length] (a side of the box)",
                          lengths);
          if (std::abs(lower_left[d]) > 1e100)
            check_magnitude(lower_left[d],
                            "Geometry/Lower left corner",
                            "[length]",
                            lengths);
          if (std::abs(upper_right[d]) > 1e100)
            check_magnitude(upper_right[d],
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
    const unsigned int dim    = dimension;
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
    if (type == GeometryType::half_disc || type == GeometryType::quarter_disc ||
        type == GeometryType::two_half_discs)
      {
        check_magnitude(radius, "Geometry/Radius", "[length]", lengths);
        curved(radius, center, "Geometry/Radius");
      }
    if (type == GeometryType::two_half_discs)
      {
        check_magnitude(lower_radius,
                        "Geometry/Lower radius",
                        "[length]",
                        lengths);
        curved(lower_radius, center, "Geometry/Lower radius");
      }
    if (type == GeometryType::mesh_file)
      for (const BoundaryManifold &manifold : manifolds)
        curved(manifold.radius, manifold.center, "Geometry/Manifolds");
  }

  void
  GeometryParameters::check_pre_refinement(const Parameters &parameters) const
  {
    if (pre_refinement_steps > 0 && !parameters.boundary.has_contact())
      throw InputError("The entry <Geometry/Pre-refinement steps> refines "
                       "toward the foundation (or the contact pairs), but "
                       "the scene has no contact boundary and no contact "
                       "pair.",
                       exit_inconsistent);
  }

  void
  GeometryParameters::check_simplices(const Parameters  &parameters,
                                      const std::string &why)
  {
    const unsigned int dim       = parameters.geometry.dimension;
    const unsigned int degree    = parameters.discretization.degree;
    const bool         contact   = parameters.boundary.has_contact();
    const std::string  simplices = dim == 2 ? "triangles" : "tetrahedra";
    const std::string  head =
      "The mesh is made of " + simplices + " (" + why + "), and deal.II 9.4 ";
    if (degree > 2)
      throw InputError(head + "has FE_SimplexP of degree 1 and 2 only: set "
                              "<Discretization/Polynomial degree> to 1 or 2.",
                       exit_inconsistent);
    if (dim == 3 && degree == 2 && contact)
      throw InputError(
        "The mesh is made of tetrahedra (" + why +
          ") and <Discretization/Polynomial degree> is 2: on a triangle "
          "face the shape functions of P2's vertices integrate to zero, so "
          "the contact nodes at the vertices would get no weight m_s "
          "(doc/simplices.md). Use degree 1 on tetrahedra, or hexahedra.",
        exit_inconsistent);
    if (degree > 1 && !parameters.boundary.contact_pairs.empty())
      throw InputError("The mesh is made of " + simplices + " (" + why +
                         "): contact pairs couple two bodies of simplices at "
                         "degree 1 only: set <Discretization/Polynomial "
                         "degree> to 1, or mesh with " +
                         (dim == 2 ? "quadrilaterals." : "hexahedra."),
                       exit_inconsistent);
    const RefinementParameters &refinement = parameters.refinement;
    const bool                  adapts =
      refinement.n_cycles > 1 || (parameters.load_path.adapt_at_every_step &&
                                  parameters.load_path.step_times().size() > 1);
    if (adapts &&
        !refinement_indicator_kind(refinement.strategy).refines_every_cell())
      throw InputError(head +
                         "has neither the error estimators nor the "
                         "coarsening that <Refinement/Strategy> " +
                         quoted(refinement.strategy) +
                         " needs on them: use 'global', which halves every "
                         "cell (nested meshes).",
                       exit_inconsistent);
    if (dim == 3 && parameters.geometry.pre_refinement_steps > 0)
      throw InputError(head + "has no hanging nodes on tetrahedra, which "
                              "<Geometry/Pre-refinement steps> would make: "
                              "set it to 0, and grade the mesh in Gmsh "
                              "instead (doc/meshes.md).",
                       exit_inconsistent);
  }

  std::vector<IneffectiveRule>
  GeometryParameters::ineffective_rules(const Parameters &) const
  {
    const bool rectangle = is_box(type);
    const bool mesh      = type == GeometryType::mesh_file;
    return {{rectangle || mesh,
             "Geometry",
             {"Center", "Radius"},
             "<Geometry/Type> is " + quoted(to_string(type)) +
               " (it is for the discs)"},
            {!mesh,
             "Geometry",
             {"Mesh file", "Manifolds"},
             "<Geometry/Type> is " + quoted(to_string(type)) +
               " (it is for 'mesh file')"},
            {!rectangle,
             "Geometry",
             {"Lower left corner", "Upper right corner", "Subdivisions"},
             "<Geometry/Type> is " + quoted(to_string(type)) +
               " (it is for the rectangle)"},
            {type != GeometryType::two_blocks,
             "Geometry",
             {"Upper subdivisions", "Upper overhang"},
             "<Geometry/Type> is " + quoted(to_string(type)) +
               " (it is for 'two blocks')"},
            {type != GeometryType::two_half_discs,
             "Geometry",
             {"Lower radius"},
             "<Geometry/Type> is " + quoted(to_string(type)) +
               " (it is for 'two half discs')"},
            {pre_refinement_steps == 0,
             "Geometry",
             {"Pre-refinement distance", "Pre-refinement grading"},
             "<Geometry/Pre-refinement steps> is 0"},
            {pre_refinement_steps == 1,
             "Geometry",
             {"Pre-refinement grading"},
             "it shrinks the distance from the second pre-refinement step on, "
             "and <Geometry/Pre-refinement steps> is 1"}};
  }
} // namespace dualcontact
