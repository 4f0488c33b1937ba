// The load and lumped-mass terms of linear elasticity on one cell: what
// assemble_elasticity() adds to each cell's stiffness, and all a solve that
// applies the stiffness without a matrix (matrix-free) assembles.
#ifndef dualcontact_cell_loads_h
#define dualcontact_cell_loads_h

#include <deal.II/base/quadrature.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>

#include <deal.II/lac/vector.h>

#include <dualcontact/scene.h>

#include <array>
#include <set>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  /**
   * The cell terms of linear elasticity without the stiffness: the load
   * int f.v + int_{Gamma_N} T.v (only the loads the scene has) and, if
   * asked, the lumped mass: int phi_i, the row sums of the mass matrix
   * int u.v, on quadrilaterals; on simplices the diagonal int phi_i^2
   * scaled to the cell's measure per component (lumped_mass.h). The
   * quadrature is the assembly's (cell_quadrature(), face_quadrature() of
   * degree + 1 points).
   */
  template <int dim>
  class CellLoads
  {
  public:
    /**
     * `cell_flags`: what `fe_values` computes besides the values, the
     * quadrature points and JxW (update_gradients for the stiffness).
     */
    CellLoads(const Mapping<dim>       &mapping,
              const FiniteElement<dim> &fe,
              const Scene<dim>         &scene,
              const UpdateFlags         cell_flags = update_default);

    /**
     * Reinit `fe_values` on `cell` and fill `rhs` and, with `with_mass`,
     * `mass` (else zero).
     */
    void
    reinit(const typename DoFHandler<dim>::active_cell_iterator &cell,
           const bool                                            with_mass);

    /** Add the resultant of the cell's loads `rhs` to `load`. */
    void
    add_resultant(std::array<double, 3> &load) const;

    const FiniteElement<dim> &fe;
    const Quadrature<dim>     quadrature;
    /** On the cell of the last reinit(). */
    FEValues<dim>  fe_values;
    Vector<double> mass, rhs;

  private:
    const Scene<dim>                  &scene;
    const bool                         simplex;
    const Quadrature<dim - 1>          face_quadrature;
    FEFaceValues<dim>                  fe_face_values;
    Vector<double>                     squares;
    std::vector<Vector<double>>        load_values, traction_values;
    const std::set<types::boundary_id> traction_ids;
  };
} // namespace dualcontact

#endif
