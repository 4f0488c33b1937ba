#include <deal.II/base/utilities.h>

#include <dualcontact/input_error.h>
#include <dualcontact/parameter_reader.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <utility>

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

  /** The entries set by one layer (the scene, or the overrides). */
  struct ParameterReader::Layer
  {
    bool                               is_scene;
    std::map<std::string, std::string> set_at; // "Sub/Entry" -> where
    // "Sub/Entry" -> folder of the file that set it
    std::map<std::string, std::filesystem::path> folder_of;
  };

  ParameterReader::ParameterReader(ParameterHandler &prm, EntryCatalog catalog)
      : prm(prm)
      , catalog(std::move(catalog))
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
        if (value != catalog.find(path, entry)->default_value)
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
    const std::vector<std::string> names =
      catalog.subsection_names(subsections);
    if (std::find(names.begin(), names.end(), subsection) == names.end())
      {
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
    const std::string          name     = join(subsections, entry);
    const EntryCatalog::Entry *declared = catalog.find(subsections, entry);
    if (declared == nullptr)
      {
        // a typo in this subsection, or the right name in the wrong one
        std::string guess =
          closest_match(entry, catalog.entry_names(subsections));
        if (!guess.empty())
          guess = join(subsections, guess);
        else
          {
            std::vector<std::string> names;
            for (const auto &[place, known] : catalog.entries())
              names.push_back(place.second);
            const std::string match = closest_match(entry, names);
            // the same name may be in several subsections: name them all
            for (const auto &[place, known] : catalog.entries())
              if (!match.empty() && place.second == match)
                guess += (guess.empty() ? "" : "> or <") +
                         join(place.first, place.second);
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
                         ">: expected " + declared->words + " (" + where + ").",
                       exit_invalid_value);
    layer.set_at[name]    = where;
    layer.folder_of[name] = folder;
  }
} // namespace dualcontact
