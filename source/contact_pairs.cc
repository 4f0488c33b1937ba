// The contact pairs (contact_pairs.h, doc/two_bodies.md): each pair's
// surfaces gathered (pair_surfaces.h), coupled by the dual mortar of
// mortar.h (2D) or mortar_3d.h (3D), or node to segment, the master nodes'
// normals and the nodes their hanging nodes hang on, each slave node
// attached to the masters it faces with its coverage, normal and gap, the
// checks of a pair, the slave nodes that face no master dropped, and the
// parallel pieces the coupling needs (the master entries of a vector, the
// Newton matrix's extra entries).
#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <deal.II/fe/fe.h>

#include <dualcontact/contact_pairs.h>
#include <dualcontact/input_error.h>
#include <dualcontact/obstacle.h>
#include <dualcontact/pair_surfaces.h>
#include <dualcontact/scene.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

namespace dualcontact
{
  namespace
  {
    using pairs::SurfaceFace;

    // Whether a slave node's entries M_sj (their sum `sum_m`) give it a
    // point of the master to measure its gap to: sum_j c_sj x_j,
    // c_sj = M_sj / sum_m, is a mean of the master nodes it couples with
    // (the c_sj sum to one), and where the master covers the node's
    // support it lies among them. Where the master covers only a part of
    // the support away from the node (the master's end, or the edge of the
    // master faces that face the slave, cuts a slave face near its other
    // end), psi_s changes sign on the covered part, sum_m is a small
    // difference of larger M_sj, and the point lies far beyond those nodes
    // (on two coarse discs of radius 3, 7 beyond them, and a gap of -7): no
    // gap can be measured to it. The point must lie within the box of the
    // master nodes the node couples with, enlarged on every side by the
    // box's diameter: the partly covered nodes of the shipped pairs keep it
    // within 0.6 of the diameter but for six of two_spheres' last mesh,
    // 3.4 beyond (sum_j |M_sj| = 30 sum_m), and the false overlaps of
    // coarse discs and balls come from points 9-11 beyond. A node whose
    // point does not is taken as facing no master, as one beyond the
    // master's end; its covered weight sum_m is then a small part of m_s.
    template <int dim>
    bool
    sees_master_point(
      const std::vector<std::pair<unsigned int, double>> &entries,
      const double                                        sum_m,
      const std::vector<Point<dim>>                      &master_points)
    {
      Point<dim> facing, lower, upper;
      bool       first = true;
      for (const auto &[j, m] : entries)
        if (m != 0.)
          {
            const Point<dim> &x = master_points[j];
            facing += (m / sum_m) * x;
            for (unsigned int d = 0; d < dim; ++d)
              {
                lower[d] = first ? x[d] : std::min(lower[d], x[d]);
                upper[d] = first ? x[d] : std::max(upper[d], x[d]);
              }
            first = false;
          }
      const double diameter = lower.distance(upper);
      for (unsigned int d = 0; d < dim; ++d)
        if (facing[d] < lower[d] - diameter || facing[d] > upper[d] + diameter)
          return false;
      return true;
    }

    // What the coupling of a pair reads of the mesh: the number of nodes of
    // a face (the support points of FE_Q(k) on it, k + 1 in 2D and (k + 1)^2
    // on a quadrilateral in 3D; a triangle's 3 vertices: a mesh has one kind
    // of cell) and the body of each coarse cell
    template <int dim>
    struct PairMesh
    {
      const Mapping<dim>              &mapping;
      const DoFHandler<dim>           &dof_handler;
      const AffineConstraints<double> &hanging;
      const AffineConstraints<double> &constraints;
      const MPI_Comm                   comm;
      const unsigned int               n_face_nodes;
      const Bodies<dim>                bodies;
    };

