// Refinement indicators between cycles: deal.II's Kelly
// estimator, and the 'contact' indicator, which adds a residual of the
// contact tractions on Gamma_C.
#ifndef dualcontact_refinement_h
#define dualcontact_refinement_h

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/mapping.h>

#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <dualcontact/contact_set.h>
#include <dualcontact/parameters.h>

#include <set>

namespace dualcontact
{
  using namespace dealii;

  /**
   * Kelly's indicator per active cell (zero on cells not owned): the jump of
   * the gradient of the ghosted `solution` across interior faces; boundary
   * faces add nothing.
   */
  template <int dim>
  Vector<float>
  kelly_indicator(const Mapping<dim>                  &mapping,
                  const DoFHandler<dim>               &dof_handler,
                  const TrilinosWrappers::MPI::Vector &solution);

  /**
   * Add the Gamma_C term of the 'contact' indicator to `indicator` (in
   * squares): for every owned cell and each of its faces F on the contact
   * ids,
   *   eta_F^2 = weight h_F / E^2 int_F |sigma(u_h) n_F + l1 n + l2 . t|^2,
   * the residual of the traction condition sigma(u) n_F = -(l1 n + l2 t)
   * that the multipliers impose (n = the contact set's normal, t its
   * tangents). Dividing by E makes it a strain, as Kelly's jump of the
   * gradient is, so the weight has no units. `multipliers` is the ghosted
   * field of ContactSet::write_fields with hanging nodes filled.
   */
  template <int dim>
  void
  add_contact_indicator(const Mapping<dim>                  &mapping,
                        const DoFHandler<dim>               &dof_handler,
                        const TrilinosWrappers::MPI::Vector &solution,
                        const TrilinosWrappers::MPI::Vector &multipliers,
                        const ContactSet<dim>               &contact,
                        const std::set<types::boundary_id>  &contact_ids,
                        const MaterialParameters            &material,
                        const double                         weight,
                        Vector<float>                       &indicator);
} // namespace dualcontact

#endif
