// The contact nodes that face another body (doc/two_bodies.md): a contact
// node and the master nodes it sees, and ContactPairs, which couples the
// slave nodes of each pair with the master surface (dual mortar or node to
// segment), gives them the master's normals, coverage and gaps, drops the
// slave nodes that face no master, and holds the parallel pieces the
// coupling needs (the master entries of a vector, the Newton matrix's extra
// entries).
#ifndef dualcontact_contact_pairs_h
#define dualcontact_contact_pairs_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/mapping.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <array>
#include <map>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  /**
   * A master node j that the dual function of a paired contact node sees:
   * its DoFs and c_sj = M_sj / sum_j M_sj (doc/two_bodies.md).
   */
  template <int dim>
  struct MasterTerm
  {
    std::array<types::global_dof_index, dim> dofs;
    double                                   coefficient = 0.;
  };

  /**
   * One contact node s: a support point on Gamma_C, or on the slave side of
   * a contact pair, that is not hanging.
   */
  template <int dim>
  struct ContactNode
  {
    std::array<types::global_dof_index, dim> dofs; // one per component
    Point<dim>                               position;
    double                                   weight = 0.; // m_s = int phi_s
    // a_s, the factor on r and r_t at the node: 1, or 1 / coverage on a
    // slave node that the master covers in part, so that its augmentation
    // m_s a_s r is a whole node's (ContactPairs::couple())
    double augmentation = 1.;
    double gap0         = 0.; // g0(x_s)
    // n_s = -m(x_s), outward for the body, and an orthonormal basis of the
    // plane orthogonal to it (tangent_basis in obstacle.h)
    Tensor<1, dim>                      normal;
    std::array<Tensor<1, dim>, dim - 1> tangents;
    // the body's outward unit normal at the node (the mean of its faces')
    Tensor<1, dim> body_normal;
    // on the slave side of a contact pair: the master nodes it sees, so that
    // its normal and tangential displacements are relative to the master's
    // sum_j c_sj v_j; empty against the rigid obstacle
    std::vector<MasterTerm<dim>> masters;
    // the slave id of its pair; invalid_boundary_id against the obstacle
    types::boundary_id pair_slave_id = numbers::invalid_boundary_id;
  };

  /**
   * An orthonormal basis of the directions in which the supports hold
   * `node`: a 'fixed' component, a 'normal fixed' plane through it. They are
   * the lines of `constraints` on the node's DoFs that involve no other
   * node's DoFs (a hanging node's line is no support).
   */
  template <int dim>
  std::vector<Tensor<1, dim>>
  held_directions(const ContactNode<dim>          &node,
                  const AffineConstraints<double> &constraints);

  /**
   * An orthonormal basis of the plane orthogonal to `n`, in which each
   * direction the `held` ones contain is a zero vector: friction does not act
   * along a direction a support holds (doc/two_bodies.md).
   */
  template <int dim>
  std::array<Tensor<1, dim>, dim - 1>
  free_tangents(const Tensor<1, dim>              &n,
                const std::vector<Tensor<1, dim>> &held);

  /**
   * The contact pairs of a scene, slave id -> master id, and the coupling of
   * their slave nodes with the master surfaces. Without pairs it does
   * nothing, and a vector's master entries are the vector itself.
   */
  template <int dim>
  class ContactPairs
  {
  public:
    /**
     * The pairs, slave id -> master id, and how their slave nodes see the
     * master: node to segment, or else the dual mortar coupling.
     */
    void
    reinit(const std::map<types::boundary_id, types::boundary_id> &pairs,
           const bool node_to_segment);

    /** Whether there are pairs at all. */
    bool
    active() const
    {
      return !pairs.empty();
    }

    /** The pairs, slave id -> master id. */
    const std::map<types::boundary_id, types::boundary_id> &
    list() const
    {
      return pairs;
    }

    /** Whether `id` is the slave id of a pair: its faces carry nodes. */
    bool
    is_slave(const types::boundary_id id) const
    {
      return pairs.count(id) > 0;
    }

    /**
     * The master terms and gaps of the `nodes` on the slave ids of the
     * pairs (`slave_id_of` each slave node's id, by its first DoF): drops
     * the nodes that face no master, and counts them. A hanging slave node
     * is no contact node: its coupling goes to the nodes it hangs on, with
     * the weights of `hanging_node_constraints`, as its weight m_s does. A
     * direction in which `all_constraints` hold a slave node carries no
     * part of the contact: its normal is turned off it, and a tangent along
     * it is zero.
     */
    void
    couple(
      const Mapping<dim>              &mapping,
      const DoFHandler<dim>           &dof_handler,
      const AffineConstraints<double> &hanging_node_constraints,
      const AffineConstraints<double> &all_constraints,
      const std::map<types::global_dof_index, types::boundary_id> &slave_id_of,
      std::vector<ContactNode<dim>>                               &nodes);

    /**
     * `v` with the entries the relative displacements read: v itself
     * without pairs, else a copy that also holds the master nodes' entries
     * of this rank's paired nodes (an import; collective).
     */
    const TrilinosWrappers::MPI::Vector &
    with_masters(const TrilinosWrappers::MPI::Vector &v) const;

    /**
     * The entries the Newton matrix needs beyond the elements': for each
     * paired node of `nodes`, its DoFs and its masters' with each other,
     * each DoF as `constraints` condense it.
     */
    void
    add_couplings(DynamicSparsityPattern              &pattern,
                  const AffineConstraints<double>     &constraints,
                  const std::vector<ContactNode<dim>> &nodes) const;

    /** The rows add_couplings() writes, in an index space of `n_dofs`
     * (none without pairs). */
    IndexSet
    coupled_rows(const AffineConstraints<double>     &constraints,
                 const std::vector<ContactNode<dim>> &nodes,
                 types::global_dof_index              n_dofs) const;

    /** Slave nodes (all ranks) that face no master node. */
    types::global_dof_index
    n_uncovered_nodes() const
    {
      return n_uncovered;
    }

    /**
     * The wall time of couple() on this mesh [s]: gathering the master
     * surface, the segments and the coupling (zero without pairs).
     */
    double
    wall_time() const
    {
      return pairing_time;
    }

  private:
    /**
     * The nodes of `nodes` not in `keep` (they face no master) dropped and
     * counted (`uncovered` on this rank), and the vector that holds the
     * master entries of the others, owned and ghost, sized.
     */
    void
    drop_uncovered_nodes(const std::vector<bool>       &keep,
                         const types::global_dof_index  uncovered,
                         const IndexSet                &owned,
                         const MPI_Comm                 comm,
                         std::vector<ContactNode<dim>> &nodes);

    std::map<types::boundary_id, types::boundary_id> pairs;
    bool                                             node_to_segment = false;
    types::global_dof_index                          n_uncovered     = 0;
    double                                           pairing_time    = 0.;
    mutable TrilinosWrappers::MPI::Vector            ghosted, owned_copy;
  };
} // namespace dualcontact

#endif
