// The contact nodes of a pair of bodies (doc/two_bodies.md): the master
// surface gathered on every rank, the dual mortar coupling of each slave
// node with the master nodes it faces (mortar.h), the gaps, the checks of a
// pair, and the parallel pieces the coupling needs (the master entries of a
// vector, the Newton matrix's extra entries).
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <deal.II/fe/fe.h>

#include <dualcontact/contact_set.h>
#include <dualcontact/input_error.h>
#include <dualcontact/mortar.h>
#include <dualcontact/parameter_helpers.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

namespace dualcontact
{
  namespace
  {
    // One face of a pair's surface as the coupling needs it: its nodes'
    // positions and DoFs (the support points of FE_Q(k) on the face: the
    // two vertices first, then the k - 1 inner ones with their coordinate
    // xi along the face), its outward normal, and the body it belongs to.
    template <int dim>
    struct SurfaceFace
    {
      std::vector<Point<dim>>                               x;
      std::vector<std::array<types::global_dof_index, dim>> dofs;
      std::vector<double>                                   xi;
      Tensor<1, dim>                                        normal;
      unsigned int                                          body = 0;
    };

    // The faces with boundary id `id` of the cells `take` accepts.
    template <int dim, typename Predicate>
    std::vector<SurfaceFace<dim>>
    surface_faces(const Mapping<dim>              &mapping,
                  const DoFHandler<dim>           &dof_handler,
                  const types::boundary_id         id,
                  const std::vector<unsigned int> &body_of_coarse_cell,
                  const Predicate                 &take)
    {
      const FiniteElement<dim>            &fe = dof_handler.get_fe();
      std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
      std::vector<SurfaceFace<dim>>        faces;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (take(cell))
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == id)
              {
                SurfaceFace<dim> face;
                face.body = body_of<dim>(cell, body_of_coarse_cell);
                cell->get_dof_indices(dof_indices);
                // the face's support points by their coordinate xi along
                // its chord, from the face's vertex 0 (xi = 0) to its
                // vertex 1 (xi = 1): at degree 1 its vertices, whose DoFs
                // are one per component in the order of the components
                // (triangles too); at degree 2-3 (quadrilaterals) FE_Q(k)'s
                // support points on the face
                const Point<dim>     v0    = cell->face(f)->vertex(0);
                const Tensor<1, dim> chord = cell->face(f)->vertex(1) - v0;
                std::map<double, std::pair<Point<dim>, unsigned int>> by_xi;
                std::map<unsigned int, std::array<types::global_dof_index, dim>>
                  dofs_of;
                if (fe.degree == 1)
                  for (unsigned int k = 0; k < 2; ++k)
                    {
                      by_xi[k] = {cell->face(f)->vertex(k), k};
                      for (unsigned int c = 0; c < dim; ++c)
                        dofs_of[k][c] = cell->face(f)->vertex_dof_index(
                          k, c, cell->active_fe_index());
                    }
                else
                  for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                    if (fe.has_support_on_face(i, f))
                      {
                        const auto [component, base] =
                          fe.system_to_component_index(i);
                        dofs_of[base][component] = dof_indices[i];
                        if (component == 0)
                          {
                            const Point<dim> x =
                              mapping.transform_unit_to_real_cell(
                                cell, fe.unit_support_point(i));
                            by_xi[(x - v0) * chord / chord.norm_square()] = {
                              x, base};
                          }
                      }
                for (const auto &[xi, point] : by_xi)
                  {
                    face.x.push_back(point.first);
                    face.dofs.push_back(dofs_of[point.second]);
                    face.xi.push_back(xi);
                  }
                // vertices first (xi = 0 and 1), then the inner nodes
                std::rotate(face.x.begin() + 1, face.x.end() - 1, face.x.end());
                std::rotate(face.dofs.begin() + 1,
                            face.dofs.end() - 1,
                            face.dofs.end());
                std::rotate(face.xi.begin() + 1,
                            face.xi.end() - 1,
                            face.xi.end());
                // the outward normal of the face's chord: the line turned
                // by 90 degrees, away from the cell's centre
                const Tensor<1, dim> along = face.x[1] - face.x[0];
                face.normal[0]             = along[1];
                face.normal[1]             = -along[0];
                face.normal /= face.normal.norm();
                if (face.normal * (face.x[0] - cell->center()) < 0.)
                  face.normal *= -1.;
                faces.push_back(face);
              }
      return faces;
    }

