// The dual mortar coupling of two surfaces in 3D (mortar_3d.h): the master
// faces sorted into a grid of boxes, and each slave face coupled with the
// master faces near it, by the clipping and quadrature of
// mortar_3d_geometry.h.
#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/lac/full_matrix.h>

#include <dualcontact/mortar_3d.h>
#include <dualcontact/mortar_3d_geometry.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <utility>

namespace dualcontact
{
  namespace mortar
  {
    namespace
    {
      using namespace geometry;

      /**
       * A face's box, the smallest axis-parallel one around its vertices.
       */
      struct Box
      {
        Point<3> lo, hi;

        /** The box around the vertices x. */
        explicit Box(const std::vector<Point<3>> &x)
            : lo(x[0])
            , hi(x[0])
        {
          for (const Point<3> &p : x)
            for (unsigned int d = 0; d < 3; ++d)
              {
                lo[d] = std::min(lo[d], p[d]);
                hi[d] = std::max(hi[d], p[d]);
              }
        }

        /** Whether the two boxes share a point. */
        bool
        meets(const Box &other) const
        {
          for (unsigned int d = 0; d < 3; ++d)
            if (other.lo[d] > hi[d] || other.hi[d] < lo[d])
              return false;
          return true;
        }
      };

      /**
       * The master faces sorted into the cells of a uniform grid over their
       * boxes: each face is listed in every cell its box meets, so that the
       * faces whose boxes meet a given box are among those of the cells the
       * box meets. The cell size is the mean diameter of the master boxes,
       * so that a face sits in a few cells and a cell holds a few faces; the
       * grid spans the master surface's box, and the cell size is doubled
       * while there are more than 8 cells per face (a curved surface fills
       * few of the cells of its box). Building it and finding the faces near
       * one box cost O(1) per face for surfaces of faces of similar sizes,
       * O(n) in all where the all-pairs search is O(n^2): 4900 slave faces
       * over 5041 master faces of a flat grid take 81 000 box tests (17 per
       * slave face, 7 of them clipped), where all pairs would take 25
       * million. A tree of boxes would do as well; the grid is simpler and
       * suits the surfaces of contact, whose faces have similar sizes.
       */
      class MasterGrid
      {
      public:
        /** The grid of the master boxes. */
        explicit MasterGrid(const std::vector<Box> &boxes)
        {
          if (boxes.empty())
            return;
          origin      = boxes[0].lo;
          Point<3> hi = boxes[0].hi;
          double   h  = 0.;
          for (const Box &b : boxes)
            {
              for (unsigned int d = 0; d < 3; ++d)
                {
                  origin[d] = std::min(origin[d], b.lo[d]);
                  hi[d]     = std::max(hi[d], b.hi[d]);
                }
              h += (b.hi - b.lo).norm() / boxes.size();
            }
          const double extent = (hi - origin).norm();
          if (h <= 1e-12 * extent || extent == 0.)
            h = std::max(extent, 1.);
          for (;;)
            {
              double n_cells = 1.;
              for (unsigned int d = 0; d < 3; ++d)
                {
                  n[d] = 1 + static_cast<unsigned int>(
                               std::min((hi[d] - origin[d]) / h, 1e6));
                  n_cells *= n[d];
                }
              if (n_cells <= 8. * boxes.size() + 64.)
                break;
              h *= 2.;
            }
          cell_size = h;
          // the lists of the cells, one after the other: count, then fill
          start.assign(n[0] * n[1] * n[2] + 1, 0);
          for (const Box &b : boxes)
            for_cells(b, [&](const unsigned int c) { ++start[c + 1]; });
          for (unsigned int c = 0; c + 1 < start.size(); ++c)
            start[c + 1] += start[c];
          faces.resize(start.back());
          std::vector<unsigned int> fill(start.begin(), start.end() - 1);
          for (unsigned int f = 0; f < boxes.size(); ++f)
            for_cells(boxes[f],
                      [&](const unsigned int c) { faces[fill[c]++] = f; });
        }

