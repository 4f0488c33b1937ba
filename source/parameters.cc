// The parameters as a whole: the subsections in their order, reading a file
// or a text, the 3D defaults, the checks in their order, and the helpers the
// subsections share. Each subsection has its own file in source/parameters/
// (<Obstacle> in source/obstacle.cc).
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <dualcontact/geometry.h>
#include <dualcontact/input_error.h>
#include <dualcontact/obstacle.h>
#include <dualcontact/parameter_helpers.h>
#include <dualcontact/parameter_reader.h>
#include <dualcontact/parameters.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <sstream>

namespace dualcontact
{
  using namespace dealii;

  // ------------------------------------------------------------ helpers

  std::vector<double>
  parse_doubles(const std::string &text)
  {
    return Utilities::string_to_double(Utilities::split_string_list(text, ','));
  }

  double
  parse_auto_or_positive(const std::string &text, const std::string &entry)
  {
    const std::string value = dealii::Utilities::trim(text);
    if (value == "auto")
      return 0.;
    char        *end    = nullptr;
    const double number = std::strtod(value.c_str(), &end);
    if (value.empty() || *end != '\0' || !std::isfinite(number) ||
        !(number > 0.))
      throw InputError("The entry <" + entry +
                         "> must be 'auto' or a positive number, not '" +
                         value + "'.",
                       exit_invalid_value);
    return number;
  }

  std::string
  number_text(const double x)
  {
    std::ostringstream out;
    out << x;
    return out.str();
  }

  void
  need_values(const std::vector<double> &values,
              const std::string         &entry,
              const unsigned int         n)
  {
    if (values.size() != n)
      throw InputError("The entry <" + entry + "> needs " + std::to_string(n) +
                         " values (one per dimension), not " +
                         std::to_string(values.size()) + ".",
                       exit_inconsistent);
  }

  void
  check_magnitude(const double       x,
                  const std::string &entry,
                  const std::string &unit,
                  const std::string &example)
  {
    // The solver scales E and the lengths out (r, chi and the tolerances
    // are relative to them), so the units do not matter, within the range
    // where their squares and products stay normal doubles.
    if (!(std::abs(x) >= 1e-100 && std::abs(x) <= 1e100))
      throw InputError("The entry <" + entry + "> = " + format_number(x) +
                         " is outside the magnitudes 1e-100 to 1e100 " + unit +
                         " that the solver's products of it can "
                         "represent: use other units (" +
                         example + ").",
                       exit_invalid_value);
  }

  std::string
  quoted(const std::string &value)
  {
    return "'" + value + "'";
  }

  std::string
  listed(const std::vector<std::string> &names,
         const std::string              &open,
         const std::string              &close)
  {
    std::string text;
    for (std::size_t i = 0; i < names.size(); ++i)
      text += std::string(i == 0                ? "" :
                          i + 1 == names.size() ? " and " :
                                                  ", ") +
              open + names[i] + close;
    return text;
  }

  std::string
  quoted_list(const std::vector<std::string> &names)
  {
    return listed(names, "'", "'");
  }

  bool
  is_zero_expression(const std::string &expression)
  {
    for (const std::string &component :
         Utilities::split_string_list(expression, ';'))
      {
        try
          {
            std::size_t  used  = 0;
            const double value = std::stod(component, &used);
            if (used != component.size() || value != 0.)
              return false;
          }
        catch (const std::exception &)
          {
            return false;
          }
      }
    return true;
  }

  std::set<std::string>
  identifiers(const std::string &expression)
  {
    // a letter or '_', then letters, digits and '_' (a number's exponent,
    // as in 1e-3, is not one)
    std::set<std::string> words;
    std::string           word;
    bool                  in_number = false;
    for (const char c : expression + " ")
      {
        const bool letter =
          std::isalpha(static_cast<unsigned char>(c)) || c == '_';
        const bool digit =
          std::isdigit(static_cast<unsigned char>(c)) || c == '.';
        if (word.empty() && !in_number && letter)
          word += c;
        else if (!word.empty() && (letter || digit))
          word += c;
        else if (word.empty() && (digit || (in_number && letter)))
          in_number = true;
        else
          {
            if (!word.empty())
              words.insert(word);
            word.clear();
            in_number = digit;
          }
      }
    return words;
  }

