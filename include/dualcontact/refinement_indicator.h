// Refinement indicators: how the cells are ranked for refinement between
// cycles (<Refinement/Strategy>). Each kind is one file in
// source/refinement_indicators/ (or in a program of one's own) that
// registers its name, its help text, its own entries and the function that
// computes the indicator; refinement.h marks the cells by it.
//
// A program adds one with, e.g.,
//
//   const bool registered = dualcontact::register_refinement_indicator(
//     "my indicator",
//     {"what it ranks the cells by", nullptr, {}, my_indicator<2>,
//      my_indicator<3>});
//
// and a scene chooses it with `set Strategy = my indicator`.
#ifndef dualcontact_refinement_indicator_h
#define dualcontact_refinement_indicator_h

#include <deal.II/base/parameter_handler.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/mapping.h>

#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <dualcontact/contact_set.h>
#include <dualcontact/postprocess.h>
#include <dualcontact/refinement_indicator_kind.h>

#include <functional>
#include <set>
#include <string>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  struct Parameters; // parameters.h

  /** What an indicator may read of a solved mesh. */
  template <int dim>
  struct IndicatorInput
  {
    const Mapping<dim>                  &mapping;
    const DoFHandler<dim>               &dof_handler;
    const TrilinosWrappers::MPI::Vector &solution; // ghosted
    const ContactSet<dim>               &contact;
    // the boundary ids with the condition 'contact' (empty without)
    const std::set<types::boundary_id> &contact_ids;
    const Parameters                   &parameters;
    // the entries of the indicator's own (RefinementIndicatorKind::entries)
    const EntryValues &values;
    // the nodal multiplier field (l1, l2_1, ..) on Gamma_C, ghosted, with
    // the hanging nodes filled (ContactSet::write_fields); computed on call
    std::function<TrilinosWrappers::MPI::Vector()> multipliers;
    // the pressure field of the mixed formulation at real points of a
    // cell, the stress then 2 mu dev eps(u) - p I (stress_from_strain());
    // empty in displacements
    PressureAt<dim> pressure;
  };

  /** The indicator of the scene's <Refinement/Strategy>. */
  template <int dim>
  Vector<float>
  compute_indicator(const IndicatorInput<dim> &input);
} // namespace dualcontact

#endif
