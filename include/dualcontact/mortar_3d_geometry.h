// The geometry and quadrature of the 3D mortar coupling (mortar_3d.h): the
// quadrature rules on triangles, the trace functions of a face and its
// bilinear map, the projected polygons of two faces clipped against each
// other, whether two faces face each other, and the dual basis of a slave
// face. Numbers and points only.
#ifndef dualcontact_mortar_3d_geometry_h
#define dualcontact_mortar_3d_geometry_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <dualcontact/mortar_3d.h>

#include <array>
#include <utility>
#include <vector>

namespace dualcontact
{
  namespace mortar
  {
    namespace geometry
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
      triangle_rule();

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
      conical_rule(const unsigned int n);

      /**
       * The values of the functions of a face's map at the parametric point
       * (xi, eta): on a triangle 1 - xi - eta, xi, eta; on a quadrilateral
       * the bilinear functions in lexicographic order.
       */
      void
      shape_values(const unsigned int n_vertices,
                   const double       xi,
                   const double       eta,
                   double            *phi);

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
                   double      *phi);

      // the most nodes of a face: (k + 1)^2 at k = 3
      constexpr unsigned int max_face_nodes = 16;

      /**
       * Whether a face's vertices and nodes fit its kind and degree (see
       * Face).
       */
      bool
      well_formed(const Face &face);

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
      parametric(const std::vector<Point<2>> &x, const Point<2> &q);

      /**
       * Twice the signed area of a polygon of the plane (positive for a
       * counter-clockwise cycle).
       */
      double
      twice_signed_area(const std::vector<Point<2>> &p);

      /**
       * The cycle of a face's vertices projected into the plane, counter-
       * clockwise: 0, 1, 2 for a triangle, 0, 1, 3, 2 for a lexicographic
       * quadrilateral, reversed if it turns the other way.
       */
      std::vector<Point<2>>
      polygon(const std::vector<Point<2>> &x);

      /**
       * The part of the convex counter-clockwise polygon `subject` inside
       * the convex counter-clockwise polygon `clip` (Sutherland and Hodgman:
       * cut by the half-plane left of each of clip's edges in turn).
       */
      std::vector<Point<2>>
      clip_polygon(std::vector<Point<2>>        subject,
                   const std::vector<Point<2>> &clip);

      /**
       * A face's unit normal at its parametric centre (the orientation of
       * its vertex cycle, not of its body), or zero for a degenerate face.
       */
      Tensor<1, 3>
      centre_normal(const Face &face);

      /**
       * Whether a face's map is affine: a triangle, or a parallelogram
       * (x_0 - x_1 - x_2 + x_3 = 0 to round-off), which is flat. The trace
       * functions of an affine face are polynomials of the coordinates of
       * any plane it is projected into.
       */
      bool
      affine(const Face &face);

      /**
       * A face's diameter: the largest distance of two of its vertices.
       */
      double
      diameter(const Face &face);

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
               const double                 tolerance);

      /**
       * A face's area: of a triangle, or of a flat quadrilateral, whose
       * surface element is affine in (xi, eta) and so its mean is the value
       * at the centre (for a curved one, that value's approximation).
       */
      double
      area(const Face &face);

      /**
       * The coefficients a_sk of a face's dual functions (see
       * dual_coefficients()) and the weights int phi_k dA of its trace
       * functions.
       */
      void
      dual_basis(const Face                       &face,
                 std::vector<std::vector<double>> &a,
                 std::vector<double>              &lumped);
    } // namespace geometry
  }   // namespace mortar
} // namespace dualcontact

#endif
