#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/lac/full_matrix.h>

#include <dualcontact/mortar_3d.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

namespace dualcontact
{
  namespace mortar
  {
    namespace
    {
      /**
       * A point of a triangle in barycentric coordinates and its weight,
       * the weights summing to one (to be multiplied by the area).
       */
      struct TrianglePoint
      {
        double lambda[3];
        double weight;
      };

      /**
       * The symmetric 7-point rule of degree 5 on a triangle: Radon (1948),
       * A. H. Stroud, Approximate Calculation of Multiple Integrals (1971),
       * formula T2:5-1, the degree-5 rule of D. A. Dunavant, IJNME 21 (1985).
       * The centroid, and two orbits of three points (a, a, 1 - 2a) with
       * a = (6 -+ sqrt 15) / 21 and weights (155 -+ sqrt 15) / 1200.
       */
      const std::vector<TrianglePoint> &
      triangle_rule()
      {
        static const std::vector<TrianglePoint> rule = [] {
          const double r  = std::sqrt(15.);
          const double a1 = (6. - r) / 21., b1 = 1. - 2. * a1;
          const double a2 = (6. + r) / 21., b2 = 1. - 2. * a2;
          const double w1 = (155. - r) / 1200., w2 = (155. + r) / 1200.;
          return std::vector<TrianglePoint>{{{1. / 3., 1. / 3., 1. / 3.},
                                             9. / 40.},
                                            {{a1, a1, b1}, w1},
                                            {{a1, b1, a1}, w1},
                                            {{b1, a1, a1}, w1},
                                            {{a2, a2, b2}, w2},
                                            {{a2, b2, a2}, w2},
                                            {{b2, a2, a2}, w2}};
        }();
        return rule;
      }

      /**
       * A conical product rule on a triangle (Stroud 1971, the conical
       * product formulas; the collapsed coordinates of M. G. Duffy, SIAM J.
       * Numer. Anal. 19 (1982)): the square [0, 1]^2 mapped onto the
       * triangle by (u, v) -> barycentric (1 - u, u (1 - v), u v), of
       * Jacobian u, with the n-point Gauss rule in each direction: n^2
       * points, exact for degree 2 n - 2 (degree p + 1 in u, p in v). It
       * serves the traces of degree k > 1, whose integrand psi_s phi_j has
       * degree 2 (k_s + k_m) on two affine faces, and the pairs whose
       * integrand is not a polynomial (a face that is not a triangle or a
       * parallelogram): there the error of the 7-point rule falls only as
       * the sixth power of the sub-triangles' size (5e-7 in the coverage for
       * inner vertices of Q1 faces moved by up to 0.2 of a cell), this one's
       * falls exponentially with the number of points (3e-13 there with
       * n = 6, round-off with n = 10).
       */
      const std::vector<TrianglePoint> &
      conical_rule(const unsigned int n)
      {
        static std::map<unsigned int, std::vector<TrianglePoint>> rules;
        std::vector<TrianglePoint> &points = rules[n];
        if (points.empty())
          {
            const QGauss<1> gauss(n);
            for (unsigned int i = 0; i < gauss.size(); ++i)
              for (unsigned int j = 0; j < gauss.size(); ++j)
                {
                  const double u = gauss.point(i)[0], v = gauss.point(j)[0];
                  points.push_back(
                    {{1. - u, u * (1. - v), u * v},
                     2. * u * gauss.weight(i) * gauss.weight(j)});
                }
          }
        return points;
      }

      /**
       * The values of the functions of a face's map at the parametric point
       * (xi, eta): on a triangle 1 - xi - eta, xi, eta; on a quadrilateral
       * the bilinear functions in lexicographic order.
       */
      void
      shape_values(const unsigned int n_vertices,
                   const double       xi,
                   const double       eta,
                   double            *phi)
      {
        if (n_vertices == 3)
          {
            phi[0] = 1. - xi - eta;
            phi[1] = xi;
            phi[2] = eta;
          }
        else
          {
            phi[0] = (1. - xi) * (1. - eta);
            phi[1] = xi * (1. - eta);
            phi[2] = (1. - xi) * eta;
            phi[3] = xi * eta;
          }
      }

      /**
       * The Gauss-Lobatto points of [0, 1] for the degree k, the support
       * points of FE_Q(k) along a line.
       */
      const std::vector<double> &
      lobatto_points(const unsigned int k)
      {
        static std::map<unsigned int, std::vector<double>> points;
        std::vector<double>                               &x = points[k];
        if (x.empty())
          {
            const QGaussLobatto<1> rule(k + 1);
            for (unsigned int i = 0; i <= k; ++i)
              x.push_back(rule.point(i)[0]);
            std::sort(x.begin(), x.end());
          }
        return x;
      }

