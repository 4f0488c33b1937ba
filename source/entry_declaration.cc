#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <dualcontact/entry_declaration.h>

#include <algorithm>
#include <set>
#include <sstream>

namespace dualcontact
{
  namespace Patterns = dealii::Patterns;

  namespace
  {
    // a bound as deal.II writes it in the pattern's description
    std::string
    bound_text(const double x)
    {
      std::ostringstream out;
      out << x;
      return out.str();
    }

    // "2 or 3 " (the number of items of a list); empty for any number
    std::string
    length_in_words(const unsigned int low, const unsigned int high)
    {
      const std::string from = std::to_string(low), to = std::to_string(high);
      if (high == Patterns::List::max_int_value)
        return low == 0 ? "" : "at least " + from + " ";
      if (low == high)
        return from + " ";
      if (high == low + 1)
        return from + " or " + to + " ";
      return from + " to " + to + " ";
    }

    std::string
    separator_in_words(const std::string &separator)
    {
      if (separator == ",")
        return "comma-separated";
      if (separator == ";")
        return "semicolon-separated";
      return "'" + separator + "'-separated";
    }

    /** Patterns::Map whose pairs are separated by commas outside parentheses.
     */
    class ExpressionMapPattern : public Patterns::PatternBase
    {
    public:
      explicit ExpressionMapPattern(const Patterns::PatternBase &key)
          : key(key.clone())
      {}

      bool
      match(const std::string &text) const override
      {
        for (const std::string &item : split_outside_parentheses(text, ','))
          {
            const auto colon = item.find(':');
            if (colon == std::string::npos ||
                !key->match(dealii::Utilities::trim(item.substr(0, colon))))
              return false;
          }
        return true;
      }

      std::string
      description(const OutputStyle) const override
      {
        return "[Map of <" + key->description() +
               ">:<expression> separated by commas outside parentheses]";
      }

      std::unique_ptr<Patterns::PatternBase>
      clone() const override
      {
        return std::make_unique<ExpressionMapPattern>(*key);
      }

    private:
      std::unique_ptr<Patterns::PatternBase> key;
    };
  } // namespace

  std::vector<std::string>
  split_outside_parentheses(const std::string &text, const char separator)
  {
    std::vector<std::string> pieces;
    std::string              piece;
    int                      depth = 0;
    for (const char c : text)
      {
        depth += (c == '(') - (c == ')');
        if (c == separator && depth <= 0)
          {
            pieces.push_back(dealii::Utilities::trim(piece));
            piece.clear();
          }
        else
          piece += c;
      }
    if (!dealii::Utilities::trim(piece).empty() || !pieces.empty())
      pieces.push_back(dealii::Utilities::trim(piece));
    return pieces;
  }

  // ------------------------------------------------------------ EntryPattern

  EntryPattern::EntryPattern(const Patterns::PatternBase &pattern,
                             std::string                  singular,
                             std::string                  plural)
      : deal_pattern(pattern.clone())
      , singular_words(std::move(singular))
      , plural_words(std::move(plural))
  {}

  EntryPattern
  EntryPattern::number(const double low, const double high)
  {
    // deal.II takes low > high for no bounds
    const bool bounded  = low <= high;
    const bool has_low  = bounded && low != Patterns::Double::min_double_value;
    const bool has_high = bounded && high != Patterns::Double::max_double_value;
    std::string bounds;
    if (has_low && has_high)
      bounds = " from " + bound_text(low) + " to " + bound_text(high);
    else if (has_low)
      bounds = " >= " + bound_text(low);
    else if (has_high)
      bounds = " <= " + bound_text(high);
    return {Patterns::Double(low, high),
            "a number" + bounds,
            "numbers" + bounds};
  }

  EntryPattern
  EntryPattern::whole_number(const int low, const int high)
  {
    const bool bounded  = low <= high;
    const bool has_low  = bounded && low != Patterns::Integer::min_int_value;
    const bool has_high = bounded && high != Patterns::Integer::max_int_value;
    const std::string from = std::to_string(low), to = std::to_string(high);
    std::string       bounds;
    if (has_low && has_high)
      bounds = static_cast<long>(high) == static_cast<long>(low) + 1 ?
                 ": " + from + " or " + to :
                 " from " + from + " to " + to;
    else if (has_low)
      bounds = " >= " + from;
    else if (has_high)
      bounds = " <= " + to;
    return {Patterns::Integer(low, high),
            "a whole number" + bounds,
            "whole numbers" + bounds};
  }

  EntryPattern
  EntryPattern::selection(const std::string &names)
  {
    std::string options;
    for (const std::string &option :
         dealii::Utilities::split_string_list(names, '|'))
      options += (options.empty() ? "" : ", ") + option;
    return {Patterns::Selection(names),
            "one of: " + options,
            "items from: " + options};
  }

