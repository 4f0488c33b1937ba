// The surfaces of a contact pair as its coupling reads them
// (contact_pairs.cc, doc/two_bodies.md): the faces of a boundary id with
// their nodes' positions and DoFs and the nodes their hanging nodes hang on,
// the master surface gathered on every rank, the faces numbered for the
// mortar coupling (mortar.h in 2D, mortar_3d.h in 3D), and the slave's
// hanging nodes condensed from a coupling.
#ifndef dualcontact_pair_surfaces_h
#define dualcontact_pair_surfaces_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>

#include <deal.II/lac/affine_constraints.h>

#include <dualcontact/bodies.h>
#include <dualcontact/mortar.h>
#include <dualcontact/mortar_3d.h>

#include <array>
#include <map>
#include <utility>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  namespace pairs
  {
    /**
     * The most nodes a hanging node of a face of `fe` hangs on: in 2D the
     * k + 1 nodes of a coarse face (at most 4), in 3D the nodes of a coarse
     * face, (k + 1)^2 on a quadrilateral (4 at degree 1: the two ends of an
     * edge or the four corners).
     */
    template <int dim>
    unsigned int
    max_parents(const FiniteElement<dim> &fe)
    {
      return dim == 2 ? 4u : std::max(4u, (fe.degree + 1) * (fe.degree + 1));
    }

    /**
     * One face of a pair's surface as the coupling needs it: its nodes'
     * positions and DoFs (in 2D the support points of FE_Q(k) on the face:
     * the two vertices first, then the k - 1 inner ones with their
     * coordinate xi along the face; in 3D a triangle's vertices, or the
     * (k + 1)^2 support points of FE_Q(k) on a quadrilateral in
     * lexicographic order, mortar_3d.h), for a hanging node the
     * DoFs of the nodes it hangs on and their weights (on the master
     * surface: the slave's hanging nodes are condensed from the
     * constraints, condense_hanging_nodes()), its outward normal, and the
     * body it belongs to.
     */
    template <int dim>
    struct SurfaceFace
    {
      std::vector<Point<dim>>                               x;
      std::vector<std::array<types::global_dof_index, dim>> dofs;
      std::vector<double>                                   xi;
      std::vector<std::vector<
        std::pair<std::array<types::global_dof_index, dim>, double>>>
                     parents;
      Tensor<1, dim> normal;
      unsigned int   body = 0;
    };

    /**
     * The faces with boundary id `id` of the owned cells (`owned_only`) or
     * of the owned and ghost cells, with the nodes their hanging nodes hang
     * on if `with_parents` (the owned faces of the master surface: their
     * cells' neighbours, which hold those nodes, are owned or ghost cells).
     */
    template <int dim>
    std::vector<SurfaceFace<dim>>
    surface_faces(const Mapping<dim>              &mapping,
                  const DoFHandler<dim>           &dof_handler,
                  const AffineConstraints<double> &hanging,
                  const types::boundary_id         id,
                  const Bodies<dim>               &bodies,
                  const bool                       owned_only,
                  const bool                       with_parents);

    /**
     * Every rank's faces on every rank (each face has `n` nodes, each
     * hanging on at most `max_parents`).
     */
    template <int dim>
    std::vector<SurfaceFace<dim>>
    gather(const std::vector<SurfaceFace<dim>> &local,
           const unsigned int                   n,
           const unsigned int                   max_parents,
           const MPI_Comm                       comm);

    /**
     * The number of the node with the first DoF `dof` in `number`, which
     * holds it: the nodes of the faces the numbering was made from (a
     * missing one is an internal error, named so).
     */
    unsigned int
    number_of(const std::map<types::global_dof_index, unsigned int> &number,
              const types::global_dof_index                          dof);

    /**
     * 2D faces as the mortar coupling takes them (mortar.h), their nodes
     * numbered in `number`, a new node's DoFs and position appended to
     * `dofs` and `points`.
     */
    std::vector<mortar::Segment>
    segments(const std::vector<SurfaceFace<2>>                   &faces,
             std::map<types::global_dof_index, unsigned int>     &number,
             std::vector<std::array<types::global_dof_index, 2>> &dofs,
             std::vector<Point<2>>                               &points);

    /** 3D faces as the mortar coupling takes them (mortar_3d.h), alike. */
    std::vector<mortar::Face>
    segments(const std::vector<SurfaceFace<3>>                   &faces,
             std::map<types::global_dof_index, unsigned int>     &number,
             std::vector<std::array<types::global_dof_index, 3>> &dofs,
             std::vector<Point<3>>                               &points);

    /**
     * A hanging slave node is no contact node: its row of the coupling (its
     * weight m_h and its M_hj) goes to the nodes p it hangs on, times the
     * weights w_hp of its constraint u_h = sum_p w_hp u_p, as its m_h goes
     * to their m_p. The multiplier of p is then psi_p + sum_h w_hp psi_h,
     * the dual of the condensed trace. The rank that owns h has all the
     * faces at h (its owned and ghost cells); the owner of p may not, so the
     * owner of h sends its row to the owner of p. The master nodes are
     * numbered alike on every rank (the gathered master surface).
     */
    void
    condense_hanging_nodes(
      mortar::Coupling                                      &coupling,
      const std::map<types::global_dof_index, unsigned int> &number,
      const AffineConstraints<double>                       &hanging,
      const IndexSet                                        &owned,
      const MPI_Comm                                         comm);
  } // namespace pairs
} // namespace dualcontact

#endif