      /**
       * The values of a face's trace functions at (xi, eta), in the order of
       * its nodes: on a triangle the linear ones, on a quadrilateral the
       * products l_i(xi) l_j(eta) of the Lagrange polynomials of degree k
       * through the Gauss-Lobatto points, node i + (k + 1) j.
       */
      void
      trace_values(const Face  &face,
                   const double xi,
                   const double eta,
                   double      *phi)
      {
        const unsigned int k = face.degree;
        if (face.x.size() == 3 || k == 1)
          {
            shape_values(face.x.size(), xi, eta, phi);
            return;
          }
        const std::vector<double> &p = lobatto_points(k);
        double                     a[4], b[4];
        for (unsigned int i = 0; i <= k; ++i)
          {
            a[i] = b[i] = 1.;
            for (unsigned int l = 0; l <= k; ++l)
              if (l != i)
                {
                  a[i] *= (xi - p[l]) / (p[i] - p[l]);
                  b[i] *= (eta - p[l]) / (p[i] - p[l]);
                }
          }
        for (unsigned int j = 0; j <= k; ++j)
          for (unsigned int i = 0; i <= k; ++i)
            phi[i + (k + 1) * j] = a[i] * b[j];
      }

      // the most nodes of a face: (k + 1)^2 at k = 3
      constexpr unsigned int max_face_nodes = 16;

      /**
       * Whether a face's vertices and nodes fit its kind and degree (see
       * Face).
       */
      bool
      well_formed(const Face &face)
      {
        if (face.x.size() == 3)
          return face.degree == 1 && face.node.size() == 3;
        return face.x.size() == 4 && face.degree >= 1 && face.degree <= 3 &&
               face.node.size() == (face.degree + 1) * (face.degree + 1);
      }

      /**
       * The tangents d x / d xi and d x / d eta of a face's map at (xi, eta),
       * for the vertices of the face in 3D or projected into the plane.
       */
      template <int spacedim>
      std::pair<Tensor<1, spacedim>, Tensor<1, spacedim>>
      tangents(const std::vector<Point<spacedim>> &x,
               const double                        xi,
               const double                        eta)
      {
        if (x.size() == 3)
          return {x[1] - x[0], x[2] - x[0]};
        return {(1. - eta) * (x[1] - x[0]) + eta * (x[3] - x[2]),
                (1. - xi) * (x[2] - x[0]) + xi * (x[3] - x[1])};
      }

      /**
       * The point of a face's map at (xi, eta).
       */
      template <int spacedim>
      Point<spacedim>
      map(const std::vector<Point<spacedim>> &x,
          const double                        xi,
          const double                        eta)
      {
        double phi[4];
        shape_values(x.size(), xi, eta, phi);
        Point<spacedim> p;
        for (unsigned int k = 0; k < x.size(); ++k)
          p += phi[k] * x[k];
        return p;
      }

      /**
       * The parametric coordinates of the point q of the plane in a face
       * projected into the plane: for a triangle one solve of its affine
       * map; for a quadrilateral Newton's method on its bilinear map from
       * the centre, which ends after one step on a parallelogram (the map is
       * affine) and converges quadratically on a convex quadrilateral.
       */
      std::array<double, 2>
      parametric(const std::vector<Point<2>> &x, const Point<2> &q)
      {
        double xi = x.size() == 3 ? 0. : 0.5, eta = xi;
        for (unsigned int it = 0; it < 30; ++it)
          {
            const auto [t0, t1]   = tangents(x, xi, eta);
            const Tensor<1, 2> r  = q - map(x, xi, eta);
            const double       dt = t0[0] * t1[1] - t0[1] * t1[0];
            if (dt == 0.)
              break;
            const double dxi  = (r[0] * t1[1] - r[1] * t1[0]) / dt;
            const double deta = (t0[0] * r[1] - t0[1] * r[0]) / dt;
            xi += dxi;
            eta += deta;
            if (x.size() == 3 || std::abs(dxi) + std::abs(deta) <= 1e-14)
              break;
          }
        return {{xi, eta}};
      }

      /**
       * Twice the signed area of a polygon of the plane (positive for a
       * counter-clockwise cycle).
       */
      double
      twice_signed_area(const std::vector<Point<2>> &p)
      {
        double a = 0.;
        for (unsigned int i = 0; i < p.size(); ++i)
          {
            const Point<2> &u = p[i], &v = p[(i + 1) % p.size()];
            a += u[0] * v[1] - u[1] * v[0];
          }
        return a;
      }

