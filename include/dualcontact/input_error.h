// Errors in the user's input, and the exit status each kind ends the program
// with.
#ifndef dualcontact_input_error_h
#define dualcontact_input_error_h

#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>

namespace dualcontact
{
  /**
   * Exit status of the program `dualcontact`. Every kind of bad input has its
   * own code so that scripts (and the tests) can tell them apart.
   */
  enum ExitCode : int
  {
    exit_success          = 0,
    exit_runtime_failure  = 1, // a solver failed, an internal error
    exit_usage            = 2, // wrong command line
    exit_cannot_read_file = 3, // parameter file missing or unreadable
    exit_unknown_entry    = 4, // unknown entry/subsection, malformed line
    exit_invalid_value  = 5, // a value that does not match its pattern or range
    exit_inconsistent   = 6, // entries that contradict each other
    exit_no_equilibrium = 7  // a load the foundation cannot hold
  };

  /**
   * Thrown for anything wrong with the input: the message names the entry or
   * the cause in one sentence, the exit code says which kind of error it is.
   * Thrown before any output file is written.
   */
  class InputError : public std::runtime_error
  {
  public:
    InputError(const std::string &message, const ExitCode code)
        : std::runtime_error(message)
        , code(code)
    {}

    const ExitCode code;
  };

  /**
   * `text` with its control characters written as escapes ("\r", "\t",
   * "\x1b"), so that a message that quotes the input stays one line on
   * the terminal whatever bytes the input holds.
   */
  inline std::string
  printable(const std::string &text)
  {
    std::ostringstream out;
    for (const char c : text)
      {
        const auto byte = static_cast<unsigned char>(c);
        if (c == '\r')
          out << "\\r";
        else if (c == '\n')
          out << "\\n";
        else if (c == '\t')
          out << "\\t";
        else if (byte < 0x20 || byte == 0x7f)
          out << "\\x" << std::hex << std::setw(2) << std::setfill('0')
              << static_cast<unsigned int>(byte) << std::dec;
        else
          out << c;
      }
    return out.str();
  }

  /**
   * The message of `exception` for one line of an error: of deal.II's, the
   * text after "Additional information:" without the stack trace; its
   * lines joined, the rules of dashes left out, at most 300 characters.
   */
  inline std::string
  exception_message(const std::exception &exception)
  {
    std::string what = exception.what();
    const auto  info = what.find("Additional information:");
    if (info != std::string::npos)
      what = what.substr(info + 23);
    const auto trace = what.find("Stacktrace:");
    if (trace != std::string::npos)
      what = what.substr(0, trace);
    std::string        line;
    std::istringstream lines(what);
    std::string        message;
    while (std::getline(lines, line))
      if (!line.empty() && line.find_first_not_of(" \t-") != std::string::npos)
        message += (message.empty() ? "" : " ") +
                   line.substr(line.find_first_not_of(" \t"));
    if (message.size() > 300)
      message = message.substr(0, 300) + "...";
    return message;
  }

  /**
   * A number for a message, in scientific notation with three significant
   * digits (std::to_string writes 1e-10 as 0.000000).
   */
  inline std::string
  format_number(const double x)
  {
    std::ostringstream s;
    s << std::scientific << std::setprecision(2) << x;
    return s.str();
  }
} // namespace dualcontact

#endif
