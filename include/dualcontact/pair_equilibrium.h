// The equilibrium of the bodies that a contact pair alone holds.
#ifndef dualcontact_pair_equilibrium_h
#define dualcontact_pair_equilibrium_h

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/trilinos_vector.h>

#include <dualcontact/contact_set.h>
#include <dualcontact/scene.h>

#include <vector>

namespace dualcontact
{
  using namespace dealii;

  /**
   * Throws (InputError, exit_no_equilibrium) if a body that no support and
   * no obstacle holds, in one contact pair, is not pressed onto the other
   * body by its loads `system_rhs`, or if the pair is flat and friction
   * cannot resist the loads' tangential part. Returns, per local contact
   * node, the start pressure N / |Gamma_pair| at the nodes of a pair where
   * only friction holds such a body tangentially, and 0 at the others (an
   * empty vector if at no node, and without pairs). Collective.
   */
  template <int dim>
  std::vector<double>
  check_pair_bodies(const ContactSet<dim>               &contact_set,
                    const DoFHandler<dim>               &dof_handler,
                    const TrilinosWrappers::MPI::Vector &system_rhs,
                    const Scene<dim>                    &scene);
} // namespace dualcontact

#endif