    // Faces as the mortar coupling takes them, numbering their nodes by
    // their first DoF in `number`
    template <int dim>
    std::vector<mortar::Segment>
    segments(const std::vector<SurfaceFace<dim>>                   &faces,
             std::map<types::global_dof_index, unsigned int>       &number,
             std::vector<std::array<types::global_dof_index, dim>> &dofs,
             std::vector<Point<dim>>                               &points)
    {
      std::vector<mortar::Segment> result;
      for (const SurfaceFace<dim> &face : faces)
        {
          mortar::Segment segment;
          for (unsigned int k = 0; k < face.x.size(); ++k)
            {
              const auto [it, inserted] =
                number.emplace(face.dofs[k][0], number.size());
              if (inserted)
                {
                  dofs.push_back(face.dofs[k]);
                  points.push_back(face.x[k]);
                }
              if (k < 2)
                {
                  segment.node[k] = it->second;
                  for (unsigned int d = 0; d < 2; ++d)
                    segment.x[k][d] = face.x[k][d];
                }
              else
                {
                  segment.inner_node.push_back(it->second);
                  segment.inner_xi.push_back(face.xi[k]);
                }
            }
          for (unsigned int d = 0; d < 2; ++d)
            segment.normal[d] = face.normal[d];
          result.push_back(segment);
        }
      return result;
    }

