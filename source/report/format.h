// The text helpers of the report (internal to source/report.cc and
// source/report/*.cc): numbers as the screen prints them, lines wrapped at
// line_width, and tables printed row by row.
#ifndef dualcontact_report_format_h
#define dualcontact_report_format_h

#include <algorithm>
#include <cstdint>
#include <functional>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace dualcontact
{
  namespace report_format
  {
    // No screen line is longer: a terminal or an editor shows it whole.
    constexpr std::size_t line_width = 120;

    /** Characters, not bytes: "§" is one. */
    std::size_t
    n_characters(const std::string &text);

    /** A count, as an integer. */
    std::string
    count(const std::uint64_t n);

    std::string
    scientific(const double x, const int digits = 2);

    std::string
    fixed(const double x, const int digits);

    /** With `digits` significant digits, as a result is printed. */
    std::string
    significant(const double x, const int digits = 8);

    /** " (1.234 s)" if `print_timing`, else nothing. */
    std::string
    seconds(const double t, const bool print_timing);

    /**
     * `prefix`, then the items joined by `separator`, as many lines as it
     * takes: a line breaks between two items (keeping the separator's
     * punctuation) where the next one would pass line_width, and goes on
     * after `indent`. Each line ends in '\n'.
     */
    std::string
    wrap(const std::string              &prefix,
         const std::vector<std::string> &items,
         const std::string              &separator,
         const std::string              &indent);

    /** A text wrapped at its blanks. */
    std::string
    wrap_words(const std::string &prefix,
               const std::string &text,
               const std::string &indent);

    /** One column of a table printed row by row: title, width, entry. */
    template <typename Row>
    struct Column
    {
      std::string                             title;
      std::size_t                             width;
      std::function<std::string(const Row &)> entry;

      /** At least one blank before the title. */
      std::size_t
      room() const
      {
        return std::max(width, title.size() + 1);
      }
    };

    /** `label`, then each column's title or entry right-aligned in it. */
    template <typename Row>
    std::string
    table_line(const std::string              &label,
               const std::vector<Column<Row>> &columns,
               const Row                      *row)
    {
      std::ostringstream line;
      line << label;
      // at least one blank between two columns, however wide an entry
      for (const Column<Row> &c : columns)
        line << ' ' << std::setw(c.room() - 1)
             << (row ? c.entry(*row) : c.title);
      return line.str() + '\n';
    }

    template <typename Row>
    std::size_t
    table_width(const std::string &label, const std::vector<Column<Row>> &c)
    {
      std::size_t width = label.size();
      for (const auto &column : c)
        width += column.room();
      return width;
    }
  } // namespace report_format
} // namespace dualcontact

#endif