    template <int dim>
    PairMesh<dim>
    pair_mesh(const Mapping<dim>              &mapping,
              const DoFHandler<dim>           &dof_handler,
              const AffineConstraints<double> &hanging,
              const AffineConstraints<double> &constraints)
    {
      const FiniteElement<dim> &fe = dof_handler.get_fe();
      AssertThrow(fe.degree == 1 ||
                    fe.reference_cell() == ReferenceCells::get_hypercube<dim>(),
                  ExcMessage("Contact pairs are built at degree 1, and at "
                             "degree 2-3 on quadrilaterals and hexahedra."));
      const unsigned int n_face_nodes =
        dim == 2 ? fe.degree + 1 :
        fe.reference_cell() == ReferenceCells::get_hypercube<dim>() ?
                   (fe.degree + 1) * (fe.degree + 1) :
                   3;
      return {mapping,
              dof_handler,
              hanging,
              constraints,
              dof_handler.get_triangulation().get_communicator(),
              n_face_nodes,
              Bodies<dim>(dof_handler.get_triangulation())};
    }

    // The two surfaces of a pair: the master surface, whole on every rank;
    // the slave faces of the owned and ghost cells, which hold every face at
    // an owned node
    template <int dim>
    struct PairSurfaces
    {
      std::vector<SurfaceFace<dim>> master, slave;
    };

    // Gather the surfaces: throws if a side has no face, or if both sides
    // lie on one body
    template <int dim>
    PairSurfaces<dim>
    gather_surfaces(const PairMesh<dim>     &mesh,
                    const types::boundary_id slave_id,
                    const types::boundary_id master_id,
                    const std::string       &pair)
    {
      const MPI_Comm    comm = mesh.comm;
      PairSurfaces<dim> surfaces;
      surfaces.master =
        pairs::gather(pairs::surface_faces(mesh.mapping,
                                           mesh.dof_handler,
                                           mesh.hanging,
                                           master_id,
                                           mesh.bodies,
                                           /*owned_only=*/true,
                                           /*with_parents=*/true),
                      mesh.n_face_nodes,
                      pairs::max_parents(mesh.dof_handler.get_fe()),
                      comm);
      surfaces.slave           = pairs::surface_faces(mesh.mapping,
                                            mesh.dof_handler,
                                            mesh.hanging,
                                            slave_id,
                                            mesh.bodies,
                                            /*owned_only=*/false,
                                            /*with_parents=*/false);
      const auto &master_faces = surfaces.master;
      const auto &slave_faces  = surfaces.slave;
      const auto  n_slave_faces =
        Utilities::MPI::sum(static_cast<unsigned int>(slave_faces.size()),
                            comm);
      if (master_faces.empty() || n_slave_faces == 0)
        throw InputError(pair +
                           " names a boundary id that no face of the "
                           "mesh has (" +
                           (master_faces.empty() ?
                              "master " + std::to_string(master_id) :
                              "slave " + std::to_string(slave_id)) +
                           ").",
                         exit_inconsistent);
      // a pair couples two bodies: a master face on a slave face's body
      // makes it a pair of one body
      std::set<unsigned int> master_bodies;
      for (const auto &face : master_faces)
        master_bodies.insert(face.body);
      unsigned int same_body = 0;
      for (const auto &face : slave_faces)
        same_body += master_bodies.count(face.body);
      if (Utilities::MPI::sum(same_body, comm) > 0)
        throw InputError(pair + " has both sides on one body (a connected "
                                "part of the mesh): a pair couples two "
                                "bodies.",
                         exit_inconsistent);
      return surfaces;
    }

    // A pair's surfaces numbered and coupled: each master node's and slave
    // node's number (by its first DoF), DoFs and position, and the coupling
    // m_s, M_sj with the slave's hanging nodes condensed
    template <int dim>
    struct PairCoupling
    {
      std::map<types::global_dof_index, unsigned int>       master_number;
      std::vector<std::array<types::global_dof_index, dim>> master_dofs;
      std::vector<Point<dim>>                               master_points;
      std::map<types::global_dof_index, unsigned int>       slave_number;
      std::vector<std::array<types::global_dof_index, dim>> slave_dofs;
      std::vector<Point<dim>>                               slave_points;
      mortar::Coupling                                      coupling;
    };

