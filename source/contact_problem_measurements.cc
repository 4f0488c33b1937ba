// ContactProblem, what a solved mesh is measured by: the contact zone (its
// extent, the largest pressure, the stick and slip zones), the reactions on
// the prescribed boundaries and the obstacle, the potential energy of the
// displacement, and the comparison of the nested solve with a cold start.
#include <deal.II/base/utilities.h>

#include <deal.II/dofs/dof_accessor.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <dualcontact/contact_functions.h>
#include <dualcontact/contact_output.h>
#include <dualcontact/contact_problem.h>
#include <dualcontact/input_error.h>
#include <dualcontact/output_directory.h>
#include <dualcontact/pair_results.h>
#include <dualcontact/plausibility.h>
#include <dualcontact/postprocess.h>
#include <dualcontact/refinement.h>
#include <dualcontact/refinement_indicator.h>
#include <dualcontact/run_size.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <utility>

namespace dualcontact
{
  namespace
  {
    /**
     * The half-width (2D) or radius (3D) of the contact zone and of its
     * stick zone, from the nodes of every rank.
     */
    template <int dim>
    void
    measure_zone_shape(const std::vector<ZoneNode> &local,
                       const ContactSet<dim>       &contact_set,
                       const MPI_Comm               mpi_communicator,
                       ContactZoneRecord           &record)
    {
      std::vector<ZoneNode> nodes;
      for (const auto &part :
           Utilities::MPI::all_gather(mpi_communicator, local))
        nodes.insert(nodes.end(), part.begin(), part.end());
      const ContactZoneShape shape =
        contact_zone_shape(nodes,
                           dim - 1,
                           0.25 * contact_set.min_face_diameter());
      record.half_width      = shape.width.nodes;
      record.edge_half_width = shape.width.extrapolated;
      record.area            = shape.area;
      record.extent          = shape.extent;
      record.mirrored        = shape.mirrored;
      if (contact_set.friction)
        record.stick_half_width = shape.stick_width;
    }

    /** The zone's relative errors against the exact values given. */
    void
    relative_zone_errors(const ExactSolutionParameters &exact,
                         ContactZoneRecord             &record)
    {
      if (exact.contact_half_width > 0.)
        record.half_width_error =
          record.edge_half_width / exact.contact_half_width - 1.;
      if (exact.stick_half_width > 0.)
        record.stick_half_width_error =
          record.stick_half_width / exact.stick_half_width - 1.;
      if (exact.peak_pressure > 0.)
        record.peak_pressure_error =
          record.max_pressure / exact.peak_pressure - 1.;
    }
  } // namespace

  template <int dim>
  ContactZoneRecord
  ContactProblem<dim>::measure_contact_zone() const
  {
    TimerOutput::Scope    t(computing_timer, "measure contact zone");
    ContactZoneRecord     record;
    double                peak = 0;
    std::vector<ZoneNode> local;
    for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
      {
        peak = std::max(peak, contact_set.l1[s]);
        ZoneNode node;
        for (unsigned int k = 0; k < dim - 1; ++k)
          node.t[k] = contact_set.nodes[s].position * contact_set.tangents[k];
        node.weight = contact_set.nodes[s].weight;
        node.gap0   = contact_set.nodes[s].gap0;
        node.l1     = contact_set.l1[s];
        node.status = contact_set.status(s);
        local.push_back(node);
      }
    add_contact_forces(contact_set, mpi_communicator, record);
    record.max_pressure = Utilities::MPI::max(peak, mpi_communicator);

    // the half-width (2D) or radius (3D) of the zone and of its stick zone
    measure_zone_shape(local, contact_set, mpi_communicator, record);

    // errors against what the scene knows
    if (const Function<dim> *exact = scene.exact_pressure())
      {
        TrilinosWrappers::MPI::Vector multipliers, threshold;
        multiplier_fields(multipliers, threshold);
        record.pressure_error = compute_pressure_error(
          mapping, dof_handler, multipliers, scene.contact_ids(), *exact);
        if (!std::isfinite(record.pressure_error))
          throw InputError("The entry <Exact solution/Contact pressure> is "
                           "not a finite number (NaN or infinity) at some "
                           "point of Gamma_C: '" +
                             parameters.exact.contact_pressure + "'.",
                           exit_invalid_value);
      }
    relative_zone_errors(parameters.exact, record);
    return record;
  }

