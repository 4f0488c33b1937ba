// What each contact pair reports: its force, and its contact nodes' rows.
#ifndef dualcontact_pair_results_h
#define dualcontact_pair_results_h

#include <deal.II/base/mpi.h>

#include <dualcontact/contact_output.h>
#include <dualcontact/contact_set.h>
#include <dualcontact/records.h>


namespace dualcontact
{
  using namespace dealii;

  /**
   * The contact forces of the solution in `contact_set` into `record`: the
   * obstacle's along the obstacle's mean normal (obstacle_force), each
   * pair's along its own nodes' direction (pair_force, in the order of
   * the pairs), their sum (contact_force), the magnitudes of their
   * tangential parts summed (tangential_force), the force of the obstacle
   * on the body (resultant), and the forces on the slave and master bodies.
   * Collective.
   */
  template <int dim>
  void
  add_contact_forces(const ContactSet<dim> &contact_set,
                     MPI_Comm               mpi_communicator,
                     ContactZoneRecord     &record);

  /**
   * The contact nodes' rows in `directory`/contact`suffix`, and each
   * contact pair's rows alone in contact_pair_<slave>_<master>`suffix`, as
   * write_contact_csv() writes them (with friction if the contact set's
   * law has it).
   */
  template <int dim>
  void
  write_contact_csvs(const std::string                      &directory,
                     const std::string                      &suffix,
                     const std::vector<ContactNodeRow<dim>> &rows,
                     const ContactSet<dim>                  &contact_set,
                     const Function<dim>                    *exact_pressure);

} // namespace dualcontact

#endif