    template <int dim>
    PairCoupling<dim>
    couple_surfaces(const PairMesh<dim>     &mesh,
                    const PairSurfaces<dim> &surfaces,
                    const bool               node_to_segment)
    {
      PairCoupling<dim> c;
      const auto        master_segments = pairs::segments(surfaces.master,
                                                   c.master_number,
                                                   c.master_dofs,
                                                   c.master_points);
      const auto        slave_segments  = pairs::segments(surfaces.slave,
                                                  c.slave_number,
                                                  c.slave_dofs,
                                                  c.slave_points);
      const auto       &slave_number    = c.slave_number;
      const auto       &master_points   = c.master_points;
      const auto       &slave_points    = c.slave_points;
      mortar::Coupling &coupling        = c.coupling;
      if constexpr (dim == 2)
        coupling = node_to_segment ?
                     mortar::couple_node_to_segment(slave_segments,
                                                    slave_number.size(),
                                                    master_segments) :
                     mortar::couple(slave_segments,
                                    slave_number.size(),
                                    master_segments);
      else
        {
          // a slave face sees the master faces in front of it as far as
          // the two surfaces reach: in the reference configuration two
          // curved bodies part as r^2 / (2 R*), and a node that a far
          // master face gets is one with a large gap; behind it, only
          // those within mortar::facing_tolerance()
          std::vector<Point<dim>> both(master_points);
          both.insert(both.end(), slave_points.begin(), slave_points.end());
          const auto [lower, upper] =
            BoundingBox<dim>(both).get_boundary_points();
          const double reach = lower.distance(upper);
          coupling           = mortar::couple(slave_segments,
                                    slave_number.size(),
                                    master_segments,
                                    reach);
        }
      pairs::condense_hanging_nodes(coupling,
                                    slave_number,
                                    mesh.hanging,
                                    mesh.dof_handler.locally_owned_dofs(),
                                    mesh.comm);
      return c;
    }

    // Each master node's outward normal, the mean of its faces', and the
    // nodes a hanging master node hangs on with their weights
    template <int dim>
    struct MasterNodes
    {
      std::vector<Tensor<1, dim>>                               normals;
      std::vector<std::vector<std::pair<unsigned int, double>>> parents;
    };

    template <int dim>
    MasterNodes<dim>
    master_normals_and_parents(
      const std::vector<SurfaceFace<dim>> &master_faces,
      PairCoupling<dim>                   &c)
    {
      auto                        &master_number = c.master_number;
      auto                        &master_dofs   = c.master_dofs;
      MasterNodes<dim>             result;
      std::vector<Tensor<1, dim>> &master_normals = result.normals;
      master_normals.resize(c.master_points.size());
      for (const SurfaceFace<dim> &face : master_faces)
        for (const auto &dofs : face.dofs)
          master_normals[pairs::number_of(master_number, dofs[0])] +=
            face.normal;
      std::vector<std::vector<std::pair<unsigned int, double>>>
        &master_parents = result.parents;
      master_parents.resize(c.master_points.size());
      // A hanging master node j moves as sum_p w_jp v_p: in a slave
      // node's displacement coupling its c_sj goes to the nodes p it
      // hangs on, so that the coupling holds only DoFs that are solved
      // for. They are nodes of the master surface, or, at degree 2-3
      // where the master's boundary id ends at a coarse edge, of the
      // face of the other id beside it: those are numbered after the
      // surface's nodes, in master_dofs only. Its position stays in the
      // gap: on a curved master it lies off the chord of its parents.
      for (const SurfaceFace<dim> &face : master_faces)
        for (unsigned int k = 0; k < face.dofs.size(); ++k)
          {
            auto &parents =
              master_parents[pairs::number_of(master_number, face.dofs[k][0])];
            parents.clear();
            for (const auto &[dofs, w] : face.parents[k])
              {
                const auto [it, inserted] =
                  master_number.emplace(dofs[0], master_dofs.size());
                if (inserted)
                  master_dofs.push_back(dofs);
                parents.emplace_back(it->second, w);
              }
          }
      return result;
    }


