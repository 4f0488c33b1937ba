// The equilibrium of the bodies that a contact pair alone holds
// (doc/two_bodies.md): their loads must press them onto the other body of
// their pair, and where the pair is flat friction must resist the loads'
// tangential part. The whole mesh's checks against the obstacle are
// ContactProblem::check_equilibrium().
#include <deal.II/base/mpi.h>

#include <deal.II/fe/fe.h>

#include <dualcontact/bodies.h>
#include <dualcontact/input_error.h>
#include <dualcontact/pair_equilibrium.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <set>
#include <string>
#include <vector>

namespace dualcontact
{
  namespace
  {
    /**
     * The bodies of a mesh of several as check_pair_bodies() sees them, per
     * body b: whether a support (1) or an obstacle (2) holds it, its
     * boundary ids, its load, the direction its pair's normals give, the
     * bodies it shares a pair with, sum_s m_s and sum_s m_s p_s over its
     * pair's nodes, their largest friction parameter and how far their
     * normals turn from their mean; per contact node its slave and master
     * body (n_bodies: an obstacle's node).
     */
    struct PairBodies
    {
      unsigned int                              n_bodies;
      std::vector<unsigned int>                 held;
      std::vector<std::set<types::boundary_id>> ids;
      std::vector<double>                       load;
      std::vector<double>                       direction;
      std::vector<unsigned int>                 pair_sides;
      std::vector<double>                       measure;
      std::vector<double>                       largest_parameter;
      std::vector<std::array<unsigned int, 2>>  sides;
      std::vector<double>                       turn;
    };

    /**
     * The direction each body must be pressed along, the pairs it is in and
     * the measure and friction parameters of their nodes; an obstacle's
     * contact node holds its body. `bodies`: each DoF's body + 1, the
     * masters' DoFs included.
     */
    template <int dim>
    void
    add_pair_sides(const ContactSet<dim>               &contact_set,
                   const TrilinosWrappers::MPI::Vector &bodies,
                   const MPI_Comm                       mpi_communicator,
                   PairBodies                          &p)
    {
      const unsigned int         n_bodies             = p.n_bodies;
      std::vector<unsigned int> &held                 = p.held;
      std::vector<double>       &load                 = p.load;
      std::vector<double>       &direction            = p.direction;
      std::vector<unsigned int> &pair_sides           = p.pair_sides;
      std::vector<double>       &measure              = p.measure;
      std::vector<double>       &largest_parameter    = p.largest_parameter;
      std::vector<std::array<unsigned int, 2>> &sides = p.sides;
      direction.assign(n_bodies * dim, 0.);
      pair_sides.assign(n_bodies * n_bodies, 0);
      // per body: sum_s m_s, sum_s m_s p_s over its pair's nodes
      measure.assign(2 * n_bodies, 0.);
      largest_parameter.assign(n_bodies, 0.);
      sides.assign(contact_set.n_local_nodes(), {{n_bodies, n_bodies}});
      for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
        {
          const ContactNode<dim> &node = contact_set.nodes[s];
          const unsigned int      slave =
            static_cast<unsigned int>(bodies[node.dofs[0]]) - 1;
          if (node.masters.empty())
            {
              held[slave] = 2;
              continue;
            }
          const unsigned int master =
            static_cast<unsigned int>(bodies[node.masters[0].dofs[0]]) - 1;
          sides[s]                              = {{slave, master}};
          pair_sides[slave * n_bodies + master] = 1;
          pair_sides[master * n_bodies + slave] = 1;
          for (const unsigned int b : {slave, master})
            {
              measure[2 * b] += node.weight;
              measure[2 * b + 1] +=
                node.weight * contact_set.friction_parameter[s];
              largest_parameter[b] =
                std::max(largest_parameter[b],
                         contact_set.friction_parameter[s]);
            }
          for (unsigned int c = 0; c < dim; ++c)
            {
              direction[slave * dim + c] += node.weight * node.normal[c];
              direction[master * dim + c] -= node.weight * node.normal[c];
            }
        }
      Utilities::MPI::sum(load, mpi_communicator, load);
      Utilities::MPI::sum(direction, mpi_communicator, direction);
      Utilities::MPI::sum(measure, mpi_communicator, measure);
      Utilities::MPI::max(largest_parameter,
                          mpi_communicator,
                          largest_parameter);
      Utilities::MPI::max(held, mpi_communicator, held);
      Utilities::MPI::max(pair_sides, mpi_communicator, pair_sides);
    }