    // every rank's faces on every rank (each face has `n` nodes)
    template <int dim>
    std::vector<SurfaceFace<dim>>
    gather(const std::vector<SurfaceFace<dim>> &local,
           const unsigned int                   n,
           const MPI_Comm                       comm)
    {
      std::vector<double>                  reals;
      std::vector<types::global_dof_index> integers;
      for (const SurfaceFace<dim> &face : local)
        {
          for (unsigned int k = 0; k < n; ++k)
            {
              for (unsigned int d = 0; d < dim; ++d)
                {
                  reals.push_back(face.x[k][d]);
                  integers.push_back(face.dofs[k][d]);
                }
              reals.push_back(face.xi[k]);
            }
          for (unsigned int d = 0; d < dim; ++d)
            reals.push_back(face.normal[d]);
          integers.push_back(face.body);
        }
      const unsigned int n_reals    = n * (dim + 1) + dim;
      const unsigned int n_integers = n * dim + 1;
      const auto         all_reals  = Utilities::MPI::all_gather(comm, reals);
      const auto all_integers = Utilities::MPI::all_gather(comm, integers);
      std::vector<SurfaceFace<dim>> faces;
      for (unsigned int rank = 0; rank < all_reals.size(); ++rank)
        for (unsigned int i = 0; i < all_integers[rank].size() / n_integers;
             ++i)
          {
            const double                  *r = &all_reals[rank][i * n_reals];
            const types::global_dof_index *z =
              &all_integers[rank][i * n_integers];
            SurfaceFace<dim> face;
            face.x.resize(n);
            face.dofs.resize(n);
            face.xi.resize(n);
            for (unsigned int k = 0; k < n; ++k)
              {
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    face.x[k][d]    = r[k * (dim + 1) + d];
                    face.dofs[k][d] = z[k * dim + d];
                  }
                face.xi[k] = r[k * (dim + 1) + dim];
              }
            for (unsigned int d = 0; d < dim; ++d)
              face.normal[d] = r[n * (dim + 1) + d];
            face.body = z[n * dim];
            faces.push_back(face);
          }
      return faces;
    }
  } // namespace

  template <int dim>
  void
  ContactSet<dim>::couple_pairs(
    const Mapping<dim>                                          &mapping,
    const DoFHandler<dim>                                       &dof_handler,
    const Scene<dim>                                            &scene,
    const std::map<types::global_dof_index, types::boundary_id> &slave_id_of)
  {
    has_pairs_   = !scene.contact_pairs().empty();
    n_uncovered  = 0;
    pairing_time = 0.;
    if (!has_pairs_)
      return;
    const MPI_Comm comm = dof_handler.get_triangulation().get_communicator();
    AssertThrow(dim == 2 && (dof_handler.get_fe().degree == 1 ||
                             dof_handler.get_fe().reference_cell() ==
                               ReferenceCells::get_hypercube<dim>()),
                ExcMessage("Contact pairs are built in 2D, at degree 2-3 "
                           "on quadrilaterals."));
    // the nodes of a face: the support points of FE_Q(k) on it
    const unsigned int n_face_nodes = dof_handler.get_fe().degree + 1;
    const std::vector<unsigned int> body_of_coarse_cell =
      bodies_of_coarse_cells(dof_handler.get_triangulation());
    const bool node_to_segment = scene.pairs_node_to_segment();
    Timer      timer(comm, /*sync_lap_times=*/true);

    std::vector<bool>       keep(nodes.size(), true);
    types::global_dof_index uncovered = 0;
    for (const auto &[slave_id, master_id] : scene.contact_pairs())
      {
        const std::string pair =
          "The contact pair " + std::to_string(slave_id) + ": " +
          std::to_string(master_id) + " (<Boundary conditions/Contact pairs>)";
        // the master surface, whole on every rank; the slave faces of the
        // owned and ghost cells, which hold every face at an owned node
        const auto master_faces =
          gather(surface_faces(mapping,
                               dof_handler,
                               master_id,
                               body_of_coarse_cell,
                               [](const auto &cell) {
                                 return cell->is_locally_owned();
                               }),
                 n_face_nodes,
                 comm);
        const auto slave_faces = surface_faces(mapping,
                                               dof_handler,
                                               slave_id,
                                               body_of_coarse_cell,
                                               [](const auto &cell) {
                                                 return !cell->is_artificial();
                                               });
        const auto n_slave_faces =
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

        std::map<types::global_dof_index, unsigned int>       master_number;
        std::vector<std::array<types::global_dof_index, dim>> master_dofs;
        std::vector<Point<dim>>                               master_points;
        const auto master_segments = segments<dim>(master_faces,
                                                   master_number,
                                                   master_dofs,
                                                   master_points);
        // each master node's outward normal: the mean of its faces'
        std::vector<Tensor<1, dim>> master_normals(master_points.size());
        for (const mortar::Segment &segment : master_segments)
          {
            std::vector<unsigned int> on_segment = {segment.node[0],
                                                    segment.node[1]};
            on_segment.insert(on_segment.end(),
                              segment.inner_node.begin(),
                              segment.inner_node.end());
            for (const unsigned int j : on_segment)
              for (unsigned int d = 0; d < 2; ++d)
                master_normals[j][d] += segment.normal[d];
          }
        std::map<types::global_dof_index, unsigned int>       slave_number;
        std::vector<std::array<types::global_dof_index, dim>> slave_dofs;
        std::vector<Point<dim>>                               slave_points;
        const auto                                            slave_segments =
          segments<dim>(slave_faces, slave_number, slave_dofs, slave_points);
        const mortar::Coupling coupling =
          node_to_segment ? mortar::couple_node_to_segment(slave_segments,
                                                           slave_number.size(),
                                                           master_segments) :
                            mortar::couple(slave_segments,
                                           slave_number.size(),
                                           master_segments);

        // the nodes of this pair: their masters, c_sj = M_sj / sum_j M_sj
        // (a node beyond the master's end sees a part of it; its gap is
        // then to the point sum_j c_sj x_j of the master), gap and normal
        unsigned int covered = 0;
        double       overlap = 0.;
        Point<dim>   overlap_at;
        for (unsigned int s = 0; s < nodes.size(); ++s)
          {
            const auto it = slave_id_of.find(nodes[s].dofs[0]);
            if (it == slave_id_of.end() || it->second != slave_id)
              continue;
            const unsigned int i     = slave_number.at(nodes[s].dofs[0]);
            double             sum_m = 0.;
            for (const auto &[j, m] : coupling.master[i])
              sum_m += m;
            if (!(sum_m > 1e-12 * coupling.weight[i]))
              {
                keep[s] = false;
                ++uncovered;
                continue;
              }
            ++covered;
            ContactNode<dim> &node = nodes[s];
            node.pair_slave_id     = slave_id;
            Point<dim>     facing;
            Tensor<1, dim> master_normal;
            node.masters.clear();
            for (const auto &[j, m] : coupling.master[i])
              if (m != 0.)
                {
                  node.masters.push_back({master_dofs[j], m / sum_m});
                  facing += (m / sum_m) * master_points[j];
                  master_normal +=
                    (m / sum_m) * master_normals[j] / master_normals[j].norm();
                }
            // The direction of the contact: the bisector of the two
            // surfaces' outward normals, n_s and -n_master (equal for two
            // flat faces). Two curved bodies press along it: for two
            // identical ones it is the normal of their plane of symmetry,
            // where the slave's own normal would tilt by x/R and bias the
            // pressure by O(a/R) (doc/two_bodies.md).
            node.normal = node.body_normal - master_normal;
            node.normal /= node.normal.norm();
            node.tangents = tangent_basis(node.normal);
            node.gap0     = node.normal * (facing - node.position);
            // Two curved surfaces that touch overlap by O(h^2 / R) between
            // their chords: that is the discrete geometry, not bad input.
            // An overlap beyond a tenth of the node's half-element (m_s at
            // degree 1) is.
            if (-node.gap0 > 0.1 * coupling.weight[i] && -node.gap0 > overlap)
              {
                overlap    = -node.gap0;
                overlap_at = node.position;
              }
          }
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
    // the nodes that face no master are no contact nodes
    std::vector<ContactNode<dim>> covered_nodes;
    for (unsigned int s = 0; s < nodes.size(); ++s)
      if (keep[s])
        covered_nodes.push_back(std::move(nodes[s]));
    nodes.swap(covered_nodes);
    n_uncovered = Utilities::MPI::sum(uncovered, comm);

    // the vector that holds the master entries of this rank's nodes
    const IndexSet &owned = dof_handler.locally_owned_dofs();
    IndexSet        relevant(owned);
    for (const ContactNode<dim> &node : nodes)
      for (const MasterTerm<dim> &master : node.masters)
        for (const types::global_dof_index dof : master.dofs)
          relevant.add_index(dof);
    relevant.compress();
    ghosted.reinit(owned, relevant, comm);
    owned_copy.reinit(owned, comm);
    timer.stop();
    pairing_time = timer.wall_time();
  }

  template <int dim>
  const TrilinosWrappers::MPI::Vector &
  ContactSet<dim>::with_masters(const TrilinosWrappers::MPI::Vector &v) const
  {
    if (!has_pairs_)
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
  ContactSet<dim>::add_pair_couplings(
    DynamicSparsityPattern          &pattern,
    const AffineConstraints<double> &constraints) const
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
  ContactSet<dim>::coupled_rows(
    const AffineConstraints<double> &constraints) const
  {
    IndexSet rows(ghosted.size());
    for (const ContactNode<dim> &node : nodes)
      if (!node.masters.empty())
        for (const types::global_dof_index row :
             condensed_group(node, constraints))
          rows.add_index(row);
    rows.compress();
    return rows;
  }

#define DUALCONTACT_INSTANTIATE(dim)                                           \
  template void ContactSet<dim>::couple_pairs(                                 \
    const Mapping<dim> &,                                                      \
    const DoFHandler<dim> &,                                                   \
    const Scene<dim> &,                                                        \
    const std::map<types::global_dof_index, types::boundary_id> &);            \
  template const TrilinosWrappers::MPI::Vector &ContactSet<dim>::with_masters( \
    const TrilinosWrappers::MPI::Vector &) const;                              \
  template void ContactSet<dim>::add_pair_couplings(                           \
    DynamicSparsityPattern &, const AffineConstraints<double> &) const;        \
  template IndexSet ContactSet<dim>::coupled_rows(                             \
    const AffineConstraints<double> &) const;
  DUALCONTACT_INSTANTIATE(2)
  DUALCONTACT_INSTANTIATE(3)
#undef DUALCONTACT_INSTANTIATE
} // namespace dualcontact