    // Slave node `node` attached to the master nodes its entries M_sj
    // (their sum sum_m) see, c_sj = M_sj / sum_m, those of a hanging master
    // node handed to its parents; its normal, tangents and gap to the point
    // sum_j c_sj x_j of the master
    template <int dim>
    void
    attach_node(ContactNode<dim>                                   &node,
                const std::vector<std::pair<unsigned int, double>> &entries,
                const double                                        sum_m,
                const PairCoupling<dim>                            &c,
                const MasterNodes<dim>                             &masters,
                const AffineConstraints<double> &all_constraints)
    {
      const auto                    &master_points  = c.master_points;
      const auto                    &master_dofs    = c.master_dofs;
      const auto                    &master_normals = masters.normals;
      const auto                    &master_parents = masters.parents;
      Point<dim>                     facing;
      Tensor<1, dim>                 master_normal;
      std::map<unsigned int, double> condensed;
      for (const auto &[j, m] : entries)
        if (m != 0.)
          {
            facing += (m / sum_m) * master_points[j];
            master_normal +=
              (m / sum_m) * master_normals[j] / master_normals[j].norm();
            if (master_parents[j].empty())
              condensed[j] += m / sum_m;
            else
              for (const auto &[p, w] : master_parents[j])
                condensed[p] += w * m / sum_m;
          }
      node.masters.clear();
      for (const auto &[j, c] : condensed)
        node.masters.push_back({master_dofs[j], c});
      // The direction of the contact: the bisector of the two
      // surfaces' outward normals, n_s and -n_master (equal for two
      // flat faces). Two curved bodies press along it: for two
      // identical ones it is the normal of their plane of symmetry,
      // where the slave's own normal would tilt by x/R and bias the
      // pressure by O(a/R) (doc/two_bodies.md).
      node.normal = node.body_normal - master_normal;
      node.normal /= node.normal.norm();
      // A support that holds the slave node in a direction (a slider
      // on a plane of symmetry, a clamp at the surface's end) takes
      // the contact's force along it: the normal is turned into the
      // plane the node moves in (at a cut of symmetry the bisector
      // tilts off it by O(h/R)), and friction acts along free
      // tangents only. A multiplier along a held tangent would move
      // the master alone, through the few c_sj of the node's end, a
      // mode so weak that the Uzawa iteration crawls at 0.98 a step.
      const std::vector<Tensor<1, dim>> held =
        held_directions(node, all_constraints);
      Tensor<1, dim> turned = node.normal;
      for (const Tensor<1, dim> &h : held)
        turned -= (turned * h) * h;
      if (turned.norm() > 0.5)
        node.normal = turned / turned.norm();
      node.tangents = free_tangents(node.normal, held);
      node.gap0     = node.normal * (facing - node.position);
    }

    // The largest overlap of a pair's slave nodes into the master body
    // beyond a tenth of their spacing, and where on this rank
    template <int dim>
    struct Overlap
    {
      double     depth = 0.;
      Point<dim> at;
    };

    // Attach the masters: the slave nodes of the pair `slave_id` among
    // `nodes` get their masters, c_sj = M_sj / sum_j M_sj (a node beyond
    // the master's end sees a part of it; its gap is then to the point
    // sum_j c_sj x_j of the master), coverage, gap and normal; those that
    // face no master are marked off in `keep` and counted in `uncovered`.
    // Returns the number attached.
    template <int dim>
    unsigned int
    attach_masters(
      std::vector<ContactNode<dim>>                               &nodes,
      std::vector<bool>                                           &keep,
      types::global_dof_index                                     &uncovered,
      Overlap<dim>                                                &largest,
      const std::map<types::global_dof_index, types::boundary_id> &slave_id_of,
      const types::boundary_id                                     slave_id,
      const PairCoupling<dim>                                     &c,
      const MasterNodes<dim>                                      &masters,
      const AffineConstraints<double> &all_constraints)
    {
      const mortar::Coupling &coupling      = c.coupling;
      const auto             &master_points = c.master_points;
      unsigned int            covered       = 0;
      double                 &overlap       = largest.depth;
      Point<dim>             &overlap_at    = largest.at;
      for (unsigned int s = 0; s < nodes.size(); ++s)
        {
          const auto it = slave_id_of.find(nodes[s].dofs[0]);
          if (it == slave_id_of.end() || it->second != slave_id)
            continue;
          const unsigned int i =
            pairs::number_of(c.slave_number, nodes[s].dofs[0]);
          double sum_m = 0.;
          for (const auto &[j, m] : coupling.master[i])
            sum_m += m;
          // (a node covered by less than 1e-4 of its weight carries less
          // than that of a node's force, and its augmentation factor
          // 1 / coverage would magnify the round-off of its gap)
          if (!(sum_m > 1e-4 * coupling.weight[i]) ||
              !sees_master_point(coupling.master[i], sum_m, master_points))
            {
              keep[s] = false;
              ++uncovered;
              continue;
            }
          ++covered;
          ContactNode<dim> &node = nodes[s];
          node.pair_slave_id     = slave_id;
          // A node whose support the master covers in part transmits its
          // multiplier over the covered part only: its weight is
          // int_covered psi_s = sum_j M_sj, not m_s, so that l1 stays the
          // pressure there (the contact patch test with the slave beyond
          // the master's end, doc/two_bodies.md).
          const double coverage = sum_m / coupling.weight[i];
          // Its augmentation is a whole node's, m_s a_s r with a_s =
          // 1 / coverage: with m_s r alone a node covered by a sliver of
          // the master holds its gap so weakly that the Uzawa iteration
          // contracts at 0.9-0.98 a step (an upper block reaching beyond
          // the lower one as the slave); a per-node r is the augmented
          // Lagrangian's diagonal R (doc/theory.md §5).
          if (std::abs(coverage - 1.) > 1e-12)
            node.weight *= coverage;
          node.augmentation = coverage < 1. ? 1. / coverage : 1.;
          attach_node(
            node, coupling.master[i], sum_m, c, masters, all_constraints);
          // Two curved surfaces that touch overlap by O(h^2 / R) between
          // their chords: that is the discrete geometry, not bad input.
          // An overlap beyond a tenth of the node's spacing (m_s in 2D,
          // its square root in 3D, at degree 1) is.
          if (-node.gap0 > 0.1 * std::pow(coupling.weight[i], 1. / (dim - 1)) &&
              -node.gap0 > overlap)
            {
              overlap    = -node.gap0;
              overlap_at = node.position;
            }
        }
      return covered;
    }

