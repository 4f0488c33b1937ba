// The lumped mass matrix of the proximal term: one vector.
#ifndef dualcontact_lumped_mass_h
#define dualcontact_lumped_mass_h

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

namespace dualcontact
{
  using namespace dealii;

  /**
   * The lumped L2 mass matrix of the proximal term (doc/theory.md §3.3): a
   * diagonal M with M_ii = int phi_i, the row sums of the mass matrix int
   * u.v after condensation (zero on constrained DoFs). It weighs the
   * proximal term like the mass matrix does, is positive on every free DoF,
   * and costs one vector instead of a matrix. On simplices, whose P2 vertex
   * functions integrate to zero, each cell's M_ii is its diagonal
   * int phi_i^2 scaled to sum to the cell's measure per component (the
   * row sums again for P1).
   */
  struct LumpedMass
  {
    TrilinosWrappers::MPI::Vector diagonal; // locally owned DoFs

    /** dst = M src (no ghosts). */
    void
    vmult(TrilinosWrappers::MPI::Vector       &dst,
          const TrilinosWrappers::MPI::Vector &src) const;

    /** matrix += factor M (on the diagonal, which must be in its pattern). */
    void
    add_to(TrilinosWrappers::SparseMatrix &matrix, const double factor) const;
  };
} // namespace dualcontact

#endif
