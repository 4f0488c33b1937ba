#include <dualcontact/friction_law.h>

#include <map>
#include <stdexcept>

namespace dualcontact
{
  namespace
  {
    // A function-local static, so that it exists before the first law
    // registers itself, whatever the order of static initialisation.
    std::map<std::string, FrictionLawFactory> &
    registry()
    {
      static std::map<std::string, FrictionLawFactory> laws;
      return laws;
    }
  } // namespace

  bool
  register_friction_law(const std::string &name, FrictionLawFactory factory)
  {
    registry()[name] = std::move(factory);
    return true;
  }

  std::vector<std::string>
  friction_law_names()
  {
    std::vector<std::string> names;
    for (const auto &[name, factory] : registry())
      names.push_back(name);
    return names;
  }

  std::unique_ptr<FrictionLaw>
  create_friction_law(const std::string &name)
  {
    const auto it = registry().find(name);
    if (it == registry().end())
      throw std::invalid_argument("There is no friction law called <" + name +
                                  ">.");
    return it->second();
  }
} // namespace dualcontact
