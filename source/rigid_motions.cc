// The rigid motions of a scene's bodies and what holds them: the Gram
// matrix of the motions over the boundary where displacements are
// prescribed, the free translations, and the check that the elastic
// problem is not singular (doc/theory.md §1).
#include <deal.II/base/mpi.h>

#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <dualcontact/discretization.h>
#include <dualcontact/input_error.h>
#include <dualcontact/scene.h>

#include <algorithm>
#include <cmath>

namespace dualcontact
{
  namespace
  {
    /**
     * The Gram matrix G_ij = int_{fixed} m_i.m_j + int_{normal fixed}
     * (m_i.n)(m_j.n) of displacement modes m_i(x) (mode(i, x, cell), on the
     * cell at x) over the constrained part of the boundary, summed over the
     * ranks; `measure` gets that part's length (area). A mode is left free
     * by the constraints iff G m = 0.
     */
    template <int dim, typename Mode>
    FullMatrix<double>
    constrained_gram(const Triangulation<dim>           &triangulation,
                     const std::set<types::boundary_id> &fixed,
                     const std::set<types::boundary_id> &slider,
                     const unsigned int                  n_modes,
                     const Mode                         &mode,
                     double                             &measure)
    {
      // the cells' straight-sided map: the boundary as its vertices'
      // polygon (or polyhedron) is exact enough for the question asked
      const Discretization<dim>           cells(cell_kind(triangulation), 1);
      const FE_Nothing<dim>               fe(cells.reference_cell());
      const std::unique_ptr<Mapping<dim>> mapping    = cells.make_mapping();
      const Quadrature<dim - 1>           quadrature = cells.face_quadrature(2);
      FEFaceValues<dim>                   fe_face(*mapping,
                                fe,
                                quadrature,
                                update_quadrature_points |
                                  update_normal_vectors | update_JxW_values);
      FullMatrix<double>                  gram(n_modes, n_modes);
      measure = 0;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && (fixed.count(face->boundary_id()) ||
                                        slider.count(face->boundary_id())))
              {
                const bool all = fixed.count(face->boundary_id()) > 0;
                fe_face.reinit(cell, face);
                for (const unsigned int q : fe_face.quadrature_point_indices())
                  {
                    const Point<dim>     &x = fe_face.quadrature_point(q);
                    const Tensor<1, dim> &n = fe_face.normal_vector(q);
                    measure += fe_face.JxW(q);
                    for (unsigned int i = 0; i < n_modes; ++i)
                      for (unsigned int j = 0; j < n_modes; ++j)
                        gram(i, j) +=
                          fe_face.JxW(q) *
                          (all ?
                             mode(i, x, cell) * mode(j, x, cell) :
                             (mode(i, x, cell) * n) * (mode(j, x, cell) * n));
                  }
              }
      const MPI_Comm comm = triangulation.get_communicator();
      for (unsigned int i = 0; i < n_modes; ++i)
        for (unsigned int j = 0; j < n_modes; ++j)
          gram(i, j) = Utilities::MPI::sum(gram(i, j), comm);
      measure = Utilities::MPI::sum(measure, comm);
      return gram;
    }
  } // namespace

  template <int dim>
  bool
  Scene<dim>::translation_is_free(const Tensor<1, dim>     &e,
                                  const Triangulation<dim> &triangulation,
                                  const Bodies<dim>        *bodies,
                                  const unsigned int        body) const
  {
    double     measure = 0;
    const auto gram    = constrained_gram(
      triangulation,
      ids_with(BoundaryCondition::fixed),
      ids_with(BoundaryCondition::normal_fixed),
      1,
      [&](const unsigned int, const Point<dim> &, const auto &cell) {
        return bodies == nullptr || bodies->of(cell) == body ? e :
                                                                  Tensor<1, dim>();
      },
      measure);
    return gram(0, 0) <= 1e-12 * measure;
  }

  template <int dim>
  Tensor<1, dim>
  Scene<dim>::rigid_motion(const unsigned int i, const Point<dim> &x) const
  {
    Tensor<1, dim> m;
    if (i < dim)
      m[i] = 1;
    else
      {
        const Tensor<1, dim> r = (x - center()) / characteristic_length();
        const unsigned int   k = i - dim; // rotation in the plane (a, b)
        const unsigned int   a = (dim == 2) ? 0 : (k == 2 ? 1 : 0);
        const unsigned int   b = (dim == 2) ? 1 : (k == 0 ? 1 : 2);
        m[a]                   = -r[b];
        m[b]                   = r[a];
      }
    return m;
  }

  template <int dim>
  FullMatrix<double>
  Scene<dim>::rigid_motion_gram(const Triangulation<dim> &triangulation,
                                double                   &measure,
                                const Bodies<dim>        *bodies) const
  {
    const unsigned int n_bodies = bodies == nullptr ? 1 : bodies->size();
    return constrained_gram(
      triangulation,
      ids_with(BoundaryCondition::fixed),
      ids_with(BoundaryCondition::normal_fixed),
      n_bodies * n_rigid_motions,
      [this,
       bodies](const unsigned int i, const Point<dim> &x, const auto &cell) {
        if (bodies != nullptr && bodies->of(cell) != i / n_rigid_motions)
          return Tensor<1, dim>();
        return rigid_motion(i % n_rigid_motions, x);
      },
      measure);
  }

  template <int dim>
  void
  Scene<dim>::check_rigid_motions(const Triangulation<dim> &triangulation) const
  {
    if (effects_.contact)
      return; // semi-coercive is allowed: contact holds the body

    const unsigned int       n_modes = n_rigid_motions;
    double                   measure = 0;
    const FullMatrix<double> gram = rigid_motion_gram(triangulation, measure);

    unsigned int n_free = n_modes;
    if (measure > 0)
      {
        LAPACKFullMatrix<double> g(n_modes);
        g = gram;
        g.compute_eigenvalues();
        n_free = 0;
        for (unsigned int i = 0; i < n_modes; ++i)
          if (std::abs(g.eigenvalue(i)) < 1e-10 * measure)
            ++n_free;
      }
    if (n_free > 0)
      throw InputError(
        "The scene leaves " + std::to_string(n_free) +
          " rigid-body motion(s) free and has no contact boundary to hold "
          "them, so the elastic problem has no unique solution. Give more of "
          "the boundary the condition 'fixed' or 'normal fixed' in <Boundary "
          "conditions/Conditions>.",
        exit_inconsistent);
  }

  template bool
  Scene<2>::translation_is_free(const Tensor<1, 2> &,
                                const Triangulation<2> &,
                                const Bodies<2> *,
                                unsigned int) const;
  template Tensor<1, 2>
  Scene<2>::rigid_motion(unsigned int, const Point<2> &) const;
  template FullMatrix<double>
  Scene<2>::rigid_motion_gram(const Triangulation<2> &,
                              double &,
                              const Bodies<2> *) const;
  template void
  Scene<2>::check_rigid_motions(const Triangulation<2> &) const;
  template bool
  Scene<3>::translation_is_free(const Tensor<1, 3> &,
                                const Triangulation<3> &,
                                const Bodies<3> *,
                                unsigned int) const;
  template Tensor<1, 3>
  Scene<3>::rigid_motion(unsigned int, const Point<3> &) const;
  template FullMatrix<double>
  Scene<3>::rigid_motion_gram(const Triangulation<3> &,
                              double &,
                              const Bodies<3> *) const;
  template void
  Scene<3>::check_rigid_motions(const Triangulation<3> &) const;
} // namespace dualcontact
