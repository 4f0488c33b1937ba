// Entry declaration: every entry of the parameters, the registered plugins'
// included, is declared through EntryDeclarer (so that ParameterReader can
// say what it expects), and each kind of pattern reads in words.
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <dualcontact/entry_declaration.h>
#include <dualcontact/parameters.h>

#include <catch2/catch.hpp>

#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace dualcontact;
using dealii::ParameterHandler;

namespace
{
  /**
   * Every entry the handler holds, as "Subsection/Entry" -> value, read
   * from its listing in the short .prm form ("subsection", "set", "end").
   */
  std::map<std::string, std::string>
  handler_entries(const ParameterHandler &prm)
  {
    std::ostringstream listing;
    prm.print_parameters(listing, ParameterHandler::ShortPRM);
    std::istringstream                 in(listing.str());
    std::vector<std::string>           path;
    std::map<std::string, std::string> entries;
    std::string                        line;
    while (std::getline(in, line))
      {
        line = dealii::Utilities::trim(line);
        if (line.rfind("subsection ", 0) == 0)
          path.push_back(line.substr(11));
        else if (line == "end")
          path.pop_back();
        else if (line.rfind("set ", 0) == 0)
          {
            const std::size_t equals = line.find('=');
            std::string       name;
            for (const std::string &subsection : path)
              name += subsection + "/";
            name += dealii::Utilities::trim(line.substr(4, equals - 4));
            entries[name] = dealii::Utilities::trim(line.substr(equals + 1));
          }
      }
    return entries;
  }
} // namespace

TEST_CASE("Every entry, the registered plugins' too, is declared through "
          "EntryDeclarer, with its default and its pattern in words",
          "[parameters]")
{
  ParameterHandler prm;
  EntryDeclarer    declarer(prm);
  Parameters::declare_parameters(declarer);

  std::map<std::string, std::string> catalogued;
  for (const auto &[key, entry] : declarer.catalog().entries())
    {
      std::string name;
      for (const std::string &subsection : key.first)
        name += subsection + "/";
      name += key.second;
      catalogued[name] = entry.default_value;
      INFO(name << ": " << entry.words);
      // words, not deal.II's pattern text ("[Double 0...1 (inclusive)]")
      CHECK(!entry.words.empty());
      CHECK(entry.words.find('[') == std::string::npos);
    }

  // an entry declared on the handler alone would be missing here
  CHECK(handler_entries(prm) == catalogued);
  CHECK(catalogued.size() > 60);
  // the library's plugins and those this test program registers
  CHECK(catalogued.count("Foundation/Normal") == 1);
  CHECK(catalogued.count("Friction/Coefficient") == 1);
  CHECK(catalogued.count("Refinement/Contact indicator weight") == 1);
  CHECK(catalogued.count("Obstacle/Floor height") == 1);
}

TEST_CASE("The subsections and entries of the catalog, as the reader asks "
          "for them",
          "[parameters]")
{
  ParameterHandler prm;
  EntryDeclarer    declarer(prm);
  declarer.enter_subsection("B");
  declarer.declare_entry("y", "1", EntryPattern::whole_number(), "");
  declarer.enter_subsection("C");
  declarer.declare_entry("z", "", EntryPattern::text(), "");
  declarer.leave_subsection();
  declarer.declare_entry("x", "0.5", EntryPattern::number(0., 1.), "");
  declarer.leave_subsection();
  declarer.enter_subsection("A");
  declarer.declare_entry("w", "true", EntryPattern::boolean(), "");
  declarer.leave_subsection();

  const EntryCatalog &catalog = declarer.catalog();
  CHECK(catalog.subsection_names({}) == std::vector<std::string>{"A", "B"});
  CHECK(catalog.subsection_names({"B"}) == std::vector<std::string>{"C"});
  CHECK(catalog.entry_names({"B"}) == std::vector<std::string>{"x", "y"});
  REQUIRE(catalog.find({"B"}, "x") != nullptr);
  CHECK(catalog.find({"B"}, "x")->default_value == "0.5");
  CHECK(catalog.find({"B"}, "x")->words == "a number from 0 to 1");
  CHECK(catalog.find({"B"}, "z") == nullptr);
  CHECK(catalog.find({"B", "C"}, "z") != nullptr);

  // a subsection's own entries first, then those of its subsections
  std::vector<std::string> order;
  for (const auto &[key, entry] : catalog.entries())
    order.push_back(key.second);
  CHECK(order == std::vector<std::string>{"w", "x", "y", "z"});

  prm.enter_subsection("B");
  CHECK(prm.get_double("x") == 0.5);
  prm.leave_subsection();
}

TEST_CASE("Each kind of pattern reads in words", "[parameters]")
{
  using P = EntryPattern;
  CHECK(P::number().words() == "a number");
  CHECK(P::number(-1., 0.5).words() == "a number from -1 to 0.5");
  CHECK(P::number(0.).words() == "a number >= 0");
  CHECK(P::number(1e-14, 1.).words() == "a number from 1e-14 to 1");
  CHECK(P::number(-2e300, 1e12).words() == "a number from -2e+300 to 1e+12");
  CHECK(P::whole_number().words() == "a whole number");
  CHECK(P::whole_number(1).words() == "a whole number >= 1");
  CHECK(P::whole_number(1, 30).words() == "a whole number from 1 to 30");
  CHECK(P::whole_number(2, 3).words() == "a whole number: 2 or 3");
  CHECK(P::selection("none|given|coulomb").words() ==
        "one of: none, given, coulomb");
  CHECK(P::boolean().words() == "true or false");
  CHECK(P::text().words() == "any text");
  CHECK(P::file_name().words() == "a file name");
  CHECK(P::folder_name().words() == "a folder name");
  CHECK(P::list(P::whole_number(1), 2, 3).words() ==
        "a comma-separated list of 2 or 3 whole numbers >= 1");
  CHECK(P::list(P::number(), 0, 3).words() ==
        "a comma-separated list of 0 to 3 numbers");
  CHECK(P::list(P::number(), 3, 3).words() ==
        "a comma-separated list of 3 numbers");
  CHECK(P::list(P::boolean(), 1).words() ==
        "a comma-separated list of at least 1 each true or false");
  CHECK(P::list(P::list(P::number(), 2, 3),
                0,
                dealii::Patterns::List::max_int_value,
                ";")
          .words() == "a semicolon-separated list of comma-separated lists "
                      "of 2 or 3 numbers");
  CHECK(P::map(P::whole_number(0, 255), P::selection("free|fixed")).words() ==
        "a comma-separated list of 'key: value' pairs (each key a whole "
        "number from 0 to 255, each value one of: free, fixed)");

  // the deal.II pattern is the one the words describe
  CHECK(P::number(-1., 0.5).pattern().description() ==
        dealii::Patterns::Double(-1., 0.5).description());
  CHECK(P::list(P::whole_number(1), 2, 3).pattern().match("2, 4"));
  CHECK(!P::list(P::whole_number(1), 2, 3).pattern().match("0, 4"));
}
