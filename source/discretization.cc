#include <deal.II/base/quadrature_lib.h>

#include <deal.II/distributed/shared_tria.h>
#include <deal.II/distributed/tria.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>

#include <deal.II/grid/reference_cell.h>

#include <dualcontact/discretization.h>

#include <algorithm>
#include <cmath>

namespace dualcontact
{
  template <int dim>
  std::unique_ptr<parallel::TriangulationBase<dim>>
  make_triangulation(const CellKind kind, const MPI_Comm mpi_communicator)
  {
    if (kind == CellKind::simplex)
      // The z-order of the cell centres partitions the same mesh the same
      // way on every rank, whatever the mesh; no artificial cells, so that
      // every rank can carry fields over a refinement on its own (see
      // FieldTransfer).
      return std::make_unique<parallel::shared::Triangulation<dim>>(
        mpi_communicator,
        Triangulation<dim>::none,
        /*allow_artificial_cells=*/false,
        parallel::shared::Triangulation<dim>::partition_zorder);
    // Mesh smoothing: only the 2:1 balance at vertices, which p4est
    // enforces on the whole forest. deal.II's other smoothing flags act on
    // the refinement flags each rank sees, so they would make the adaptive
    // meshes depend on the number of ranks.
    return std::make_unique<parallel::distributed::Triangulation<dim>>(
      mpi_communicator, Triangulation<dim>::limit_level_difference_at_vertices);
  }

  template <int dim>
  std::unique_ptr<FiniteElement<dim>>
  make_element(const CellKind kind, const unsigned int degree)
  {
    if (kind == CellKind::simplex)
      return std::make_unique<FESystem<dim>>(FE_SimplexP<dim>(degree), dim);
    return std::make_unique<FESystem<dim>>(FE_Q<dim>(degree), dim);
  }

  template <int dim>
  std::unique_ptr<Mapping<dim>>
  make_mapping(const CellKind kind, const unsigned int degree)
  {
    if (kind == CellKind::simplex)
      return std::make_unique<SimplexMapping<dim>>(degree);
    return std::make_unique<MappingQ<dim>>(degree);
  }

  template <int dim>
  SimplexMapping<dim>::SimplexMapping(const unsigned int degree)
      : MappingFE<dim>(FE_SimplexP<dim>(std::min(degree, 2u)))
      , degree(std::min(degree, 2u))
  {}

  template <int dim>
  std::unique_ptr<Mapping<dim>>
  SimplexMapping<dim>::clone() const
  {
    return std::make_unique<SimplexMapping<dim>>(degree);
  }

  template <int dim>
  std::vector<Point<dim>>
  SimplexMapping<dim>::compute_mapping_support_points(
    const typename Triangulation<dim>::cell_iterator &cell) const
  {
    // FE_SimplexP(1)'s support points are the reference cell's vertices,
    // FE_SimplexP(2)'s the vertices and then the midpoints of the lines, in
    // the cell's vertex and line order
    std::vector<Point<dim>> points;
    for (const unsigned int v : cell->vertex_indices())
      points.push_back(cell->vertex(v));
    if (degree == 2)
      for (const unsigned int l : cell->line_indices())
        points.push_back(cell->line(l)->center(/*respect_manifold=*/true));
    return points;
  }

  namespace
  {
    /**
     * The Gauss rule of the reference cell, capped on triangles and
     * tetrahedra (a line is both a hypercube and a simplex: QGauss).
     */
    template <int q_dim>
    Quadrature<q_dim>
    gauss_rule(const ReferenceCell &cell, const unsigned int n)
    {
      return !cell.is_hyper_cube() ?
               cell.get_gauss_type_quadrature<q_dim>(std::min(n, 4u)) :
               cell.get_gauss_type_quadrature<q_dim>(n);
    }
  } // namespace

  template <int dim>
  Quadrature<dim>
  cell_quadrature(const FiniteElement<dim> &fe, const unsigned int n)
  {
    return gauss_rule<dim>(fe.reference_cell(), n);
  }

  template <int dim>
  Quadrature<dim - 1>
  face_quadrature(const FiniteElement<dim> &fe, const unsigned int n)
  {
    // all faces of a triangle, a tetrahedron, a quadrilateral or a
    // hexahedron are of one kind
    return gauss_rule<dim - 1>(fe.reference_cell().face_reference_cell(0), n);
  }

