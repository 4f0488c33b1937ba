// What a run measures, one quantity at a time: the mesh, the loops' counts,
// the contact zone, friction, the errors against an exact solution, the
// reactions, the wall times... Each quantity says whether a scene has it
// (frictionless scenes have no tangential columns, 2D scenes no contact
// area), and adds its own columns to cycles.csv, to the summary table and
// to the row a quiet run prints per cycle, and its own lines to a cycle's
// results. doc/output.md, "Columns of cycles.csv", says which quantity
// writes which columns.
//
// Adding a quantity is one registration, in any file of the library
// (source/report/*.cc) or of a program of one's own: its name, and a
// function that fills in its parts, each a formula from a cycle's result
// to its columns or lines:
//
//   /** Every scene: my_column. */
//   const bool my_quantity_registered =
//     register_report_quantity("my quantity", [](auto &q) {
//       q.csv = [](const auto &, const CycleResult &r, TableEntries &t) {
//         t.add(610, "my_column", r.memory_mb);
//       };
//     });
//
// The quantity fills in only the parts it needs (`has` too, where not
// every scene has the quantity); a class derived from ReportQuantity and
// registered with register_report_quantity<Class>(name) does the same. The
// report asks the quantities in the alphabetical order of their names, and
// nothing it writes depends on that order: the columns of cycles.csv and of the
// summary table, the columns of a quiet run's row and the lines of a cycle's
// results follow their places, and no two quantities of a scene share a place
// (entries of one place keep the order they were added in, which between two
// quantities would be the order of their names).
#ifndef dualcontact_report_quantity_h
#define dualcontact_report_quantity_h

#include <deal.II/base/convergence_table.h>
#include <deal.II/base/table_handler.h>

