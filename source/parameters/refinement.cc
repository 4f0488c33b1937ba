// <Refinement>: the sequence of meshes; the strategy is a refinement
// indicator registered in refinement_indicator_kind.h, whose file declares the
// indicator's own entries.
#include <deal.II/base/utilities.h>

#include <dualcontact/input_error.h>
#include <dualcontact/parameter_helpers.h>
#include <dualcontact/parameters.h>
#include <dualcontact/refinement_indicator_kind.h>

#include <algorithm>
#include <map>

namespace dualcontact
{
  using namespace dealii;

  void
  RefinementParameters::declare_parameters(EntryDeclarer &declarer)
  {
    declarer.enter_subsection("Refinement");
    declarer.declare_entry(
      "Initial global refinement",
      "0",
      EntryPattern::whole_number(0, 20),
      "Number of global refinements of the coarse mesh before "
      "the first cycle [-].");
    declarer.declare_entry(
      "Number of cycles",
      "1",
      EntryPattern::whole_number(1, 30),
      "Number of meshes solved on; each after the first is "
      "the previous one refined [-].");
    std::string names, help;
    for (const std::string &name : refinement_indicator_names())
      {
        names += (names.empty() ? "" : "|") + name;
        help += " '" + name + "' " + refinement_indicator_kind(name).help;
      }
    declarer.declare_entry("Strategy",
                           "global",
                           EntryPattern::selection(names),
                           "How the mesh is refined between cycles; every mesh "
                           "is the previous one refined (nested meshes)." +
                             help);
    declarer.declare_entry(
      "Refine fraction",
      "0.3",
      EntryPattern::number(0., 1.),
      "Adaptive strategies (not 'global'): the fraction of the cells, "
      "those with the largest indicators, refined per cycle "
      "[-].");
    declarer.declare_entry(
      "Coarsen fraction",
      "0",
      EntryPattern::number(0., 1.),
      "Adaptive strategies (not 'global'): the fraction of the cells, "
      "those with the smallest indicators, coarsened per "
      "cycle [-]. Refine + coarsen fractions must not exceed "
      "1.");
    declarer.declare_entry(
      "Nested iteration",
      "true",
      EntryPattern::boolean(),
      "Carry the displacement v (by interpolation) and the multipliers l1, "
      "l2 and the threshold g (by interpolation of their nodal values, then "
      "projected so that l1 >= 0 and |l2| <= g) from each mesh to the next, "
      "and start the solver there. false: every mesh starts cold, from v = 0 "
      "and l1 = l2 = 0.");
    declarer.declare_entry(
      "Compare with cold start",
      "false",
      EntryPattern::boolean(),
      "With nested iteration: also solve each refined mesh from a cold "
      "start, before the nested solve, and report the Uzawa, loop-1 and "
      "Newton steps and the time saved, and the difference of the two "
      "solutions (columns cold_* of cycles.csv). Doubles the cost.");
    declarer.leave_subsection();
    // the indicators' own entries
    for (const std::string &name : refinement_indicator_names())
      if (refinement_indicator_kind(name).declare_parameters != nullptr)
        refinement_indicator_kind(name).declare_parameters(declarer);
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

  std::vector<IneffectiveRule>
  RefinementParameters::ineffective_rules(const Parameters &parameters) const
  {
    const bool                   contact  = parameters.boundary.has_contact();
    const bool                   one_mesh = n_cycles == 1;
    const std::string            never = "<Refinement/Number of cycles> is 1, "
                                         "so the mesh is never refined";
    std::vector<IneffectiveRule> rules = {
      {one_mesh,
       "Refinement",
       {"Strategy",
        "Refine fraction",
        "Coarsen fraction",
        "Nested iteration",
        "Compare with cold start"},
       never},
      {!one_mesh && refinement_indicator_kind(strategy).refines_every_cell(),
       "Refinement",
       {"Refine fraction", "Coarsen fraction"},
       "<Refinement/Strategy> is " + quoted(strategy) +
         " (every cell is refined)"},
      {!one_mesh && !nested_iteration,
       "Refinement",
       {"Compare with cold start"},
       "<Refinement/Nested iteration> is false: every mesh starts cold "
       "already"},
      {!one_mesh && nested_iteration && !contact,
       "Refinement",
       {"Compare with cold start"},
       "the scene has no contact boundary (the comparison is of contact "
       "solves)"}};

    // the entries of the refinement indicators: without refinement none
    // is read, else those of the scene's indicator
    std::map<std::string, std::vector<std::string>> indicator_entries;
    for (const std::string &name : refinement_indicator_names())
      for (const std::string &entry : refinement_indicator_kind(name).entries)
        indicator_entries[entry].push_back(name);
    const auto &own = refinement_indicator_kind(strategy).entries;
    for (const auto &[entry, names] : indicator_entries)
      {
        const std::string subsection = entry.substr(0, entry.find('/'));
        const std::string name       = entry.substr(entry.find('/') + 1);
        if (one_mesh)
          rules.push_back({true, subsection, {name}, never});
        else if (std::find(own.begin(), own.end(), entry) == own.end())
          rules.push_back({true,
                           subsection,
                           {name},
                           "<Refinement/Strategy> is " + quoted(strategy) +
                             " (it is for " + quoted_list(names) + ")"});
      }
    return rules;
  }
} // namespace dualcontact
