// A registry of named factories: friction laws and obstacles register
// themselves by name from their own files, and the parameters offer the
// names that are there.
#ifndef dualcontact_registry_h
#define dualcontact_registry_h

#include <dualcontact/input_error.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace dualcontact
{
  template <typename Factory>
  class Registry
  {
  public:
    /**
     * The registry of this Factory type, a function-local static so that it
     * exists before the first kind registers itself, whatever the order of
     * static initialisation.
     */
    static Registry &
    instance()
    {
      static Registry registry;
      return registry;
    }

    void
    add(const std::string &name, Factory factory)
    {
      factories[name] = std::move(factory);
    }

    /** The registered names, in alphabetical order. */
    std::vector<std::string>
    names() const
    {
      std::vector<std::string> result;
      for (const auto &[name, factory] : factories)
        result.push_back(name);
      return result;
    }

    /** The factory called `name`, or nullptr. */
    const Factory *
    find(const std::string &name) const
    {
      const auto it = factories.find(name);
      return it == factories.end() ? nullptr : &it->second;
    }

    /**
     * The factory called `name`; InputError (exit 5) otherwise: "There is no
     * `kind` called 'name' (<entry>)."
     */
    const Factory &
    get(const std::string &name,
        const std::string &kind,
        const std::string &entry) const
    {
      const Factory *factory = find(name);
      if (factory == nullptr)
        throw InputError("There is no " + kind + " called '" + name + "' (<" +
                           entry + ">).",
                         exit_invalid_value);
      return *factory;
    }

  private:
    std::map<std::string, Factory> factories;
  };
} // namespace dualcontact

#endif