        /**
         * Calls f(c) for every cell c the box meets.
         */
        template <typename F>
        void
        for_cells(const Box &b, const F &f) const
        {
          if (start.empty())
            return;
          unsigned int lo[3], hi[3];
          for (unsigned int d = 0; d < 3; ++d)
            {
              const double l = (b.lo[d] - origin[d]) / cell_size;
              const double u = (b.hi[d] - origin[d]) / cell_size;
              if (u < 0. || l >= n[d])
                return;
              lo[d] = l <= 0. ? 0 : static_cast<unsigned int>(l);
              hi[d] = std::min(n[d] - 1, static_cast<unsigned int>(u));
            }
          for (unsigned int i = lo[0]; i <= hi[0]; ++i)
            for (unsigned int j = lo[1]; j <= hi[1]; ++j)
              for (unsigned int k = lo[2]; k <= hi[2]; ++k)
                f((i * n[1] + j) * n[2] + k);
        }

        /**
         * The master faces listed in cell c.
         */
        std::pair<const unsigned int *, const unsigned int *>
        cell(const unsigned int c) const
        {
          return {faces.data() + start[c], faces.data() + start[c + 1]};
        }

      private:
        Point<3>                  origin;
        double                    cell_size = 1.;
        unsigned int              n[3]      = {0, 0, 0};
        std::vector<unsigned int> start;
        std::vector<unsigned int> faces;
      };

      /**
       * The master faces as the search for a slave face's partners sees
       * them: their boxes sorted into a grid, and whether each is affine,
       * and its diameter.
       */
      struct MasterSurface
      {
        explicit MasterSurface(const std::vector<Face> &master)
        {
          boxes.reserve(master.size());
          for (const Face &m : master)
            {
              AssertThrow(well_formed(m),
                          ExcMessage("A master face is a triangle of degree 1 "
                                     "or a quadrilateral of degree 1-3 with "
                                     "(k + 1)^2 node numbers."));
              boxes.emplace_back(m.x);
            }
          grid = std::make_unique<MasterGrid>(boxes);
          is_affine.resize(master.size());
          diameters.resize(master.size());
          for (unsigned int g = 0; g < master.size(); ++g)
            {
              is_affine[g] = affine(master[g]);
              diameters[g] = diameter(master[g]);
            }
        }

        std::vector<Box>            boxes;
        std::unique_ptr<MasterGrid> grid;
        std::vector<bool>           is_affine;
        std::vector<double>         diameters;
      };

      /**
       * A slave face and its auxiliary plane: through its centre, normal to
       * it there (n0, zero for a degenerate face), with the orthonormal
       * axes e0, e1; its vertices projected (xs), their polygon and its
       * area, its dual functions a_sk, whether it is affine, its diameter,
       * and its box enlarged by a quarter of its diameter, and by the reach
       * along its normal.
       */
      struct SlavePlane
      {
        SlavePlane(const Face &s, const double reach)
            : box(s.x)
        {
          dual_basis(s, a, lumped);
          is_affine = affine(s);
          n0        = centre_normal(s);
          if (n0.norm() == 0.)
            return;
          const unsigned int ns = s.x.size();
          const double       c  = ns == 3 ? 1. / 3. : 0.5;
          centre                = map(s.x, c, c);
          e0 = (s.x[1] - s.x[0]) - ((s.x[1] - s.x[0]) * n0) * n0;
          e0 /= e0.norm();
          e1 = cross_product_3d(n0, e0);
          xs.resize(ns);
          for (unsigned int k = 0; k < ns; ++k)
            xs[k] = project(s.x[k]);
          polygon       = geometry::polygon(xs);
          area          = 0.5 * twice_signed_area(polygon);
          face_diameter = diameter(s);
          for (unsigned int d = 0; d < 3; ++d)
            {
              box.lo[d] -= 0.25 * face_diameter + reach * std::abs(n0[d]);
              box.hi[d] += 0.25 * face_diameter + reach * std::abs(n0[d]);
            }
        }

        /** A point's coordinates in the plane. */
        Point<2>
        project(const Point<3> &p) const
        {
          return Point<2>((p - centre) * e0, (p - centre) * e1);
        }

        std::vector<std::vector<double>> a;
        std::vector<double>              lumped;
        bool                             is_affine = false;
        Tensor<1, 3>                     n0;
        Point<3>                         centre;
        Tensor<1, 3>                     e0, e1;
        std::vector<Point<2>>            xs, polygon;
        double                           area          = 0.;
        double                           face_diameter = 0.;
        Box                              box;
      };