  EntryPattern
  EntryPattern::boolean()
  {
    return {Patterns::Bool(), "true or false", "each true or false"};
  }

  EntryPattern
  EntryPattern::text()
  {
    return {Patterns::Anything(), "any text", "any texts"};
  }

  EntryPattern
  EntryPattern::file_name()
  {
    return {Patterns::FileName(Patterns::FileName::input),
            "a file name",
            "file names"};
  }

  EntryPattern
  EntryPattern::folder_name()
  {
    return {Patterns::DirectoryName(), "a folder name", "folder names"};
  }

  EntryPattern
  EntryPattern::list(const EntryPattern &item,
                     const unsigned int  min_length,
                     const unsigned int  max_length,
                     const std::string  &separator)
  {
    const std::string count = length_in_words(min_length, max_length);
    const std::string kind  = separator_in_words(separator) + " list";
    return {Patterns::List(item.pattern(), min_length, max_length, separator),
            "a " + kind + " of " + count + item.plural(),
            kind + "s of " + count + item.plural()};
  }

  EntryPattern
  EntryPattern::map(const EntryPattern &key,
                    const EntryPattern &value,
                    const unsigned int  min_length,
                    const unsigned int  max_length,
                    const std::string  &separator,
                    const std::string  &key_separator)
  {
    const std::string words = "a " + separator_in_words(separator) +
                              " list of 'key" + key_separator +
                              " value' pairs (each key " + key.words() +
                              ", each value " + value.words() + ")";
    return {Patterns::Map(key.pattern(),
                          value.pattern(),
                          min_length,
                          max_length,
                          separator,
                          key_separator),
            words,
            words};
  }

  EntryPattern
  EntryPattern::expression_map(const EntryPattern &key)
  {
    const std::string words =
      "a comma-separated list of 'key: expression' pairs (each key " +
      key.words() + "; commas inside parentheses belong to the expression)";
    return {ExpressionMapPattern(key.pattern()), words, words};
  }

  const Patterns::PatternBase &
  EntryPattern::pattern() const
  {
    return *deal_pattern;
  }

  const std::string &
  EntryPattern::words() const
  {
    return singular_words;
  }

  const std::string &
  EntryPattern::plural() const
  {
    return plural_words;
  }

  // ------------------------------------------------------------ EntryCatalog

  void
  EntryCatalog::add(const Key &key, const Entry &entry)
  {
    by_place[key] = entry;
  }

  const EntryCatalog::Entry *
  EntryCatalog::find(const std::vector<std::string> &subsections,
                     const std::string              &name) const
  {
    const auto it = by_place.find({subsections, name});
    return it == by_place.end() ? nullptr : &it->second;
  }

  std::vector<std::string>
  EntryCatalog::entry_names(const std::vector<std::string> &subsections) const
  {
    std::vector<std::string> names;
    for (const auto &[key, entry] : by_place)
      if (key.first == subsections)
        names.push_back(key.second);
    return names;
  }

  std::vector<std::string>
  EntryCatalog::subsection_names(
    const std::vector<std::string> &subsections) const
  {
    std::set<std::string> names;
    for (const auto &[key, entry] : by_place)
      if (key.first.size() > subsections.size() &&
          std::equal(subsections.begin(), subsections.end(), key.first.begin()))
        names.insert(key.first[subsections.size()]);
    return {names.begin(), names.end()};
  }

  const std::map<EntryCatalog::Key, EntryCatalog::Entry> &
  EntryCatalog::entries() const
  {
    return by_place;
  }

  // ----------------------------------------------------------- EntryDeclarer

  EntryDeclarer::EntryDeclarer(dealii::ParameterHandler &prm)
      : prm(prm)
  {}

  void
  EntryDeclarer::enter_subsection(const std::string &name)
  {
    // ParameterReader and --set name entries as "Subsection/Entry"
    Assert(name.find('/') == std::string::npos,
           dealii::ExcMessage("The subsection <" + name + "> has a '/'."));
    prm.enter_subsection(name);
    subsections.push_back(name);
  }

  void
  EntryDeclarer::leave_subsection()
  {
    Assert(!subsections.empty(),
           dealii::ExcMessage("leave_subsection() without a subsection."));
    prm.leave_subsection();
    subsections.pop_back();
  }

  void
  EntryDeclarer::declare_entry(const std::string  &name,
                               const std::string  &default_value,
                               const EntryPattern &pattern,
                               const std::string  &help)
  {
    Assert(name.find('/') == std::string::npos,
           dealii::ExcMessage("The entry <" + name + "> has a '/'."));
    prm.declare_entry(name, default_value, pattern.pattern(), help);
    declared.add({subsections, name}, {default_value, pattern.words()});
  }

  const EntryCatalog &
  EntryDeclarer::catalog() const
  {
    return declared;
  }
} // namespace dualcontact
