// AppendedCsvFile: a CSV file that grows a row at a time.
#include <dualcontact/report.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace dualcontact
{
  namespace
  {
    /** The fields of one line of CSV (no field holds a comma). */
    std::vector<std::string>
    fields_of(const std::string &line)
    {
      std::vector<std::string> fields;
      std::istringstream       in(line);
      std::string              field;
      while (std::getline(in, field, ','))
        fields.push_back(field);
      if (!line.empty() && line.back() == ',')
        fields.emplace_back();
      return fields;
    }
  } // namespace

  void
  keep_rows_up_to(const std::string &filename,
                  const std::string &column,
                  const double       last)
  {
    std::vector<std::string> lines;
    {
      std::ifstream in(filename);
      std::string   line;
      while (std::getline(in, line))
        lines.push_back(line);
    }
    if (lines.empty())
      return;
    const std::vector<std::string> header = fields_of(lines.front());
    const auto where = std::find(header.begin(), header.end(), column);
    if (where == header.end())
      return;
    const std::size_t c = where - header.begin();
    std::ofstream     out(filename, std::ios::trunc);
    out << lines.front() << '\n';
    for (std::size_t l = 1; l < lines.size(); ++l)
      {
        const std::vector<std::string> fields = fields_of(lines[l]);
        // a line cut short by a stopped run has fewer fields: it goes
        if (fields.size() == header.size() && std::stod(fields[c]) <= last)
          out << lines[l] << '\n';
      }
  }

  void
  AppendedCsvFile::resume(const std::string &filename,
                          const unsigned int last_step)
  {
    file.close();
    name_of_file = filename;
    keep_rows_up_to(filename, "step", last_step);
    std::ifstream in(filename);
    std::string   header;
    std::getline(in, header);
    columns = fields_of(header);
    file.open(filename, std::ios::app);
  }

  void
  AppendedCsvFile::open(const std::string &filename)
  {
    file.close();
    name_of_file = filename;
    columns.clear();
  }

  void
  AppendedCsvFile::add_rows(const std::vector<Row> &rows)
  {
    if (rows.empty())
      return;
    if (!file.is_open())
      {
        // the first rows: the header is the first row's columns
        file.open(name_of_file, std::ios::trunc);
        for (const auto &[key, text] : rows.front())
          columns.push_back(key);
        for (std::size_t c = 0; c < columns.size(); ++c)
          file << (c > 0 ? "," : "") << columns[c];
        file << '\n';
      }
    const std::size_t old_size = columns.size();
    for (const Row &row : rows)
      for (const auto &[key, text] : row)
        if (std::find(columns.begin(), columns.end(), key) == columns.end())
          columns.push_back(key);
    if (columns.size() > old_size)
      rewrite_with_columns(old_size);

    for (const Row &row : rows)
      {
        std::vector<std::string> line(columns.size());
        for (const auto &[key, text] : row)
          line[std::find(columns.begin(), columns.end(), key) -
               columns.begin()] = text;
        for (std::size_t c = 0; c < line.size(); ++c)
          file << (c > 0 ? "," : "") << line[c];
        file << '\n';
      }
    file.flush();
  }

  void
  AppendedCsvFile::rewrite_with_columns(const std::size_t old_size)
  {
    file.close();
    const std::string temporary = name_of_file + ".new";
    {
      std::ifstream in(name_of_file);
      std::ofstream out(temporary, std::ios::trunc);
      std::string   line;
      std::getline(in, line); // the old header
      for (std::size_t c = 0; c < columns.size(); ++c)
        out << (c > 0 ? "," : "") << columns[c];
      out << '\n';
      while (std::getline(in, line))
        {
          std::vector<std::string> fields = fields_of(line);
          fields.resize(old_size);
          fields.resize(columns.size());
          for (std::size_t c = 0; c < fields.size(); ++c)
            out << (c > 0 ? "," : "") << fields[c];
          out << '\n';
        }
    }
    std::rename(temporary.c_str(), name_of_file.c_str());
    file.open(name_of_file, std::ios::app);
  }
} // namespace dualcontact
