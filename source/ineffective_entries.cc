// Entries that were given but have no effect in the scene: the run goes on,
// but the user learns that a value they set is not used (a friction
// coefficient without a friction law is the common case: it looks like
// friction and computes frictionless contact). Each subsection gives its
// rules (ineffective_rules() in source/parameters/); here they are gathered
// and the given entries among them named.
#include <dualcontact/parameters.h>

#include <algorithm>
#include <string>
#include <tuple>

namespace dualcontact
{
  std::vector<std::string>
  Parameters::ineffective_entries() const
  {
    // the subsections in the order of the listing; the warnings on entries
    // given at the same place (several --set) keep this order
    std::vector<IneffectiveRule> rules;
    for (const std::vector<IneffectiveRule> &more :
         {geometry.ineffective_rules(*this),
          obstacle.ineffective_rules(*this),
          friction.ineffective_rules(*this),
          solver.ineffective_rules(*this),
          refinement.ineffective_rules(*this),
          exact.ineffective_rules(*this),
          load_path.ineffective_rules(*this),
          output.ineffective_rules(*this)})
      rules.insert(rules.end(), more.begin(), more.end());

    // in the order the input gives the entries: by file, then line (the
    // overrides of --set, which have no line, last)
    std::vector<std::tuple<std::string, long, std::string>> found;
    for (const IneffectiveRule &rule : rules)
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
