#include <deal.II/base/utilities.h>

#include <dualcontact/input_error.h>
#include <dualcontact/parameter_reader.h>

#include <algorithm>
#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

namespace dualcontact
{
  using dealii::ParameterHandler;
  namespace Utilities = dealii::Utilities;

  namespace
  {
    /**
     * The first word of `value` (words separated by list and map separators
     * and blanks) that reads as a number outside what a double holds with
     * full precision: a nonzero magnitude below the smallest normal double
     * (2.2e-308: 1e-320 is subnormal, 1e-400 underflows to zero) or above
     * the largest (1.8e308). deal.II's patterns accept such words but its
     * conversion refuses them; "" if there is none.
     */
    std::string
    number_out_of_range(const std::string &value)
    {
      std::string word;
      const auto  check = [&word]() {
        if (word.empty())
          return false;
        char *end = nullptr;
        errno     = 0;
        std::strtod(word.c_str(), &end);
        return end == word.c_str() + word.size() && errno == ERANGE;
      };
      for (const char c : value + " ")
        if (std::string(",;:| \t").find(c) != std::string::npos)
          {
            if (check())
              return word;
            word.clear();
          }
        else
          word += c;
      return "";
    }

    std::string
    lower_case(std::string text)
    {
      for (char &c : text)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      return text;
    }

    bool
    starts_with(const std::string &text, const std::string &prefix)
    {
      return text.compare(0, prefix.size(), prefix) == 0;
    }

    // deal.II's keywords are either lower or upper case ("set" or "SET")
    bool
    starts_with_keyword(const std::string &line, const std::string &keyword)
    {
      std::string upper = keyword;
      for (char &c : upper)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      return starts_with(line, keyword) || starts_with(line, upper);
    }

    std::string
    join(const std::vector<std::string> &parts, const std::string &entry = "")
    {
      std::string result;
      for (const std::string &part : parts)
        result += (result.empty() ? "" : "/") + part;
      if (!entry.empty())
        result += (result.empty() ? "" : "/") + entry;
      return result;
    }

    std::string
    location(const std::string &source, const unsigned int line)
    {
      return source + ":" + std::to_string(line);
    }

