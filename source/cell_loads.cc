// The load and lumped-mass terms of linear elasticity on one cell
// (cell_loads.h).
#include <dualcontact/cell_loads.h>
#include <dualcontact/discretization.h>

namespace dualcontact
{
  template <int dim>
  CellLoads<dim>::CellLoads(const Mapping<dim>       &mapping,
                            const FiniteElement<dim> &fe,
                            const Scene<dim>         &scene,
                            const UpdateFlags         cell_flags)
      : fe(fe)
      , quadrature(cell_quadrature(fe, fe.degree + 1))
      , fe_values(mapping,
                  fe,
                  quadrature,
                  update_values | cell_flags | update_quadrature_points |
                    update_JxW_values)
      , mass(fe.n_dofs_per_cell())
      , rhs(fe.n_dofs_per_cell())
      , scene(scene)
      , simplex(!fe.reference_cell().is_hyper_cube())
      , face_quadrature(dualcontact::face_quadrature(fe, fe.degree + 1))
      , fe_face_values(mapping,
                       fe,
                       face_quadrature,
                       update_values | update_quadrature_points |
                         update_JxW_values)
      , squares(fe.n_dofs_per_cell())
      , load_values(quadrature.size(), Vector<double>(dim))
      , traction_values(face_quadrature.size(), Vector<double>(dim))
      , traction_ids(scene.ids_with(BoundaryCondition::traction))
  {}

  template <int dim>
  void
  CellLoads<dim>::reinit(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const bool                                            with_mass)
  {
    const unsigned int   n_dofs     = fe.n_dofs_per_cell();
    const Function<dim> *body_force = scene.body_force();
    fe_values.reinit(cell);
    mass           = 0;
    squares        = 0;
    rhs            = 0;
    double measure = 0.;
    if (body_force != nullptr)
      body_force->vector_value_list(fe_values.get_quadrature_points(),
                                    load_values);
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        const double JxW = fe_values.JxW(q);
        measure += JxW;
        for (unsigned int i = 0; i < n_dofs; ++i)
          {
            // the row sum of int u.v: the shape functions of a
            // component sum to one
            if (with_mass)
              {
                const double phi = fe_values.shape_value(i, q);
                mass(i) += phi * JxW;
                squares(i) += phi * phi * JxW;
              }
            if (body_force != nullptr)
              rhs(i) += load_values[q](fe.system_to_component_index(i).first) *
                        fe_values.shape_value(i, q) * JxW;
          }
      }
    // P2's vertex functions on a triangle integrate to zero: the
    // diagonal, scaled so that each component's entries sum to the
    // cell's measure, is positive (and equals the row sums for P1)
    if (with_mass && simplex)
      {
        double sum = 0.;
        for (unsigned int i = 0; i < n_dofs; ++i)
          if (fe.system_to_component_index(i).first == 0)
            sum += squares(i);
        for (unsigned int i = 0; i < n_dofs; ++i)
          mass(i) = squares(i) * measure / sum;
      }

    for (const auto &face : cell->face_iterators())
      if (face->at_boundary() && traction_ids.count(face->boundary_id()))
        if (const Function<dim> *traction = scene.traction(face->boundary_id()))
          {
            fe_face_values.reinit(cell, face);
            traction->vector_value_list(fe_face_values.get_quadrature_points(),
                                        traction_values);
            for (const unsigned int q :
                 fe_face_values.quadrature_point_indices())
              for (unsigned int i = 0; i < n_dofs; ++i)
                rhs(i) +=
                  traction_values[q](fe.system_to_component_index(i).first) *
                  fe_face_values.shape_value(i, q) * fe_face_values.JxW(q);
          }
  }

  template <int dim>
  void
  CellLoads<dim>::add_resultant(std::array<double, 3> &load) const
  {
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      load[fe.system_to_component_index(i).first] += rhs(i);
  }

  template class CellLoads<2>;
  template class CellLoads<3>;
} // namespace dualcontact
