// A friction law: the friction threshold g at a contact node from the
// node's friction parameter (a coefficient F, or a given threshold) and its
// contact pressure l1 (doc/theory.md §1, §3.1). The scene chooses one law,
// once, by the name in <Friction/Law>; the solver asks it, and nothing else,
// what the threshold is.
//
// Adding a law is one new file in source/friction_laws/ (or in a program of
// one's own): a class derived from FrictionLaw, which declares its own
// entry in subsection Friction, and one line that registers it under its
// name, e.g.
//
//   const bool registered = register_friction_law(
//     "my law", [] { return std::make_unique<MyLaw>(); });
//
// The name then appears in the pattern and the help text of <Friction/Law>.
#ifndef dualcontact_friction_law_h
#define dualcontact_friction_law_h

#include <dualcontact/entry_declaration.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace dualcontact
{
  class FrictionLaw
  {
  public:
    virtual ~FrictionLaw() = default;

    /** The name in <Friction/Law>. */
    virtual std::string
    name() const = 0;

    /** One line for the list of composed effects: what runs. */
    virtual std::string
    description() const = 0;

    /** What <Friction/Law> = this name means, for its help text. */
    virtual std::string
    help() const
    {
      return description();
    }

    /**
     * Declares the law's own entry, parameter_entry(), in subsection
     * Friction through `declarer` (entry_declaration.h: its pattern, default
     * and help text with units). Not called if another law declared the
     * entry already.
     */
    virtual void
    declare_parameters(EntryDeclarer &declarer) const
    {
      (void)declarer;
    }

    /**
     * Whether there is friction at all: without it there is no tangential
     * multiplier l2 and no threshold, and the Uzawa iteration works on l1
     * alone.
     */
    virtual bool
    has_friction() const
    {
      return true;
    }

    /**
     * Whether the threshold depends on the contact pressure. Then the
     * problem is a quasi-variational inequality and the threshold iteration
     * (loop 1) runs around the Uzawa iteration; otherwise g is fixed.
     */
    virtual bool
    depends_on_pressure() const = 0;

    /**
     * The entry of subsection Friction whose expression gives the friction
     * parameter at each contact node (FrictionParameters::parameter); empty
     * if the law has none.
     */
    virtual std::string
    parameter_entry() const = 0;

    /**
     * The threshold g at a node with friction parameter `parameter` and
     * contact pressure `pressure` = l1 >= 0.
     */
    virtual double
    threshold(const double parameter, const double pressure) const = 0;

    /**
     * What friction can resist tangentially at most, for the equilibrium
     * check before a solve, from the sum over Gamma_C of m_s times the
     * parameter, the largest parameter, and the net normal load N (< 0 if
     * it is not known from the loads alone, because something other than
     * the contact also holds the body normally). < 0: not known. `why`
     * gets a few words on where the figure comes from.
     */
    virtual double
    capacity(const double weighted_parameter_sum,
             const double largest_parameter,
             const double normal_load,
             std::string &why) const = 0;
  };

  using FrictionLawFactory = std::function<std::unique_ptr<FrictionLaw>()>;

  /**
   * Make `name` known to <Friction/Law>. Called once per law, at load time,
   * from the law's own file. Returns true (for the static initialiser).
   */
  bool
  register_friction_law(const std::string &name, FrictionLawFactory factory);

  /** The registered names, in alphabetical order. */
  std::vector<std::string>
  friction_law_names();

  /**
   * The laws' own entries (FrictionLaw::parameter_entry), each with the
   * names of the laws that read it.
   */
  std::map<std::string, std::vector<std::string>>
  friction_law_entries();

  /** The law called `name`; throws if there is none. */
  std::unique_ptr<FrictionLaw>
  create_friction_law(const std::string &name);
} // namespace dualcontact

#endif
