// What a run writes about Gamma_C: contact_NN.csv (one row per contact
// node) and the boundary output contact_NN.pvtu (the contact fields on the
// faces of Gamma_C only).
#ifndef dualcontact_contact_output_h
#define dualcontact_contact_output_h

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/mapping.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <dualcontact/contact_set.h>

#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  /** One contact node as contact_NN.csv shows it. */
  template <int dim>
  struct ContactNodeRow
  {
    Point<dim>     position;
    double         along  = 0.; // position . t, t the mean tangent of Gamma_C
    double         weight = 0.; // m_s
    double         l1     = 0.; // pressure
    Tensor<1, dim> l2;          // sum_k l2_k t_k, in global coordinates
    double         threshold = 0.;
    double         gap       = 0.; // current gap g0 - u_n
    Tensor<1, dim> normal;         // n_s, outward for the body
    unsigned int   status = 0;     // ContactSet::status()
    // the slave id of the node's contact pair, -1 against the obstacle
    int pair_slave_id = -1;
  };

  /**
   * The rows of all contact nodes, gathered on rank 0 (the other ranks get
   * none): in 2D sorted along the boundary (by position . t, t the mean
   * tangent of Gamma_C), in 3D by their coordinates along the two mean
   * tangents. `displacement` is the (ghosted) solution. Collective.
   */
  template <int dim>
  std::vector<ContactNodeRow<dim>>
  gather_contact_rows(const ContactSet<dim>               &contact_set,
                      const TrilinosWrappers::MPI::Vector &displacement,
                      const MPI_Comm                       comm);

  /**
   * Write `rows` as CSV. Columns: s (position . t), x, y, (z), weight, l1,
   * l2 (2D: the component along t_s = (-n_y, n_x); 3D: l2_x, l2_y, l2_z),
   * g, gap (g0 - u_n), n_x, n_y, (n_z), status (separated, stick or slip;
   * 'contact' without friction), and exact_pressure if `exact_pressure` is
   * not null.
   */
  template <int dim>
  void
  write_contact_csv(const std::string                      &filename,
                    const std::vector<ContactNodeRow<dim>> &rows,
                    const bool                              friction,
                    const Function<dim>                    *exact_pressure);

  /**
   * The contact fields on the faces of Gamma_C, for ParaView: one patch per
   * contact face of a locally owned cell, the fields at its support points
   * (the contact nodes, k + 1 per edge for FE_Q(k), placed by `mapping`; a
   * hanging node has the interpolation of its masters, a node whose every
   * component is prescribed status -1). Fields:
   * contact_pressure (l1), gap (g0 - u_n), contact_status (-1 not a contact
   * node, 0 separated, 1 in contact (sticking), 2 slipping), the vectors
   * displacement, normal (n_s) and tangential_slip (u_t), and with friction
   * friction_threshold (g) and tangential_traction (l2, a vector).
   */
  template <int dim>
  class ContactBoundaryOutput : public DataOutInterface<dim - 1, dim>
  {
  public:
    void
    build_patches(const Mapping<dim>                  &mapping,
                  const DoFHandler<dim>               &dof_handler,
                  const std::set<types::boundary_id>  &contact_ids,
                  const ContactSet<dim>               &contact_set,
                  const TrilinosWrappers::MPI::Vector &displacement,
                  const AffineConstraints<double>     &hanging_node_constraints,
                  const IndexSet                      &locally_relevant_dofs);

  private:
    const std::vector<DataOutBase::Patch<dim - 1, dim>> &
    get_patches() const override
    {
      return patches;
    }

    std::vector<std::string>
    get_dataset_names() const override
    {
      return names;
    }

    std::vector<
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>>
    get_nonscalar_data_ranges() const override
    {
      return vector_ranges;
    }

    std::vector<DataOutBase::Patch<dim - 1, dim>> patches;
    std::vector<std::string>                      names;
    std::vector<
      std::tuple<unsigned int,
                 unsigned int,
                 std::string,
                 DataComponentInterpretation::DataComponentInterpretation>>
      vector_ranges;
  };
} // namespace dualcontact

#endif
