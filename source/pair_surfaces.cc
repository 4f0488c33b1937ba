// The surfaces of a contact pair (pair_surfaces.h): the faces of a boundary
// id with their nodes in the order the mortar coupling reads them (face
// collection), the nodes their hanging nodes hang on (hanging parents), the
// master surface gathered on every rank, the faces numbered as mortar
// segments, and the slave's hanging nodes condensed.
#include <deal.II/base/quadrature_lib.h>

#include <dualcontact/discretization.h>
#include <dualcontact/pair_surfaces.h>
#include <dualcontact/scene.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace dualcontact
{
  namespace pairs
  {
    namespace
    {
      // The coordinates (xi, eta) of the point x in the bilinear map of a
      // quadrilateral's vertices v (lexicographic), nearest to it
      // (Gauss-Newton from the centre; one step on a flat parallelogram)
      std::array<double, 2>
      face_coordinates(const std::array<Point<3>, 4> &v, const Point<3> &x)
      {
        double xi = 0.5, eta = 0.5;
        for (unsigned int it = 0; it < 20; ++it)
          {
            const Tensor<1, 3> t0 =
              (1. - eta) * (v[1] - v[0]) + eta * (v[3] - v[2]);
            const Tensor<1, 3> t1 =
              (1. - xi) * (v[2] - v[0]) + xi * (v[3] - v[1]);
            const Point<3> y = (1. - xi) * (1. - eta) * v[0] +
                               xi * (1. - eta) * v[1] + (1. - xi) * eta * v[2] +
                               xi * eta * v[3];
            const Tensor<1, 3> r = x - y;
            const double       a = t0 * t0, b = t0 * t1, c = t1 * t1;
            const double       det = a * c - b * b;
            if (!(det > 0.))
              break;
            const double dxi  = (c * (t0 * r) - b * (t1 * r)) / det;
            const double deta = (a * (t1 * r) - b * (t0 * r)) / det;
            xi += dxi;
            eta += deta;
            if (std::abs(dxi) + std::abs(deta) <= 1e-14)
              break;
          }
        return {{xi, eta}};
      }

      // The DoFs, one per component, of the support points whose first DoF
      // is in `keys`, from the cells this rank has (owned and ghost): the
      // nodes that hanging nodes of the owned faces hang on. At degree 2-3 a
      // node of a surface may hang on one off it: where the surface's
      // boundary id ends at a coarse edge (a flat boundary split into ids),
      // the DoF inside that edge belongs to the coarse neighbour's face of
      // the other id alone.
      template <int dim>
      std::map<types::global_dof_index,
               std::array<types::global_dof_index, dim>>
      support_point_dofs(const DoFHandler<dim>                   &dof_handler,
                         const std::set<types::global_dof_index> &keys)
      {
        std::map<types::global_dof_index,
                 std::array<types::global_dof_index, dim>>
          result;
        if (keys.empty())
          return result;
        const FiniteElement<dim>            &fe = dof_handler.get_fe();
        std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (!cell->is_artificial())
            {
              cell->get_dof_indices(dof_indices);
              std::map<unsigned int, std::array<types::global_dof_index, dim>>
                by_base;
              for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                {
                  const auto [component, base] =
                    fe.system_to_component_index(i);
                  by_base[base][component] = dof_indices[i];
                }
              for (const auto &[base, dofs] : by_base)
                if (keys.count(dofs[0]))
                  result[dofs[0]] = dofs;
              if (result.size() == keys.size())
                break;
            }
        return result;
      }

      // The support points of FE_Q(k) on face f of a cell: the DoFs of each
      // (one per component) into dofs_of[base], base the point's number in
      // the base element, and take(x, base) with its position x.
      template <int dim, typename Cell, typename Take>
      void
      support_points_on_face(
        const Mapping<dim>                         &mapping,
        const Cell                                 &cell,
        const unsigned int                          f,
        const std::vector<types::global_dof_index> &dof_indices,
        std::map<unsigned int, std::array<types::global_dof_index, dim>>
                   &dofs_of,
        const Take &take)
      {
        const FiniteElement<dim> &fe = cell->get_fe();
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          if (support_on_face(fe, i, f))
            {
              const auto [component, base] = fe.system_to_component_index(i);
              dofs_of[base][component]     = dof_indices[i];
              if (component == 0)
                take(mapping.transform_unit_to_real_cell(
                       cell, fe.unit_support_point(i)),
                     base);
            }
      }

      // The nodes of face f of a 3D cell, and the normal of the face from
      // the vertices at (0, 0), (1, 0) and (0, 1) of the reference face (its
      // sign not yet the outward one)
      template <int dim>
      void
      face_nodes_3d(const Mapping<dim> &mapping,
                    const typename DoFHandler<dim>::active_cell_iterator &cell,
                    const unsigned int                                    f,
                    const std::vector<types::global_dof_index> &dof_indices,
                    SurfaceFace<dim>                           &face)
      {
        const FiniteElement<dim> &fe      = cell->get_fe();
        const auto                face_it = cell->face(f);
        const unsigned int        k       = fe.degree;
        if (k == 1)
          // the face's vertices in deal.II's order
          // (lexicographic on a quadrilateral), the DoFs of a
          // vertex one per component in the order of the
          // components
          for (const unsigned int v : face_it->vertex_indices())
            {
              face.x.push_back(face_it->vertex(v));
              face.dofs.emplace_back();
              for (unsigned int c = 0; c < dim; ++c)
                face.dofs.back()[c] =
                  face_it->vertex_dof_index(v, c, cell->active_fe_index());
            }
        else
          {
            // FE_Q(k)'s support points on the quadrilateral, in
            // lexicographic order of their coordinates in the
            // bilinear map of its vertices (whatever the face's
            // orientation in the cell): node i + (k + 1) j at
            // the i-th Gauss-Lobatto point along xi and the
            // j-th along eta
            std::array<Point<3>, 4> v;
            for (unsigned int i = 0; i < 4; ++i)
              v[i] = face_it->vertex(i);
            const QGaussLobatto<1> rule(k + 1);
            std::vector<double>    lobatto;
            for (const Point<1> &p : rule.get_points())
              lobatto.push_back(p[0]);
            std::sort(lobatto.begin(), lobatto.end());
            const auto index = [&](const double t) {
              unsigned int best = 0;
              for (unsigned int i = 1; i <= k; ++i)
                if (std::abs(lobatto[i] - t) < std::abs(lobatto[best] - t))
                  best = i;
              return best;
            };
            std::map<unsigned int, std::pair<Point<dim>, unsigned int>> by_node;
            std::map<unsigned int, std::array<types::global_dof_index, dim>>
              dofs_of;
            support_points_on_face<dim>(
              mapping,
              cell,
              f,
              dof_indices,
              dofs_of,
              [&](const Point<dim> &x, const unsigned int base) {
                const auto [xi, eta] = face_coordinates(v, x);
                by_node[index(xi) + (k + 1) * index(eta)] = {x, base};
              });
            AssertThrow(by_node.size() == (k + 1) * (k + 1),
                        ExcMessage("The support points of a face of a "
                                   "contact pair do not fall on their "
                                   "lexicographic places."));
            for (const auto &[node, point] : by_node)
              {
                face.x.push_back(point.first);
                face.dofs.push_back(dofs_of[point.second]);
              }
          }
        face.xi.assign(face.x.size(), 0.);
        // its normal from the vertices at (0, 0), (1, 0) and
        // (0, 1) of the reference face
        const bool         triangle = face.x.size() == 3;
        const unsigned int right    = triangle ? 1 : k;
        const unsigned int up       = triangle ? 2 : k * (k + 1);
        face.normal =
          cross_product_3d(face.x[right] - face.x[0], face.x[up] - face.x[0]);
      }

      // The nodes of face f of a 2D cell, and the normal of its chord (its
      // sign not yet the outward one)
      template <int dim>
      void
      face_nodes_2d(const Mapping<dim> &mapping,
                    const typename DoFHandler<dim>::active_cell_iterator &cell,
                    const unsigned int                                    f,
                    const std::vector<types::global_dof_index> &dof_indices,
                    SurfaceFace<dim>                           &face)
      {
        const FiniteElement<dim> &fe = cell->get_fe();
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
                dofs_of[k][c] =
                  cell->face(f)->vertex_dof_index(k,
                                                  c,
                                                  cell->active_fe_index());
            }
        else
          support_points_on_face<dim>(
            mapping,
            cell,
            f,
            dof_indices,
            dofs_of,
            [&](const Point<dim> &x, const unsigned int base) {
              by_xi[(x - v0) * chord / chord.norm_square()] = {x, base};
            });
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
        std::rotate(face.xi.begin() + 1, face.xi.end() - 1, face.xi.end());
        // the normal of the face's chord: the line turned by 90
        // degrees
        const Tensor<1, dim> along = face.x[1] - face.x[0];
        face.normal[0]             = along[1];
        face.normal[1]             = -along[0];
      }

      // Face collection: the faces with boundary id `id` of the cells taken
      // (surface_faces()), with their nodes, their outward normals and, if
      // `with_parents`, the first DoFs of the nodes their hanging nodes hang
      // on (all of their DoFs from hanging_parents())
      template <int dim>
      std::vector<SurfaceFace<dim>>
      collect_faces(const Mapping<dim>              &mapping,
                    const DoFHandler<dim>           &dof_handler,
                    const AffineConstraints<double> &hanging,
                    const types::boundary_id         id,
                    const Bodies<dim>               &bodies,
                    const bool                       owned_only,
                    const bool                       with_parents)
      {
        const FiniteElement<dim>            &fe = dof_handler.get_fe();
        std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
        std::vector<SurfaceFace<dim>>        faces;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (owned_only ? cell->is_locally_owned() : !cell->is_artificial())
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  cell->face(f)->boundary_id() == id)
                {
                  SurfaceFace<dim> face;
                  face.body = bodies.of(cell);
                  cell->get_dof_indices(dof_indices);
                  if constexpr (dim == 3)
                    face_nodes_3d<dim>(mapping, cell, f, dof_indices, face);
                  else
                    face_nodes_2d<dim>(mapping, cell, f, dof_indices, face);
                  // outward: away from the cell's centre
                  face.normal /= face.normal.norm();
                  if (face.normal * (face.x[0] - cell->center()) < 0.)
                    face.normal *= -1.;
                  for (const auto &dofs : face.dofs)
                    {
                      // the first DoFs of the nodes it hangs on, their other
                      // DoFs below
                      face.parents.emplace_back();
                      if (with_parents && hanging.is_constrained(dofs[0]))
                        for (const auto &[parent, w] :
                             *hanging.get_constraint_entries(dofs[0]))
                          {
                            std::array<types::global_dof_index, dim> first;
                            first.fill(parent);
                            face.parents.back().emplace_back(first, w);
                          }
                      AssertThrow(face.parents.back().size() <= max_parents(fe),
                                  ExcMessage(
                                    "A hanging node of a contact pair's "
                                    "surface hangs on more nodes than "
                                    "a face has."));
                    }
                  faces.push_back(face);
                }
        return faces;
      }

      // Hanging parents: each parent's first DoF in `faces` replaced by all
      // of its DoFs, from the cells this rank has
      template <int dim>
      void
      hanging_parents(const DoFHandler<dim>         &dof_handler,
                      std::vector<SurfaceFace<dim>> &faces)
      {
        std::set<types::global_dof_index> hung_on;
        for (const SurfaceFace<dim> &face : faces)
          for (const auto &parents : face.parents)
            for (const auto &[dofs, w] : parents)
              hung_on.insert(dofs[0]);
        const auto parent_dofs = support_point_dofs(dof_handler, hung_on);
        for (SurfaceFace<dim> &face : faces)
          for (auto &parents : face.parents)
            for (auto &[dofs, w] : parents)
              {
                const auto it = parent_dofs.find(dofs[0]);
                AssertThrow(it != parent_dofs.end(),
                            ExcMessage(
                              "A node that a hanging node of a contact "
                              "pair's surface hangs on lies on no cell "
                              "of the rank that owns the hanging "
                              "node's face."));
                dofs = it->second;
              }
      }

      // The number of node k of `face` in `number` (by its first DoF), a new
      // node's DoFs and position appended to `dofs` and `points`
      template <int dim>
      unsigned int
      node_number(const SurfaceFace<dim>                                &face,
                  const unsigned int                                     k,
                  std::map<types::global_dof_index, unsigned int>       &number,
                  std::vector<std::array<types::global_dof_index, dim>> &dofs,
                  std::vector<Point<dim>>                               &points)
      {
        const auto [it, inserted] =
          number.emplace(face.dofs[k][0], number.size());
        if (inserted)
          {
            dofs.push_back(face.dofs[k]);
            points.push_back(face.x[k]);
          }
        return it->second;
      }
    } // namespace

    template <int dim>
    std::vector<SurfaceFace<dim>>
    surface_faces(const Mapping<dim>              &mapping,
                  const DoFHandler<dim>           &dof_handler,
                  const AffineConstraints<double> &hanging,
                  const types::boundary_id         id,
                  const Bodies<dim>               &bodies,
                  const bool                       owned_only,
                  const bool                       with_parents)
    {
      std::vector<SurfaceFace<dim>> faces = collect_faces(
        mapping, dof_handler, hanging, id, bodies, owned_only, with_parents);
      hanging_parents(dof_handler, faces);
      return faces;
    }

    unsigned int
    number_of(const std::map<types::global_dof_index, unsigned int> &number,
              const types::global_dof_index                          dof)
    {
      const auto it = number.find(dof);
      AssertThrow(it != number.end(),
                  ExcMessage("A node of a contact pair is missing from the "
                             "numbering of its surface's nodes."));
      return it->second;
    }

    std::vector<mortar::Segment>
    segments(const std::vector<SurfaceFace<2>>                   &faces,
             std::map<types::global_dof_index, unsigned int>     &number,
             std::vector<std::array<types::global_dof_index, 2>> &dofs,
             std::vector<Point<2>>                               &points)
    {
      std::vector<mortar::Segment> result;
      for (const SurfaceFace<2> &face : faces)
        {
          mortar::Segment segment;
          for (unsigned int k = 0; k < face.x.size(); ++k)
            {
              const unsigned int j =
                node_number<2>(face, k, number, dofs, points);
              if (k < 2)
                {
                  segment.node[k] = j;
                  segment.x[k]    = face.x[k];
                }
              else
                {
                  segment.inner_node.push_back(j);
                  segment.inner_xi.push_back(face.xi[k]);
                }
            }
          segment.normal = face.normal;
          result.push_back(segment);
        }
      return result;
    }

    std::vector<mortar::Face>
    segments(const std::vector<SurfaceFace<3>>                   &faces,
             std::map<types::global_dof_index, unsigned int>     &number,
             std::vector<std::array<types::global_dof_index, 3>> &dofs,
             std::vector<Point<3>>                               &points)
    {
      std::vector<mortar::Face> result;
      for (const SurfaceFace<3> &face : faces)
        {
          mortar::Face m;
          if (face.x.size() == 3)
            m.x = face.x;
          else
            {
              // (k + 1)^2 nodes: the vertices are the lexicographic corners
              const unsigned int k = static_cast<unsigned int>(
                                       std::lround(std::sqrt(face.x.size()))) -
                                     1;
              m.degree = k;
              m.x      = {face.x[0],
                          face.x[k],
                          face.x[k * (k + 1)],
                          face.x[(k + 1) * (k + 1) - 1]};
            }
          for (unsigned int k = 0; k < face.x.size(); ++k)
            m.node.push_back(node_number<3>(face, k, number, dofs, points));
          m.normal = face.normal;
          result.push_back(m);
        }
      return result;
    }

    void
    condense_hanging_nodes(
      mortar::Coupling                                      &coupling,
      const std::map<types::global_dof_index, unsigned int> &number,
      const AffineConstraints<double>                       &hanging,
      const IndexSet                                        &owned,
      const MPI_Comm                                         comm)
    {
      // (p, w_hp, h) for the hanging nodes h this rank owns
      std::vector<types::global_dof_index>         parents;
      std::vector<std::pair<double, unsigned int>> weight_and_node;
      for (const auto &[dof, h] : number)
        if (owned.is_element(dof) && hanging.is_constrained(dof))
          for (const auto &[p, w] : *hanging.get_constraint_entries(dof))
            {
              parents.push_back(p);
              weight_and_node.emplace_back(w, h);
            }
      IndexSet all(owned.size());
      all.add_indices(parents.begin(), parents.end());
      const std::vector<unsigned int> owners =
        Utilities::MPI::compute_index_owner(owned, all, comm);
      // to each owner: p, w m_h, the number of entries, then (j, w M_hj)
      std::map<unsigned int, std::vector<double>> rows;
      for (unsigned int k = 0; k < parents.size(); ++k)
        {
          const auto [w, h] = weight_and_node[k];
          std::vector<double> &row =
            rows[owners[all.index_within_set(parents[k])]];
          row.push_back(parents[k]);
          row.push_back(w * coupling.weight[h]);
          row.push_back(coupling.master[h].size());
          for (const auto &[j, m] : coupling.master[h])
            {
              row.push_back(j);
              row.push_back(w * m);
            }
        }
      for (const auto &[rank, row] : Utilities::MPI::some_to_some(comm, rows))
        for (std::size_t i = 0; i < row.size();)
          {
            const auto n = static_cast<std::size_t>(row[i + 2]);
            // At degree 2-3, where the slave's boundary id ends at a coarse
            // edge, h may hang on a node off the slave surface (in that
            // edge, support_point_dofs()): that node is no contact node and
            // carries no multiplier, and its share of h's row is left out,
            // as the rigid obstacle's contact set leaves out the weight a
            // hanging node hands to a node off Gamma_C.
            const auto found =
              number.find(static_cast<types::global_dof_index>(row[i]));
            if (found == number.end())
              {
                i += 3 + 2 * n;
                continue;
              }
            const unsigned int p = found->second;
            coupling.weight[p] += row[i + 1];
            std::map<unsigned int, double> merged(coupling.master[p].begin(),
                                                  coupling.master[p].end());
            for (std::size_t e = 0; e < n; ++e)
              merged[static_cast<unsigned int>(row[i + 3 + 2 * e])] +=
                row[i + 4 + 2 * e];
            coupling.master[p].assign(merged.begin(), merged.end());
            i += 3 + 2 * n;
          }
    }

    // every rank's faces on every rank (each face has `n` nodes, each
    // hanging on at most `max_parents`)
    template <int dim>
    std::vector<SurfaceFace<dim>>
    gather(const std::vector<SurfaceFace<dim>> &local,
           const unsigned int                   n,
           const unsigned int                   max_parents,
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
              for (unsigned int p = 0; p < max_parents; ++p)
                {
                  const bool has = p < face.parents[k].size();
                  for (unsigned int d = 0; d < dim; ++d)
                    integers.push_back(has ? face.parents[k][p].first[d] :
                                             numbers::invalid_dof_index);
                  reals.push_back(has ? face.parents[k][p].second : 0.);
                }
            }
          for (unsigned int d = 0; d < dim; ++d)
            reals.push_back(face.normal[d]);
          integers.push_back(face.body);
        }
      // per node: its position, xi and the parents' weights; its DoFs and
      // the parents' DoFs
      const unsigned int reals_per_node    = dim + 1 + max_parents;
      const unsigned int integers_per_node = dim * (1 + max_parents);
      const unsigned int n_reals           = n * reals_per_node + dim;
      const unsigned int n_integers        = n * integers_per_node + 1;
      const auto         all_reals = Utilities::MPI::all_gather(comm, reals);
      const auto all_integers      = Utilities::MPI::all_gather(comm, integers);
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
            face.parents.resize(n);
            for (unsigned int k = 0; k < n; ++k)
              {
                const double                  *rk = r + k * reals_per_node;
                const types::global_dof_index *zk = z + k * integers_per_node;
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    face.x[k][d]    = rk[d];
                    face.dofs[k][d] = zk[d];
                  }
                face.xi[k] = rk[dim];
                for (unsigned int p = 0; p < max_parents; ++p)
                  if (zk[dim * (1 + p)] != numbers::invalid_dof_index)
                    {
                      std::array<types::global_dof_index, dim> dofs;
                      for (unsigned int d = 0; d < dim; ++d)
                        dofs[d] = zk[dim * (1 + p) + d];
                      face.parents[k].emplace_back(dofs, rk[dim + 1 + p]);
                    }
              }
            for (unsigned int d = 0; d < dim; ++d)
              face.normal[d] = r[n * reals_per_node + d];
            face.body = z[n * integers_per_node];
            faces.push_back(face);
          }
      return faces;
    }

    template std::vector<SurfaceFace<2>>
    surface_faces(const Mapping<2> &,
                  const DoFHandler<2> &,
                  const AffineConstraints<double> &,
                  types::boundary_id,
                  const Bodies<2> &,
                  bool,
                  bool);
    template std::vector<SurfaceFace<3>>
    surface_faces(const Mapping<3> &,
                  const DoFHandler<3> &,
                  const AffineConstraints<double> &,
                  types::boundary_id,
                  const Bodies<3> &,
                  bool,
                  bool);
    template std::vector<SurfaceFace<2>>
    gather(const std::vector<SurfaceFace<2>> &,
           unsigned int,
           unsigned int,
           MPI_Comm);
    template std::vector<SurfaceFace<3>>
    gather(const std::vector<SurfaceFace<3>> &,
           unsigned int,
           unsigned int,
           MPI_Comm);
  } // namespace pairs
} // namespace dualcontact
