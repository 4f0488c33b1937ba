// The record of a checkpoint and the comparison of the parameters it was
// written with (checkpoint.h).
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <dualcontact/checkpoint.h>

#include <fstream>
#include <iomanip>
#include <sstream>
#include <utility>
#include <vector>

namespace dualcontact
{
  std::string
  checkpoint_folder(const std::string &directory)
  {
    return directory + "/checkpoint";
  }

  void
  CheckpointRecord::set(const std::string &key, const std::string &value)
  {
    Assert(key.find_first_of(" \n") == std::string::npos &&
             value.find('\n') == std::string::npos,
           dealii::ExcMessage("A checkpoint's key is one word, its value one "
                              "line."));
    values[key] = value;
  }

  void
  CheckpointRecord::set(const std::string &key, const double value)
  {
    std::ostringstream text;
    text << std::setprecision(17) << value;
    set(key, text.str());
  }

  const std::string &
  CheckpointRecord::text(const std::string &key) const
  {
    const auto found = values.find(key);
    AssertThrow(found != values.end(),
                dealii::ExcMessage("The checkpoint's state.txt has no '" + key +
                                   "': it was not written by this version "
                                   "of dualcontact, or not completely."));
    return found->second;
  }

  double
  CheckpointRecord::number(const std::string &key) const
  {
    return std::stod(text(key));
  }

  std::map<std::string, std::string>
  CheckpointRecord::with_prefix(const std::string &prefix) const
  {
    std::map<std::string, std::string> found;
    for (auto entry = values.lower_bound(prefix);
         entry != values.end() &&
         entry->first.compare(0, prefix.size(), prefix) == 0;
         ++entry)
      found.insert(*entry);
    return found;
  }

  void
  CheckpointRecord::write(const std::string &filename) const
  {
    std::ofstream out(filename);
    for (const auto &[key, value] : values)
      out << key << ' ' << value << '\n';
    AssertThrow(out, dealii::ExcMessage("Cannot write " + filename + "."));
  }

  bool
  CheckpointRecord::read(const std::string &filename)
  {
    std::ifstream in(filename);
    if (!in)
      return false;
    values.clear();
    std::string line;
    while (std::getline(in, line))
      {
        const std::size_t space = line.find(' ');
        if (space != std::string::npos)
          values[line.substr(0, space)] = line.substr(space + 1);
      }
    return true;
  }

  namespace
  {
    /**
     * The entries of a PRM listing, "Subsection/Entry" -> value, in their
     * order.
     */
    std::vector<std::pair<std::string, std::string>>
    entries_of(const std::string &listing)
    {
      std::vector<std::pair<std::string, std::string>> entries;
      std::vector<std::string>                         path;
      std::istringstream                               in(listing);
      std::string                                      line;
      while (std::getline(in, line))
        {
          line = dealii::Utilities::trim(line.substr(0, line.find('#')));
          if (line.compare(0, 11, "subsection ") == 0)
            path.push_back(dealii::Utilities::trim(line.substr(11)));
          else if (line == "end" && !path.empty())
            path.pop_back();
          else if (line.compare(0, 4, "set ") == 0)
            {
              const std::size_t equal = line.find('=');
              std::string       name;
              for (const std::string &part : path)
                name += part + "/";
              name += dealii::Utilities::trim(line.substr(4, equal - 4));
              entries.emplace_back(name,
                                   equal == std::string::npos ?
                                     std::string() :
                                     dealii::Utilities::trim(
                                       line.substr(equal + 1)));
            }
        }
      return entries;
    }
  } // namespace

  std::string
  first_difference(const std::string           &now,
                   const std::string           &saved,
                   const std::set<std::string> &ignored)
  {
    const auto                         entries_now = entries_of(now);
    std::map<std::string, std::string> entries_saved;
    for (const auto &[name, value] : entries_of(saved))
      entries_saved[name] = value;
    for (const auto &[name, value] : entries_now)
      {
        if (ignored.count(name))
          continue;
        const auto found = entries_saved.find(name);
        if (found == entries_saved.end())
          return "<" + name + "> is '" + value +
                 "' in the scene and not in the checkpoint";
        if (found->second != value)
          return "<" + name + "> is '" + value + "' in the scene and '" +
                 found->second + "' in the checkpoint";
        entries_saved.erase(found);
      }
    for (const auto &[name, value] : entries_saved)
      if (!ignored.count(name))
        return "<" + name + "> is '" + value +
               "' in the checkpoint and not in the scene";
    return {};
  }
} // namespace dualcontact
