// What the files of the parameter subsections (source/parameters/) share:
// reading numbers from entry values, and the words of their messages.
#ifndef dualcontact_parameter_helpers_h
#define dualcontact_parameter_helpers_h

#include <string>
#include <vector>

namespace dualcontact
{
  /** The numbers of a comma-separated entry value. */
  std::vector<double>
  parse_doubles(const std::string &text);

  /**
   * The value of an entry that takes 'auto' or a number > 0: 0 for 'auto',
   * else the number; InputError (exit 5) otherwise: "The entry <entry> must
   * be 'auto' or a positive number, not 'value'."
   */
  double
  parse_auto_or_positive(const std::string &value, const std::string &entry);

  /** A number as the user would write it (0, -1, 2.5). */
  std::string
  number_text(const double x);

  /**
   * InputError (exit 6) unless `values` has `n` of them, one per dimension:
   * "The entry <entry> needs n values (one per dimension), not m."
   */
  void
  need_values(const std::vector<double> &values,
              const std::string         &entry,
              unsigned int               n);

  /**
   * InputError (exit 5) unless |x| lies in 1e-100 to 1e100, where the
   * solver's squares and products of it stay normal doubles: "The entry
   * <entry> = x is outside the magnitudes ... unit ...: use other units
   * (example)."
   */
  void
  check_magnitude(double             x,
                  const std::string &entry,
                  const std::string &unit,
                  const std::string &example);

  /** 'value' */
  std::string
  quoted(const std::string &value);

  /** `open`a`close`, `open`b`close` and `open`c`close`: <a>, <b> and <c> */
  std::string
  listed(const std::vector<std::string> &names,
         const std::string              &open,
         const std::string              &close);

  /** 'a', 'b' and 'c' */
  std::string
  quoted_list(const std::vector<std::string> &names);
} // namespace dualcontact

#endif
