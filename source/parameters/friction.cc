// <Friction>: the friction law (a name registered in friction_law.h, whose
// file declares the law's own entry) and the threshold iteration.
#include <deal.II/base/utilities.h>

#include <dualcontact/friction_law.h>
#include <dualcontact/input_error.h>
#include <dualcontact/parameter_helpers.h>
#include <dualcontact/parameters.h>

#include <map>
#include <set>
#include <string>

namespace dualcontact
{
  using namespace dealii;

  namespace
  {
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

  const NameTable<FrictionStrategy> &
  friction_strategy_names()
  {
    static const NameTable<FrictionStrategy> table = {
      {FrictionStrategy::nested, "nested"},
      {FrictionStrategy::merged, "merged"}};
    return table;
  }

  const NameTable<InitialThreshold> &
  initial_threshold_names()
  {
    static const NameTable<InitialThreshold> table = {
      {InitialThreshold::zero, "zero"},
      {InitialThreshold::frictionless, "frictionless"}};
    return table;
  }

  void
  FrictionParameters::declare_parameters(EntryDeclarer &declarer)
  {
    declarer.enter_subsection("Friction");
    // the laws registered in source/friction_laws/ (friction_law.h)
    std::string names;
    for (const std::string &name : friction_law_names())
      names += (names.empty() ? "" : "|") + name;
    std::string help;
    for (const std::string &name : friction_law_names())
      help += std::string(help.empty() ? "" : ", ") + "'" + name + "' (" +
              create_friction_law(name)->help() + ")";
    declarer.declare_entry("Law",
                           "none",
                           EntryPattern::selection(names),
                           "Friction on the contact boundary, one of " + help +
                             ".");
    declarer.leave_subsection();
    // each law's own entry, once
    std::set<std::string> declared;
    for (const std::string &name : friction_law_names())
      {
        const auto        law   = create_friction_law(name);
        const std::string entry = law->parameter_entry();
        if (!entry.empty() && declared.insert(entry).second)
          law->declare_parameters(declarer);
      }
    declarer.enter_subsection("Friction");
    declarer.declare_entry(
      "Threshold iteration",
      "merged",
      EntryPattern::selection(friction_strategy_names().names()),
      "Coulomb only, the threshold iteration: 'nested' solves the "
      "given-friction problem with the threshold g fixed, then sets g = F "
      "l1, until g settles (successive approximations); 'merged' sets g = F "
      "l1 after every Uzawa step (one loop). Both give the same solution "
      "within the tolerances.");
    declarer.declare_entry(
      "Initial threshold",
      "zero",
      EntryPattern::selection(initial_threshold_names().names()),
      "Coulomb only: g^0 = 0, or g^0 = F times the contact "
      "pressure of the frictionless problem (solved first).");
    declarer.declare_entry(
      "Threshold tolerance",
      "1e-6",
      EntryPattern::number(1e-14, 1.),
      "Coulomb only: the threshold iteration stops when |g_new - g| <= tol "
      "|g_new| (nodal Euclidean norms) [-].");
    declarer.declare_entry(
      "Maximum threshold steps",
      "100",
      EntryPattern::whole_number(1),
      "Coulomb only: the threshold iteration gives up (with an error naming "
      "the cause) after this many steps [-].");
    declarer.leave_subsection();
  }

  void
  FrictionParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Friction");
    law                     = prm.get("Law");
    const std::string entry = create_friction_law(law)->parameter_entry();
    parameter               = entry.empty() ? "" : prm.get(entry);
    strategy = friction_strategy_names().value(prm.get("Threshold iteration"));
    initial_threshold =
      initial_threshold_names().value(prm.get("Initial threshold"));
    tolerance = prm.get_double("Threshold tolerance");
    max_steps = prm.get_integer("Maximum threshold steps");
    prm.leave_subsection();
  }

  void
  FrictionParameters::check(const Parameters &parameters) const
  {
    if (!parameters.boundary.has_contact() &&
        create_friction_law(law)->has_friction())
      throw InputError("The entry <Friction/Law> asks for friction, but no "
                       "boundary id has the condition 'contact' and there "
                       "is no <Boundary conditions/Contact pairs>.",
                       exit_inconsistent);
    check_friction_entries(*this, parameters.given);
  }

  std::vector<IneffectiveRule>
  FrictionParameters::ineffective_rules(const Parameters &) const
  {
    const auto                   friction_law = create_friction_law(law);
    const std::string            law_entry    = friction_law->parameter_entry();
    std::vector<IneffectiveRule> rules        = {
             {!friction_law->depends_on_pressure(),
              "Friction",
              {"Threshold iteration",
               "Initial threshold",
               "Threshold tolerance",
               "Maximum threshold steps"},
              "the law " + quoted(law) +
                " has no pressure-dependent threshold, so there is no threshold "
                       "iteration"}};
    // the entries of the friction laws the scene's law does not read
    for (const auto &[entry, laws] : friction_law_entries())
      if (entry != law_entry)
        rules.push_back(
          {true,
           "Friction",
           {entry},
           law_entry.empty() ?
             "<Friction/Law> is " + quoted(law) +
               " (frictionless); set <Friction/Law> to use friction" :
             "the law " + quoted(law) + " takes <Friction/" + law_entry +
               "> (<Friction/" + entry + "> is for " + quoted_list(laws) +
               ")"});
    return rules;
  }
} // namespace dualcontact