    /**
     * How far the pair's normals of each body turn from their mean (0 on a
     * flat pair): sum_s m_s |n_s -+ d| over its nodes.
     */
    template <int dim>
    void
    add_normal_turn(const ContactSet<dim> &contact_set,
                    const MPI_Comm         mpi_communicator,
                    PairBodies            &p)
    {
      const unsigned int                              n_bodies  = p.n_bodies;
      const std::vector<double>                      &direction = p.direction;
      const std::vector<std::array<unsigned int, 2>> &sides     = p.sides;
      std::vector<double>                            &turn      = p.turn;
      turn.assign(n_bodies, 0.);
      for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
        for (unsigned int side = 0; side < 2; ++side)
          {
            const unsigned int b = sides[s][side];
            if (b == n_bodies)
              continue;
            Tensor<1, dim> d;
            for (unsigned int c = 0; c < dim; ++c)
              d[c] = direction[b * dim + c];
            if (d.norm() > 0.)
              turn[b] += contact_set.nodes[s].weight *
                         ((side == 0 ? 1. : -1.) * contact_set.nodes[s].normal -
                          d / d.norm())
                           .norm();
          }
      Utilities::MPI::sum(turn, mpi_communicator, turn);
    }

    /** The largest of the bodies' loads, max_b |f_b|. */
    template <int dim>
    double
    largest_load(const PairBodies &p)
    {
      const std::vector<double> &load    = p.load;
      double                     largest = 0.;
      for (unsigned int b = 0; b < p.n_bodies; ++b)
        {
          double size = 0.;
          for (unsigned int c = 0; c < dim; ++c)
            size += load[b * dim + c] * load[b * dim + c];
          largest = std::max(largest, std::sqrt(size));
        }
      return largest;
    }