  template <int dim>
  double
  ContactProblem<dim>::dissipation() const
  {
    double local = 0.;
    if (contact_set.friction)
      {
        const TrilinosWrappers::MPI::Vector &u =
          contact_set.with_masters(solution);
        for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
          local += contact_set.nodes[s].weight *
                   (contact_set.l2[s] * contact_set.slip(u, s));
      }
    return Utilities::MPI::sum(local, mpi_communicator);
  }

  template <int dim>
  double
  ContactProblem<dim>::potential_energy() const
  {
    TimerOutput::Scope t(computing_timer, "postprocess");
    // in the mixed formulation the deviatoric energy, and the pressure's
    // (1/2) p.C p
    return dualcontact::potential_energy(mapping,
                                         dof_handler,
                                         scene,
                                         solution) +
           (mixed ? mixed->compliance_energy() : 0.);
  }

  template <int dim>
  ColdStartRecord
  ContactProblem<dim>::compare_with_cold_start()
  {
    ColdStartRecord record;
    if (!carried || !parameters.refinement.compare_cold_start)
      return record;
    TimerOutput::Scope t(computing_timer, "cold start (comparison)");
    report.start_cold_start();
    ContactSet<dim> cold_set = contact_set;
    cold_set.reset_multipliers();
    TrilinosWrappers::MPI::Vector v_cold(locally_owned_dofs, mpi_communicator);
    constraints.distribute(v_cold);
    // its steps are neither printed nor logged
    const ContactStatistics cold = threshold_iteration.solve(
      contact_system(), cold_set, v_cold, nullptr, held_by_friction_pressure);
    report.end_cold_start();
    record.uzawa_steps     = cold.uzawa_steps;
    record.newton_steps    = cold.newton_steps;
    record.threshold_steps = cold.threshold_steps;

    // in the energy norm a(e, e) = e.(K - chi M)e, blind to the rigid
    // motions that only the proximal term fixes (a semi-coercive scene
    // keeps the one its start selects); on the condensed matrices, i.e.
    // over the unconstrained DoFs
    const auto energy = [&](TrilinosWrappers::MPI::Vector e) {
      homogeneous_constraints.set_zero(e);
      TrilinosWrappers::MPI::Vector Ke(e), Me(e);
      system_matrix.vmult(Ke, e);
      mass.vmult(Me, e);
      return std::sqrt(std::max(e * Ke - chi * (e * Me), 0.));
    };
    TrilinosWrappers::MPI::Vector difference(locally_owned_dofs,
                                             mpi_communicator);
    difference = solution;
    difference -= v_cold;
    record.difference_v = relative_change(energy(difference), energy(v_cold));
    double sums[2]      = {0., 0.};
    for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
      {
        const double m = contact_set.nodes[s].weight;
        sums[0] += m * std::pow(contact_set.l1[s] - cold_set.l1[s], 2);
        sums[1] += m * cold_set.l1[s] * cold_set.l1[s];
      }
    Utilities::MPI::sum(ArrayView<const double>(sums, 2),
                        mpi_communicator,
                        ArrayView<double>(sums, 2));
    record.difference_l1 =
      relative_change(std::sqrt(sums[0]), std::sqrt(sums[1]));
    return record;
  }