    // ParameterHandler's JSON output spells every character other than
    // [a-zA-Z0-9] as _XX (its ASCII code in hexadecimal).
    std::string
    demangle(const std::string &name)
    {
      std::string result;
      for (std::size_t i = 0; i < name.size(); ++i)
        if (name[i] == '_' && i + 2 < name.size() &&
            std::isxdigit(static_cast<unsigned char>(name[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(name[i + 2])))
          {
            result +=
              static_cast<char>(std::stoi(name.substr(i + 1, 2), nullptr, 16));
            i += 2;
          }
        else
          result += name[i];
      return result;
    }

    // ----------------------------------------------- patterns in words

    struct Words
    {
      std::string singular; // "a number >= 0"
      std::string plural;   // "numbers >= 0"
    };

    Words
    words_of(const std::string &description);

    // The index of the ']' that closes the '[' at `open`, or npos.
    std::size_t
    closing_bracket(const std::string &text, const std::size_t open)
    {
      int depth = 0;
      for (std::size_t i = open; i < text.size(); ++i)
        if (text[i] == '[')
          ++depth;
        else if (text[i] == ']' && --depth == 0)
          return i;
      return std::string::npos;
    }

    // "<[inner pattern]>" at `pos`: the inner description; `pos` moves past
    // the '>'.
    bool
    read_inner(const std::string &text, std::size_t &pos, std::string &inner)
    {
      if (pos + 1 >= text.size() || text[pos] != '<' || text[pos + 1] != '[')
        return false;
      const std::size_t close = closing_bracket(text, pos + 1);
      if (close == std::string::npos || close + 1 >= text.size() ||
          text[close + 1] != '>')
        return false;
      inner = text.substr(pos + 1, close - pos);
      pos   = close + 2;
      return true;
    }

    // " of length 2...3 (inclusive)" -> "2 or 3 "; empty for any length
    std::string
    length_in_words(const std::string &text)
    {
      const auto dots = text.find("...");
      if (dots == std::string::npos)
        return "";
      const std::string low = Utilities::trim(text.substr(0, dots));
      const std::string high =
        Utilities::trim(text.substr(dots + 3, text.find(' ', dots) - dots - 3));
      const bool unbounded =
        high == std::to_string(std::numeric_limits<unsigned int>::max());
      if (unbounded)
        return low == "0" ? "" : "at least " + low + " ";
      if (low == high)
        return low + " ";
      if (std::stoul(high) == std::stoul(low) + 1)
        return low + " or " + high + " ";
      return low + " to " + high + " ";
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

    // "[List of <[Double ...]> of length 2...3 (inclusive)]", optionally
    // with " separated by <;>" before the ']'
    bool
    list_in_words(const std::string &d, Words &words)
    {
      const std::string head = "[List of ";
      std::size_t       pos  = head.size();
      std::string       inner;
      if (!starts_with(d, head) || !read_inner(d, pos, inner))
        return false;
      std::string rest      = d.substr(pos, d.size() - 1 - pos);
      std::string separator = ",";
      const auto  by        = rest.find(" separated by <");
      if (by != std::string::npos)
        {
          separator = rest.substr(by + 15, rest.find('>', by) - by - 15);
          rest      = rest.substr(0, by);
        }
      const std::string count =
        length_in_words(rest.substr(rest.find("length") + 6));
      const std::string list = separator_in_words(separator) + " list";
      words.singular = "a " + list + " of " + count + words_of(inner).plural;
      words.plural   = list + "s of " + count + words_of(inner).plural;
      return true;
    }

    // "[Map of <[key]>:<[value]> of length ...]", optionally with
    // " separated by <;>"
    bool
    map_in_words(const std::string &d, Words &words)
    {
      const std::string head = "[Map of ";
      std::size_t       pos  = head.size();
      std::string       key, value;
      if (!starts_with(d, head) || !read_inner(d, pos, key))
        return false;
      const std::size_t value_start = d.find('<', pos);
      if (value_start == std::string::npos)
        return false;
      const std::string key_separator =
        Utilities::trim(d.substr(pos, value_start - pos));
      pos = value_start;
      if (!read_inner(d, pos, value))
        return false;
      std::string separator = ",";
      const auto  by        = d.find(" separated by <", pos);
      if (by != std::string::npos)
        separator = d.substr(by + 15, d.find('>', by) - by - 15);
      words.singular = "a " + separator_in_words(separator) + " list of 'key" +
                       key_separator + " value' pairs (each key " +
                       words_of(key).singular + ", each value " +
                       words_of(value).singular + ")";
      words.plural = words.singular;
      return true;
    }

    // "[Integer range 1...30 (inclusive)]", "[Double 0...MAX_DOUBLE
    // (inclusive)]", "[Integer]", "[Double]"
    bool
    range_in_words(const std::string &d, Words &words)
    {
      const bool integer = starts_with(d, "[Integer");
      if (!integer && !starts_with(d, "[Double"))
        return false;
      const std::string noun   = integer ? "whole number" : "number";
      const auto        dots   = d.find("...");
      std::string       bounds = "";
      if (dots != std::string::npos)
        {
          const auto        start = d.rfind(' ', dots) + 1;
          const std::string low   = d.substr(start, dots - start);
          const std::string high =
            d.substr(dots + 3, d.find(' ', dots) - dots - 3);
          const bool no_low =
            low == "-MAX_DOUBLE" ||
            low == std::to_string(std::numeric_limits<int>::min());
          const bool no_high =
            high == "MAX_DOUBLE" ||
            high == std::to_string(std::numeric_limits<int>::max());
          if (!no_low && !no_high)
            bounds = integer && std::stol(high) == std::stol(low) + 1 ?
                       ": " + low + " or " + high :
                       " from " + low + " to " + high;
          else if (!no_low)
            bounds = " >= " + low;
          else if (!no_high)
            bounds = " <= " + high;
        }
      words.singular = "a " + noun + bounds;
      words.plural   = noun + "s" + bounds;
      return true;
    }

    Words
    words_of(const std::string &d)
    {
      Words words;
      if (range_in_words(d, words) || list_in_words(d, words) ||
          map_in_words(d, words))
        return words;
      if (starts_with(d, "[Selection "))
        {
          std::string options;
          for (const std::string &option :
               Utilities::split_string_list(d.substr(11, d.size() - 12), '|'))
            options += (options.empty() ? "" : ", ") + option;
          return {"one of: " + options, "items from: " + options};
        }
      if (d == "[Bool]")
        return {"true or false", "each true or false"};
      if (d == "[Anything]")
        return {"any text", "any texts"};
      if (starts_with(d, "[DirectoryName"))
        return {"a folder name", "folder names"};
      if (starts_with(d, "[FileName"))
        return {"a file name", "file names"};
      return {d, d};
    }

    // --------------------------------------------------- suggestions

    // Edit distance (optimal string alignment: a swap of two neighbours is
    // one edit), case-insensitive.
    std::size_t
    edit_distance(const std::string &a_, const std::string &b_)
    {
      const std::string a = lower_case(a_), b = lower_case(b_);
      std::vector<std::vector<std::size_t>> d(
        a.size() + 1, std::vector<std::size_t>(b.size() + 1));
      for (std::size_t i = 0; i <= a.size(); ++i)
        d[i][0] = i;
      for (std::size_t j = 0; j <= b.size(); ++j)
        d[0][j] = j;
      for (std::size_t i = 1; i <= a.size(); ++i)
        for (std::size_t j = 1; j <= b.size(); ++j)
          {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            d[i][j]                = std::min(
              {d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
              d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
          }
      return d[a.size()][b.size()];
    }
  } // namespace

  std::string
  pattern_in_words(const std::string &description)
  {
    return words_of(description).singular;
  }

  std::string
  closest_match(const std::string              &word,
                const std::vector<std::string> &candidates)
  {
    // a quarter of the letters wrong (at least one) still reads as a typo;
    // more is a different word
    const std::size_t limit = std::max<std::size_t>(1, word.size() / 4);
    std::string       best;
    std::size_t       best_distance = limit + 1;
    for (const std::string &candidate : candidates)
      {
        const std::size_t distance = edit_distance(word, candidate);
        if (distance < best_distance)
          {
            best          = candidate;
            best_distance = distance;
          }
      }
    return best;
  }

  // ------------------------------------------------------------ Catalog

  /** What the handler declares: subsections, entries, pattern texts. */
  struct ParameterReader::Catalog
  {
    struct Section
    {
      struct Entry
      {
        std::string pattern; // deal.II's description of the pattern
        std::string default_value;
      };
      std::map<std::string, Entry>   entries;
      std::map<std::string, Section> subsections;
    };

    explicit Catalog(const ParameterHandler &prm)
    {
      std::stringstream json;
      prm.print_parameters(json, ParameterHandler::JSON);
      boost::property_tree::ptree tree;
      boost::property_tree::read_json(json, tree);
      fill(root, tree);
    }

    static void
    fill(Section &section, const boost::property_tree::ptree &tree)
    {
      for (const auto &[key, node] : tree)
        if (node.get_optional<std::string>("value"))
          section.entries[demangle(key)] = {
            node.get<std::string>("pattern_description"),
            node.get<std::string>("default_value")};
        else if (!node.empty())
          fill(section.subsections[demangle(key)], node);
    }

    const Section &
    at(const std::vector<std::string> &path) const
    {
      const Section *section = &root;
      for (const std::string &name : path)
        section = &section->subsections.at(name);
      return *section;
    }

    /** Every entry as (subsection path, name). */
    void
    all_entries(const Section                                    &section,
                const std::string                                &path,
                std::vector<std::pair<std::string, std::string>> &out) const
    {
      for (const auto &[name, pattern] : section.entries)
        out.emplace_back(path, name);
      for (const auto &[name, sub] : section.subsections)
        all_entries(sub, path.empty() ? name : path + "/" + name, out);
    }

    Section root;
  };

  /** The entries set by one layer (the scene, or the overrides). */
  struct ParameterReader::Layer
  {
    bool                               is_scene;
    std::map<std::string, std::string> set_at; // "Sub/Entry" -> where
    // "Sub/Entry" -> folder of the file that set it
    std::map<std::string, std::filesystem::path> folder_of;
  };

  ParameterReader::ParameterReader(ParameterHandler &prm)
      : prm(prm)
      , catalog(std::make_unique<Catalog>(prm))
      , scene(std::make_unique<Layer>(Layer{true, {}, {}}))
      , overrides(std::make_unique<Layer>(Layer{false, {}, {}}))
  {}

  ParameterReader::~ParameterReader() = default;

  void
  ParameterReader::read_file(const std::string &filename)
  {
    std::error_code error;
    if (std::filesystem::is_directory(filename, error))
      throw InputError("The parameter file <" + filename +
                         "> is a directory, not a file.",
                       exit_cannot_read_file);
    std::ifstream in(filename);
    if (!in)
      throw InputError("Cannot open the parameter file <" + filename + ">.",
                       exit_cannot_read_file);
    open_files.push_back(std::filesystem::weakly_canonical(filename, error));
    read_stream(in,
                filename,
                std::filesystem::path(filename).parent_path(),
                *scene);
    open_files.pop_back();
  }

  void
  ParameterReader::read_text(const std::string &text, const std::string &source)
  {
    std::istringstream in(text);
    read_stream(in, source, "", *scene);
  }

  void
  ParameterReader::read_overlay(const std::string &text,
                                const std::string &source)
  {
    std::istringstream in(text);
    read_stream(in, source, "", *overrides);
  }

  void
  ParameterReader::set_override(const std::string &assignment)
  {
    const auto equals = assignment.find('=');
    const auto slash  = assignment.find('/');
    if (equals == std::string::npos || slash == std::string::npos ||
        slash > equals)
      throw InputError("The override --set '" + assignment +
                         "' is not of the form 'Subsection/Entry=value' "
                         "(it needs a '/' before the '=').",
                       exit_usage);
    // split by hand: Utilities::split_string_list drops a last empty name
    std::vector<std::string> names(1);
    for (const char c : assignment.substr(0, equals))
      if (c == '/')
        names.emplace_back();
      else
        names.back() += c;
    for (std::string &name : names)
      name = Utilities::trim(name);
    if (std::find(names.begin(), names.end(), "") != names.end())
      throw InputError("The override --set '" + assignment +
                         "' has an empty subsection or entry name.",
                       exit_usage);
    const std::string entry = names.back();
    names.pop_back();

    // check the subsections one by one, so that a misspelt one is named
    path.clear();
    for (const std::string &name : names)
      enter(name, "--set");
    path.clear();
    assign(names,
           entry,
           Utilities::trim(assignment.substr(equals + 1)),
           "--set",
           "",
           *overrides);
  }

  std::map<std::string, std::string>
  ParameterReader::given_entries() const
  {
    std::map<std::string, std::string> set_at = scene->set_at;
    for (const auto &[name, where] : overrides->set_at)
      set_at[name] = where;
    // an entry set to its default changes nothing (a listing of every
    // entry, such as parameters.prm, sets them all)
    std::map<std::string, std::string> given;
    for (const auto &[name, where] : set_at)
      {
        std::vector<std::string> path;
        for (const std::string &part : Utilities::split_string_list(name, '/'))
          path.push_back(part);
        const std::string entry = path.back();
        path.pop_back();
        for (const std::string &subsection : path)
          prm.enter_subsection(subsection);
        const std::string value = prm.get(entry);
        for (std::size_t i = 0; i < path.size(); ++i)
          prm.leave_subsection();
        if (value != catalog->at(path).entries.at(entry).default_value)
          given[name] = where;
      }
    return given;
  }

  std::set<std::string>
  ParameterReader::set_entries() const
  {
    std::set<std::string> names;
    for (const Layer *layer : {scene.get(), overrides.get()})
      for (const auto &[name, where] : layer->set_at)
        names.insert(name);
    return names;
  }

  std::filesystem::path
  ParameterReader::folder_of(const std::string &entry) const
  {
    if (overrides->set_at.count(entry) > 0)
      return "";
    const auto it = scene->folder_of.find(entry);
    return it == scene->folder_of.end() ? std::filesystem::path() : it->second;
  }

  bool
  ParameterReader::scene_has_entries() const
  {
    return !scene->set_at.empty();
  }

  void
  ParameterReader::read_stream(std::istream                &in,
                               const std::string           &source,
                               const std::filesystem::path &folder,
                               Layer                       &layer)
  {
    // like deal.II: a line ending in '\' continues on the next one, and a
    // file leaves the subsections as it found them
    const std::size_t depth = path.size();
    std::string       line, logical_line;
    unsigned int      number = 0, first = 0;
    bool              continued = false;
    while (std::getline(in, line))
      {
        ++number;
        if (!continued)
          first = number;
        line      = Utilities::trim(line);
        continued = !line.empty() && line.back() == '\\';
        logical_line += continued ? line.substr(0, line.size() - 1) : line;
        if (continued)
          continue;
        scan_line(logical_line, location(source, first), folder, depth, layer);
        logical_line.clear();
      }
    if (continued)
      scan_line(logical_line, location(source, first), folder, depth, layer);
    if (path.size() > depth)
      throw InputError("The subsection <" + path.back().first + "> opened at " +
                         path.back().second +
                         " is not closed: an 'end' is "
                         "missing before the end of " +
                         source + ".",
                       exit_unknown_entry);
  }

  void
  ParameterReader::scan_line(const std::string           &raw_line,
                             const std::string           &where,
                             const std::filesystem::path &folder,
                             const std::size_t            depth_at_file_start,
                             Layer                       &layer)
  {
    std::string line = raw_line.substr(0, raw_line.find('#'));
    std::replace(line.begin(), line.end(), '\t', ' ');
    line = Utilities::trim(line);
    if (line.empty())
      return;

    if (starts_with_keyword(line, "subsection "))
      enter(Utilities::trim(line.substr(11)), where);
    else if (starts_with_keyword(line, "end"))
      {
        if (!Utilities::trim(line.substr(3)).empty())
          throw InputError("Unexpected text after 'end': '" + raw_line + "' (" +
                             where + ").",
                           exit_unknown_entry);
        if (path.size() <= depth_at_file_start)
          throw InputError("An 'end' closes no subsection: there is one 'end' "
                           "too many (" +
                             where + ").",
                           exit_unknown_entry);
        path.pop_back();
      }
    else if (starts_with_keyword(line, "set "))
      {
        const auto equals = line.find('=');
        if (equals == std::string::npos)
          throw InputError("The line '" + line +
                             "' has no '=': expected 'set Entry = value' (" +
                             where + ").",
                           exit_unknown_entry);
        std::vector<std::string> subsections;
        for (const auto &[name, opened] : path)
          subsections.push_back(name);
        assign(subsections,
               Utilities::trim(line.substr(4, equals - 4)),
               Utilities::trim(line.substr(equals + 1)),
               where,
               folder,
               layer);
      }
    else if (starts_with_keyword(line, "include "))
      {
        const std::filesystem::path file = Utilities::trim(line.substr(8));
        read_included_file(file.is_relative() ? folder / file : file,
                           where,
                           layer);
      }
    else
      throw InputError("The line '" + raw_line +
                         "' is not a 'set', 'subsection', 'end' or 'include' "
                         "line (" +
                         where + ").",
                       exit_unknown_entry);
  }

  void
  ParameterReader::read_included_file(const std::filesystem::path &file,
                                      const std::string           &where,
                                      Layer                       &layer)
  {
    const std::string name = file.lexically_normal().string();
    std::error_code   error;
    if (std::filesystem::is_directory(file, error))
      throw InputError("The included file <" + name + "> is a directory (" +
                         where + ").",
                       exit_cannot_read_file);
    std::ifstream in(file);
    if (!in)
      throw InputError("Cannot open the included file <" + name +
                         "> (include paths are relative to the including "
                         "file's folder) (" +
                         where + ").",
                       exit_cannot_read_file);
    const auto canonical = std::filesystem::weakly_canonical(file, error);
    if (std::find(open_files.begin(), open_files.end(), canonical) !=
        open_files.end())
      throw InputError("The file <" + name + "> includes itself (" + where +
                         ").",
                       exit_unknown_entry);
    open_files.push_back(canonical);
    read_stream(in, name, file.parent_path(), layer);
    open_files.pop_back();
  }

  void
  ParameterReader::enter(const std::string &subsection,
                         const std::string &where)
  {
    std::vector<std::string> subsections;
    for (const auto &[name, opened] : path)
      subsections.push_back(name);
    const Catalog::Section &section = catalog->at(subsections);
    if (section.subsections.count(subsection) == 0)
      {
        std::vector<std::string> names;
        for (const auto &[name, sub] : section.subsections)
          names.push_back(name);
        const std::string guess = closest_match(subsection, names);
        const std::string parent =
          subsections.empty() ? "" : " of " + join(subsections);
        throw InputError("<" + join(subsections, subsection) +
                           "> is not a subsection" + parent +
                           (guess.empty() ? "" :
                                            "; did you mean <" +
                                              join(subsections, guess) + ">?") +
                           " (" + where + ")",
                         exit_unknown_entry);
      }
    path.emplace_back(subsection, where);
  }

  void
  ParameterReader::assign(const std::vector<std::string> &subsections,
                          const std::string              &entry,
                          const std::string              &value,
                          const std::string              &where,
                          const std::filesystem::path    &folder,
                          Layer                          &layer)
  {
    const std::string       name    = join(subsections, entry);
    const Catalog::Section &section = catalog->at(subsections);
    const auto              it      = section.entries.find(entry);
    if (it == section.entries.end())
      {
        // a typo in this subsection, or the right name in the wrong one
        std::vector<std::string> names;
        for (const auto &[known, pattern] : section.entries)
          names.push_back(known);
        std::string guess = closest_match(entry, names);
        if (!guess.empty())
          guess = join(subsections, guess);
        else
          {
            std::vector<std::pair<std::string, std::string>> all;
            catalog->all_entries(catalog->root, "", all);
            std::vector<std::string> entry_names;
            for (const auto &[sub, known] : all)
              entry_names.push_back(known);
            const std::string match = closest_match(entry, entry_names);
            // the same name may be in several subsections: name them all
            for (const auto &[sub, known] : all)
              if (!match.empty() && known == match)
                guess += (guess.empty() ? "" : "> or <") + sub + "/" + known;
          }
        throw InputError("<" + name + "> is not an entry of " +
                           (subsections.empty() ?
                              "the top level (every entry is in a "
                              "subsection)" :
                              "subsection " + join(subsections)) +
                           (guess.empty() ? "" :
                                            "; did you mean <" + guess + ">?") +
                           " (" + where + ")",
                         exit_unknown_entry);
      }

    const auto earlier = layer.set_at.find(name);
    if (earlier != layer.set_at.end())
      throw InputError("<" + name + "> is set twice, at " + earlier->second +
                         " and at " + where +
                         (layer.is_scene ?
                            "; set each entry once (to try another value, "
                            "override it with --set)" :
                            "; override each entry once") +
                         ".",
                       exit_unknown_entry);

    const std::string out_of_range = number_out_of_range(value);
    if (!out_of_range.empty())
      throw InputError("Invalid value '" + value + "' for <" + name +
                         ">: the number " + out_of_range +
                         " is outside the range of double precision "
                         "(magnitudes from 2.2e-308 to 1.8e+308, or 0); "
                         "write 0, or rescale the units (" +
                         where + ").",
                       exit_invalid_value);
    for (const std::string &subsection : subsections)
      prm.enter_subsection(subsection);
    bool matches = true;
    try
      {
        prm.set(entry, value);
      }
    catch (const ParameterHandler::ExcValueDoesNotMatchPattern &)
      {
        matches = false;
      }
    for (std::size_t i = 0; i < subsections.size(); ++i)
      prm.leave_subsection();
    if (!matches)
      throw InputError("Invalid value '" + value + "' for <" + name +
                         ">: expected " + pattern_in_words(it->second.pattern) +
                         " (" + where + ").",
                       exit_invalid_value);
    layer.set_at[name]    = where;
    layer.folder_of[name] = folder;
  }
} // namespace dualcontact
