// The record of a checkpoint and the comparison of the parameters it was
// written with (checkpoint.h).
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <dualcontact/checkpoint.h>

#include <algorithm>
#include <boost/crc.hpp>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
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
    // (output/ gives output/checkpoint, not output//checkpoint: the path
    // is named in messages)
    return (std::filesystem::path(directory) / "checkpoint").string();
  }

  InputError
  damaged_checkpoint(const std::string &file, const std::string &what)
  {
    // (what may end with deal.II's period)
    const bool period = !what.empty() && what.back() == '.';
    return InputError("The checkpoint file " + file + " is damaged: " + what +
                        (period ? " " : ". ") +
                        "Resume from a whole copy of the folder "
                        "checkpoint/, or run the scene afresh without "
                        "--resume.",
                      exit_cannot_read_file);
  }

  std::string
  file_checksum(const std::string &file)
  {
    std::ifstream in(file, std::ios::binary);
    if (!in)
      return {};
    boost::crc_32_type crc;
    std::vector<char>  buffer(1 << 20);
    while (in)
      {
        in.read(buffer.data(), buffer.size());
        crc.process_bytes(buffer.data(), in.gcount());
      }
    if (in.bad())
      return {};
    std::ostringstream text;
    text << std::hex << std::setw(8) << std::setfill('0') << crc.checksum();
    return text.str();
  }

  bool
  read_number(const std::string &word, double &x)
  {
    if (word.empty() || std::isspace(static_cast<unsigned char>(word[0])))
      return false;
    char *end = nullptr;
    x         = std::strtod(word.c_str(), &end);
    return end == word.c_str() + word.size() && std::isfinite(x);
  }

  bool
  read_whole_number(const std::string &word, unsigned long long &n)
  {
    if (word.empty() || word.size() > 19 ||
        word.find_first_not_of("0123456789") != std::string::npos)
      return false;
    n = std::stoull(word);
    return true;
  }

  void
  CheckpointRecord::set(const std::string &key, const std::string &value)
  {
    Assert(!key.empty() && key.find_first_of(" \n") == std::string::npos &&
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
    if (found == values.end())
      throw damaged_checkpoint(name_of_file,
                               "it has no '" + key +
                                 "' (it was cut short, or written by "
                                 "another version of dualcontact)");
    taken.insert(key);
    return found->second;
  }

  double
  CheckpointRecord::number(const std::string &key, const double lowest) const
  {
    double x = 0.;
    if (!read_number(text(key), x))
      throw damaged(key, "not a finite number");
    if (x < lowest)
      {
        std::ostringstream bound;
        bound << lowest;
        throw damaged(key, "less than " + bound.str());
      }
    return x;
  }

  unsigned long long
  CheckpointRecord::whole_number(const std::string       &key,
                                 const unsigned long long lowest,
                                 const unsigned long long highest) const
  {
    unsigned long long n = 0;
    if (!read_whole_number(text(key), n))
      throw damaged(key, "not a whole number");
    if (n < lowest)
      throw damaged(key, "less than " + std::to_string(lowest));
    if (n > highest)
      throw damaged(key, "more than " + std::to_string(highest));
    return n;
  }

  std::vector<unsigned long long>
  CheckpointRecord::whole_numbers(const std::string &key,
                                  const std::size_t  n) const
  {
    const std::vector<std::string>  split = words(key);
    std::vector<unsigned long long> numbers(split.size());
    for (std::size_t i = 0; i < split.size(); ++i)
      if (!read_whole_number(split[i], numbers[i]))
        throw damaged(key, "not " + std::to_string(n) + " whole numbers");
    if (numbers.size() != n)
      throw damaged(key, "not " + std::to_string(n) + " whole numbers");
    return numbers;
  }

  std::vector<std::string>
  CheckpointRecord::words(const std::string &key) const
  {
    // every space separates: two in a row, or one at an end, give an
    // empty word, which no reader takes
    const std::string       &value = text(key);
    std::vector<std::string> split;
    std::size_t              begin = 0;
    for (std::size_t space;
         (space = value.find(' ', begin)) != std::string::npos;
         begin = space + 1)
      split.push_back(value.substr(begin, space - begin));
    split.push_back(value.substr(begin));
    return split;
  }

  std::map<std::string, std::string>
  CheckpointRecord::with_prefix(const std::string &prefix) const
  {
    std::map<std::string, std::string> found;
    for (auto entry = values.lower_bound(prefix);
         entry != values.end() &&
         entry->first.compare(0, prefix.size(), prefix) == 0;
         ++entry)
      {
        found.insert(*entry);
        taken.insert(entry->first);
      }
    return found;
  }

  InputError
  CheckpointRecord::damaged(const std::string &key,
                            const std::string &what) const
  {
    const auto  found = values.find(key);
    std::string value = found == values.end() ? "" : found->second;
    // (a long value is named by its beginning)
    if (value.size() > 60)
      value = value.substr(0, 60) + "...";
    return damaged_checkpoint(name_of_file,
                              "'" + key + "' is '" + printable(value) + "', " +
                                what);
  }

  void
  CheckpointRecord::check_all_taken() const
  {
    for (const auto &[key, value] : values)
      if (taken.count(key) == 0)
        throw damaged_checkpoint(name_of_file,
                                 "'" + printable(key) +
                                   "' is not a field of a checkpoint");
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
    name_of_file = filename;
    values.clear();
    taken.clear();
    std::ostringstream whole;
    whole << in.rdbuf();
    const std::string text = whole.str();
    // write() ends every line: a file that ends within one was cut short
    if (!text.empty() && text.back() != '\n')
      throw damaged_checkpoint(filename,
                               "its last line has no end (the file was cut "
                               "short)");
    std::istringstream lines(text);
    std::string        line;
    for (unsigned int number = 1; std::getline(lines, line); ++number)
      {
        const std::size_t space = line.find(' ');
        if (space == 0 || space == std::string::npos)
          throw damaged_checkpoint(filename,
                                   "line " + std::to_string(number) + " ('" +
                                     printable(line.substr(0, 60)) +
                                     "') is not 'key value'");
        if (!values.emplace(line.substr(0, space), line.substr(space + 1))
               .second)
          throw damaged_checkpoint(filename,
                                   "line " + std::to_string(number) +
                                     " gives '" +
                                     printable(line.substr(0, space)) +
                                     "' a second time");
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
  first_difference(const std::string              &now,
                   const std::string              &saved,
                   const std::set<std::string>    &ignored,
                   const std::vector<std::string> &first)
  {
    auto                               entries_now = entries_of(now);
    std::map<std::string, std::string> entries_saved;
    for (const auto &[name, value] : entries_of(saved))
      entries_saved[name] = value;
    // (a stable partition keeps the others in their order)
    const auto rank = [&first](const std::string &name) {
      return std::find(first.begin(), first.end(), name) - first.begin();
    };
    std::stable_sort(entries_now.begin(),
                     entries_now.end(),
                     [&rank](const auto &a, const auto &b) {
                       return rank(a.first) < rank(b.first);
                     });
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
