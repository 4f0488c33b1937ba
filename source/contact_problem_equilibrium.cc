// ContactProblem, the equilibrium checks: before a contact solve, whether
// the obstacle and friction can hold the loads at all (the net load toward
// the obstacle, the tangential load against what friction can resist, the
// moment that would tip the body over); after it, the balance of the loads
// and the reactions. A load that cannot be held is refused with exit status
// 7 instead of being left to the iterations to diverge on.
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
#include <dualcontact/plausibility.h>
#include <dualcontact/postprocess.h>
#include <dualcontact/refinement.h>
#include <dualcontact/refinement_indicator.h>
#include <dualcontact/run_size.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <numeric>
#include <set>

namespace dualcontact
{
  template <int dim>
  double
  ContactProblem<dim>::net_load(const Tensor<1, dim> &direction) const
  {
    // b . E, E the nodal vector of the rigid translation along `direction`
    TrilinosWrappers::MPI::Vector translation(locally_owned_dofs,
                                              mpi_communicator);
    for (unsigned int c = 0; c < dim; ++c)
      {
        ComponentMask mask(dim, false);
        mask.set(c, true);
        for (const auto i : DoFTools::extract_dofs(dof_handler, mask))
          translation[i] = direction[c];
      }
    translation.compress(VectorOperation::insert);
    return system_rhs * translation;
  }

