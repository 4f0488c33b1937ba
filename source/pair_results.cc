// What each contact pair reports (doc/two_bodies.md): the contact forces
// apart (the obstacle's, each pair's, those on the slave and master
// bodies), and the contact nodes' rows of each pair in a file of its own.
#include <deal.II/base/mpi.h>

#include <dualcontact/pair_results.h>

#include <utility>

namespace dualcontact
{
  namespace
  {
    /**
     * The force on the slave nodes of the contact pair of `slave_id`, and
     * the direction it is measured along: the resultant of its normal
     * forces sum_s m_s l1_s n_s, without pressure the mean normal of its
     * slave nodes.
     */
    template <int dim>
    std::pair<Tensor<1, dim>, Tensor<1, dim>>
    pair_force_and_direction(const ContactSet<dim>   &contact_set,
                             const types::boundary_id slave_id,
                             const MPI_Comm           mpi_communicator)
    {
      Tensor<1, dim> force, pressed, facing;
      for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
        if (contact_set.nodes[s].pair_slave_id == slave_id)
          {
            const ContactNode<dim> &node = contact_set.nodes[s];
            force += contact_set.nodal_force(s);
            pressed += node.weight * contact_set.l1[s] * node.normal;
            facing += node.weight * node.normal;
          }
      for (unsigned int c = 0; c < dim; ++c)
        {
          force[c]   = Utilities::MPI::sum(force[c], mpi_communicator);
          pressed[c] = Utilities::MPI::sum(pressed[c], mpi_communicator);
          facing[c]  = Utilities::MPI::sum(facing[c], mpi_communicator);
        }
      const Tensor<1, dim> direction = pressed.norm() > 0. ? pressed : facing;
      return {force, direction};
    }

  } // namespace

  template <int dim>
  void
  add_contact_forces(const ContactSet<dim> &contact_set,
                     const MPI_Comm         mpi_communicator,
                     ContactZoneRecord     &record)
  {
    Tensor<1, dim> on_obstacle, on_slave, on_master;
    for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
      {
        // a pair's node pushes the master body, which pushes it back: a
        // force inside the mesh, no load on it
        const Tensor<1, dim> force = contact_set.nodal_force(s);
        if (contact_set.nodes[s].masters.empty())
          on_obstacle += force;
        else
          {
            on_slave -= force;
            for (const MasterTerm<dim> &master : contact_set.nodes[s].masters)
              on_master += master.coefficient * force;
          }
      }
    for (unsigned int c = 0; c < dim; ++c)
      {
        on_obstacle[c] = Utilities::MPI::sum(on_obstacle[c], mpi_communicator);
        on_slave[c]    = Utilities::MPI::sum(on_slave[c], mpi_communicator);
        on_master[c]   = Utilities::MPI::sum(on_master[c], mpi_communicator);
        record.on_slave_body[c]  = on_slave[c];
        record.on_master_body[c] = on_master[c];
      }
    // the obstacle's force is the resultant's component along the mean
    // direction of its nodes, the direction of the applied load it
    // balances: a sum of the pressures m_s l1_s would also count the parts
    // of the normals that cancel (a curved zone), or that point elsewhere
    // (a node beside an obstacle's corner). Each pair's the same along its
    // own direction, the resultant of its normal forces sum_s m_s l1_s n_s
    // (without pressure the mean normal of its slave nodes): pairs that
    // face other ways (a stack on the plane whose pair's slave is the lower
    // body's top) must not cancel.
    record.obstacle_force = on_obstacle * contact_set.normal;
    record.contact_force  = record.obstacle_force;
    // the tangential forces likewise: each contact's in the plane normal to
    // its own direction, their magnitudes summed (the sum of the vectors
    // would depend on which side of a pair is the slave: in a stack on the
    // plane the pair's force on the slave is the upper load's, or its
    // opposite)
    const auto tangential = [](const Tensor<1, dim> &force,
                               const Tensor<1, dim> &direction) {
      return direction.norm() > 0. ? (force - (force * direction) * direction /
                                                direction.norm_square())
                                       .norm() :
                                     force.norm();
    };
    record.tangential_force = tangential(on_obstacle, contact_set.normal);
    for (const auto &[slave_id, master_id] : contact_set.pairs().list())
      {
        const auto [force, direction] =
          pair_force_and_direction(contact_set, slave_id, mpi_communicator);
        const double pair_force =
          direction.norm() > 0. ? force * direction / direction.norm() : 0.;
        record.pair_force.push_back(pair_force);
        record.contact_force += pair_force;
        record.tangential_force += tangential(force, direction);
      }
    // the force of the obstacle on the body, -sum_s m_s (l1_s n_s + T_s l2_s)
    const Tensor<1, dim> resultant = -on_obstacle;
    for (unsigned int c = 0; c < dim; ++c)
      record.resultant[c] = resultant[c];
  }

  template <int dim>
  void
  write_contact_csvs(const std::string                      &directory,
                     const std::string                      &suffix,
                     const std::vector<ContactNodeRow<dim>> &rows,
                     const ContactSet<dim>                  &contact_set,
                     const Function<dim>                    *exact_pressure)
  {
    const bool friction = contact_set.law->has_friction();
    write_contact_csv(directory + "/contact" + suffix,
                      rows,
                      friction,
                      exact_pressure);
    for (const auto &[slave, master] : contact_set.pairs().list())
      {
        std::vector<ContactNodeRow<dim>> pair_rows;
        for (const ContactNodeRow<dim> &row : rows)
          if (row.pair_slave_id == static_cast<int>(slave))
            pair_rows.push_back(row);
        write_contact_csv(directory + "/contact_pair_" + std::to_string(slave) +
                            "_" + std::to_string(master) + suffix,
                          pair_rows,
                          friction,
                          exact_pressure);
      }
  }

  template void
  add_contact_forces(const ContactSet<2> &, MPI_Comm, ContactZoneRecord &);
  template void
  add_contact_forces(const ContactSet<3> &, MPI_Comm, ContactZoneRecord &);
  template void
  write_contact_csvs(const std::string &,
                     const std::string &,
                     const std::vector<ContactNodeRow<2>> &,
                     const ContactSet<2> &,
                     const Function<2> *);
  template void
  write_contact_csvs(const std::string &,
                     const std::string &,
                     const std::vector<ContactNodeRow<3>> &,
                     const ContactSet<3> &,
                     const Function<3> *);
} // namespace dualcontact
