// The contact nodes of a pair of bodies (doc/two_bodies.md): the master
// surface gathered on every rank, the dual mortar coupling of each slave
// node with the master nodes it faces (mortar.h in 2D, mortar_3d.h in 3D),
// the hanging nodes on either surface condensed, the gaps, the checks of a
// pair, and the parallel pieces the coupling needs (the master entries of a
// vector, the Newton matrix's extra entries).
#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>

#include <deal.II/fe/fe.h>

#include <dualcontact/contact_set.h>
#include <dualcontact/discretization.h>
#include <dualcontact/input_error.h>
#include <dualcontact/mortar.h>
#include <dualcontact/mortar_3d.h>
#include <dualcontact/parameter_helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

namespace dualcontact
{
  namespace
  {
    // The most nodes a hanging node of a face of `fe` hangs on: in 2D the
    // k + 1 nodes of a coarse face (at most 4), in 3D the nodes of a coarse
    // face, (k + 1)^2 on a quadrilateral (4 at degree 1: the two ends of an
    // edge or the four corners)
    template <int dim>
    unsigned int
    max_parents(const FiniteElement<dim> &fe)
    {
      return dim == 2 ? 4u : std::max(4u, (fe.degree + 1) * (fe.degree + 1));
    }

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

    // One face of a pair's surface as the coupling needs it: its nodes'
    // positions and DoFs (in 2D the support points of FE_Q(k) on the face:
    // the two vertices first, then the k - 1 inner ones with their
    // coordinate xi along the face; in 3D a triangle's vertices, or the
    // (k + 1)^2 support points of FE_Q(k) on a quadrilateral in
    // lexicographic order, mortar_3d.h), for a hanging node the
    // DoFs of the nodes it hangs on and their weights (on the master
    // surface: the slave's hanging nodes are condensed from the
    // constraints, condense_hanging_nodes()), its outward normal, and the
    // body it belongs to.
    template <int dim>
    struct SurfaceFace
    {
      std::vector<Point<dim>>                               x;
      std::vector<std::array<types::global_dof_index, dim>> dofs;
      std::vector<double>                                   xi;
      std::vector<std::vector<
        std::pair<std::array<types::global_dof_index, dim>, double>>>
                     parents;
      Tensor<1, dim> normal;
      unsigned int   body = 0;
    };

    // The DoFs, one per component, of the support points whose first DoF
    // is in `keys`, from the cells this rank has (owned and ghost): the
    // nodes that hanging nodes of the owned faces hang on. At degree 2-3 a
    // node of a surface may hang on one off it: where the surface's
    // boundary id ends at a coarse edge (a flat boundary split into ids),
    // the DoF inside that edge belongs to the coarse neighbour's face of
    // the other id alone.
    template <int dim>
    std::map<types::global_dof_index, std::array<types::global_dof_index, dim>>
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
                const auto [component, base] = fe.system_to_component_index(i);
                by_base[base][component]     = dof_indices[i];
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
      std::map<unsigned int, std::array<types::global_dof_index, dim>> &dofs_of,
      const Take                                                       &take)
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

