// Entries that were given but have no effect in the scene: the run goes on,
// but the user learns that a value they set is not used (a friction
// coefficient without a friction law is the common case: it looks like
// friction and computes frictionless contact).
#include <dualcontact/friction_law.h>
#include <dualcontact/obstacle.h>
#include <dualcontact/parameters.h>
#include <dualcontact/refinement_indicator.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <tuple>

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

    // 'a', 'b' and 'c'
    std::string
    quoted_list(const std::vector<std::string> &names)
    {
      std::string text;
      for (std::size_t i = 0; i < names.size(); ++i)
        text += std::string(i == 0                ? "" :
                            i + 1 == names.size() ? " and " :
                                                    ", ") +
                quoted(names[i]);
      return text;
    }

    std::string
    subsection_of(const std::string &entry)
    {
      return entry.substr(0, entry.find('/'));
    }

    std::string
    name_of(const std::string &entry)
    {
      return entry.substr(entry.find('/') + 1);
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
        "Nested iteration",
        "Compare with cold start"},
       "<Refinement/Number of cycles> is 1, so the mesh is never refined"},
      {!one_mesh &&
         refinement_indicator_kind(refinement.strategy).refines_every_cell(),
       "Refinement",
       {"Refine fraction", "Coarsen fraction"},
       "<Refinement/Strategy> is " + quoted(refinement.strategy) +
         " (every cell is refined)"},
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

    // the entries of the obstacle kinds the scene's kind does not read
    const unsigned int    dim              = geometry.dimension;
    const auto            readers          = obstacle_entry_readers(dim);
    const auto            readers_2d3d     = obstacle_entry_readers(5 - dim);
    std::set<std::string> obstacle_entries = {"Obstacle/Type",
                                              "Obstacle/Displacement"};
    for (const auto *map : {&readers, &readers_2d3d})
      for (const auto &[entry, kinds] : *map)
        obstacle_entries.insert(entry);
    for (const std::string &entry : obstacle_entries)
      {
        const auto here = readers.find(entry);
        if (!contact)
          rules.push_back({true,
                           subsection_of(entry),
                           {name_of(entry)},
                           "no boundary id has the condition 'contact'"});
        else if (here == readers.end() && readers_2d3d.count(entry) > 0)
          rules.push_back({true,
                           subsection_of(entry),
                           {name_of(entry)},
                           "<Obstacle/Type> is " + quoted(obstacle.type) +
                             " in " + std::to_string(dim) + "D (it is for " +
                             quoted_list(readers_2d3d.at(entry)) + " in " +
                             std::to_string(5 - dim) + "D)"});
        else if (here != readers.end() &&
                 std::find(here->second.begin(),
                           here->second.end(),
                           obstacle.type) == here->second.end())
          rules.push_back({true,
                           subsection_of(entry),
                           {name_of(entry)},
                           "<Obstacle/Type> is " + quoted(obstacle.type) +
                             " (it is for " + quoted_list(here->second) + ")"});
      }

    // the entries of the refinement indicators: without refinement none
    // is read, else those of the scene's indicator
    std::map<std::string, std::vector<std::string>> indicator_entries;
    for (const std::string &name : refinement_indicator_names())
      for (const std::string &entry : refinement_indicator_kind(name).entries)
        indicator_entries[entry].push_back(name);
    const auto &own = refinement_indicator_kind(refinement.strategy).entries;
    for (const auto &[entry, names] : indicator_entries)
      if (one_mesh)
        rules.push_back({true,
                         subsection_of(entry),
                         {name_of(entry)},
                         "<Refinement/Number of cycles> is 1, so the mesh is "
                         "never refined"});
      else if (std::find(own.begin(), own.end(), entry) == own.end())
        rules.push_back({true,
                         subsection_of(entry),
                         {name_of(entry)},
                         "<Refinement/Strategy> is " +
                           quoted(refinement.strategy) + " (it is for " +
                           quoted_list(names) + ")"});

    // the entries of the friction laws the scene's law does not read
    for (const auto &[entry, laws] : friction_law_entries())
      if (entry != law_entry)
        rules.push_back(
          {true,
           "Friction",
           {entry},
           law_entry.empty() ?
             "<Friction/Law> is " + quoted(friction.law) +
               " (frictionless); set <Friction/Law> to use friction" :
             "the law " + quoted(friction.law) + " takes <Friction/" +
               law_entry + "> (<Friction/" + entry + "> is for " +
               quoted_list(laws) + ")"});

    // in the order the input gives the entries: by file, then line (the
    // overrides of --set, which have no line, last)
    std::vector<std::tuple<std::string, long, std::string>> found;
    for (const Rule &rule : rules)
      if (rule.applies)
        for (const std::string &entry : rule.entries)
          {
            const std::string name = rule.subsection + "/" + entry;
            const auto        it   = given.find(name);
            if (it == given.end())
              continue;
            const std::string &where = it->second;
            const auto         colon = where.rfind(':');
            const bool         line =
              colon != std::string::npos && colon + 1 < where.size() &&
              where.find_first_not_of("0123456789", colon + 1) ==
                std::string::npos;
            found.emplace_back(line ? where.substr(0, colon) : "\x7f" + where,
                               line ? std::stol(where.substr(colon + 1)) : 0,
                               "<" + name + "> has no effect: " + rule.why +
                                 " (" + where + ").");
          }
    std::stable_sort(found.begin(),
                     found.end(),
                     [](const auto &a, const auto &b) {
                       return std::tie(std::get<0>(a), std::get<1>(a)) <
                              std::tie(std::get<0>(b), std::get<1>(b));
                     });
    std::vector<std::string> warnings;
    for (const auto &item : found)
      warnings.push_back(std::get<2>(item));
    return warnings;
  }
} // namespace dualcontact
