// The two kinds of cells and what each takes: the triangulation, the
// finite element, the mapping and the quadrature rules (doc/theory.md §4,
// doc/simplices.md). Discretization answers these questions for a scene's
// cell kind and degree, so that the rest of the code does not branch on
// the kind.
#ifndef dualcontact_discretization_h
#define dualcontact_discretization_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>

#include <deal.II/distributed/tria_base.h>

#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/fe/mapping_fe.h>

#include <deal.II/grid/reference_cell.h>

#include <dualcontact/cell_kind.h>

#include <memory>
#include <string>

namespace dualcontact
{
  using namespace dealii;

  /**
   * The empty triangulation of the kind (CellKind, cell_kind.h), on the
   * communicator. Quadrilaterals (hexahedra in 3D): a
   * parallel::distributed::Triangulation (p4est: each rank holds its own
   * cells and a layer of ghosts). Simplices: a
   * parallel::shared::Triangulation (p4est takes no simplices: every rank
   * holds the whole mesh and owns a part of its cells).
   */
  template <int dim>
  std::unique_ptr<parallel::TriangulationBase<dim>>
  make_triangulation(CellKind kind, MPI_Comm mpi_communicator);

  /** FESystem of dim copies of FE_Q(degree) or FE_SimplexP(degree). */
  template <int dim>
  std::unique_ptr<FiniteElement<dim>>
  make_element(CellKind kind, unsigned int degree);

  /**
   * MappingQ(degree), which follows curved boundaries at that order; on
   * simplices SimplexMapping(degree).
   */
  template <int dim>
  std::unique_ptr<Mapping<dim>>
  make_mapping(CellKind kind, unsigned int degree);

  /**
   * The map of each simplex by FE_SimplexP(k), k = 1 or 2 (higher degrees
   * map as 2): at k = 1 the affine map from the vertices, at k = 2 the
   * quadratic one through the vertices and the midpoints of the lines,
   * each midpoint on its line's manifold, so that a P2 cell follows a
   * curved boundary between its vertices (the circle of a half disc) as
   * MappingQ(2) does, and the contact nodes in the middle of a face lie on
   * the body's surface, not on the chord. deal.II 9.4's MappingFE places
   * those points on the cell's manifold and asks that all parts of the
   * cell carry its manifold id, which a cell with one face on a curve does
   * not; the lines' own manifolds are what the map needs.
   */
  template <int dim>
  class SimplexMapping : public MappingFE<dim>
  {
  public:
    explicit SimplexMapping(unsigned int degree);

    std::unique_ptr<Mapping<dim>>
    clone() const override;

  protected:
    std::vector<Point<dim>>
    compute_mapping_support_points(
      const typename Triangulation<dim>::cell_iterator &cell) const override;

  private:
    const unsigned int degree;
  };

  /**
   * Gauss rules with n points per direction on the element's cells and on
   * their faces: QGauss on quadrilaterals and hexahedra and on the lines
   * that bound a triangle; QGaussSimplex on triangles and tetrahedra, at
   * most 4 points per direction (exact to degree 7, the highest deal.II 9.4
   * has), which covers every product of P1 and P2 shape functions the code
   * integrates.
   */
  template <int dim>
  Quadrature<dim>
  cell_quadrature(const FiniteElement<dim> &fe, unsigned int n);

  template <int dim>
  Quadrature<dim - 1>
  face_quadrature(const FiniteElement<dim> &fe, unsigned int n);

  /**
   * Whether the shape function `i` of `fe` (FE_Q(k) or FE_SimplexP(k), or
   * an FESystem of copies of one) is nonzero on the face `face` of the
   * reference cell, that is, whether its support point lies on the face.
   * On quadrilaterals and hexahedra FE_Q's has_support_on_face() says so.
   * FE_SimplexP in deal.II 9.4 takes FiniteElement's default, true for
   * every function on every face, which would count the vertex opposite a
   * face among the face's nodes (with a weight int phi = 0 up to
   * round-off); there the support point is tested against the face's
   * plane in the reference cell.
   */
  template <int dim>
  bool
  support_on_face(const FiniteElement<dim> &fe,
                  unsigned int              i,
                  unsigned int              face);

  /**
   * The cells of a scene and its element: every question whose answer
   * depends on the cell kind (CellKind, cell_kind.h), answered for the
   * kind and the polynomial degree it is built with.
   */
  template <int dim>
  class Discretization
  {
  public:
    Discretization(CellKind kind, unsigned int degree);

    CellKind
    cell_kind() const
    {
      return kind;
    }

    unsigned int
    degree() const
    {
      return degree_;
    }

    /**
     * Whether every rank holds the whole mesh (a
     * parallel::shared::Triangulation of simplices): a refinement flags the
     * cells every rank sees alike, not only the locally owned ones, and a
     * checkpoint (p4est's forest) cannot keep it.
     */
    bool
    mesh_is_replicated() const
    {
      return kind == CellKind::simplex;
    }

    /** The empty triangulation on the communicator (make_triangulation). */
    std::unique_ptr<parallel::TriangulationBase<dim>>
    make_triangulation(MPI_Comm mpi_communicator) const;

    /** The element of the degree (make_element). */
    std::unique_ptr<FiniteElement<dim>>
    make_element() const;

    /** The mapping of the degree, or of `degree` (make_mapping). */
    std::unique_ptr<Mapping<dim>>
    make_mapping() const;
    std::unique_ptr<Mapping<dim>>
    make_mapping(unsigned int degree) const;

    /** The reference cell: the square (cube) or the triangle (tetrahedron). */
    ReferenceCell
    reference_cell() const;

    /**
     * Gauss rules with n points per direction on a cell and on a face of
     * the reference cell (cell_quadrature(), face_quadrature()).
     */
    Quadrature<dim>
    cell_quadrature(unsigned int n) const;
    Quadrature<dim - 1>
    face_quadrature(unsigned int n) const;

    /**
     * The cells and element in words for the log: " of triangles, P2" on
     * simplices, empty for quadrilaterals (the default).
     */
    std::string
    cells_in_words() const;

  private:
    const CellKind     kind;
    const unsigned int degree_;
  };

  /** The kind of the cells of a triangulation (simplex if any is one). */
  template <int dim>
  CellKind
  cell_kind(const Triangulation<dim> &triangulation);
} // namespace dualcontact

#endif
