// The two kinds of cells a mesh is made of (<Geometry/Cell type>); which
// element, quadrature and mapping each takes is discretization.h's answer.
#ifndef dualcontact_cell_kind_h
#define dualcontact_cell_kind_h

namespace dualcontact
{
  /**
   * Quadrilaterals (hexahedra in 3D) with FE_Q(k), or simplices, triangles
   * (tetrahedra) with FE_SimplexP(k): <Geometry/Cell type> (discretization.h).
   */
  enum class CellKind
  {
    quadrilateral,
    simplex
  };
} // namespace dualcontact

#endif
