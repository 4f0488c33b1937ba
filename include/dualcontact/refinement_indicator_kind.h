// What a refinement indicator registers from its own file: its name, help
// text, entries and indicator function (<Refinement/Strategy>). The
// parameters read the registered kinds through this header alone; what an
// indicator computes from, IndicatorInput, is in refinement_indicator.h,
// which the solver's side includes.
#ifndef dualcontact_refinement_indicator_kind_h
#define dualcontact_refinement_indicator_kind_h

#include <deal.II/lac/vector.h>

#include <dualcontact/entry_declaration.h>

#include <functional>
#include <string>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  /** What an indicator may read of a solved mesh (refinement_indicator.h). */
  template <int dim>
  struct IndicatorInput;

  /**
   * One value per active cell (those of the cells not owned are not read);
   * the largest are refined.
   */
  template <int dim>
  using IndicatorFunction =
    std::function<Vector<float>(const IndicatorInput<dim> &input)>;

  /** What a refinement indicator registers from its own file. */
  struct RefinementIndicatorKind
  {
    /** What <Refinement/Strategy> = this name does: a sentence or two. */
    std::string help;

    /**
     * Declares its own entries (in subsection Refinement) through
     * `declarer` (entry_declaration.h), or nullptr.
     */
    void (*declare_parameters)(EntryDeclarer &declarer) = nullptr;

    /** Its own entries, "Refinement/Entry". */
    std::vector<std::string> entries;

    /**
     * The indicator. Empty functions: every cell is refined (then the
     * fractions have no effect).
     */
    IndicatorFunction<2> indicator_2d;
    IndicatorFunction<3> indicator_3d;

    bool
    refines_every_cell() const
    {
      return !indicator_2d;
    }
  };

  /**
   * Make `name` known to <Refinement/Strategy>. Called once per kind, at
   * load time. Returns true (for the static initialiser).
   */
  bool
  register_refinement_indicator(const std::string      &name,
                                RefinementIndicatorKind kind);

  /** The registered names, in alphabetical order. */
  std::vector<std::string>
  refinement_indicator_names();

  /** The kind registered as `name`; InputError naming the entry. */
  const RefinementIndicatorKind &
  refinement_indicator_kind(const std::string &name);

} // namespace dualcontact

#endif
