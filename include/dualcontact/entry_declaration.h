// Declaring the entries of a parameter file. Every entry, the library's and a
// plugin's, is declared through an EntryDeclarer: it gives deal.II's
// ParameterHandler the entry's name, default, pattern and help text, and
// records in an EntryCatalog the default and what the pattern accepts in
// words, from which ParameterReader phrases its messages ("Invalid value
// '0.7' for <Material/Poisson's ratio>: expected a number from -1 to 0.5").
//
// A declaration reads like deal.II's, with an EntryPattern for the pattern:
//
//   void
//   declare(EntryDeclarer &declarer)
//   {
//     declarer.enter_subsection("Obstacle");
//     declarer.declare_entry("Floor height",
//                            "0",
//                            EntryPattern::number(),
//                            "The height h of the floor [length].");
//     declarer.leave_subsection();
//   }
#ifndef dualcontact_entry_declaration_h
#define dualcontact_entry_declaration_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/patterns.h>

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace dualcontact
{
  /**
   * The entries a plugin (an obstacle kind, a refinement indicator) reads,
   * as the scene gives them: "Subsection/Entry" -> value.
   */
  using EntryValues = std::map<std::string, std::string>;

  /**
   * What an entry accepts: the deal.II pattern that checks a value, and the
   * same in words, singular ("a number >= 0") and plural ("numbers >= 0",
   * for the items of a list). Bounds are inclusive; a bound left at its
   * default is no bound.
   */
  class EntryPattern
  {
  public:
    /** A number from `low` to `high` (Patterns::Double). */
    static EntryPattern
    number(double low  = dealii::Patterns::Double::min_double_value,
           double high = dealii::Patterns::Double::max_double_value);

    /** A whole number from `low` to `high` (Patterns::Integer). */
    static EntryPattern
    whole_number(int low  = dealii::Patterns::Integer::min_int_value,
                 int high = dealii::Patterns::Integer::max_int_value);

    /** One of the names "a|b|c" (Patterns::Selection). */
    static EntryPattern
    selection(const std::string &names);

    /** true or false (Patterns::Bool). */
    static EntryPattern
    boolean();

    /**
     * Any text (Patterns::Anything): expressions and the like, which the
     * code that reads the entry checks.
     */
    static EntryPattern
    text();

    /** The name of a file to read (Patterns::FileName::input). */
    static EntryPattern
    file_name();

    /** The name of a folder (Patterns::DirectoryName). */
    static EntryPattern
    folder_name();

    /**
     * From `min_length` to `max_length` items, each accepted by `item`,
     * separated by `separator` (Patterns::List).
     */
    static EntryPattern
    list(const EntryPattern &item,
         unsigned int        min_length = 0,
         unsigned int        max_length = dealii::Patterns::List::max_int_value,
         const std::string  &separator  = ",");

    /**
     * Pairs 'key: value' separated by `separator`, each key accepted by
     * `key` and each value by `value` (Patterns::Map).
     */
    static EntryPattern
    map(const EntryPattern &key,
        const EntryPattern &value,
        unsigned int        min_length = 0,
        unsigned int        max_length = dealii::Patterns::Map::max_int_value,
        const std::string  &separator  = ",",
        const std::string  &key_separator = ":");

    /**
     * Pairs 'key: expression' separated by commas outside parentheses, so
     * that an expression may hold commas (if(t <= 1, t, 2 - t)), each key
     * accepted by `key`; the expression is the text after the first ':'.
     */
    static EntryPattern
    expression_map(const EntryPattern &key);

    /** The deal.II pattern. */
    const dealii::Patterns::PatternBase &
    pattern() const;

    /** What one value is, in words: "a number from -1 to 0.5". */
    const std::string &
    words() const;

    /** What the items of a list are, in words: "numbers from -1 to 0.5". */
    const std::string &
    plural() const;

  private:
    EntryPattern(const dealii::Patterns::PatternBase &pattern,
                 std::string                          singular,
                 std::string                          plural);

    std::shared_ptr<const dealii::Patterns::PatternBase> deal_pattern;
    std::string                                          singular_words;
    std::string                                          plural_words;
  };

  /**
   * `text` split at each `separator` outside parentheses, the pieces
   * trimmed: "1: if(t < 1, t, 1), 2: 0" gives "1: if(t < 1, t, 1)" and "2: 0".
   */
  std::vector<std::string>
  split_outside_parentheses(const std::string &text, char separator);

  /**
   * The entries declared through an EntryDeclarer: for each, where it is
   * (its subsections from the top, and its name), its default and what its
   * pattern accepts in words.
   */
  class EntryCatalog
  {
  public:
    struct Entry
    {
      std::string default_value;
      std::string words; // EntryPattern::words()
    };

    /** An entry's place: its subsections from the top, and its name. */
    using Key = std::pair<std::vector<std::string>, std::string>;

    /** Record an entry; a second declaration replaces the first. */
    void
    add(const Key &key, const Entry &entry);

    /** The entry `name` of subsection `subsections`, or nullptr. */
    const Entry *
    find(const std::vector<std::string> &subsections,
         const std::string              &name) const;

    /** The names of the entries right in `subsections`, alphabetically. */
    std::vector<std::string>
    entry_names(const std::vector<std::string> &subsections) const;

    /**
     * The names of the subsections right in `subsections` that hold
     * entries, alphabetically.
     */
    std::vector<std::string>
    subsection_names(const std::vector<std::string> &subsections) const;

    /**
     * Every entry, by subsections (a subsection's own entries before those
     * of the subsections in it), then by name.
     */
    const std::map<Key, Entry> &
    entries() const;

  private:
    std::map<Key, Entry> by_place;
  };

  /**
   * Declares entries in a ParameterHandler, in the subsections entered
   * through it, and records each in its catalog().
   */
  class EntryDeclarer
  {
  public:
    explicit EntryDeclarer(dealii::ParameterHandler &prm);

    /** Enter subsection `name` of the present one (no '/' in `name`). */
    void
    enter_subsection(const std::string &name);

    /** Back to the enclosing subsection. */
    void
    leave_subsection();

    /**
     * Declare entry `name` (no '/' in it) of the present subsection: its
     * default, what it accepts and its help text (with units).
     */
    void
    declare_entry(const std::string  &name,
                  const std::string  &default_value,
                  const EntryPattern &pattern,
                  const std::string  &help);

    /** The entries declared so far. */
    const EntryCatalog &
    catalog() const;

  private:
    dealii::ParameterHandler &prm;
    std::vector<std::string>  subsections;
    EntryCatalog              declared;
  };
} // namespace dualcontact

#endif