  template <int dim>
  ReactionRecord
  ContactProblem<dim>::compute_reactions(const ContactZoneRecord &zone) const
  {
    TimerOutput::Scope t(computing_timer, "postprocess");
    // one more pass over the cells: where there are supports, or several
    // bodies to balance one by one
    ReactionRecord                record;
    const bool                    pairs = contact_set.has_pairs();
    TrilinosWrappers::MPI::Vector contact_forces;
    if (scene.ids_with(BoundaryCondition::fixed).empty() &&
        scene.ids_with(BoundaryCondition::normal_fixed).empty() && !pairs)
      record.applied_load = applied_load;
    else
      {
        contact_forces.reinit(locally_owned_dofs, mpi_communicator);
        if (scene.effects().contact)
          contact_set.add_nodal_forces(contact_forces);
        TrilinosWrappers::MPI::Vector pressure_forces;
        if (mixed)
          pressure_forces =
            mixed->unconstrained_pressure_forces(mapping, dof_handler);
        record =
          dualcontact::compute_reactions(mapping,
                                         dof_handler,
                                         scene,
                                         constraints,
                                         hanging_node_constraints,
                                         solution,
                                         &contact_forces,
                                         mixed ? &pressure_forces : nullptr);
      }

    // Equilibrium of the whole mesh: contact force, reactions and applied
    // loads sum to zero, up to the solver tolerances.
    std::array<double, 3> sum   = record.applied_load;
    double                scale = std::sqrt(norm_square(record.applied_load));
    for (const auto &[id, force] : record.on_id)
      {
        for (unsigned int c = 0; c < dim; ++c)
          sum[c] += force[c];
        scale = std::max(scale, std::sqrt(norm_square(force)));
      }
    for (unsigned int c = 0; c < dim; ++c)
      sum[c] += zone.resultant[c];
    scale = std::max(scale, std::sqrt(norm_square(zone.resultant)));
    // and of each body, with the contact forces on it (the obstacle's and
    // the other bodies')
    std::vector<std::array<double, 3>> body_sums;
    for (unsigned int b = 0; b < record.on_body.size(); ++b)
      {
        std::array<double, 3> &body = body_sums.emplace_back();
        for (unsigned int c = 0; c < dim; ++c)
          body[c] = record.load_on_body[b][c] + record.on_body[b][c] +
                    record.contact_on_body[b][c];
        for (const auto *force : {&record.load_on_body[b],
                                  &record.on_body[b],
                                  &record.contact_on_body[b]})
          scale = std::max(scale, std::sqrt(norm_square(*force)));
      }
    // along a load path, not below the previous step's contact force: a
    // step that unloads everything balances to the round-off of the path
    scale = std::max(scale, previous_size.contact_force);
    // and not below a hundredth of E |u|_max L^(dim-2), the force that
    // would strain the body by |u|_max / L: where the displacement is
    // (nearly) a rigid motion that carries no force (a clamped body moved
    // clear of the obstacle, two bodies lifted apart), every force is the
    // round-off of that motion, and their sum relative to themselves is
    // 1 (doc/theory.md §8)
    scale          = std::max(scale,
                     1e-2 * parameters.material.stiffest().youngs_modulus *
                       solution.linfty_norm() *
                       std::pow(scene.characteristic_length(), dim - 2));
    double largest = std::sqrt(norm_square(sum));
    for (const auto &body : body_sums)
      largest = std::max(largest, std::sqrt(norm_square(body)));
    record.imbalance = scale > 0. ? largest / scale : 0.;
    return record;
  }


  template ContactZoneRecord
  ContactProblem<2>::measure_contact_zone() const;
  template ContactZoneRecord
  ContactProblem<3>::measure_contact_zone() const;
  template double
  ContactProblem<2>::dissipation() const;
  template double
  ContactProblem<3>::dissipation() const;
  template double
  ContactProblem<2>::potential_energy() const;
  template double
  ContactProblem<3>::potential_energy() const;
  template ColdStartRecord
  ContactProblem<2>::compare_with_cold_start();
  template ColdStartRecord
  ContactProblem<3>::compare_with_cold_start();
  template ReactionRecord
  ContactProblem<2>::compute_reactions(const ContactZoneRecord &zone) const;
  template ReactionRecord
  ContactProblem<3>::compute_reactions(const ContactZoneRecord &zone) const;
} // namespace dualcontact
