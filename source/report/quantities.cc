// The registry of the report's quantities, and the tables' entries they
// fill. The quantities register themselves from their own files
// (contact_quantities.cc, run_quantities.cc).
#include <dualcontact/registry.h>
#include <dualcontact/report_quantity.h>

#include <algorithm>
#include <iomanip>
#include <sstream>
#include <utility>

namespace dualcontact
{
  void
  TableEntries::add(const unsigned int place,
                    const std::string &key,
                    const Value       &value)
  {
    entries.push_back({place, key, value, false});
  }

  void
  TableEntries::add_error(const unsigned int place,
                          const std::string &key,
                          const double       error)
  {
    entries.push_back({place, key, error, true});
  }

  bool
  TableEntries::has_errors() const
  {
    return std::any_of(entries.begin(), entries.end(), [](const Entry &e) {
      return e.error;
    });
  }

  namespace
  {
    template <typename EntryType>
    std::vector<EntryType>
    by_place(std::vector<EntryType> entries)
    {
      std::stable_sort(entries.begin(),
                       entries.end(),
                       [](const EntryType &a, const EntryType &b) {
                         return a.place < b.place;
                       });
      return entries;
    }
  } // namespace

  void
  TableEntries::write_to(TableHandler &table) const
  {
    for (const Entry &e : by_place(entries))
      std::visit([&](const auto value) { table.add_value(e.key, value); },
                 e.value);
  }

  std::vector<std::pair<std::string, std::string>>
  TableEntries::csv_row() const
  {
    std::vector<std::pair<std::string, std::string>> row;
    for (const Entry &e : by_place(entries))
      {
        std::ostringstream text;
        text << std::scientific << std::setprecision(10);
        std::visit([&text](const auto value) { text << value; }, e.value);
        row.emplace_back(e.key, text.str());
      }
    return row;
  }

  void
  ScreenLines::add(const unsigned int place, const std::string &text)
  {
    lines.emplace_back(place, text);
  }

  std::string
  ScreenLines::text() const
  {
    auto sorted = lines;
    std::stable_sort(sorted.begin(),
                     sorted.end(),
                     [](const auto &a, const auto &b) {
                       return a.first < b.first;
                     });
    std::string all;
    for (const auto &line : sorted)
      all += line.second;
    return all;
  }

  template <int dim>
  void
  add_report_quantity(const std::string         &name,
                      ReportQuantityFactory<dim> factory)
  {
    Registry<ReportQuantityFactory<dim>>::instance().add(name,
                                                         std::move(factory));
  }

  template <int dim>
  std::vector<std::unique_ptr<ReportQuantity<dim>>>
  report_quantities(const Parameters &parameters, const Scene<dim> &scene)
  {
    const auto &registry = Registry<ReportQuantityFactory<dim>>::instance();
    std::vector<std::unique_ptr<ReportQuantity<dim>>> list;
    for (const std::string &name : registry.names())
      {
        const ReportQuantityFactory<dim> &factory = *registry.find(name);
        if (factory.has(parameters, scene))
          list.push_back(factory.create(parameters, scene));
      }
    return list;
  }

  template void
  add_report_quantity(const std::string &, ReportQuantityFactory<2>);
  template void
  add_report_quantity(const std::string &, ReportQuantityFactory<3>);
  template std::vector<std::unique_ptr<ReportQuantity<2>>>
  report_quantities(const Parameters &, const Scene<2> &);
  template std::vector<std::unique_ptr<ReportQuantity<3>>>
  report_quantities(const Parameters &, const Scene<3> &);
} // namespace dualcontact
