#include <dualcontact/friction_law.h>
#include <dualcontact/registry.h>


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

  std::map<std::string, std::vector<std::string>>
  friction_law_entries()
  {
    std::map<std::string, std::vector<std::string>> entries;
    for (const std::string &name : friction_law_names())
      {
        const std::string entry = create_friction_law(name)->parameter_entry();
        if (!entry.empty())
          entries[entry].push_back(name);
      }
    return entries;
  }

  std::unique_ptr<FrictionLaw>
  create_friction_law(const std::string &name)
  {
    return Registry<FrictionLawFactory>::instance().get(name,
                                                        "friction law",
                                                        "Friction/Law")();
  }
} // namespace dualcontact