    /**
     * The pressure at which the contact pair of body `b` holds it by
     * friction alone (0: something else holds it, or its loads need none),
     * after checking that its loads press it onto the other body and that
     * friction can resist their tangential part (InputError otherwise).
     */
    template <int dim>
    double
    pair_pressure_of_body(const unsigned int        b,
                          const PairBodies         &p,
                          const double              largest,
                          const Scene<dim>         &scene,
                          const Triangulation<dim> &triangulation,
                          const Bodies<dim>        &bodies,
                          const MPI_Comm            mpi_communicator)
    {
      const unsigned int               n_bodies          = p.n_bodies;
      const std::vector<unsigned int> &held              = p.held;
      const auto                      &ids               = p.ids;
      const std::vector<double>       &load              = p.load;
      const std::vector<double>       &direction         = p.direction;
      const std::vector<unsigned int> &pair_sides        = p.pair_sides;
      const std::vector<double>       &measure           = p.measure;
      const std::vector<double>       &largest_parameter = p.largest_parameter;
      const std::vector<double>       &turn              = p.turn;
      const unsigned int               partners =
        std::accumulate(pair_sides.begin() + b * n_bodies,
                        pair_sides.begin() + (b + 1) * n_bodies,
                        0u);
      if (held[b] == 2 || partners != 1)
        return 0.;
      Tensor<1, dim> d, f;
      for (unsigned int c = 0; c < dim; ++c)
        {
          d[c] = direction[b * dim + c];
          f[c] = load[b * dim + c];
        }
      if (!(d.norm() > 0.))
        return 0.;
      const bool supported = held[b] == 1;
      if (supported &&
          !scene.translation_is_free(d / d.norm(), triangulation, &bodies, b))
        return 0.;
      // a body without load rests, or parts from the other body; one that
      // supports hold sideways, without load along d
      const double toward = f * d / d.norm();
      if (!(f.norm() > 1e-10 * largest) ||
          (supported && !(std::abs(toward) > 1e-10 * largest)))
        return 0.;
      // the body by its boundary ids, as the user knows it
      const auto body_name = [&]() {
        std::set<types::boundary_id> all_ids;
        for (const auto &part : Utilities::MPI::all_gather(
               mpi_communicator,
               std::vector<types::boundary_id>(ids[b].begin(), ids[b].end())))
          all_ids.insert(part.begin(), part.end());
        std::string names;
        for (const types::boundary_id id : all_ids)
          names += (names.empty() ? "" : ", ") + std::to_string(id);
        return "the body with boundary ids " + names;
      };
      if (!(toward > 1e-10 * f.norm()))
        {
          std::string force;
          for (unsigned int c = 0; c < dim; ++c)
            force += (c == 0 ? "(" : ", ") + format_number(f[c]);
          throw InputError(
            "No equilibrium: " +
              (supported ? "the supports of " + body_name() +
                             " leave it free to move along the normal of "
                             "its contact pair" :
                           "nothing holds " + body_name() +
                             " (no 'fixed' or 'normal fixed' id, no "
                             "obstacle)") +
              ", and its loads " + force +
              ") do not press it onto the other body of its contact pair: "
              "only that contact could hold it, and it can only push. Hold "
              "the body (<Boundary conditions/Conditions>) or load it toward "
              "the other body.",
            exit_no_equilibrium);
        }
      if (supported)
        return 0.;
      // the tangential part, on a flat pair (a curved one also holds it
      // by its normal pressure)
      if (turn[b] > 1e-8 * measure[2 * b])
        return 0.;
      const double tangential = (f - toward * d / d.norm()).norm();
      if (!(tangential > 1e-10 * f.norm()))
        return 0.;
      std::string  why;
      const double capacity = scene.effects().friction_law().capacity(
        measure[2 * b + 1], largest_parameter[b], toward, why);
      if (capacity >= 0. &&
          tangential > capacity * (1. + 1e-10) + 1e-10 * f.norm())
        throw InputError(
          "No equilibrium: the net tangential load " +
            format_number(tangential) + " on " + body_name() +
            " exceeds what friction can resist, " + format_number(capacity) +
            " (" + why +
            "), and only friction holds it along the other body of its "
            "contact pair (a flat one, and nothing else holds the body). "
            "Reduce the tangential load, raise <Friction/Coefficient>, or "
            "hold the body (<Boundary conditions/Conditions>).",
          exit_no_equilibrium);
      return toward / measure[2 * b];
    }
    /**
     * Each body's boundary ids, whether a support holds it, and its loads
     * (`system_rhs` summed by body and component), into `p`.
     * `body_plus_one`: each owned DoF's body + 1.
     */
    template <int dim>
    void
    add_held_and_loads(const DoFHandler<dim>               &dof_handler,
                       const Bodies<dim>                   &bodies,
                       const TrilinosWrappers::MPI::Vector &body_plus_one,
                       const TrilinosWrappers::MPI::Vector &system_rhs,
                       const Scene<dim>                    &scene,
                       PairBodies                          &pair_bodies)
    {
      const IndexSet &locally_owned_dofs    = dof_handler.locally_owned_dofs();
      const FiniteElement<dim>    &fe       = dof_handler.get_fe();
      const unsigned int           n_bodies = pair_bodies.n_bodies;
      std::set<types::boundary_id> supports;
      for (const BoundaryCondition condition :
           {BoundaryCondition::fixed, BoundaryCondition::normal_fixed})
        for (const types::boundary_id id : scene.ids_with(condition))
          supports.insert(id);

      // each owned DoF's body (+1) and component; the bodies' ids and
      // supports; the loads on each body
      std::vector<unsigned int> component(locally_owned_dofs.n_elements());
      // 1 where a support holds the body, 2 where an obstacle does
      std::vector<unsigned int> &held = pair_bodies.held;
      held.assign(n_bodies, 0);
      std::vector<std::set<types::boundary_id>> &ids = pair_bodies.ids;
      ids.resize(n_bodies);
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const unsigned int body = bodies.of(cell);
            cell->get_dof_indices(dofs);
            for (unsigned int k = 0; k < dofs.size(); ++k)
              if (locally_owned_dofs.is_element(dofs[k]))
                component[locally_owned_dofs.index_within_set(dofs[k])] =
                  fe.system_to_component_index(k).first;
            for (const auto &face : cell->face_iterators())
              if (face->at_boundary())
                {
                  ids[body].insert(face->boundary_id());
                  if (supports.count(face->boundary_id()))
                    held[body] = 1;
                }
          }
      std::vector<double> &load = pair_bodies.load;
      load.assign(n_bodies * dim, 0.);
      for (unsigned int k = 0; k < locally_owned_dofs.n_elements(); ++k)
        {
          const auto i = locally_owned_dofs.nth_index_in_set(k);
          load[(static_cast<unsigned int>(body_plus_one[i]) - 1) * dim +
               component[k]] += system_rhs[i];
        }
    }

  } // namespace

  template <int dim>
  std::vector<double>
  check_pair_bodies(const ContactSet<dim>               &contact_set,
                    const DoFHandler<dim>               &dof_handler,
                    const TrilinosWrappers::MPI::Vector &system_rhs,
                    const Scene<dim>                    &scene)
  {
    // A body that no support ('fixed', 'normal fixed') and no obstacle
    // holds, and that touches the rest through one contact pair only, is
    // held by that contact alone: its loads must press it onto the other
    // body, along n_s (the slave nodes' contact direction) if it is the
    // slave, along -n_s if it is the master. Otherwise the contact would
    // have to pull, and the iterations would wander with the proximal term.
    // So must the loads of a body whose supports leave it free to move
    // along that direction (sliders that hold it sideways only).
    // A body without load rests (or parts from the other body). Where the
    // pair is flat, friction alone holds the loads' tangential part, as
    // against a plane obstacle: no more than the friction law can resist,
    // and the threshold iteration starts from the mean pressure of the
    // pair, since g = 0 could not hold it.
    std::vector<double> held_pressure;
    if (!contact_set.has_pairs())
      return held_pressure;
    const Triangulation<dim> &triangulation = dof_handler.get_triangulation();
    const MPI_Comm     mpi_communicator     = triangulation.get_communicator();
    const Bodies<dim>  bodies(triangulation);
    const unsigned int n_bodies = bodies.size();
    const TrilinosWrappers::MPI::Vector body_plus_one =
      bodies.of_dofs_plus_one(dof_handler);
    PairBodies pair_bodies;
    pair_bodies.n_bodies = n_bodies;
    add_held_and_loads(
      dof_handler, bodies, body_plus_one, system_rhs, scene, pair_bodies);

    // the direction each body must be pressed along, the pairs it is in
    // and the measure and friction parameters of their nodes
    add_pair_sides(contact_set,
                   contact_set.with_masters(body_plus_one),
                   mpi_communicator,
                   pair_bodies);
    add_normal_turn(contact_set, mpi_communicator, pair_bodies);

    const double        largest = largest_load<dim>(pair_bodies);
    std::vector<double> pair_pressure(n_bodies, 0.);
    for (unsigned int b = 0; b < n_bodies; ++b)
      pair_pressure[b] = pair_pressure_of_body(b,
                                               pair_bodies,
                                               largest,
                                               scene,
                                               triangulation,
                                               bodies,
                                               mpi_communicator);

    // the start pressure at the nodes of each pair that holds a body by
    // friction alone
    if (std::any_of(pair_pressure.begin(),
                    pair_pressure.end(),
                    [](const double p) { return p > 0.; }))
      {
        held_pressure.resize(contact_set.n_local_nodes(), 0.);
        for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
          for (const unsigned int b : pair_bodies.sides[s])
            if (b < n_bodies)
              held_pressure[s] = std::max(held_pressure[s], pair_pressure[b]);
      }
    return held_pressure;
  }


  template std::vector<double>
  check_pair_bodies(const ContactSet<2> &,
                    const DoFHandler<2> &,
                    const TrilinosWrappers::MPI::Vector &,
                    const Scene<2> &);
  template std::vector<double>
  check_pair_bodies(const ContactSet<3> &,
                    const DoFHandler<3> &,
                    const TrilinosWrappers::MPI::Vector &,
                    const Scene<3> &);
} // namespace dualcontact
