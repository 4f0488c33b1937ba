#include <dualcontact/friction_law.h>
#include <dualcontact/registry.h>

#include <stdexcept>

namespace dualcontact
{
  bool
  register_friction_law(const std::string &name, FrictionLawFactory factory)
  {
    Registry<FrictionLawFactory>::instance().add(name, std::move(factory));
    return true;
  }

  std::vector<std::string>
  friction_law_names()
  {
    return Registry<FrictionLawFactory>::instance().names();
  }

  std::unique_ptr<FrictionLaw>
  create_friction_law(const std::string &name)
  {
    const auto *factory = Registry<FrictionLawFactory>::instance().find(name);
    if (factory == nullptr)
      throw std::invalid_argument("There is no friction law called <" + name +
                                  ">.");
    return (*factory)();
  }
} // namespace dualcontact