    // Check the pair: some slave node faces the master, and none lies
    // inside the master body beyond a tenth of its spacing
    template <int dim>
    void
    check_pair(const std::string  &pair,
               const unsigned int  covered,
               const Overlap<dim> &largest_here,
               const MPI_Comm      comm)
    {
      const double      overlap    = largest_here.depth;
      const Point<dim> &overlap_at = largest_here.at;
      if (Utilities::MPI::sum(covered, comm) == 0)
        throw InputError(pair + " has no slave node that faces the "
                                "master surface.",
                         exit_inconsistent);
      const double largest = Utilities::MPI::max(overlap, comm);
      if (largest > 0.)
        {
          // the place of the largest overlap, from the rank that has it
          const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
          const unsigned int first =
            Utilities::MPI::min(overlap == largest ?
                                  rank :
                                  Utilities::MPI::n_mpi_processes(comm),
                                comm);
          Point<dim> at;
          for (unsigned int d = 0; d < dim; ++d)
            at[d] =
              Utilities::MPI::sum(rank == first ? overlap_at[d] : 0., comm);
          std::string where;
          for (unsigned int d = 0; d < dim; ++d)
            where += (d == 0 ? "(" : ", ") + format_number(at[d]);
          throw InputError(pair +
                             " starts with the bodies overlapping: "
                             "slave nodes lie up to " +
                             format_number(largest) +
                             " [length] inside the master body (at " + where +
                             ")); move them apart or mesh them touching.",
                           exit_inconsistent);
        }
    }
  } // namespace


  template <int dim>
  void
  ContactPairs<dim>::reinit(
    const std::map<types::boundary_id, types::boundary_id> &pairs,
    const bool                                              node_to_segment)
  {
    this->pairs           = pairs;
    this->node_to_segment = node_to_segment;
  }

