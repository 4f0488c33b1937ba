// The dual mortar coupling of two surfaces in 3D, the counterpart of
// mortar.h's segments: the slave surface carries the contact nodes and their
// multipliers, the master surface is the other body. The traces are linear
// on triangles and those of FE_Q(k), k = 1-3, on quadrilaterals; on each
// slave face the dual basis
//   psi_s = sum_k a_sk phi_k,   A = D M^{-1},
//   D = diag(int_face phi_k dA),   M_kl = int_face phi_k phi_l dA,
// computed with the face's own Jacobian, is biorthogonal to the slave's
// traces on that face, int psi_s phi_t dA = delta_st int phi_s dA, also on a
// quadrilateral that is not a parallelogram. The returned Coupling holds, as
// in 2D, the lumped weight m_s = int phi_s dA of every slave node and
//   M_sj = int_{slave} psi_s phi_j^master dA.
//
// M_sj is integrated over segments: each slave face and each master face
// that faces it are projected onto an auxiliary plane (through the slave
// face's centre, normal to the slave face there), the projected slave
// polygon is clipped against the projected master polygon, the clipped
// polygon is cut into triangles from its vertex centroid, and each triangle
// is integrated by a symmetric 7-point rule of degree 5 for two linear or
// bilinear traces, by a conical product rule of degree 2 (k_s + k_m) for
// traces of degrees k_s, k_m > 1, and by one of degree 2 (k_s + k_m) + 6
// (at least 10) where a face of the pair is neither a triangle nor a
// parallelogram, so that the integrand is not a polynomial. At each point the
// slave's and the master's parametric coordinates are those of the same
// point of the plane (the inverse of each face's projected map), and the
// weight carries the ratio of the slave's surface element to the plane's,
// so that the integral is over the slave surface. For flat slave and master
// faces that are triangles or parallelograms, psi_s and phi_j are
// polynomials of degree 2 k_s and 2 k_m in the plane's coordinates and the
// ratio is 1:
// the integral is exact to round-off, which is what passes the contact
// patch test on non-matching meshes (sum_s M_sj = int phi_j^master where the
// slave covers the master, sum_j M_sj x_j = m_s x_s where the master covers
// the support of psi_s). On other faces (a flat quadrilateral that is not a
// parallelogram, curved surfaces) the integrand is a smooth non-polynomial
// function and the rule approximates it (the coverage of a node to 3e-13
// for inner vertices of a flat grid moved by up to 0.2 of a cell). Where
// the master covers only part of the support of psi_s, Coupling::coverage()
// is the covered part of int psi_s dA / m_s, which may be negative (psi_s is
// negative near the face's other vertices); a node whose support no master
// face overlaps has no entries. No mesh, no MPI: numbers and points only.
#ifndef dualcontact_mortar_3d_h
#define dualcontact_mortar_3d_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <dualcontact/mortar.h>

#include <vector>

namespace dualcontact
{
  using namespace dealii;

  namespace mortar
  {
    /**
     * A face of a surface in 3D: a triangle (3 vertices) with a linear
     * trace, or a quadrilateral (4 vertices) with the trace of FE_Q(k) on
     * it, the tensor product of the Lagrange polynomials of degree k
     * through the k + 1 Gauss-Lobatto points of [0, 1] in each direction.
     * Its vertices, and the numbers the caller gives its nodes (on one
     * surface, 0 to the number of its nodes - 1): a triangle's 3 vertices;
     * a quadrilateral's (k + 1)^2 nodes in lexicographic order, node
     * i + (k + 1) j at the i-th point along xi and the j-th along eta. A
     * quadrilateral's vertices are in deal.II's lexicographic order: 0 at
     * (0, 0), 1 at (1, 0), 2 at (0, 1), 3 at (1, 1) of the reference square,
     * so that 0, 1, 3, 2 is its cycle. The face's map is the bilinear one of
     * its vertices (a curved face is taken along it, as in 2D along the
     * chord).
     */
    struct Face
    {
      std::vector<Point<3>>     x;
      std::vector<unsigned int> node;
      // the trace's degree k: 1 on a triangle, 1-3 on a quadrilateral
      unsigned int degree = 1;
      // the outward unit normal of its body, or zero: two faces couple only
      // if they face each other (n_slave . n_master < -1/2, and each in
      // front of the other, facing_tolerance()), so that a curved master's
      // far side, which projects onto the slave's plane as well, stays out
      Tensor<1, 3> normal;
    };

    /**
     * The coefficients a_sk (row s, column k, in the face's node order)
     * of the dual functions psi_s = sum_k a_sk phi_k of a face, A = D M^{-1}
     * with the face's own Jacobian (a Gauss rule exact for a flat face).
     * Each column sums to one, so that the psi_s sum to one on the face.
     * D > 0 at every degree this takes: the Gauss-Lobatto weights of the
     * reference square are positive.
     */
    std::vector<std::vector<double>>
    dual_coefficients(const Face &face);

    /**
     * m_s and M_sj for the slave faces against the master faces (see the
     * top of this file). A pair adds nothing if the normals are given and
     * n_slave . n_master >= -1/2, if the boxes around the faces are apart
     * (the slave's enlarged by a quarter of its diameter, so that faces a
     * little apart still meet, and by `reach` along its normal, so that the
     * master faces that far in front of it are seen: two curved bodies
     * part as r^2 / (2 R*) away from where they touch), if the master
     * projects onto a sliver of the plane (it stands at a right angle to
     * the slave), if the clipped polygon's area is at most 1e-14 times the
     * slave face's, or if the normals are given and at a corner of the
     * clipped polygon one face lies behind the other by more than
     * facing_tolerance() of their diameters (mortar.h). The master
     * faces are sorted into the cells of a uniform grid by their boxes, so
     * that each slave face looks only at the masters near it.
     */
    Coupling
    couple(const std::vector<Face> &slave,
           unsigned int             n_slave_nodes,
           const std::vector<Face> &master,
           double                   reach = 0.);
  } // namespace mortar
} // namespace dualcontact

#endif
