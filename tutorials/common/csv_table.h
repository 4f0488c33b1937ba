// A CSV file as the library writes them (cycles.csv, contact_NN.csv,
// contact_step_NNN.csv), read into its rows and looked up by column name,
// the way a user's script would: the one reader of the steps that compare
// the library's files with their formulas (steps 6, 7, 10 and 11).
//
// Header-only, as tutorial_tools.h (which includes it): a step stays one
// program that builds with the library alone.
#ifndef dualcontact_tutorial_csv_table_h
#define dualcontact_tutorial_csv_table_h

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace dualcontact
{
  namespace tutorial
  {
    /**
     * A CSV file as the library writes them (cycles.csv, contact_NN.csv):
     * a header line of column names, then rows of cells, read by column
     * name the way a user's script would.
     */
    class CsvTable
    {
    public:
      explicit CsvTable(const std::string &filename)
          : filename(filename)
      {
        std::ifstream in(filename);
        if (!in)
          throw std::runtime_error("cannot read " + filename);
        std::string line;
        std::getline(in, line);
        names = split(line);
        while (std::getline(in, line))
          if (!line.empty())
            {
              cells.push_back(split(line));
              if (cells.back().size() != names.size())
                throw std::runtime_error(filename + ": a row of " +
                                         std::to_string(cells.back().size()) +
                                         " cells under a header of " +
                                         std::to_string(names.size()));
            }
      }

      unsigned int
      n_rows() const
      {
        return cells.size();
      }

      /** The cell of row `i` in the column `name`, as text. */
      const std::string &
      text(const unsigned int i, const std::string &name) const
      {
        return cells.at(i)[column(name)];
      }

      /** The cell of row `i` in the column `name`, as a number. */
      double
      number(const unsigned int i, const std::string &name) const
      {
        return std::stod(text(i, name));
      }

    private:
      std::string                           filename;
      std::vector<std::string>              names;
      std::vector<std::vector<std::string>> cells;

      unsigned int
      column(const std::string &name) const
      {
        const auto it = std::find(names.begin(), names.end(), name);
        if (it == names.end())
          throw std::runtime_error("no column '" + name + "' in " + filename);
        return it - names.begin();
      }

      static std::vector<std::string>
      split(const std::string &line)
      {
        std::vector<std::string> cells;
        std::istringstream       s(line);
        for (std::string cell; std::getline(s, cell, ',');)
          cells.push_back(cell);
        return cells;
      }
    };
  } // namespace tutorial
} // namespace dualcontact

#endif
