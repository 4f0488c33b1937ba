#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_values.h>

#include <dualcontact/contact_set.h>
#include <dualcontact/discretization.h>
#include <dualcontact/input_error.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

namespace dualcontact
{
  template <int dim>
  void
  ContactSet<dim>::setup(
    const Mapping<dim>              &mapping,
    const DoFHandler<dim>           &dof_handler,
    const AffineConstraints<double> &hanging_node_constraints,
    const AffineConstraints<double> &all_constraints,
    const ContactSetup<dim>         &input)
  {
    const MPI_Comm  comm  = dof_handler.get_triangulation().get_communicator();
    const IndexSet &owned = dof_handler.locally_owned_dofs();
    // the slave ids of the contact pairs
    std::map<types::global_dof_index, types::boundary_id> slave_id_of;

    obstacle              = input.obstacle;
    characteristic_length = input.characteristic_length;
    center                = input.center;
    pairs_.reinit(input.pairs, input.node_to_segment);

    // Weights m_s = int_{Gamma_C} phi_s, with the weight of hanging nodes
    // handed to their masters, and the body's outward normals at the nodes
    // (find_candidates()).
    TrilinosWrappers::MPI::Vector weights(owned, comm);
    TrilinosWrappers::MPI::Vector body_normals(owned, comm);
    double                        h_min = std::numeric_limits<double>::max();
    std::map<types::global_dof_index, ContactNode<dim>> candidates =
      find_candidates(mapping,
                      dof_handler,
                      hanging_node_constraints,
                      input.contact_ids,
                      weights,
                      body_normals,
                      slave_id_of,
                      h_min);

    nodes.clear();
    types::global_dof_index hanging = 0;
    for (auto &[key, node] : candidates)
      {
        if (!owned.is_element(key))
          continue;
        if (hanging_node_constraints.is_constrained(key))
          {
            ++hanging;
            continue;
          }
        bool any_free = false;
        for (unsigned int c = 0; c < dim; ++c)
          any_free |= !all_constraints.is_constrained(node.dofs[c]);
        if (!any_free || !(weights[key] > 0.))
          continue;
        node.weight = weights[key];
        for (unsigned int c = 0; c < dim; ++c)
          node.body_normal[c] = body_normals[node.dofs[c]];
        if (node.body_normal.norm() > 0.)
          node.body_normal /= node.body_normal.norm();
        nodes.push_back(node);
      }
    pairs_.couple(mapping,
                  dof_handler,
                  hanging_node_constraints,
                  all_constraints,
                  slave_id_of,
                  nodes);
    place_obstacle(*input.obstacle, comm);

    l1.assign(nodes.size(), 0.);
    statuses.assign(nodes.size(), separated);
    slip_origin.assign(nodes.size(), Tensor<1, dim - 1>());
    set_friction(input, comm);

    n_global = Utilities::MPI::sum<types::global_dof_index>(nodes.size(), comm);
    n_hanging            = Utilities::MPI::sum(hanging, comm);
    h_min_               = Utilities::MPI::min(h_min, comm);
    double local_measure = 0;
    for (const auto &node : nodes)
      local_measure += node.weight;
    measure_ = Utilities::MPI::sum(local_measure, comm);
  }