  template <int dim>
  void
  ContactPairs<dim>::couple(
    const Mapping<dim>              &mapping,
    const DoFHandler<dim>           &dof_handler,
    const AffineConstraints<double> &hanging_node_constraints,
    const AffineConstraints<double> &all_constraints,
    const std::map<types::global_dof_index, types::boundary_id> &slave_id_of,
    std::vector<ContactNode<dim>>                               &nodes)
  {
    n_uncovered  = 0;
    pairing_time = 0.;
    if (!active())
      return;
    const PairMesh<dim> mesh = pair_mesh(mapping,
                                         dof_handler,
                                         hanging_node_constraints,
                                         all_constraints);
    const MPI_Comm      comm = mesh.comm;
    Timer               timer(comm, /*sync_lap_times=*/true);

    std::vector<bool>       keep(nodes.size(), true);
    types::global_dof_index uncovered = 0;
    for (const auto &[slave_id, master_id] : pairs)
      {
        const std::string pair =
          "The contact pair " + std::to_string(slave_id) + ": " +
          std::to_string(master_id) + " (<Boundary conditions/Contact pairs>)";
        const PairSurfaces<dim> surfaces =
          gather_surfaces(mesh, slave_id, master_id, pair);
        PairCoupling<dim> coupled =
          couple_surfaces(mesh, surfaces, node_to_segment);
        const MasterNodes<dim> masters =
          master_normals_and_parents(surfaces.master, coupled);
        Overlap<dim>       overlap;
        const unsigned int covered = attach_masters(nodes,
                                                    keep,
                                                    uncovered,
                                                    overlap,
                                                    slave_id_of,
                                                    slave_id,
                                                    coupled,
                                                    masters,
                                                    all_constraints);
        check_pair(pair, covered, overlap, comm);
      }
    drop_uncovered_nodes(
      keep, uncovered, dof_handler.locally_owned_dofs(), comm, nodes);
    timer.stop();
    pairing_time = timer.wall_time();
  }

  template <int dim>
  void
  ContactPairs<dim>::drop_uncovered_nodes(
    const std::vector<bool>       &keep,
    const types::global_dof_index  uncovered,
    const IndexSet                &owned,
    const MPI_Comm                 comm,
    std::vector<ContactNode<dim>> &nodes)
  {
    // the nodes that face no master are no contact nodes
    std::vector<ContactNode<dim>> covered_nodes;
    for (unsigned int s = 0; s < nodes.size(); ++s)
      if (keep[s])
        covered_nodes.push_back(std::move(nodes[s]));
    nodes.swap(covered_nodes);
    n_uncovered = Utilities::MPI::sum(uncovered, comm);

    // the vector that holds the master entries of this rank's nodes
    IndexSet relevant(owned);
    for (const ContactNode<dim> &node : nodes)
      for (const MasterTerm<dim> &master : node.masters)
        for (const types::global_dof_index dof : master.dofs)
          relevant.add_index(dof);
    relevant.compress();
    ghosted.reinit(owned, relevant, comm);
    owned_copy.reinit(owned, comm);
  }

  template <int dim>
  const TrilinosWrappers::MPI::Vector &
  ContactPairs<dim>::with_masters(const TrilinosWrappers::MPI::Vector &v) const
  {
    if (!active())
      return v;
    // an import needs one side without ghosts
    if (v.has_ghost_elements())
      {
        owned_copy = v;
        ghosted    = owned_copy;
      }
    else
      ghosted = v;
    return ghosted;
  }

  namespace
  {
    // the DoFs of a paired node and of its masters, each as the condensed
    // space sees it (itself, the DoFs it hangs on, or none if prescribed)
    template <int dim>
    std::vector<types::global_dof_index>
    condensed_group(const ContactNode<dim>          &node,
                    const AffineConstraints<double> &constraints)
    {
      std::vector<types::global_dof_index> group;
      const auto add = [&](const types::global_dof_index dof) {
        if (!constraints.is_constrained(dof))
          group.push_back(dof);
        else if (const auto *entries = constraints.get_constraint_entries(dof))
          for (const auto &[master, weight] : *entries)
            group.push_back(master);
      };
      for (const types::global_dof_index dof : node.dofs)
        add(dof);
      for (const MasterTerm<dim> &master : node.masters)
        for (const types::global_dof_index dof : master.dofs)
          add(dof);
      std::sort(group.begin(), group.end());
      group.erase(std::unique(group.begin(), group.end()), group.end());
      return group;
    }
  } // namespace

  template <int dim>
  void
  ContactPairs<dim>::add_couplings(
    DynamicSparsityPattern              &pattern,
    const AffineConstraints<double>     &constraints,
    const std::vector<ContactNode<dim>> &nodes) const
  {
    for (const ContactNode<dim> &node : nodes)
      if (!node.masters.empty())
        {
          const auto group = condensed_group(node, constraints);
          for (const types::global_dof_index row : group)
            pattern.add_entries(row, group.begin(), group.end(), true);
        }
  }

