// Entries that were given but have no effect in the scene: the run goes on,
// but the user learns that a value they set is not used (a friction
// coefficient without a friction law is the common case: it looks like
// friction and computes frictionless contact).
#include <dualcontact/friction_law.h>
#include <dualcontact/parameters.h>

namespace dualcontact
{
  namespace
  {
    /** Entries that have no effect in a scene, and why. */
    struct Rule
    {
      bool                     applies;
      std::string              subsection;
      std::vector<std::string> entries;
      std::string              why;
    };

    std::string
    quoted(const std::string &value)
    {
      return "'" + value + "'";
    }
  } // namespace

  std::vector<std::string>
  Parameters::ineffective_entries() const
  {
    const bool contact = !boundary.ids_with(BoundaryCondition::contact).empty();
    const bool rectangle = geometry.type == GeometryType::rectangle;
    const bool mesh_file = geometry.type == GeometryType::mesh_file;
    const bool one_mesh  = refinement.n_cycles == 1;
    const auto law       = create_friction_law(friction.law);
    const std::string              law_entry           = law->parameter_entry();
    const std::vector<std::string> threshold_iteration = {
      "Threshold iteration",
      "Initial threshold",
      "Threshold tolerance",
      "Maximum threshold steps"};

    std::vector<Rule> rules = {
      {rectangle || mesh_file,
       "Geometry",
       {"Center", "Radius"},
       "<Geometry/Type> is " + quoted(to_string(geometry.type)) +
         " (it is for the discs)"},
      {!mesh_file,
       "Geometry",
       {"Mesh file", "Manifolds"},
       "<Geometry/Type> is " + quoted(to_string(geometry.type)) +
         " (it is for 'mesh file')"},
      {!rectangle,
       "Geometry",
       {"Lower left corner", "Upper right corner", "Subdivisions"},
       "<Geometry/Type> is " + quoted(to_string(geometry.type)) +
         " (it is for the rectangle)"},
      {geometry.pre_refinement_steps == 0,
       "Geometry",
       {"Pre-refinement distance", "Pre-refinement grading"},
       "<Geometry/Pre-refinement steps> is 0"},
      {geometry.pre_refinement_steps == 1,
       "Geometry",
       {"Pre-refinement grading"},
       "it shrinks the distance from the second pre-refinement step on, and "
       "<Geometry/Pre-refinement steps> is 1"},
      {!contact,
       "Foundation",
       {"Point", "Normal"},
       "no boundary id has the condition 'contact'"},
      {!contact,
       "Obstacle",
       {"Type", "Center", "Radius", "Axis", "Distance", "Displacement"},
       "no boundary id has the condition 'contact'"},
      {contact && obstacle.type != "plane",
       "Foundation",
       {"Point", "Normal"},
       "<Obstacle/Type> is " + quoted(obstacle.type) +
         " (the foundation is the plane obstacle)"},
      {contact && (obstacle.type == "plane" || obstacle.type == "distance"),
       "Obstacle",
       {"Center", "Radius", "Axis"},
       "<Obstacle/Type> is " + quoted(obstacle.type) +
         " (they are for 'cylinder' and 'sphere')"},
      {contact && obstacle.type != "plane" && obstacle.type != "distance" &&
         (geometry.dimension == 2 || obstacle.type == "sphere"),
       "Obstacle",
       {"Axis"},
       "it is the axis of a cylinder in 3D"},
      {contact && obstacle.type != "distance",
       "Obstacle",
       {"Distance"},
       "<Obstacle/Type> is " + quoted(obstacle.type) +
         " (it is for 'distance')"},
      {law_entry.empty(),
       "Friction",
       {"Coefficient", "Threshold"},
       "<Friction/Law> is " + quoted(friction.law) +
         " (frictionless); set <Friction/Law> to use friction"},
      {law_entry == "Threshold",
       "Friction",
       {"Coefficient"},
       "the law " + quoted(friction.law) +
         " takes <Friction/Threshold> (the coefficient is for 'coulomb')"},
      {law_entry == "Coefficient",
       "Friction",
       {"Threshold"},
       "the law " + quoted(friction.law) +
         " takes <Friction/Coefficient> (the threshold is for 'given')"},
      {contact && law_entry.empty(),
       "Solver",
       {"Tangential augmentation parameter"},
       "<Friction/Law> is " + quoted(friction.law) +
         " (frictionless): there are no friction terms"},
      {!law->depends_on_pressure(),
       "Friction",
       threshold_iteration,
       "the law " + quoted(friction.law) +
         " has no pressure-dependent threshold, so there is no threshold "
         "iteration"},
      {!contact,
       "Solver",
       {"Augmentation parameter",
        "Tangential augmentation parameter",
        "Proximal parameter",
        "Uzawa tolerance",
        "Maximum Uzawa steps",
        "Newton tolerance factor",
        "Initial inner tolerance",
        "Inner tolerance reduction",
        "Inner tolerance factor",
        "Maximum Newton steps",
        "Line search",
        "AMG rebuild fraction",
        "Time a reference linear solve"},
       "the scene has no contact boundary (one linear elasticity solve per "
       "mesh, no Uzawa or Newton iteration)"},
      {one_mesh,
       "Refinement",
       {"Strategy",
        "Refine fraction",
        "Coarsen fraction",
        "Contact indicator weight",
        "Nested iteration",
        "Compare with cold start"},
       "<Refinement/Number of cycles> is 1, so the mesh is never refined"},
      {!one_mesh && refinement.strategy == RefinementStrategy::global,
       "Refinement",
       {"Refine fraction", "Coarsen fraction", "Contact indicator weight"},
       "<Refinement/Strategy> is 'global' (every cell is refined)"},
      {!one_mesh && refinement.strategy == RefinementStrategy::kelly,
       "Refinement",
       {"Contact indicator weight"},
       "<Refinement/Strategy> is 'kelly' (the weight is for 'contact')"},
      {!one_mesh && !refinement.nested_iteration,
       "Refinement",
       {"Compare with cold start"},
       "<Refinement/Nested iteration> is false: every mesh starts cold "
       "already"},
      {!one_mesh && refinement.nested_iteration && !contact,
       "Refinement",
       {"Compare with cold start"},
       "the scene has no contact boundary (the comparison is of contact "
       "solves)"},
      {!contact,
       "Exact solution",
       {"Contact pressure",
        "Contact half-width",
        "Stick half-width",
        "Peak pressure"},
       "the scene has no contact boundary"},
      {contact && law_entry.empty(),
       "Exact solution",
       {"Stick half-width"},
       "<Friction/Law> is " + quoted(friction.law) +
         " (frictionless): there is no stick zone"}};

    std::vector<std::string> warnings;
    for (const Rule &rule : rules)
      if (rule.applies)
        for (const std::string &entry : rule.entries)
          {
            const std::string name = rule.subsection + "/" + entry;
            const auto        it   = given.find(name);
            if (it != given.end())
              warnings.push_back("<" + name + "> has no effect: " + rule.why +
                                 " (" + it->second + ").");
          }
    return warnings;
  }
} // namespace dualcontact