  template <int dim>
  std::map<types::global_dof_index, ContactNode<dim>>
  ContactSet<dim>::find_candidates(
    const Mapping<dim>                                    &mapping,
    const DoFHandler<dim>                                 &dof_handler,
    const AffineConstraints<double>                       &hanging,
    const std::set<types::boundary_id>                    &contact_ids,
    TrilinosWrappers::MPI::Vector                         &weights,
    TrilinosWrappers::MPI::Vector                         &body_normals,
    std::map<types::global_dof_index, types::boundary_id> &slave_id_of,
    double                                                &h_min) const
  {
    const FiniteElement<dim> &fe = dof_handler.get_fe();
    // Every component carries the same weight. The body's outward normal
    // at a node, the mean int_{Gamma_C} phi_s nu of the faces' normals, is
    // assembled alike, component c of it on the node's DoF of component c.
    const Quadrature<dim - 1> quadrature = face_quadrature(fe, fe.degree + 1);
    FEFaceValues<dim>         fe_face(mapping,
                              fe,
                              quadrature,
                              update_values | update_normal_vectors |
                                update_JxW_values);
    Vector<double>            local_weights(fe.n_dofs_per_cell());
    Vector<double>            local_normals(fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());

    // Candidate nodes: cell-local support points on contact faces (as
    // support_on_face() finds them: on a triangle not the vertex opposite
    // the face), grouped by their scalar shape function (the "base"
    // index), from the owned and the ghost cells: a node this rank owns
    // may lie on contact faces of other ranks' cells only (a vertex of a
    // triangle fan whose owned triangle touches Gamma_C at that vertex
    // alone). Weights and normals come from the owned cells, summed over
    // the ranks.
    std::map<types::global_dof_index, ContactNode<dim>> candidates;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() || cell->is_ghost())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              contact_ids.count(cell->face(f)->boundary_id()))
            {
              cell->get_dof_indices(dof_indices);
              if (cell->is_locally_owned())
                {
                  h_min = std::min(h_min, cell->face(f)->diameter());
                  fe_face.reinit(cell, f);
                  local_weights = 0;
                  local_normals = 0;
                  for (const unsigned int q :
                       fe_face.quadrature_point_indices())
                    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                      {
                        const double phi_dx =
                          fe_face.shape_value(i, q) * fe_face.JxW(q);
                        local_weights(i) += phi_dx;
                        local_normals(i) +=
                          phi_dx * fe_face.normal_vector(
                                     q)[fe.system_to_component_index(i).first];
                      }
                  hanging.distribute_local_to_global(local_weights,
                                                     dof_indices,
                                                     weights);
                  hanging.distribute_local_to_global(local_normals,
                                                     dof_indices,
                                                     body_normals);
                }

              std::map<unsigned int, ContactNode<dim>> on_face;
              for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                if (support_on_face(fe, i, f))
                  {
                    const auto [component, base] =
                      fe.system_to_component_index(i);
                    ContactNode<dim> &node = on_face[base];
                    node.dofs[component]   = dof_indices[i];
                    if (component == 0)
                      node.position = mapping.transform_unit_to_real_cell(
                        cell, fe.unit_support_point(i));
                  }
              for (const auto &[base, node] : on_face)
                {
                  candidates.emplace(node.dofs[0], node);
                  if (pairs_.is_slave(cell->face(f)->boundary_id()))
                    slave_id_of[node.dofs[0]] = cell->face(f)->boundary_id();
                }
            }
    weights.compress(VectorOperation::add);
    body_normals.compress(VectorOperation::add);
    return candidates;
  }

  template <int dim>
  void
  ContactSet<dim>::set_friction(const ContactSetup<dim> &input,
                                const MPI_Comm           comm)
  {
    // Friction data at the nodes: the law's parameter (F or g), never
    // negative, and the threshold it gives at zero pressure.
    law      = input.friction_law;
    friction = law->has_friction();
    l2.assign(nodes.size(), Tensor<1, dim - 1>());
    threshold.assign(nodes.size(), 0.);
    friction_parameter.assign(nodes.size(), 0.);
    if (friction)
      {
        double       smallest   = 0.;
        unsigned int not_finite = 0;
        for (unsigned int s = 0; s < nodes.size(); ++s)
          {
            const double value =
              input.friction_parameter->value(nodes[s].position);
            not_finite += !std::isfinite(value);
            smallest              = std::min(smallest, value);
            friction_parameter[s] = value;
            threshold[s]          = law->threshold(value, 0.);
          }
        if (Utilities::MPI::sum(not_finite, comm) > 0)
          throw InputError("The entry <Friction/" + law->parameter_entry() +
                             "> is not a finite number (NaN or infinity) "
                             "at " +
                             std::to_string(
                               Utilities::MPI::sum(not_finite, comm)) +
                             " contact node(s).",
                           exit_invalid_value);
        if (Utilities::MPI::min(smallest, comm) < 0.)
          throw InputError("The entry <Friction/" + law->parameter_entry() +
                             "> is negative at some contact node.",
                           exit_invalid_value);
      }
  }

  template <int dim>
  void
  ContactSet<dim>::place_obstacle(const PlacedObstacle<dim> &obstacle,
                                  const MPI_Comm             comm)
  {
    this->obstacle         = &obstacle;
    unsigned int no_normal = 0, corners = 0;
    for (auto &node : nodes)
      {
        // a paired node's gap and normal are the pair's
        // (ContactPairs::couple())
        if (!node.masters.empty())
          continue;
        node.gap0                            = obstacle.distance(node.position);
        std::tie(node.normal, node.tangents) = basis_at(node.position);
        // Where the obstacle's nearest point is a corner or an edge, its
        // normal (from the corner toward the node) is no normal of its
        // surface: a smooth surface touched by a corner is pushed along its
        // own normal, and the gap stays the distance to the corner
        // (doc/theory.md §10). The classical punch problems keep the
        // surface beside the punch free, as this does; the direction from
        // the corner would turn the punch's side into a wall that the
        // surface beside it meets.
        if (obstacle.has_corner_near(node.position) &&
            node.body_normal.norm() > 0.5)
          {
            node.normal   = node.body_normal;
            node.tangents = tangent_basis(node.normal);
            ++corners;
          }
        if (!(node.normal.norm() > 0.5))
          ++no_normal;
      }
    n_corner = Utilities::MPI::sum(corners, comm);
    if (Utilities::MPI::sum(no_normal, comm) > 0)
      throw InputError(
        "The obstacle has no usable normal at " +
          std::to_string(Utilities::MPI::sum(no_normal, comm)) +
          " contact node(s): the gradient of its distance is zero or not "
          "finite there (" +
          obstacle.entries() + ").",
        exit_invalid_value);

    // the direction of first contact: the mean normal of the nodes closest
    // to the obstacle (all nodes on a plane parallel to a plane obstacle);
    // a contact pair's nodes face another body, and count only where the
    // obstacle has none (a pair's slave on the top of a body that stands
    // on the plane would cancel the plane's normal)
    const bool on_obstacle =
      Utilities::MPI::logical_or(std::any_of(nodes.begin(),
                                             nodes.end(),
                                             [](const auto &node) {
                                               return node.masters.empty();
                                             }),
                                 comm);
    const auto counts = [on_obstacle](const ContactNode<dim> &node) {
      return !on_obstacle || node.masters.empty();
    };
    double closest = std::numeric_limits<double>::max();
    for (const auto &node : nodes)
      if (counts(node))
        closest = std::min(closest, node.gap0);
    closest                  = Utilities::MPI::min(closest, comm);
    const double   tolerance = 1e-8 * characteristic_length;
    Tensor<1, dim> mean;
    for (const auto &node : nodes)
      if (counts(node) && node.gap0 <= closest + tolerance)
        mean += node.weight * node.normal;
    for (unsigned int d = 0; d < dim; ++d)
      mean[d] = Utilities::MPI::sum(mean[d], comm);
    if (mean.norm() > 0)
      normal = mean / mean.norm();
    else // no contact node at all, or normals that cancel: the obstacle's
      normal = -obstacle.normal(center);
    tangents = tangent_basis(normal);
    tangent  = tangents[0];
  }

  template <int dim>
  void
  ContactSet<dim>::set_slip_origin(const TrilinosWrappers::MPI::Vector &u,
                                   const Tensor<1, dim> &obstacle_step)
  {
    const TrilinosWrappers::MPI::Vector &w = with_masters(u);
    for (unsigned int s = 0; s < nodes.size(); ++s)
      {
        slip_origin[s] = tangential_displacement(w, s);
        // the obstacle's translation moves the origin of the nodes that
        // face it; a pair's nodes slip against the master only
        if (nodes[s].masters.empty())
          for (unsigned int k = 0; k < dim - 1; ++k)
            slip_origin[s][k] += obstacle_step * nodes[s].tangents[k];
      }
  }

  template <int dim>
  void
  ContactSet<dim>::set_touch_origin(const TrilinosWrappers::MPI::Vector &u,
                                    const TrilinosWrappers::MPI::Vector &u_free)
  {
    // the previous step's gaps and tangential positions first: with pairs,
    // with_masters() reuses one buffer
    std::vector<double>             gap_before(nodes.size());
    std::vector<Tensor<1, dim - 1>> t_before(nodes.size());
    {
      const TrilinosWrappers::MPI::Vector &w = with_masters(u);
      for (unsigned int s = 0; s < nodes.size(); ++s)
        {
          gap_before[s] = nodes[s].gap0 - normal_displacement(w, s);
          t_before[s]   = tangential_displacement(w, s);
        }
    }
    const TrilinosWrappers::MPI::Vector &w = with_masters(u_free);
    for (unsigned int s = 0; s < nodes.size(); ++s)
      {
        if (l1[s] > 0. || !(gap_before[s] > 0.))
          continue;
        const double gap_free = nodes[s].gap0 - normal_displacement(w, s);
        if (!(gap_free < gap_before[s]))
          continue; // moving away: it touches, if at all, by the others' motion
        const double theta =
          gap_free < 0. ? gap_before[s] / (gap_before[s] - gap_free) : 1.;
        slip_origin[s] =
          (1. - theta) * t_before[s] + theta * tangential_displacement(w, s);
      }
  }

  template <int dim>
  std::pair<Tensor<1, dim>, std::array<Tensor<1, dim>, dim - 1>>
  ContactSet<dim>::basis_at(const Point<dim> &x) const
  {
    const Tensor<1, dim> n = -obstacle->normal(x);
    return {n, tangent_basis(n)};
  }

  template <int dim>
  void
  ContactSet<dim>::write_fields(
    TrilinosWrappers::MPI::Vector &multipliers,
    TrilinosWrappers::MPI::Vector &threshold_field) const
  {
    multipliers     = 0.;
    threshold_field = 0.;
    for (unsigned int s = 0; s < nodes.size(); ++s)
      {
        multipliers[nodes[s].dofs[0]] = l1[s];
        for (unsigned int k = 0; k < dim - 1; ++k)
          multipliers[nodes[s].dofs[k + 1]] = l2[s][k];
        threshold_field[nodes[s].dofs[0]] = threshold[s];
      }
    multipliers.compress(VectorOperation::insert);
    threshold_field.compress(VectorOperation::insert);
  }

  template <int dim>
  std::pair<double, double>
  ContactSet<dim>::read_fields(
    const TrilinosWrappers::MPI::Vector &multipliers,
    const TrilinosWrappers::MPI::Vector &threshold_field,
    const bool                           project)
  {
    double smallest_l1 = std::numeric_limits<double>::max();
    double excess      = -std::numeric_limits<double>::max();
    for (unsigned int s = 0; s < nodes.size(); ++s)
      {
        const double raw = multipliers[nodes[s].dofs[0]];
        smallest_l1      = std::min(smallest_l1, raw);
        l1[s]            = project ? std::max(raw, 0.) : raw;
        if (!friction)
          continue;
        if (law->depends_on_pressure())
          threshold[s] = project ?
                           std::max(threshold_field[nodes[s].dofs[0]], 0.) :
                           threshold_field[nodes[s].dofs[0]];
        Tensor<1, dim - 1> t;
        for (unsigned int k = 0; k < dim - 1; ++k)
          t[k] = multipliers[nodes[s].dofs[k + 1]];
        const double norm = t.norm();
        excess            = std::max(excess, norm - threshold[s]);
        l2[s] = project && norm > threshold[s] ? t * (threshold[s] / norm) : t;
      }
    return {smallest_l1, excess};
  }

  template <int dim>
  void
  ContactSet<dim>::augmented_state(const TrilinosWrappers::MPI::Vector &v,
                                   const double                         r,
                                   const double                         r_t,
                                   std::vector<double>                 &z,
                                   std::vector<Tensor<1, dim - 1>>     &y) const
  {
    z.resize(nodes.size());
    y.resize(nodes.size());
    const TrilinosWrappers::MPI::Vector &w = with_masters(v);
    for (unsigned int s = 0; s < nodes.size(); ++s)
      {
        const double a = nodes[s].augmentation;
        z[s] = l1[s] + a * r * (normal_displacement(w, s) - nodes[s].gap0);
        if (friction)
          y[s] = l2[s] + a * r_t * slip(w, s);
      }
  }

  template <int dim>
  void
  ContactSet<dim>::add_nodal_forces(TrilinosWrappers::MPI::Vector &forces) const
  {
    std::vector<types::global_dof_index> dofs;
    std::vector<double>                  values;
    for (unsigned int s = 0; s < nodes.size(); ++s)
      {
        const Tensor<1, dim> force = nodal_force(s);
        dofs.assign(nodes[s].dofs.begin(), nodes[s].dofs.end());
        values.assign(force.begin_raw(), force.end_raw());
        for (const MasterTerm<dim> &master : nodes[s].masters)
          for (unsigned int c = 0; c < dim; ++c)
            {
              dofs.push_back(master.dofs[c]);
              values.push_back(-master.coefficient * force[c]);
            }
        forces.add(dofs, values);
      }
    forces.compress(VectorOperation::add);
  }

  template <int dim>
  IndexSet
  ContactSet<dim>::master_dofs(const types::global_dof_index n_dofs) const
  {
    IndexSet dofs(n_dofs);
    for (const ContactNode<dim> &node : nodes)
      for (const MasterTerm<dim> &master : node.masters)
        for (const types::global_dof_index dof : master.dofs)
          dofs.add_index(dof);
    dofs.compress();
    return dofs;
  }


  template class ContactSet<2>;
  template class ContactSet<3>;
} // namespace dualcontact
