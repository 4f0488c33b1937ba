// <Geometry>: the shape of the body and its initial mesh.
#include <deal.II/base/utilities.h>

#include <dualcontact/geometry.h>
#include <dualcontact/input_error.h>
#include <dualcontact/parameter_helpers.h>
#include <dualcontact/parameters.h>
#include <dualcontact/refinement_indicator_kind.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace dualcontact
{
  using namespace dealii;


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
  BoundaryManifold::kind_name() const
  {
    return manifold_kind_names().name(kind);
  }

  namespace
  {
    /**
     * Calls `hook` of every registered kind once per distinct hook (the
     * kinds of one file share theirs), in the order of the listing.
     */
    template <typename Hook, typename... Arguments>
    void
    call_each_kind(Hook GeometryKind::*hook, Arguments &...arguments)
    {
      std::vector<Hook> called;
      for (const std::string &name : geometry_names())
        {
          const Hook function = geometry_kind(name).*hook;
          if (function != nullptr &&
              std::find(called.begin(), called.end(), function) == called.end())
            {
              function(arguments...);
              called.push_back(function);
            }
        }
    }
  } // namespace

  void
  GeometryParameters::declare_parameters(EntryDeclarer &declarer)
  {
    std::string names, help;
    for (const std::string &name : geometry_names())
      {
        names += (names.empty() ? "" : "|") + name;
        help += " " + geometry_kind(name).help;
      }
    declarer.enter_subsection("Geometry");
    declarer.declare_entry(
      "Dimension",
      "2",
      EntryPattern::whole_number(2, 3),
      "Space dimension of the body. 2 means plane strain.");
    declarer.declare_entry("Type",
                           "rectangle",
                           EntryPattern::selection(names),
                           "Shape of the body." + help);
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
    call_each_kind(&GeometryKind::declare_parameters, declarer);
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
    dimension = prm.get_integer("Dimension");
    type      = prm.get("Type");
    cell_kind = cell_kind_names().value(prm.get("Cell type"));
    call_each_kind(&GeometryKind::parse_parameters, prm, *this);
    pre_refinement_steps    = prm.get_integer("Pre-refinement steps");
    pre_refinement_distance = prm.get_double("Pre-refinement distance");
    pre_refinement_grading  = prm.get_double("Pre-refinement grading");
    prm.leave_subsection();
    const GeometryKind &kind = geometry_kind(type);
    if (kind.check_parsed != nullptr)
      kind.check_parsed(*this);
    if (pre_refinement_steps > 1 && !(pre_refinement_grading > 0.))
      throw InputError("The entry <Geometry/Pre-refinement grading> must be "
                       "positive: 0 shrinks the pre-refinement band to "
                       "nothing after the first step.",
                       exit_invalid_value);
  }

  void
  GeometryParameters::check(const Parameters &parameters) const
  {
    const unsigned int  dim   = dimension;
    const GeometryKind &shape = geometry_kind(type);
    if (shape.check_sizes != nullptr)
      shape.check_sizes(*this);

    // E's magnitude, then the lengths' (the sizes are known to be right)
    parameters.check_magnitudes();

    if (shape.check != nullptr)
      shape.check(parameters);
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
  }

  void
  GeometryParameters::check_magnitudes() const
  {
    const GeometryKind &kind = geometry_kind(type);
    if (kind.check_magnitudes != nullptr)
      kind.check_magnitudes(*this);
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
    // the entries each kind owns, where the chosen kind reads none of them
    const std::vector<std::string> &reads = geometry_kind(type).entries;
    std::vector<IneffectiveRule>    rules;
    for (const std::string &name : geometry_names())
      for (const GeometryEntryGroup &group : geometry_kind(name).owned_entries)
        {
          const bool listed =
            std::any_of(rules.begin(), rules.end(), [&](const auto &rule) {
              return rule.entries == group.entries;
            });
          if (!listed && !group.entries.empty())
            rules.push_back(
              {std::find(reads.begin(), reads.end(), group.entries[0]) ==
                 reads.end(),
               "Geometry",
               group.entries,
               "<Geometry/Type> is " + quoted(type) + " (it is for " +
                 group.purpose + ")"});
        }
    const std::vector<IneffectiveRule> refinement = {
      {pre_refinement_steps == 0,
       "Geometry",
       {"Pre-refinement distance", "Pre-refinement grading"},
       "<Geometry/Pre-refinement steps> is 0"},
      {pre_refinement_steps == 1,
       "Geometry",
       {"Pre-refinement grading"},
       "it shrinks the distance from the second pre-refinement step on, "
       "and <Geometry/Pre-refinement steps> is 1"}};
    rules.insert(rules.end(), refinement.begin(), refinement.end());
    return rules;
  }
} // namespace dualcontact