      /**
       * The cycle of a face's vertices projected into the plane, counter-
       * clockwise: 0, 1, 2 for a triangle, 0, 1, 3, 2 for a lexicographic
       * quadrilateral, reversed if it turns the other way.
       */
      std::vector<Point<2>>
      polygon(const std::vector<Point<2>> &x)
      {
        std::vector<Point<2>> p;
        if (x.size() == 3)
          p = x;
        else
          p = {x[0], x[1], x[3], x[2]};
        if (twice_signed_area(p) < 0.)
          std::reverse(p.begin(), p.end());
        return p;
      }

      /**
       * The part of the convex counter-clockwise polygon `subject` inside
       * the convex counter-clockwise polygon `clip` (Sutherland and Hodgman:
       * cut by the half-plane left of each of clip's edges in turn).
       */
      std::vector<Point<2>>
      clip_polygon(std::vector<Point<2>>        subject,
                   const std::vector<Point<2>> &clip)
      {
        std::vector<Point<2>> out;
        for (unsigned int e = 0; e < clip.size() && subject.size() > 2; ++e)
          {
            const Point<2>    &a = clip[e];
            const Tensor<1, 2> t = clip[(e + 1) % clip.size()] - a;
            // the distance left of the edge, times its length
            const auto left = [&](const Point<2> &p) {
              return t[0] * (p[1] - a[1]) - t[1] * (p[0] - a[0]);
            };
            out.clear();
            for (unsigned int i = 0; i < subject.size(); ++i)
              {
                const Point<2> &p  = subject[i];
                const Point<2> &q  = subject[(i + 1) % subject.size()];
                const double    dp = left(p), dq = left(q);
                if (dp >= 0.)
                  out.push_back(p);
                if ((dp >= 0.) != (dq >= 0.))
                  out.push_back(p + dp / (dp - dq) * (q - p));
              }
            std::swap(subject, out);
          }
        return subject;
      }

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
       * A face's unit normal at its parametric centre (the orientation of
       * its vertex cycle, not of its body), or zero for a degenerate face.
       */
      Tensor<1, 3>
      centre_normal(const Face &face)
      {
        const double c       = face.x.size() == 3 ? 1. / 3. : 0.5;
        const auto [t0, t1]  = tangents(face.x, c, c);
        const Tensor<1, 3> n = cross_product_3d(t0, t1);
        const double       l = n.norm();
        return l > 0. ? n / l : Tensor<1, 3>();
      }

      /**
       * Whether a face's map is affine: a triangle, or a parallelogram
       * (x_0 - x_1 - x_2 + x_3 = 0 to round-off), which is flat. The trace
       * functions of an affine face are polynomials of the coordinates of
       * any plane it is projected into.
       */
      bool
      affine(const Face &face)
      {
        if (face.x.size() == 3)
          return true;
        const Tensor<1, 3> twist =
          face.x[0] - face.x[1] - face.x[2] + face.x[3];
        return twist.norm() <= 1e-12 * ((face.x[3] - face.x[0]).norm() +
                                        (face.x[2] - face.x[1]).norm());
      }

      /**
       * A face's diameter: the largest distance of two of its vertices.
       */
      double
      diameter(const Face &face)
      {
        double d = 0.;
        for (const Point<3> &p : face.x)
          for (const Point<3> &q : face.x)
            d = std::max(d, p.distance(q));
        return d;
      }

      /**
       * Whether the slave face s and the master face m lie on each other's
       * front side, each up to `tolerance`, at the points `overlap` of the
       * plane (the corners of the clipped polygon): at each, with x_s and
       * x_m the points of the two faces that project onto it (xs and xm
       * the faces' vertices projected), n_s . (x_m - x_s) and
       * n_m . (x_s - x_m) at least -tolerance. Faces without normals (zero)
       * are taken as facing.
       */
      bool
      in_front(const Face                  &s,
               const Face                  &m,
               const std::vector<Point<2>> &xs,
               const std::vector<Point<2>> &xm,
               const std::vector<Point<2>> &overlap,
               const double                 tolerance)
      {
        if (!(s.normal.norm() > 0. && m.normal.norm() > 0.))
          return true;
        for (const Point<2> &q : overlap)
          {
            const auto [xi, eta]     = parametric(xs, q);
            const auto [zeta, theta] = parametric(xm, q);
            const Tensor<1, 3> d = map(m.x, zeta, theta) - map(s.x, xi, eta);
            if (s.normal * d < -tolerance || m.normal * d > tolerance)
              return false;
          }
        return true;
      }