      /**
       * int phi_k phi_l over the clipped polygon `overlap` of the plane
       * (entry k * (number of master nodes) + l): the triangles from its
       * vertex centroid, each integrated by `rule`, with the slave's
       * surface element against the plane's.
       */
      std::vector<double>
      integrate_overlap(const Face                       &s,
                        const Face                       &m,
                        const SlavePlane                 &plane,
                        const std::vector<Point<2>>      &xm,
                        const std::vector<Point<2>>      &overlap,
                        const std::vector<TrianglePoint> &rule)
      {
        const std::vector<Point<2>> &xs       = plane.xs;
        const Tensor<1, 3>          &n0       = plane.n0;
        const unsigned int           ns_nodes = s.node.size();
        const unsigned int           nm_nodes = m.node.size();
        Point<2>                     middle;
        for (const Point<2> &p : overlap)
          middle += (1. / overlap.size()) * p;
        std::vector<double> local(ns_nodes * nm_nodes, 0.);
        for (unsigned int i = 0; i < overlap.size(); ++i)
          {
            const Point<2> &p = overlap[i];
            const Point<2> &q = overlap[(i + 1) % overlap.size()];
            const double area = 0.5 * ((p[0] - middle[0]) * (q[1] - middle[1]) -
                                       (p[1] - middle[1]) * (q[0] - middle[0]));
            if (area <= 0.)
              continue;
            for (const TrianglePoint &r : rule)
              {
                const Point<2> x =
                  r.lambda[0] * middle + r.lambda[1] * p + r.lambda[2] * q;
                const auto [xi, eta]     = parametric(xs, x);
                const auto [zeta, theta] = parametric(xm, x);
                // the slave's surface element against the plane's
                const auto [t0, t1]       = tangents(s.x, xi, eta);
                const Tensor<1, 3> normal = cross_product_3d(t0, t1);
                const double ratio = normal.norm() / std::abs(normal * n0);
                double       phi_s[max_face_nodes], phi_m[max_face_nodes];
                trace_values(s, xi, eta, phi_s);
                trace_values(m, zeta, theta, phi_m);
                const double w = r.weight * area * ratio;
                for (unsigned int k = 0; k < ns_nodes; ++k)
                  for (unsigned int l = 0; l < nm_nodes; ++l)
                    local[k * nm_nodes + l] += w * phi_s[k] * phi_m[l];
              }
          }
        return local;
      }

      /**
       * Whether the slave face s and the master face m couple (see
       * couple() in mortar_3d.h); if so, their entries
       * int psi_s phi_j = sum_k a_sk int phi_k phi_j added to `entries`.
       */
      void
      couple_faces(
        const Face       &s,
        const Face       &m,
        const SlavePlane &plane,
        const bool        master_affine,
        const double      master_diameter,
        std::vector<std::vector<std::pair<unsigned int, double>>> &entries)
      {
        const std::vector<Point<2>> &xs       = plane.xs;
        const unsigned int           ns_nodes = s.node.size();
        const unsigned int           nm       = m.x.size();
        std::vector<Point<2>>        xm(nm);
        for (unsigned int k = 0; k < nm; ++k)
          xm[k] = plane.project(m.x[k]);
        // a master at a right angle to the slave projects onto a
        // sliver: its projected area against its own
        const std::vector<Point<2>> master_polygon = polygon(xm);
        if (0.5 * twice_signed_area(master_polygon) <= 1e-12 * area(m))
          return;
        const std::vector<Point<2>> overlap =
          clip_polygon(plane.polygon, master_polygon);
        if (overlap.size() < 3 ||
            0.5 * twice_signed_area(overlap) <= 1e-14 * plane.area)
          return;
        // the two faces face each other where they overlap: at each
        // corner of the clipped polygon (between them the distance
        // of two flat faces is affine) each lies in front of the
        // other up to facing_tolerance()
        if (!in_front(s,
                      m,
                      xs,
                      xm,
                      overlap,
                      facing_tolerance(plane.face_diameter, master_diameter)))
          return;

        // the triangles from the vertex centroid, each integrated
        // by a rule exact for two affine faces (psi_s phi_j of
        // degree 2 (k_s + k_m)), or else by a finer one
        const unsigned int                nm_nodes = m.node.size();
        const unsigned int                degrees  = s.degree + m.degree;
        const std::vector<TrianglePoint> &rule =
          !(plane.is_affine && master_affine) ?
            conical_rule(std::max(6u, degrees + 4)) :
          degrees == 2 ? triangle_rule() :
                         conical_rule(degrees + 1);
        const std::vector<double> local =
          integrate_overlap(s, m, plane, xm, overlap, rule);
        const std::vector<std::vector<double>> &a = plane.a;
        // int psi_s phi_j = sum_k a_sk int phi_k phi_j
        for (unsigned int i = 0; i < ns_nodes; ++i)
          for (unsigned int l = 0; l < nm_nodes; ++l)
            {
              double v = 0.;
              for (unsigned int k = 0; k < ns_nodes; ++k)
                v += a[i][k] * local[k * nm_nodes + l];
              entries[s.node[i]].emplace_back(m.node[l], v);
            }
      }