  bool
  uses_coordinates(const std::string &expression, const unsigned int dim)
  {
    const std::set<std::string> words = identifiers(expression);
    return words.count("x") || words.count("y") ||
           (dim == 3 && words.count("z"));
  }

  bool
  uses_time(const std::string &expression)
  {
    return identifiers(expression).count("t") > 0;
  }

  // ------------------------------------------------------------ Parameters

  void
  Parameters::declare_parameters(EntryDeclarer &declarer)
  {
    GeometryParameters::declare_parameters(declarer);
    MaterialParameters::declare_parameters(declarer);
    BoundaryParameters::declare_parameters(declarer);
    LoadParameters::declare_parameters(declarer);
    ObstacleParameters::declare_parameters(declarer);
    FrictionParameters::declare_parameters(declarer);
    DiscretizationParameters::declare_parameters(declarer);
    SolverParameters::declare_parameters(declarer);
    RefinementParameters::declare_parameters(declarer);
    OutputParameters::declare_parameters(declarer);
    ExactSolutionParameters::declare_parameters(declarer);
    LoadPathParameters::declare_parameters(declarer);
  }

  void
  Parameters::parse_parameters(ParameterHandler &prm)
  {
    geometry.parse_parameters(prm);
    material.parse_parameters(prm);
    boundary.parse_parameters(prm);
    loads.parse_parameters(prm);
    obstacle.parse_parameters(prm);
    friction.parse_parameters(prm);
    discretization.parse_parameters(prm);
    solver.parse_parameters(prm);
    refinement.parse_parameters(prm);
    output.parse_parameters(prm);
    exact.parse_parameters(prm);
    load_path.parse_parameters(prm);
    check_consistency();
  }

  void
  Parameters::read_file(const std::string              &filename,
                        const std::vector<std::string> &overrides)
  {
    ParameterHandler prm;
    EntryDeclarer    declarer(prm);
    declare_parameters(declarer);
    ParameterReader reader(prm, declarer.catalog());
    reader.read_file(filename);
    // A file without a single 'set' line (in it or in a file it includes)
    // is empty, or only comments: every entry would keep its default, which
    // is never meant.
    if (!reader.scene_has_entries())
      throw InputError("The parameter file <" + filename +
                         "> has no entries (no 'set' line): it is empty or "
                         "holds only comments.",
                       exit_cannot_read_file);
    std::string source = filename;
    for (const std::string &assignment : overrides)
      {
        reader.set_override(assignment);
        source += " --set \"" + assignment + "\"";
      }
    use(prm, reader);
    parameter_file = "# The parameters of a dualcontact run: " + source + "\n" +
                     parameter_file;
  }

  void
  Parameters::read_string(const std::string &text, const std::string &overlay)
  {
    ParameterHandler prm;
    EntryDeclarer    declarer(prm);
    declare_parameters(declarer);
    ParameterReader reader(prm, declarer.catalog());
    reader.read_text(text, "parameters");
    if (!overlay.empty())
      reader.read_overlay(overlay, "overlay");
    use(prm, reader);
  }

  namespace
  {
    // The points and vectors whose declared defaults are 2D, with their 3D
    // defaults: in a 3D scene an entry it does not give takes these, so
    // that a 3D scene states only what differs (a foundation z = 0 with
    // the normal +z, the unit cube, shapes about the origin, no body force).
    // Set into the handler, so that the listing (parameters.prm) repeats the
    // run. An entry the scene sets keeps its value, even one equal to the 2D
    // default: its count of values is then checked like any other's.
    void
    apply_3d_defaults(ParameterHandler &prm, const std::set<std::string> &set)
    {
      prm.enter_subsection("Geometry");
      const bool three = prm.get_integer("Dimension") == 3;
      prm.leave_subsection();
      if (!three)
        return;
      const std::vector<std::array<std::string, 3>> defaults = {
        {{"Loads", "Body force", "0; 0; 0"}}};
      std::vector<std::array<std::string, 3>> all = defaults;
      for (const std::string &name : geometry_names())
        for (const auto &entry : geometry_kind(name).defaults_3d)
          if (std::find(all.begin(), all.end(), entry) == all.end())
            all.push_back(entry);
      for (const std::string &name : obstacle_names())
        for (const auto &entry : obstacle_kind(name).defaults_3d)
          if (std::find(all.begin(), all.end(), entry) == all.end())
            all.push_back(entry);
      for (const auto &[subsection, entry, value] : all)
        if (set.count(subsection + "/" + entry) == 0)
          {
            prm.enter_subsection(subsection);
            prm.set(entry, value);
            prm.leave_subsection();
          }
    }
  } // namespace

