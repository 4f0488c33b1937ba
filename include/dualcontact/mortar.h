// The dual mortar coupling of two surfaces in 2D: the slave surface carries
// the contact nodes and their multipliers, the master surface is the
// other body. With piecewise-polynomial traces of degree k on both, and on
// each slave segment the dual basis psi_s = sum_t a_st phi_t, A = D M^-1
// (D the diagonal of int phi_t over the segment, M its mass matrix),
// biorthogonal to the slave's own basis,
//   int psi_s phi_t = delta_st m_s,   m_s = int phi_s,
// the weighted gap and the slip of slave node s read
//   n_s . (u_s - sum_j c_sj u_j) + g0_s,   c_sj = M_sj / m_s
// (where the master covers the node's support; contact_pairs.cc divides by
// sum_j M_sj, and takes that as the node's weight, where it covers a part),
//   M_sj = int_{slave} psi_s phi_j^master,
// so that the slave block of the coupling is the lumped weight m_s the
// rigid obstacle already uses, and only the master columns c_sj are new.
// Each M_sj is integrated exactly over the segments where a slave and a
// master segment overlap (the master's end points projected onto the
// slave segment along its normal): the exactness on non-matching meshes is
// what makes a uniform pressure pass across the interface (the contact
// patch test). No mesh, no MPI: numbers and points only.
#ifndef dualcontact_mortar_h
#define dualcontact_mortar_h

#include <deal.II/base/point.h>

#include <array>
#include <utility>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  namespace mortar
  {
    /**
     * A straight segment of a surface in 2D with a linear trace: its end
     * points and the numbers the caller gives their nodes (on one surface,
     * 0 to the number of its nodes - 1).
     */
    struct Segment
    {
      std::array<Point<2>, 2>     x;
      std::array<unsigned int, 2> node;
      // the outward unit normal of its body, or zero: two segments couple
      // only if they face each other (n_slave . n_master < -1/2, and each
      // in front of the other, facing_tolerance()), so that a curved
      // master's far side, which projects onto the slave's line as well,
      // stays out
      Tensor<1, 2> normal;
      // at degree k > 1 the k - 1 nodes between the end points: their
      // numbers and their coordinates xi in (0, 1) along x[0] -> x[1]; the
      // trace is the polynomial of degree k through all k + 1 nodes (a
      // curved face is taken along its chord)
      std::vector<unsigned int> inner_node;
      std::vector<double>       inner_xi;
    };

    /**
     * The coupling of the slave surface's nodes with the master's: for
     * each slave node s its weight m_s = int phi_s over the slave segments
     * and the entries M_sj of the master nodes j its dual function sees.
     */
    struct Coupling
    {
      std::vector<double>                                       weight;
      std::vector<std::vector<std::pair<unsigned int, double>>> master;

      /**
       * sum_j M_sj / m_s: 1 where the master covers the support of psi_s
       * (the master's functions sum to one), less at a slave node beyond
       * the master's end, 0 where no master segment faces the node.
       */
      double
      coverage(unsigned int s) const;
    };

    /**
     * How far a master face may lie behind a slave face, or the slave face
     * behind the master face, along the one's outward normal where their
     * projections overlap, for the two to couple: the larger of the two
     * faces' sizes h (their lengths in 2D, their diameters in 3D).
     * - Two curved surfaces that touch overlap between their chords by the
     *   sagittas h^2 / (8 R) of both faces, at most a quarter of each face
     *   (a chord is at most 2 R), and a little more across faces tilted
     *   against each other: h keeps every pair of faces near where they
     *   touch, on the coarsest meshes too.
     * - Bodies that overlap at the start by a fraction of an element stay
     *   coupled, so that their gaps show it, and the check of a pair
     *   (contact_pairs.cc, overlaps beyond a tenth of the node spacing)
     *   reports it.
     * - The far side of the other body, which faces the slave as well and
     *   projects onto it, lies the body's thickness behind the slave: more
     *   than one of its faces, and it stays out.
     */
    double
    facing_tolerance(double slave_size, double master_size);

    /**
     * m_s and M_sj for the slave segments against the master segments.
     * Each master segment is projected onto the line of each slave segment
     * along the slave segment's normal; where the projections overlap,
     * psi_s phi_j is a polynomial of degree 2k of the slave coordinate,
     * integrated exactly by k + 1 Gauss points. The dual basis exists
     * where every int phi_t > 0 (the Gauss-Lobatto nodes of FE_Q(k),
     * k = 1-3). A master segment that
     * projects onto a point (it stands at a right angle to the slave), or
     * that does not face the slave segment (normals given, and
     * n_slave . n_master >= -1/2, or at an end of the overlap one segment
     * behind the other by more than facing_tolerance()), adds nothing. The
     * search is over all pairs (for the surfaces of a test or of a 2D
     * interface; a bounding-box tree replaces it for large ones).
     */
    Coupling
    couple(const std::vector<Segment> &slave,
           unsigned int                n_slave_nodes,
           const std::vector<Segment> &master);

    /**
     * The one-pass node-to-segment coupling, for comparison: slave node s
     * takes the gap to the master point its normal (the mean of its
     * segments' normals) meets, so that its entries are m_s phi_j(eta_s),
     * the master's functions at that point (sum_j = m_s where a facing
     * master segment is met, as couple() takes them: the nearest one with
     * n_s . n_master < -1/2 and the node and the point met in front of each
     * other up to facing_tolerance(); no entries where none is). It
     * transmits a uniform pressure as the nodal forces m_s p phi_j(eta_s),
     * which are not int p phi_j on non-matching meshes: it fails the
     * contact patch test that the dual mortar passes (doc/two_bodies.md).
     */
    Coupling
    couple_node_to_segment(const std::vector<Segment> &slave,
                           unsigned int                n_slave_nodes,
                           const std::vector<Segment> &master);
  } // namespace mortar
} // namespace dualcontact

#endif