      /**
       * Each slave node's entries (j, M_sj) in the order of j, those of one
       * master node summed in the order they came.
       */
      std::vector<std::vector<std::pair<unsigned int, double>>>
      merge_entries(
        std::vector<std::vector<std::pair<unsigned int, double>>> &entries)
      {
        const unsigned int n_slave_nodes = entries.size();
        std::vector<std::vector<std::pair<unsigned int, double>>> master(
          n_slave_nodes);
        for (unsigned int s = 0; s < n_slave_nodes; ++s)
          {
            auto &e = entries[s];
            std::stable_sort(e.begin(),
                             e.end(),
                             [](const auto &p, const auto &q) {
                               return p.first < q.first;
                             });
            for (const auto &[j, v] : e)
              if (!master[s].empty() && master[s].back().first == j)
                master[s].back().second += v;
              else
                master[s].emplace_back(j, v);
          }
        return master;
      }
    } // namespace



    std::vector<std::vector<double>>
    dual_coefficients(const Face &face)
    {
      std::vector<std::vector<double>> a;
      std::vector<double>              lumped;
      dual_basis(face, a, lumped);
      return a;
    }



    Coupling
    couple(const std::vector<Face> &slave,
           const unsigned int       n_slave_nodes,
           const std::vector<Face> &master,
           const double             reach)
    {
      Coupling coupling;
      coupling.weight.assign(n_slave_nodes, 0.);
      std::vector<std::vector<std::pair<unsigned int, double>>> entries(
        n_slave_nodes);
      const MasterSurface masters(master);
      // the slave face that last looked at each master face, so that a
      // master listed in several cells is taken once
      std::vector<unsigned int> seen(master.size(),
                                     numbers::invalid_unsigned_int);

      for (unsigned int f = 0; f < slave.size(); ++f)
        {
          const Face &s = slave[f];
          AssertThrow(well_formed(s),
                      ExcMessage("A slave face is a triangle of degree 1 or "
                                 "a quadrilateral of degree 1-3 with "
                                 "(k + 1)^2 node numbers."));
          // the dual functions, the weights int phi_k dA, and the plane
          const SlavePlane plane(s, reach);
          for (unsigned int k = 0; k < s.node.size(); ++k)
            coupling.weight[s.node[k]] += plane.lumped[k];
          if (plane.n0.norm() == 0.)
            continue;
          masters.grid->for_cells(plane.box, [&](const unsigned int cell) {
            const auto [begin, end] = masters.grid->cell(cell);
            for (const unsigned int *it = begin; it != end; ++it)
              {
                const unsigned int g = *it;
                if (seen[g] == f)
                  continue;
                seen[g]       = f;
                const Face &m = master[g];
                if (s.normal.norm() > 0. && m.normal.norm() > 0. &&
                    s.normal * m.normal >= -0.5)
                  continue;
                if (!plane.box.meets(masters.boxes[g]))
                  continue;
                couple_faces(s,
                             m,
                             plane,
                             masters.is_affine[g],
                             masters.diameters[g],
                             entries);
              }
          });
        }
      coupling.master = merge_entries(entries);
      return coupling;
    }
  } // namespace mortar
} // namespace dualcontact