      /**
       * A face's area: of a triangle, or of a flat quadrilateral, whose
       * surface element is affine in (xi, eta) and so its mean is the value
       * at the centre (for a curved one, that value's approximation).
       */
      double
      area(const Face &face)
      {
        const double c      = face.x.size() == 3 ? 1. / 3. : 0.5;
        const auto [t0, t1] = tangents(face.x, c, c);
        return (face.x.size() == 3 ? 0.5 : 1.) *
               cross_product_3d(t0, t1).norm();
      }

      /**
       * The coefficients a_sk of a face's dual functions (see
       * dual_coefficients()) and the weights int phi_k dA of its trace
       * functions.
       */
      void
      dual_basis(const Face                       &face,
                 std::vector<std::vector<double>> &a,
                 std::vector<double>              &lumped)
      {
        const unsigned int n = face.node.size();
        FullMatrix<double> mass(n, n);
        lumped.assign(n, 0.);
        // the integration points of the reference face and their weights:
        // the 7-point rule on a triangle (the Jacobian is constant, the
        // integrand phi_k phi_l of degree 2), the Gauss rule of max(4, k + 2)
        // points in each direction on a square (on a flat quadrilateral
        // |x_xi x x_eta| is affine in (xi, eta) and phi_k phi_l |x_xi x x_eta|
        // of degree 2 k + 1 in each variable; on a curved one an
        // approximation)
        std::vector<std::array<double, 3>> points;
        if (face.x.size() == 3)
          for (const TrianglePoint &p : triangle_rule())
            points.push_back({{p.lambda[1], p.lambda[2], 0.5 * p.weight}});
        else
          {
            const QGauss<2> gauss(std::max(4u, face.degree + 2));
            for (unsigned int q = 0; q < gauss.size(); ++q)
              points.push_back(
                {{gauss.point(q)[0], gauss.point(q)[1], gauss.weight(q)}});
          }
        for (const auto &[xi, eta, w] : points)
          {
            const auto [t0, t1] = tangents(face.x, xi, eta);
            const double dA     = w * cross_product_3d(t0, t1).norm();
            double       phi[max_face_nodes];
            trace_values(face, xi, eta, phi);
            for (unsigned int k = 0; k < n; ++k)
              {
                lumped[k] += dA * phi[k];
                for (unsigned int l = 0; l < n; ++l)
                  mass(k, l) += dA * phi[k] * phi[l];
              }
          }
        FullMatrix<double> inverse(n, n);
        inverse.invert(mass);
        a.assign(n, std::vector<double>(n));
        for (unsigned int s = 0; s < n; ++s)
          for (unsigned int k = 0; k < n; ++k)
            a[s][k] = lumped[s] * inverse(s, k);
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

      std::vector<Box> master_boxes;
      master_boxes.reserve(master.size());
      for (const Face &m : master)
        {
          AssertThrow(well_formed(m),
                      ExcMessage("A master face is a triangle of degree 1 "
                                 "or a quadrilateral of degree 1-3 with "
                                 "(k + 1)^2 node numbers."));
          master_boxes.emplace_back(m.x);
        }
      const MasterGrid    grid(master_boxes);
      std::vector<bool>   master_affine(master.size());
      std::vector<double> master_diameter(master.size());
      for (unsigned int g = 0; g < master.size(); ++g)
        {
          master_affine[g]   = affine(master[g]);
          master_diameter[g] = diameter(master[g]);
        }
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
          // its vertices and its nodes
          const unsigned int ns = s.x.size(), ns_nodes = s.node.size();
          // the dual functions, and the weights int phi_k dA
          std::vector<std::vector<double>> a;
          std::vector<double>              lumped;
          dual_basis(s, a, lumped);
          for (unsigned int k = 0; k < ns_nodes; ++k)
            coupling.weight[s.node[k]] += lumped[k];
          const bool slave_affine = affine(s);
          // the auxiliary plane: through the centre, normal to the face there
          const Tensor<1, 3> n0 = centre_normal(s);
          if (n0.norm() == 0.)
            continue;
          const double   c      = ns == 3 ? 1. / 3. : 0.5;
          const Point<3> centre = map(s.x, c, c);
          Tensor<1, 3>   e0 = (s.x[1] - s.x[0]) - ((s.x[1] - s.x[0]) * n0) * n0;
          e0 /= e0.norm();
          const Tensor<1, 3> e1      = cross_product_3d(n0, e0);
          const auto         project = [&](const Point<3> &p) {
            return Point<2>((p - centre) * e0, (p - centre) * e1);
          };
          std::vector<Point<2>> xs(ns);
          for (unsigned int k = 0; k < ns; ++k)
            xs[k] = project(s.x[k]);
          const std::vector<Point<2>> slave_polygon = polygon(xs);
          const double slave_area = 0.5 * twice_signed_area(slave_polygon);

          // the slave box, enlarged by a quarter of the face's diameter,
          // and by the reach along its normal
          Box          box(s.x);
          const double slave_diameter = diameter(s);
          for (unsigned int d = 0; d < 3; ++d)
            {
              box.lo[d] -= 0.25 * slave_diameter + reach * std::abs(n0[d]);
              box.hi[d] += 0.25 * slave_diameter + reach * std::abs(n0[d]);
            }

          grid.for_cells(box, [&](const unsigned int cell) {
            const auto [begin, end] = grid.cell(cell);
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
                if (!box.meets(master_boxes[g]))
                  continue;
                const unsigned int    nm = m.x.size();
                std::vector<Point<2>> xm(nm);
                for (unsigned int k = 0; k < nm; ++k)
                  xm[k] = project(m.x[k]);
                // a master at a right angle to the slave projects onto a
                // sliver: its projected area against its own
                const std::vector<Point<2>> master_polygon = polygon(xm);
                if (0.5 * twice_signed_area(master_polygon) <= 1e-12 * area(m))
                  continue;
                const std::vector<Point<2>> overlap =
                  clip_polygon(slave_polygon, master_polygon);
                if (overlap.size() < 3 ||
                    0.5 * twice_signed_area(overlap) <= 1e-14 * slave_area)
                  continue;
                // the two faces face each other where they overlap: at each
                // corner of the clipped polygon (between them the distance
                // of two flat faces is affine) each lies in front of the
                // other up to facing_tolerance()
                if (!in_front(s,
                              m,
                              xs,
                              xm,
                              overlap,
                              facing_tolerance(slave_diameter,
                                               master_diameter[g])))
                  continue;

                // the triangles from the vertex centroid, each integrated
                // by a rule exact for two affine faces (psi_s phi_j of
                // degree 2 (k_s + k_m)), or else by a finer one
                const unsigned int                nm_nodes = m.node.size();
                const unsigned int                degrees = s.degree + m.degree;
                const std::vector<TrianglePoint> &rule =
                  !(slave_affine && master_affine[g]) ?
                    conical_rule(std::max(6u, degrees + 4)) :
                  degrees == 2 ? triangle_rule() :
                                 conical_rule(degrees + 1);
                Point<2> middle;
                for (const Point<2> &p : overlap)
                  middle += (1. / overlap.size()) * p;
                std::vector<double> local(ns_nodes * nm_nodes, 0.);
                for (unsigned int i = 0; i < overlap.size(); ++i)
                  {
                    const Point<2> &p = overlap[i];
                    const Point<2> &q = overlap[(i + 1) % overlap.size()];
                    const double    area =
                      0.5 * ((p[0] - middle[0]) * (q[1] - middle[1]) -
                             (p[1] - middle[1]) * (q[0] - middle[0]));
                    if (area <= 0.)
                      continue;
                    for (const TrianglePoint &r : rule)
                      {
                        const Point<2> x = r.lambda[0] * middle +
                                           r.lambda[1] * p + r.lambda[2] * q;
                        const auto [xi, eta]     = parametric(xs, x);
                        const auto [zeta, theta] = parametric(xm, x);
                        // the slave's surface element against the plane's
                        const auto [t0, t1]       = tangents(s.x, xi, eta);
                        const Tensor<1, 3> normal = cross_product_3d(t0, t1);
                        const double       ratio =
                          normal.norm() / std::abs(normal * n0);
                        double phi_s[max_face_nodes], phi_m[max_face_nodes];
                        trace_values(s, xi, eta, phi_s);
                        trace_values(m, zeta, theta, phi_m);
                        const double w = r.weight * area * ratio;
                        for (unsigned int k = 0; k < ns_nodes; ++k)
                          for (unsigned int l = 0; l < nm_nodes; ++l)
                            local[k * nm_nodes + l] += w * phi_s[k] * phi_m[l];
                      }
                  }
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
          });
        }

      coupling.master.resize(n_slave_nodes);
      for (unsigned int s = 0; s < n_slave_nodes; ++s)
        {
          auto &e = entries[s];
          std::stable_sort(e.begin(),
                           e.end(),
                           [](const auto &p, const auto &q) {
                             return p.first < q.first;
                           });
          for (const auto &[j, v] : e)
            if (!coupling.master[s].empty() &&
                coupling.master[s].back().first == j)
              coupling.master[s].back().second += v;
            else
              coupling.master[s].emplace_back(j, v);
        }
      return coupling;
    }
  } // namespace mortar
} // namespace dualcontact
