#include "format.h"

namespace dualcontact
{
  namespace report_format
  {
    std::size_t
    n_characters(const std::string &text)
    {
      return std::count_if(text.begin(), text.end(), [](const char c) {
        return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
      });
    }

    std::string
    count(const std::uint64_t n)
    {
      return std::to_string(n);
    }

    std::string
    scientific(const double x, const int digits)
    {
      std::ostringstream s;
      s << std::scientific << std::setprecision(digits) << x;
      return s.str();
    }

    std::string
    fixed(const double x, const int digits)
    {
      std::ostringstream s;
      s << std::fixed << std::setprecision(digits) << x;
      return s.str();
    }

    std::string
    significant(const double x, const int digits)
    {
      std::ostringstream s;
      s << std::setprecision(digits) << x;
      return s.str();
    }

    std::string
    seconds(const double t, const bool print_timing)
    {
      std::ostringstream s;
      if (print_timing)
        s << "  (" << std::fixed << std::setprecision(3) << t << " s)";
      return s.str();
    }

    std::string
    wrap(const std::string              &prefix,
         const std::vector<std::string> &items,
         const std::string              &separator,
         const std::string              &indent)
    {
      std::string punctuation = separator;
      while (!punctuation.empty() && punctuation.back() == ' ')
        punctuation.pop_back();
      std::string text, line = prefix;
      for (std::size_t i = 0; i < items.size(); ++i)
        {
          // room for the punctuation a break after this item would add
          const std::string room =
            i + 1 < items.size() ? punctuation : std::string();
          if (i == 0)
            line += items[i];
          else if (n_characters(line + separator + items[i] + room) <=
                   line_width)
            line += separator + items[i];
          else
            {
              text += line + punctuation + '\n';
              line = indent + items[i];
            }
        }
      return text + line + '\n';
    }

    std::string
    wrap_words(const std::string &prefix,
               const std::string &text,
               const std::string &indent)
    {
      std::vector<std::string> words;
      std::istringstream       in(text);
      for (std::string word; in >> word;)
        words.push_back(word);
      return wrap(prefix, words, " ", indent);
    }
  } // namespace report_format
} // namespace dualcontact
