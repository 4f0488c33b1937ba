// The list of the report's quantities, and the tables' entries they fill.
#include "quantities.h"

#include <algorithm>

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

  void
  TableEntries::write_to(TableHandler &table) const
  {
    std::vector<Entry> sorted = entries;
    std::stable_sort(sorted.begin(),
                     sorted.end(),
                     [](const Entry &a, const Entry &b) {
                       return a.place < b.place;
                     });
    for (const Entry &e : sorted)
      std::visit([&](const auto value) { table.add_value(e.key, value); },
                 e.value);
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

  namespace
  {
    /** `Quantity` appended to `list` if the scene has it. */
    template <template <int> class Quantity, int dim>
    void
    add_if_present(std::vector<std::unique_ptr<ReportQuantity<dim>>> &list,
                   const Parameters &parameters,
                   const Scene<dim> &scene)
    {
      if (Quantity<dim>::has(parameters, scene))
        list.push_back(std::make_unique<Quantity<dim>>(parameters, scene));
    }
  } // namespace

  template <int dim>
  std::vector<std::unique_ptr<ReportQuantity<dim>>>
  report_quantities(const Parameters &parameters, const Scene<dim> &scene)
  {
    using namespace report_quantities_impl;
    std::vector<std::unique_ptr<ReportQuantity<dim>>> list;
    add_if_present<MeshSize>(list, parameters, scene);
    add_if_present<NestedIteration>(list, parameters, scene);
    add_if_present<ContactSolve>(list, parameters, scene);
    add_if_present<ContactSolveTimes>(list, parameters, scene);
    add_if_present<Friction>(list, parameters, scene);
    add_if_present<ThresholdSteps>(list, parameters, scene);
    add_if_present<LinearSolves>(list, parameters, scene);
    add_if_present<ContactErrors>(list, parameters, scene);
    add_if_present<ContactArea>(list, parameters, scene);
    add_if_present<ObstacleForce>(list, parameters, scene);
    add_if_present<Displacement>(list, parameters, scene);
    add_if_present<ColdStart>(list, parameters, scene);
    add_if_present<Reactions>(list, parameters, scene);
    add_if_present<ReferenceSolve>(list, parameters, scene);
    add_if_present<WallTimes>(list, parameters, scene);
    add_if_present<Memory>(list, parameters, scene);
    return list;
  }

  template std::vector<std::unique_ptr<ReportQuantity<2>>>
  report_quantities(const Parameters &, const Scene<2> &);
  template std::vector<std::unique_ptr<ReportQuantity<3>>>
  report_quantities(const Parameters &, const Scene<3> &);
} // namespace dualcontact