    // The faces with boundary id `id` of the cells `take` accepts, with
    // the nodes their hanging nodes hang on if `with_parents` (the owned
    // faces of the master surface: their cells' neighbours, which hold
    // those nodes, are owned or ghost cells).
    template <int dim, typename Predicate>
    std::vector<SurfaceFace<dim>>
    surface_faces(const Mapping<dim>              &mapping,
                  const DoFHandler<dim>           &dof_handler,
                  const AffineConstraints<double> &hanging,
                  const types::boundary_id         id,
                  const std::vector<unsigned int> &body_of_coarse_cell,
                  const Predicate                 &take,
                  const bool                       with_parents)
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
                if constexpr (dim == 3)
                  {
                    const auto         face_it = cell->face(f);
                    const unsigned int k       = fe.degree;
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
                            face.dofs.back()[c] = face_it->vertex_dof_index(
                              v, c, cell->active_fe_index());
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
                            if (std::abs(lobatto[i] - t) <
                                std::abs(lobatto[best] - t))
                              best = i;
                          return best;
                        };
                        std::map<unsigned int,
                                 std::pair<Point<dim>, unsigned int>>
                          by_node;
                        std::map<unsigned int,
                                 std::array<types::global_dof_index, dim>>
                          dofs_of;
                        support_points_on_face<dim>(
                          mapping,
                          cell,
                          f,
                          dof_indices,
                          dofs_of,
                          [&](const Point<dim> &x, const unsigned int base) {
                            const auto [xi, eta] = face_coordinates(v, x);
                            by_node[index(xi) + (k + 1) * index(eta)] = {x,
                                                                         base};
                          });
                        AssertThrow(by_node.size() == (k + 1) * (k + 1),
                                    ExcMessage(
                                      "The support points of a face of a "
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
                    face.normal = cross_product_3d(face.x[right] - face.x[0],
                                                   face.x[up] - face.x[0]);
                  }
                else
                  {
                    // the face's support points by their coordinate xi along
                    // its chord, from the face's vertex 0 (xi = 0) to its
                    // vertex 1 (xi = 1): at degree 1 its vertices, whose DoFs
                    // are one per component in the order of the components
                    // (triangles too); at degree 2-3 (quadrilaterals) FE_Q(k)'s
                    // support points on the face
                    const Point<dim>     v0    = cell->face(f)->vertex(0);
                    const Tensor<1, dim> chord = cell->face(f)->vertex(1) - v0;
                    std::map<double, std::pair<Point<dim>, unsigned int>> by_xi;
                    std::map<unsigned int,
                             std::array<types::global_dof_index, dim>>
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
                      support_points_on_face<dim>(
                        mapping,
                        cell,
                        f,
                        dof_indices,
                        dofs_of,
                        [&](const Point<dim> &x, const unsigned int base) {
                          by_xi[(x - v0) * chord / chord.norm_square()] = {
                            x, base};
                        });
                    for (const auto &[xi, point] : by_xi)
                      {
                        face.x.push_back(point.first);
                        face.dofs.push_back(dofs_of[point.second]);
                        face.xi.push_back(xi);
                      }
                    // vertices first (xi = 0 and 1), then the inner nodes
                    std::rotate(face.x.begin() + 1,
                                face.x.end() - 1,
                                face.x.end());
                    std::rotate(face.dofs.begin() + 1,
                                face.dofs.end() - 1,
                                face.dofs.end());
                    std::rotate(face.xi.begin() + 1,
                                face.xi.end() - 1,
                                face.xi.end());
                    // the normal of the face's chord: the line turned by 90
                    // degrees
                    const Tensor<1, dim> along = face.x[1] - face.x[0];
                    face.normal[0]             = along[1];
                    face.normal[1]             = -along[0];
                  }
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
                                ExcMessage("A hanging node of a contact pair's "
                                           "surface hangs on more nodes than "
                                           "a face has."));
                  }
                faces.push_back(face);
              }
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
                          ExcMessage("A node that a hanging node of a contact "
                                     "pair's surface hangs on lies on no cell "
                                     "of the rank that owns the hanging "
                                     "node's face."));
              dofs = it->second;
            }
      return faces;
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

    // The number of the node with the first DoF `dof` in `number`, which
    // holds it: the nodes of the faces the numbering was made from (a
    // missing one is an internal error, named so)
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

    // 2D faces as the mortar coupling takes them (mortar.h), their nodes
    // numbered in `number`
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

    // 3D faces as the mortar coupling takes them (mortar_3d.h), their
    // nodes numbered in `number`
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

    // A hanging slave node is no contact node: its row of the coupling (its
    // weight m_h and its M_hj) goes to the nodes p it hangs on, times the
    // weights w_hp of its constraint u_h = sum_p w_hp u_p, as its m_h goes
    // to their m_p. The multiplier of p is then psi_p + sum_h w_hp psi_h,
    // the dual of the condensed trace. The rank that owns h has all the
    // faces at h (its owned and ghost cells); the owner of p may not, so the
    // owner of h sends its row to the owner of p. The master nodes are
    // numbered alike on every rank (the gathered master surface).
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
  } // namespace

  template <int dim>
  void
  ContactSet<dim>::couple_pairs(
    const Mapping<dim>              &mapping,
    const DoFHandler<dim>           &dof_handler,
    const AffineConstraints<double> &hanging_node_constraints,
    const AffineConstraints<double> &all_constraints,
    const Scene<dim>                &scene,
    const std::map<types::global_dof_index, types::boundary_id> &slave_id_of)
  {
    has_pairs_   = !scene.contact_pairs().empty();
    n_uncovered  = 0;
    pairing_time = 0.;
    if (!has_pairs_)
      return;
    const MPI_Comm comm = dof_handler.get_triangulation().get_communicator();
    const FiniteElement<dim> &fe = dof_handler.get_fe();
    AssertThrow(fe.degree == 1 ||
                  fe.reference_cell() == ReferenceCells::get_hypercube<dim>(),
                ExcMessage("Contact pairs are built at degree 1, and at "
                           "degree 2-3 on quadrilaterals and hexahedra."));
    // the nodes of a face: the support points of FE_Q(k) on it, k + 1 in
    // 2D and (k + 1)^2 on a quadrilateral in 3D; a triangle's 3 vertices
    // (a mesh has one kind of cell)
    const unsigned int n_face_nodes =
      dim == 2 ? fe.degree + 1 :
      fe.reference_cell() == ReferenceCells::get_hypercube<dim>() ?
                 (fe.degree + 1) * (fe.degree + 1) :
                 3;
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
          gather(surface_faces(
                   mapping,
                   dof_handler,
                   hanging_node_constraints,
                   master_id,
                   body_of_coarse_cell,
                   [](const auto &cell) { return cell->is_locally_owned(); },
                   /*with_parents=*/true),
                 n_face_nodes,
                 max_parents(fe),
                 comm);
        const auto slave_faces = surface_faces(
          mapping,
          dof_handler,
          hanging_node_constraints,
          slave_id,
          body_of_coarse_cell,
          [](const auto &cell) { return !cell->is_artificial(); },
          /*with_parents=*/false);
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
        std::map<types::global_dof_index, unsigned int>       slave_number;
        std::vector<std::array<types::global_dof_index, dim>> slave_dofs;
        std::vector<Point<dim>>                               slave_points;
        const auto                                            master_segments =
          segments(master_faces, master_number, master_dofs, master_points);
        const auto slave_segments =
          segments(slave_faces, slave_number, slave_dofs, slave_points);
        mortar::Coupling coupling;
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
        condense_hanging_nodes(coupling,
                               slave_number,
                               hanging_node_constraints,
                               dof_handler.locally_owned_dofs(),
                               comm);
        // each master node's outward normal: the mean of its faces'
        std::vector<Tensor<1, dim>> master_normals(master_points.size());
        for (const SurfaceFace<dim> &face : master_faces)
          for (const auto &dofs : face.dofs)
            master_normals[number_of(master_number, dofs[0])] += face.normal;
        // A hanging master node j moves as sum_p w_jp v_p: in a slave
        // node's displacement coupling its c_sj goes to the nodes p it
        // hangs on, so that the coupling holds only DoFs that are solved
        // for. They are nodes of the master surface, or, at degree 2-3
        // where the master's boundary id ends at a coarse edge, of the
        // face of the other id beside it: those are numbered after the
        // surface's nodes, in master_dofs only. Its position stays in the
        // gap: on a curved master it lies off the chord of its parents.
        std::vector<std::vector<std::pair<unsigned int, double>>>
          master_parents(master_points.size());
        for (const SurfaceFace<dim> &face : master_faces)
          for (unsigned int k = 0; k < face.dofs.size(); ++k)
            {
              auto &parents =
                master_parents[number_of(master_number, face.dofs[k][0])];
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
            const unsigned int i = number_of(slave_number, nodes[s].dofs[0]);
            double             sum_m = 0.;
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
            Point<dim>                     facing;
            Tensor<1, dim>                 master_normal;
            std::map<unsigned int, double> condensed;
            for (const auto &[j, m] : coupling.master[i])
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
            // Two curved surfaces that touch overlap by O(h^2 / R) between
            // their chords: that is the discrete geometry, not bad input.
            // An overlap beyond a tenth of the node's spacing (m_s in 2D,
            // its square root in 3D, at degree 1) is.
            if (-node.gap0 >
                  0.1 * std::pow(coupling.weight[i], 1. / (dim - 1)) &&
                -node.gap0 > overlap)
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
    const AffineConstraints<double> &,                                         \
    const AffineConstraints<double> &,                                         \
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
