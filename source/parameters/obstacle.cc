// <Obstacle>: the checks that need the dimension and the boundary
// conditions, and the entries that have no effect. The subsection is
// declared and parsed in source/obstacle.cc, beside the registry of kinds.
#include <deal.II/base/utilities.h>

#include <dualcontact/input_error.h>
#include <dualcontact/obstacle.h>
#include <dualcontact/parameter_helpers.h>
#include <dualcontact/parameters.h>

#include <algorithm>
#include <set>

namespace dualcontact
{
  void
  ObstacleParameters::check(const Parameters &parameters) const
  {
    if (parameters.boundary.ids_with(BoundaryCondition::contact).empty())
      return;
    const unsigned int  dim  = parameters.geometry.dimension;
    const ObstacleKind &kind = obstacle_kind(type);
    if (kind.check != nullptr)
      kind.check(values, dim);
    const std::size_t n = displacement_components().size();
    if (n > 0 && n != dim)
      throw InputError("The entry <Obstacle/Displacement> needs " +
                         std::to_string(dim) +
                         " values (one per dimension), not " +
                         std::to_string(n) + ".",
                       exit_inconsistent);
  }

  std::vector<std::string>
  ObstacleParameters::displacement_components() const
  {
    if (displacement.find_first_not_of(" \t") == std::string::npos)
      return {};
    return Utilities::split_string_list(
      displacement, displacement.find(';') != std::string::npos ? ';' : ',');
  }

  std::vector<IneffectiveRule>
  ObstacleParameters::ineffective_rules(const Parameters &parameters) const
  {
    // the entries of the obstacle kinds the scene's kind does not read
    const bool contact =
      !parameters.boundary.ids_with(BoundaryCondition::contact).empty();
    const unsigned int    dim          = parameters.geometry.dimension;
    const auto            readers      = obstacle_entry_readers(dim);
    const auto            readers_2d3d = obstacle_entry_readers(5 - dim);
    std::set<std::string> entries = {"Obstacle/Type", "Obstacle/Displacement"};
    for (const auto *map : {&readers, &readers_2d3d})
      for (const auto &[entry, kinds] : *map)
        entries.insert(entry);
    std::vector<IneffectiveRule> rules;
    for (const std::string &entry : entries)
      {
        const std::string subsection = entry.substr(0, entry.find('/'));
        const std::string name       = entry.substr(entry.find('/') + 1);
        const auto        here       = readers.find(entry);
        if (!contact)
          rules.push_back({true,
                           subsection,
                           {name},
                           "no boundary id has the condition 'contact'"});
        else if (here == readers.end() && readers_2d3d.count(entry) > 0)
          rules.push_back({true,
                           subsection,
                           {name},
                           "<Obstacle/Type> is " + quoted(type) + " in " +
                             std::to_string(dim) + "D (it is for " +
                             quoted_list(readers_2d3d.at(entry)) + " in " +
                             std::to_string(5 - dim) + "D)"});
        else if (here != readers.end() &&
                 std::find(here->second.begin(), here->second.end(), type) ==
                   here->second.end())
          rules.push_back({true,
                           subsection,
                           {name},
                           "<Obstacle/Type> is " + quoted(type) +
                             " (it is for " + quoted_list(here->second) + ")"});
      }
    return rules;
  }
} // namespace dualcontact