  void
  Parameters::use(ParameterHandler &prm, const ParameterReader &reader)
  {
    given = reader.given_entries();
    // <Geometry/Mesh file> is relative to the folder of the file that set
    // it (an override: the working directory). The listing (parameters.prm
    // in the output folder) gets the absolute path, so that it repeats the
    // run from wherever it is.
    prm.enter_subsection("Geometry");
    const std::string mesh_file_given = prm.get("Mesh file");
    if (!mesh_file_given.empty())
      {
        std::filesystem::path file(mesh_file_given);
        if (file.is_relative())
          file = reader.folder_of("Geometry/Mesh file") / file;
        prm.set("Mesh file",
                std::filesystem::absolute(file).lexically_normal().string());
      }
    prm.leave_subsection();
    apply_3d_defaults(prm, reader.set_entries());
    std::ostringstream out;
    prm.print_parameters(out, ParameterHandler::PRM);
    parameter_file = out.str();
    parse_parameters(prm);
    geometry.mesh_file_given = mesh_file_given;
  }

  void
  Parameters::check_magnitudes() const
  {
    material.check_magnitudes();
    geometry.check_magnitudes();
  }

  void
  Parameters::check_consistency() const
  {
    // in this order: the first error found is the one reported, and the
    // tests in tests/prm/bad/ hold it
    output.check(*this);
    geometry.check(*this); // with check_magnitudes() once the sizes are right
    boundary.check(*this);
    obstacle.check(*this);
    friction.check(*this);
    load_path.check(*this);
    // last: without contact, a friction law is the more direct cause
    geometry.check_pre_refinement(*this);
    if (geometry.cell_kind == CellKind::simplex)
      GeometryParameters::check_simplices(*this,
                                          "<Geometry/Cell type> is 'simplex'");
    // the mixed formulation's pair of elements must be stable
    if (material.formulation == Formulation::mixed)
      {
        const std::string refusal =
          mixed_pair_refusal(geometry.cell_kind, discretization.degree);
        if (!refusal.empty())
          throw InputError(refusal, exit_inconsistent);
      }
  }

  EntryValues
  read_entry_values(ParameterHandler               &prm,
                    const std::vector<std::string> &entries)
  {
    EntryValues values;
    for (const std::string &entry : entries)
      {
        const auto slash = entry.find('/');
        prm.enter_subsection(entry.substr(0, slash));
        values[entry] = prm.get(entry.substr(slash + 1));
        prm.leave_subsection();
      }
    return values;
  }

  std::vector<double>
  numbers_of(const EntryValues &values, const std::string &entry)
  {
    const auto it = values.find(entry);
    AssertThrow(it != values.end(),
                ExcMessage("A plugin reads <" + entry +
                           ">, which it does not list among its entries."));
    return Utilities::string_to_double(
      Utilities::split_string_list(it->second, ','));
  }

  std::vector<double>
  vector_of(const EntryValues &values,
            const std::string &entry,
            const unsigned int n,
            const bool         nonzero)
  {
    const std::vector<double> v = numbers_of(values, entry);
    need_values(v, entry, n);
    double norm = 0.;
    for (const double c : v)
      norm += c * c;
    if (nonzero && !(std::sqrt(norm) > 1e-12))
      throw InputError("The entry <" + entry + "> must not be the zero vector.",
                       exit_invalid_value);
    return v;
  }

  std::string
  default_parameter_file()
  {
    ParameterHandler prm;
    EntryDeclarer    declarer(prm);
    Parameters::declare_parameters(declarer);
    std::ostringstream out;
    prm.print_parameters(out, ParameterHandler::PRM);
    return out.str();
  }
} // namespace dualcontact