  template <int dim>
  std::vector<double>
  ContactProblem<dim>::check_equilibrium() const
  {
    // A translation that only the contact can stop must be balanced by
    // contact forces: they push along m (never pull) and their tangential
    // part is at most what the friction law can resist. Necessary
    // conditions, checked before solving so that an impossible load never
    // loops (doc/theory.md §8). The obstacle's checks see the whole mesh
    // (its bodies held together by their pairs) and the obstacle's contact
    // nodes; each body held by a pair alone is checked on its own.
    std::vector<double> held_pressure;
    if (contact_set.has_pairs())
      check_pair_bodies(held_pressure);
    const auto on_obstacle = [this](const unsigned int s) {
      return contact_set.nodes[s].masters.empty();
    };
    unsigned int n_obstacle = 0;
    for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
      n_obstacle += on_obstacle(s);
    if (Utilities::MPI::sum(n_obstacle, mpi_communicator) == 0)
      return held_pressure;

    const Tensor<1, dim> m = -contact_set.normal; // into the body
    LoadBalance          balance;
    Tensor<1, dim>       resultant;
    for (unsigned int d = 0; d < dim; ++d)
      {
        Tensor<1, dim> e;
        e[d]         = 1.;
        resultant[d] = net_load(e);
      }
    balance.resultant   = resultant.norm();
    balance.normal_free = scene.translation_is_free(m, triangulation);
    balance.load_away   = net_load(m);

    // what the friction law can resist: from sum_s m_s p_s, max_s p_s (p
    // its parameter) and the normal load, over the obstacle's nodes
    double weighted = 0., largest = 0., measure = 0.;
    for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
      if (on_obstacle(s))
        {
          weighted +=
            contact_set.nodes[s].weight * contact_set.friction_parameter[s];
          largest = std::max(largest, contact_set.friction_parameter[s]);
          measure += contact_set.nodes[s].weight;
        }
    measure = Utilities::MPI::sum(measure, mpi_communicator);

    // N / |Gamma_C| if only friction holds a tangential load and N is known
    // (on a plane: a curved obstacle also holds tangential loads by its
    // normal pressure)
    double     pressure = 0.;
    const bool plane    = scene.obstacle()->is_plane();
    for (const Tensor<1, dim> &t : contact_set.tangents)
      if (plane && scene.translation_is_free(t, triangulation))
        {
          const double load = std::abs(net_load(t));
          balance.tangential_loads.push_back(load);
          if (balance.normal_free && load > 1e-10 * balance.resultant)
            pressure = -balance.load_away / measure;
        }

    std::string  why;
    const double capacity = scene.effects().friction_law().capacity(
      Utilities::MPI::sum(weighted, mpi_communicator),
      Utilities::MPI::max(largest, mpi_communicator),
      balance.normal_free ? -balance.load_away : -1.,
      why);
    dualcontact::check_equilibrium(balance, capacity, why);
    if (balance.normal_free && plane)
      check_moment(balance);
    if (pressure > 0.)
      {
        held_pressure.resize(contact_set.n_local_nodes(), 0.);
        for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
          if (on_obstacle(s))
            held_pressure[s] = pressure;
      }
    return held_pressure;
  }

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
    pair_pressure_of_body(const unsigned int               b,
                          const PairBodies                &p,
                          const double                     largest,
                          const Scene<dim>                &scene,
                          const Triangulation<dim>        &triangulation,
                          const std::vector<unsigned int> &body_of_coarse_cell,
                          const MPI_Comm                   mpi_communicator)
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
      if (supported && !scene.translation_is_free(
                         d / d.norm(), triangulation, &body_of_coarse_cell, b))
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
     * The error of loads that tip the body over: the line of action of
     * their resultant meets the foundation at `centre`, `outside` outside
     * the hull of the contact nodes. Points of the plane are told as
     * coordinates.
     */
    template <int dim>
    [[noreturn]] void
    throw_tipped_over(const Point<dim>                         &origin,
                      const ContactSet<dim>                    &contact_set,
                      const double                              flat,
                      const double                              N,
                      const std::array<double, 2>              &centre,
                      const double                              outside,
                      const std::vector<std::array<double, 2>> &hull)
    {
      const auto on_plane = [&](const std::array<double, 2> &p) {
        Point<dim> x = origin;
        for (unsigned int k = 0; k < dim - 1; ++k)
          x += p[k] * contact_set.tangents[k];
        std::ostringstream out;
        out << "(";
        for (unsigned int c = 0; c < dim; ++c)
          out << (c > 0 ? ", " : "") << std::setprecision(4)
              << (std::abs(x[c]) < flat ? 0. : x[c]);
        return out.str() + ")";
      };
      std::ostringstream text;
      text << "No equilibrium: the loads tip the body over. Only the contact "
              "holds the body, and it can only push: the loads press it onto "
              "the foundation with "
           << format_number(N)
           << ", but the line of action of their resultant meets the "
              "foundation at "
           << on_plane(centre) << ", " << format_number(outside)
           << " outside the contact boundary's "
           << (dim == 2 ? "extent on it, from " + on_plane(hull.front()) +
                            " to " + on_plane(hull.back()) :
                          std::string("convex hull on it"))
           << ", so no contact pressure balances their moment. Reduce the "
              "tangential loads or their lever arm, or hold the body "
              "(<Boundary conditions/Conditions>).";
      throw InputError(text.str(), exit_no_equilibrium);
    }
  } // namespace

  template <int dim>
  void
  ContactProblem<dim>::check_pair_bodies(
    std::vector<double> &held_pressure) const
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
    const std::vector<unsigned int> body_of_coarse_cell =
      bodies_of_coarse_cells(triangulation);
    const unsigned int n_bodies =
      1 +
      *std::max_element(body_of_coarse_cell.begin(), body_of_coarse_cell.end());
    std::set<types::boundary_id> supports;
    for (const BoundaryCondition condition :
         {BoundaryCondition::fixed, BoundaryCondition::normal_fixed})
      for (const types::boundary_id id : scene.ids_with(condition))
        supports.insert(id);

    // each owned DoF's body (+1) and component; the bodies' ids and
    // supports; the loads on each body
    const TrilinosWrappers::MPI::Vector body_plus_one =
      bodies_of_dofs(body_of_coarse_cell);
    std::vector<unsigned int> component(locally_owned_dofs.n_elements());
    PairBodies                pair_bodies;
    pair_bodies.n_bodies = n_bodies;
    // 1 where a support holds the body, 2 where an obstacle does
    std::vector<unsigned int> &held = pair_bodies.held;
    held.assign(n_bodies, 0);
    std::vector<std::set<types::boundary_id>> &ids = pair_bodies.ids;
    ids.resize(n_bodies);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const unsigned int body = body_of<dim>(cell, body_of_coarse_cell);
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
                                               body_of_coarse_cell,
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
  }

  template <int dim>
  void
  ContactProblem<dim>::check_moment(const LoadBalance &balance) const
  {
    // Where only the contact holds the body (no prescribed displacement
    // holds any rigid motion), the contact forces must also balance the
    // loads' moment. On a plane they push along m at the nodes of Gamma_C;
    // their friction parts lie in the plane, and where the nodes lie on it
    // their moment about a point O of the plane is normal to it. So the
    // loads' moment M about O, normal part aside, is balanced by pressures
    // alone: their centre c = O + (M x m) / N must lie in the convex hull
    // of the nodes, N the load toward the plane. Without friction the
    // nodes may lie anywhere on Gamma_C (only their projections count);
    // with friction off the plane a tangential force has a lever arm, and
    // the check cannot decide (doc/theory.md §8).
    double     measure = 0.;
    const auto gram    = scene.rigid_motion_gram(triangulation, measure);
    if (gram.frobenius_norm() > 1e-12 * std::max(measure, 1e-300))
      return;
    const double N = -balance.load_away;
    if (!(N > 1e-10 * balance.resultant))
      return;
    const double         length = scene.characteristic_length();
    const double         flat   = 1e-8 * length;
    const Tensor<1, dim> m      = -contact_set.normal; // into the body
    // O: the body's centre moved onto the plane along m
    Point<dim> origin = scene.center();
    origin -= scene.initial_gap(origin) * m;
    bool                               off_plane = false;
    std::vector<std::array<double, 2>> points;
    for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
      {
        const ContactNode<dim> &node = contact_set.nodes[s];
        // the obstacle's nodes: a pair's are inside the mesh it holds
        if (!node.masters.empty())
          continue;
        off_plane = off_plane || node.gap0 > flat;
        std::array<double, 2> p{};
        for (unsigned int k = 0; k < dim - 1; ++k)
          p[k] = contact_set.tangents[k] * (node.position - origin);
        points.push_back(p);
      }
    if (Utilities::MPI::logical_or(off_plane, mpi_communicator) &&
        contact_set.friction)
      return;
    // each rank's hull, then the hull of theirs
    std::vector<double> local;
    for (const auto &p : convex_hull(points, dim - 1))
      local.insert(local.end(), p.begin(), p.end());
    std::vector<std::array<double, 2>> hull;
    for (const auto &part : Utilities::MPI::all_gather(mpi_communicator, local))
      for (std::size_t i = 0; i + 1 < part.size(); i += 2)
        hull.push_back(std::array<double, 2>{{part[i], part[i + 1]}});
    hull = convex_hull(hull, dim - 1);

    // M about O: b . R_k for the rigid rotations R_k(x) = e_k x (x - O)
    // (in 2D the one about the normal of the plane)
    const unsigned int n_rotations = dim == 2 ? 1 : 3;
    Tensor<1, 3>       moment;
    const IndexSet    &owned = locally_owned_dofs;
    for (unsigned int k = 0; k < n_rotations; ++k)
      {
        TrilinosWrappers::MPI::Vector rotation(owned, mpi_communicator);
        const unsigned int            axis = dim == 2 ? 2 : k;
        interpolate_field<dim>(
          mapping,
          dof_handler,
          [&origin, axis](const Point<dim> &x) {
            const Tensor<1, dim> r   = x - origin;
            const double       r3[3] = {r[0], r[1], dim == 3 ? r[dim - 1] : 0.};
            const unsigned int a = (axis + 1) % 3, b = (axis + 2) % 3;
            Tensor<1, 3>       u; // e_axis x r, r in 3D
            u[a] = -r3[b];
            u[b] = r3[a];
            Tensor<1, dim> value;
            for (unsigned int c = 0; c < dim; ++c)
              value[c] = u[c];
            return value;
          },
          rotation);
        moment[dim == 2 ? 2 : k] = system_rhs * rotation;
      }
    Tensor<1, 3> m3;
    for (unsigned int c = 0; c < dim; ++c)
      m3[c] = m[c];
    const Tensor<1, 3>    offset = cross_product_3d(moment, m3) / N;
    std::array<double, 2> centre{};
    for (unsigned int k = 0; k < dim - 1; ++k)
      for (unsigned int c = 0; c < dim; ++c)
        centre[k] += contact_set.tangents[k][c] * offset[c];
    const double outside = distance_outside_hull(hull, centre, dim - 1);
    if (!(outside > flat))
      return;

    throw_tipped_over(origin, contact_set, flat, N, centre, outside, hull);
  }

  template <int dim>
  void
  ContactProblem<dim>::check_balance(const ReactionRecord &reactions) const
  {
    // The converged solution balances the loads up to the solver
    // tolerances (1e-14 to 1e-10 on the shipped scenes, doc/theory.md §8);
    // a solve that stopped on its tests without balancing them (a proximal
    // weight so large that v never moves, say) is not a solution.
    const double tolerance =
      std::clamp(1e2 * parameters.solver.uzawa_tolerance, 1e-6, 1e-2);
    if (!(reactions.imbalance <= tolerance))
      AssertThrow(
        false,
        ExcMessage("The solution does not balance the loads: contact "
                   "force, reactions and applied loads sum to " +
                   format_number(reactions.imbalance) +
                   " of the largest of them (at most " +
                   format_number(tolerance) + " for <Solver/Uzawa tolerance> " +
                   format_number(parameters.solver.uzawa_tolerance) +
                   "). The solver stopped without a solution: check "
                   "<Solver/Proximal parameter> and <Solver/Augmentation "
                   "parameter> (their defaults suit every scene)."));
  }


  template double
  ContactProblem<2>::net_load(const Tensor<1, 2> &direction) const;
  template double
  ContactProblem<3>::net_load(const Tensor<1, 3> &direction) const;
  template std::vector<double>
  ContactProblem<2>::check_equilibrium() const;
  template std::vector<double>
  ContactProblem<3>::check_equilibrium() const;
  template void
  ContactProblem<2>::check_pair_bodies(std::vector<double> &) const;
  template void
  ContactProblem<3>::check_pair_bodies(std::vector<double> &) const;
  template void
  ContactProblem<2>::check_moment(const LoadBalance &balance) const;
  template void
  ContactProblem<3>::check_moment(const LoadBalance &balance) const;
  template void
  ContactProblem<2>::check_balance(const ReactionRecord &reactions) const;
  template void
  ContactProblem<3>::check_balance(const ReactionRecord &reactions) const;
} // namespace dualcontact