  template <int dim>
  bool
  support_on_face(const FiniteElement<dim> &fe,
                  const unsigned int        i,
                  const unsigned int        face)
  {
    const ReferenceCell &cell = fe.reference_cell();
    if (cell.is_hyper_cube())
      return fe.has_support_on_face(i, face);
    // the reference simplex's vertices are the origin and the unit
    // vectors: a support point on a face (a vertex, the midpoint of a line)
    // lies in the face's plane to round-off, one off it a distance of the
    // order of one away
    const Point<dim> corner =
      cell.template vertex<dim>(cell.face_to_cell_vertices(face, 0, 1));
    return std::abs(cell.template unit_normal_vectors<dim>(face) *
                    (fe.unit_support_point(i) - corner)) <= 1e-12;
  }

  template <int dim>
  Discretization<dim>::Discretization(const CellKind     kind,
                                      const unsigned int degree)
      : kind(kind)
      , degree_(degree)
  {}

  template <int dim>
  std::unique_ptr<parallel::TriangulationBase<dim>>
  Discretization<dim>::make_triangulation(const MPI_Comm mpi_communicator) const
  {
    return dualcontact::make_triangulation<dim>(kind, mpi_communicator);
  }

  template <int dim>
  std::unique_ptr<FiniteElement<dim>>
  Discretization<dim>::make_element() const
  {
    return dualcontact::make_element<dim>(kind, degree_);
  }

  template <int dim>
  std::unique_ptr<Mapping<dim>>
  Discretization<dim>::make_mapping() const
  {
    return dualcontact::make_mapping<dim>(kind, degree_);
  }

  template <int dim>
  std::unique_ptr<Mapping<dim>>
  Discretization<dim>::make_mapping(const unsigned int degree) const
  {
    return dualcontact::make_mapping<dim>(kind, degree);
  }

  template <int dim>
  ReferenceCell
  Discretization<dim>::reference_cell() const
  {
    return kind == CellKind::simplex ? ReferenceCells::get_simplex<dim>() :
                                       ReferenceCells::get_hypercube<dim>();
  }

  template <int dim>
  Quadrature<dim>
  Discretization<dim>::cell_quadrature(const unsigned int n) const
  {
    return gauss_rule<dim>(reference_cell(), n);
  }

  template <int dim>
  Quadrature<dim - 1>
  Discretization<dim>::face_quadrature(const unsigned int n) const
  {
    return gauss_rule<dim - 1>(reference_cell().face_reference_cell(0), n);
  }

  template <int dim>
  std::string
  Discretization<dim>::cells_in_words() const
  {
    return kind == CellKind::simplex ?
             std::string(dim == 2 ? " of triangles" : " of tetrahedra") +
               ", P" + std::to_string(degree_) :
             "";
  }

  template <int dim>
  CellKind
  cell_kind(const Triangulation<dim> &triangulation)
  {
    for (const ReferenceCell &cell : triangulation.get_reference_cells())
      if (!cell.is_hyper_cube())
        return CellKind::simplex;
    return CellKind::quadrilateral;
  }

  template std::unique_ptr<parallel::TriangulationBase<2>>
    make_triangulation<2>(CellKind, MPI_Comm);
  template std::unique_ptr<parallel::TriangulationBase<3>>
    make_triangulation<3>(CellKind, MPI_Comm);
  template std::unique_ptr<FiniteElement<2>>
  make_element<2>(CellKind, unsigned int);
  template std::unique_ptr<FiniteElement<3>>
  make_element<3>(CellKind, unsigned int);
  template std::unique_ptr<Mapping<2>>
  make_mapping<2>(CellKind, unsigned int);
  template std::unique_ptr<Mapping<3>>
  make_mapping<3>(CellKind, unsigned int);
  template class Discretization<2>;
  template class Discretization<3>;
  template class SimplexMapping<2>;
  template class SimplexMapping<3>;
  template Quadrature<2>
  cell_quadrature(const FiniteElement<2> &, unsigned int);
  template Quadrature<3>
  cell_quadrature(const FiniteElement<3> &, unsigned int);
  template Quadrature<1>
  face_quadrature(const FiniteElement<2> &, unsigned int);
  template Quadrature<2>
  face_quadrature(const FiniteElement<3> &, unsigned int);
  template bool
  support_on_face(const FiniteElement<2> &, unsigned int, unsigned int);
  template bool
  support_on_face(const FiniteElement<3> &, unsigned int, unsigned int);
  template CellKind
  cell_kind(const Triangulation<2> &);
  template CellKind
  cell_kind(const Triangulation<3> &);
} // namespace dualcontact