  template <int dim>
  IndexSet
  ContactPairs<dim>::coupled_rows(const AffineConstraints<double> &constraints,
                                  const std::vector<ContactNode<dim>> &nodes,
                                  const types::global_dof_index n_dofs) const
  {
    IndexSet rows(n_dofs);
    for (const ContactNode<dim> &node : nodes)
      if (!node.masters.empty())
        for (const types::global_dof_index row :
             condensed_group(node, constraints))
          rows.add_index(row);
    rows.compress();
    return rows;
  }

  template <int dim>
  std::vector<Tensor<1, dim>>
  held_directions(const ContactNode<dim>          &node,
                  const AffineConstraints<double> &constraints)
  {
    std::vector<Tensor<1, dim>> held;
    for (unsigned int c = 0; c < dim; ++c)
      {
        if (!constraints.is_constrained(node.dofs[c]))
          continue;
        // v_c = sum_j a_j v_j + b, the v_j the node's own: (e_c - sum_j a_j
        // e_j) . v = b
        Tensor<1, dim> h;
        h[c]            = 1.;
        bool       own  = true;
        const auto line = constraints.get_constraint_entries(node.dofs[c]);
        if (line != nullptr)
          for (const auto &[dof, a] : *line)
            {
              const auto it =
                std::find(node.dofs.begin(), node.dofs.end(), dof);
              own &= it != node.dofs.end();
              if (it != node.dofs.end())
                h[it - node.dofs.begin()] -= a;
            }
        if (!own)
          continue;
        for (const Tensor<1, dim> &g : held)
          h -= (h * g) * g;
        if (h.norm() > 1e-8)
          held.push_back(h / h.norm());
      }
    return held;
  }

  template <int dim>
  std::array<Tensor<1, dim>, dim - 1>
  free_tangents(const Tensor<1, dim>              &n,
                const std::vector<Tensor<1, dim>> &held)
  {
    std::array<Tensor<1, dim>, dim - 1> t = tangent_basis(n);
    if (held.empty())
      return t;
    // G_kl = t_k . P t_l, P the projection onto the held directions: an
    // eigenvalue 1 is a tangent they contain
    const double tolerance = 1e-8;
    const auto   G         = [&](const unsigned int k, const unsigned int l) {
      double sum = 0.;
      for (const Tensor<1, dim> &h : held)
        sum += (t[k] * h) * (t[l] * h);
      return sum;
    };
    if constexpr (dim == 2)
      {
        if (G(0, 0) > 1. - tolerance)
          t[0] = Tensor<1, dim>();
      }
    else
      {
        const double a = G(0, 0), b = G(0, 1), c = G(1, 1);
        const double mean = (a + c) / 2, radius = std::hypot((a - c) / 2, b);
        if (mean - radius > 1. - tolerance) // both held
          return {};
        if (mean + radius > 1. - tolerance) // one: keep the other
          {
            // the eigenvector of the larger eigenvalue, a tangent held
            const double         lambda = mean + radius;
            const Tensor<1, dim> w =
              std::abs(a - lambda) > std::abs(c - lambda) ?
                b * t[0] + (lambda - a) * t[1] :
                (lambda - c) * t[0] + b * t[1];
            const Tensor<1, dim> along = w.norm() > 0. ? w / w.norm() : t[0];
            t[0]                       = cross_product_3d(n / n.norm(), along);
            t[1]                       = Tensor<1, dim>();
          }
      }
    return t;
  }

  template std::vector<Tensor<1, 2>>
  held_directions(const ContactNode<2> &, const AffineConstraints<double> &);
  template std::vector<Tensor<1, 3>>
  held_directions(const ContactNode<3> &, const AffineConstraints<double> &);
  template std::array<Tensor<1, 2>, 1>
  free_tangents(const Tensor<1, 2> &, const std::vector<Tensor<1, 2>> &);
  template std::array<Tensor<1, 3>, 2>
  free_tangents(const Tensor<1, 3> &, const std::vector<Tensor<1, 3>> &);

  template class ContactPairs<2>;
  template class ContactPairs<3>;
} // namespace dualcontact