#include <dualcontact/parameters.h>
#include <dualcontact/records.h>
#include <dualcontact/scene.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  /**
   * The entries the quantities give one table for one cycle, each with its
   * place: the table's columns follow their places (ascending; entries of
   * one place keep the order they were added in). The places of a table
   * are spaced by 10 in the order of its columns, so that a new quantity
   * can put its columns between two others.
   */
  class TableEntries
  {
  public:
    using Value = std::variant<unsigned int, std::uint64_t, double>;

    void
    add(const unsigned int place, const std::string &key, const Value &value);

    /** An error against an exact solution (the summary's legend says so). */
    void
    add_error(const unsigned int place, const std::string &key, double error);

    bool
    has_errors() const;

    /** One row of `table`, the entries in the order of their places. */
    void
    write_to(TableHandler &table) const;

    /**
     * The same row as (column, text) pairs, the text as `table`'s CSV has
     * it: integers as they are, reals with 10 digits after the point in
     * scientific notation.
     */
    std::vector<std::pair<std::string, std::string>>
    csv_row() const;

  private:
    struct Entry
    {
      unsigned int place;
      std::string  key;
      Value        value;
      bool         error;
    };
    std::vector<Entry> entries;
  };

  /** Lines of text, each with its place, told in the order of their places. */
  class ScreenLines
  {
  public:
    /** `text`: one or more lines, each ending in '\n'. */
    void
    add(const unsigned int place, const std::string &text);

    std::string
    text() const;

  private:
    std::vector<std::pair<unsigned int, std::string>> lines;
  };

  /**
   * A column of the row a quiet run prints per cycle: its place, its title
   * and width, and its entry. While the row is wider than a screen line,
   * the columns of the largest `priority` are left out (0: always shown).
   */
  struct RowColumn
  {
    unsigned int                                    place;
    unsigned int                                    priority;
    std::string                                     title;
    std::size_t                                     width;
    std::function<std::string(const CycleResult &)> entry;
  };

  /**
   * One measured quantity. The static `has(parameters, scene)` says
   * whether the scene has the quantity (the report asks only those); a
   * quantity that not every scene has hides it with its own. Its functions
   * then add what it measures.
   */
  template <int dim>
  class ReportQuantity
  {
  public:
    ReportQuantity(const Parameters &parameters, const Scene<dim> &scene)
        : parameters(parameters)
        , scene(scene)
    {}

    virtual ~ReportQuantity() = default;

    /** Every scene has it. */
    static bool
    has(const Parameters & /*parameters*/, const Scene<dim> & /*scene*/)
    {
      return true;
    }

    /** Its columns of cycles.csv. */
    virtual void
    csv_entries(const CycleResult &result, TableEntries &csv) const = 0;

    /** Its columns of the summary table at the end of the run. */
    virtual void
    summary_entries(const CycleResult & /*result*/,
                    TableEntries & /*summary*/) const
    {}

    /** The number format of its summary columns, and their rates. */
    virtual void
    format_summary(ConvergenceTable & /*table*/) const
    {}

    /** Its columns of the row a quiet run prints per cycle. */
    virtual void
    row_columns(std::vector<RowColumn> & /*columns*/) const
    {}

    /** Its lines of a cycle's results (verbosity normal and detailed). */
    virtual void
    print(const CycleResult & /*result*/, ScreenLines & /*lines*/) const
    {}

  protected:
    const Parameters &parameters;
    const Scene<dim> &scene;
  };

  /**
   * A quantity as its parts: which scenes have it (`has`), and the
   * formulas that add its columns and lines, each given the quantity first
   * (its `parameters` and `scene`). A part left empty adds nothing.
   */
  template <int dim>
  class QuantityFromParts;

  template <int dim>
  struct QuantityParts
  {
    static constexpr int dimension = dim;
    using Quantity                 = QuantityFromParts<dim>;

    std::function<bool(const Parameters &, const Scene<dim> &)> has =
      &ReportQuantity<dim>::has;
    /** ReportQuantity::csv_entries() */
    std::function<void(const Quantity &, const CycleResult &, TableEntries &)>
      csv;
    /** ReportQuantity::summary_entries() */
    std::function<void(const Quantity &, const CycleResult &, TableEntries &)>
      summary;
    /** ReportQuantity::format_summary() */
    std::function<void(const Quantity &, ConvergenceTable &)> format_summary;
    /** ReportQuantity::row_columns() */
    std::function<void(const Quantity &, std::vector<RowColumn> &)> row;
    /** ReportQuantity::print() */
    std::function<void(const Quantity &, const CycleResult &, ScreenLines &)>
      print;
  };

  /** The dimension of a QuantityParts<dim>, for the function that fills it. */
  template <typename Parts>
  constexpr int dimension_of = std::decay_t<Parts>::dimension;

  /** The ReportQuantity that calls its parts. */
  template <int dim>
  class QuantityFromParts : public ReportQuantity<dim>
  {
  public:
    QuantityFromParts(const Parameters         &parameters,
                      const Scene<dim>         &scene,
                      const QuantityParts<dim> &parts)
        : ReportQuantity<dim>(parameters, scene)
        , parts(parts)
    {}

    using ReportQuantity<dim>::parameters;
    using ReportQuantity<dim>::scene;

    void
    csv_entries(const CycleResult &result, TableEntries &csv) const override
    {
      if (parts.csv)
        parts.csv(*this, result, csv);
    }

    void
    summary_entries(const CycleResult &result,
                    TableEntries      &summary) const override
    {
      if (parts.summary)
        parts.summary(*this, result, summary);
    }

    void
    format_summary(ConvergenceTable &table) const override
    {
      if (parts.format_summary)
        parts.format_summary(*this, table);
    }

    void
    row_columns(std::vector<RowColumn> &columns) const override
    {
      if (parts.row)
        parts.row(*this, columns);
    }

    void
    print(const CycleResult &result, ScreenLines &lines) const override
    {
      if (parts.print)
        parts.print(*this, result, lines);
    }

  private:
    const QuantityParts<dim> parts;
  };

  /**
   * What the registry holds of a quantity for one dimension: whether a
   * scene has it, and how to make it.
   */
  template <int dim>
  struct ReportQuantityFactory
  {
    std::function<bool(const Parameters &, const Scene<dim> &)> has;
    std::function<std::unique_ptr<ReportQuantity<dim>>(const Parameters &,
                                                       const Scene<dim> &)>
      create;
  };

  /** The factory of the class template `Quantity` in dimension dim. */
  template <template <int> class Quantity, int dim>
  ReportQuantityFactory<dim>
  report_quantity_factory()
  {
    return {&Quantity<dim>::has,
            [](const Parameters &parameters, const Scene<dim> &scene)
              -> std::unique_ptr<ReportQuantity<dim>> {
              return std::make_unique<Quantity<dim>>(parameters, scene);
            }};
  }

  /** The factory of the quantity of `parts` in dimension dim. */
  template <int dim>
  ReportQuantityFactory<dim>
  parts_factory(const QuantityParts<dim> &parts)
  {
    return {parts.has,
            [parts](const Parameters &parameters, const Scene<dim> &scene)
              -> std::unique_ptr<ReportQuantity<dim>> {
              return std::make_unique<QuantityFromParts<dim>>(parameters,
                                                              scene,
                                                              parts);
            }};
  }

  /** Adds `factory` to the registry of dimension dim, as `name`. */
  template <int dim>
  void
  add_report_quantity(const std::string         &name,
                      ReportQuantityFactory<dim> factory);

  /**
   * Makes the class template `Quantity` (derived from ReportQuantity) known
   * to the report as `name`, in 2D and 3D. Called
   * once per quantity, at load time, from the quantity's own file. Returns
   * true (for the static initialiser).
   */
  template <template <int> class Quantity>
  bool
  register_report_quantity(const std::string &name)
  {
    add_report_quantity<2>(name, report_quantity_factory<Quantity, 2>());
    add_report_quantity<3>(name, report_quantity_factory<Quantity, 3>());
    return true;
  }

  /**
   * Makes the quantity whose parts `fill_parts(QuantityParts<dim> &)` fills
   * in (a generic lambda: dimension_of<decltype(parts)> is its dim) known
   * to the report as `name`, in 2D and 3D. Returns true (for the static
   * initialiser).
   */
  template <typename FillParts>
  bool
  register_report_quantity(const std::string &name, const FillParts &fill_parts)
  {
    QuantityParts<2> parts_2d;
    fill_parts(parts_2d);
    QuantityParts<3> parts_3d;
    fill_parts(parts_3d);
    add_report_quantity<2>(name, parts_factory(parts_2d));
    add_report_quantity<3>(name, parts_factory(parts_3d));
    return true;
  }

  /** The quantities the scene has, in the alphabetical order of their names. */
  template <int dim>
  std::vector<std::unique_ptr<ReportQuantity<dim>>>
  report_quantities(const Parameters &parameters, const Scene<dim> &scene);
} // namespace dualcontact

#endif
