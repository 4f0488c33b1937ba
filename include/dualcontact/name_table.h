// One table per choice entry: the names a .prm file writes and the enum
// values they stand for, read in both directions (parsing an entry, naming a
// value in a message) and giving the Patterns::Selection of the entry.
#ifndef dualcontact_name_table_h
#define dualcontact_name_table_h

#include <deal.II/base/exceptions.h>

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace dualcontact
{
  template <typename Enum>
  class NameTable
  {
  public:
    NameTable(std::initializer_list<std::pair<Enum, std::string>> rows)
        : rows(rows)
    {}

    /** The name of `value`, as the .prm file writes it. */
    const std::string &
    name(const Enum value) const
    {
      for (const auto &[v, n] : rows)
        if (v == value)
          return n;
      AssertThrow(false, dealii::ExcInternalError());
      return rows.front().second;
    }

    /** Whether `name` is one of the names. */
    bool
    has(const std::string &name) const
    {
      for (const auto &[v, n] : rows)
        if (n == name)
          return true;
      return false;
    }

    /**
     * The value called `name`; the entry's pattern admits only the names,
     * so any other is a programming error.
     */
    Enum
    value(const std::string &name) const
    {
      for (const auto &[v, n] : rows)
        if (n == name)
          return v;
      AssertThrow(false,
                  dealii::ExcMessage("'" + name + "' is not in the table."));
      return rows.front().first;
    }

    /** The names joined by `separator`: "a|b|c" for Patterns::Selection. */
    std::string
    names(const std::string &separator = "|") const
    {
      std::string text;
      for (const auto &[v, n] : rows)
        text += (text.empty() ? "" : separator) + n;
      return text;
    }

  private:
    std::vector<std::pair<Enum, std::string>> rows;
  };
} // namespace dualcontact

#endif
