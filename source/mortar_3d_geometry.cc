// The geometry and quadrature of the 3D mortar coupling
// (mortar_3d_geometry.h): quadrature rules, trace functions, the face maps'
// inverses, polygon clipping, the facing test and the dual basis.
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/lac/full_matrix.h>

#include <dualcontact/mortar_3d_geometry.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace dualcontact
{
  namespace mortar
  {
    namespace geometry
    {
      namespace
      {
        /**

         * The Gauss-Lobatto points of [0, 1] for the degree k, the support

         * points of FE_Q(k) along a line.

         */

        const std::vector<double> &

        lobatto_points(const unsigned int k)

        {
          static std::map<unsigned int, std::vector<double>> points;

          std::vector<double> &x = points[k];

          if (x.empty())

            {
              const QGaussLobatto<1> rule(k + 1);

              for (unsigned int i = 0; i <= k; ++i)

                x.push_back(rule.point(i)[0]);

              std::sort(x.begin(), x.end());
            }

          return x;
        }
      } // namespace

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

      bool
      well_formed(const Face &face)
      {
        if (face.x.size() == 3)
          return face.degree == 1 && face.node.size() == 3;
        return face.x.size() == 4 && face.degree >= 1 && face.degree <= 3 &&
               face.node.size() == (face.degree + 1) * (face.degree + 1);
      }

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

      Tensor<1, 3>
      centre_normal(const Face &face)
      {
        const double c       = face.x.size() == 3 ? 1. / 3. : 0.5;
        const auto [t0, t1]  = tangents(face.x, c, c);
        const Tensor<1, 3> n = cross_product_3d(t0, t1);
        const double       l = n.norm();
        return l > 0. ? n / l : Tensor<1, 3>();
      }

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

      double
      diameter(const Face &face)
      {
        double d = 0.;
        for (const Point<3> &p : face.x)
          for (const Point<3> &q : face.x)
            d = std::max(d, p.distance(q));
        return d;
      }

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

      double
      area(const Face &face)
      {
        const double c      = face.x.size() == 3 ? 1. / 3. : 0.5;
        const auto [t0, t1] = tangents(face.x, c, c);
        return (face.x.size() == 3 ? 0.5 : 1.) *
               cross_product_3d(t0, t1).norm();
      }

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
    } // namespace geometry
  }   // namespace mortar
} // namespace dualcontact
