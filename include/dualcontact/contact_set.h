// The discrete contact boundary (doc/theory.md §4): the contact nodes on
// Gamma_C with their nodal-quadrature weights m_s, the normal n_s and tangents
// from the obstacle at each node, the initial gaps g0, and the multipliers
// that live on them.
#ifndef dualcontact_contact_set_h
#define dualcontact_contact_set_h

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/mapping.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <dualcontact/contact_functions.h>
#include <dualcontact/contact_pairs.h>
#include <dualcontact/friction_law.h>
#include <dualcontact/obstacle.h>

#include <array>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace dualcontact
{
  using namespace dealii;

  /**
   * What ContactSet::setup() reads of a scene: the ids whose faces carry
   * contact nodes, the contact pairs, the obstacle, the friction law and its
   * parameter, and the body's size and centre.
   */
  template <int dim>
  struct ContactSetup
  {
    // the ids of the condition 'contact' and the slave ids of the pairs
    std::set<types::boundary_id> contact_ids;
    // the contact pairs, slave id -> master id, and whether their slave
    // nodes see the master node to segment (else by the dual mortar)
    std::map<types::boundary_id, types::boundary_id> pairs;
    bool                                             node_to_segment = false;
    const PlacedObstacle<dim>                       *obstacle        = nullptr;
    const FrictionLaw                               *friction_law    = nullptr;
    // F (Coulomb) or g (a given threshold) as a function of x; nullptr
    // without friction
    const Function<dim> *friction_parameter    = nullptr;
    double               characteristic_length = 1.;
    // rotations and the obstacle's normal without contact nodes are
    // taken at it
    Point<dim> center;
  };

  /**
   * The contact nodes owned by this rank, and the multipliers on them.
   *
   * The body's normal at node s is n_s = -m(x_s) (m: the obstacle's normal,
   * pointing into the body), so v_n = v.n_s > 0 moves the body toward the
   * obstacle and the non-penetration condition reads v_n(s) <= g0(s) at
   * every node (doc/theory.md §10).
   */
  template <int dim>
  class ContactSet
  {
  public:
    /**
     * Find the contact nodes on the boundary ids of `input` (those of the
     * condition 'contact' and the pairs' slave ids) and compute their weights
     * m_s = int_{Gamma_C} phi_s. The weight of a hanging node goes to the nodes
     * it hangs on (through `hanging_node_constraints`), so sums over contact
     * nodes remain exact quadratures. Nodes whose every component is otherwise
     * constrained are left out. Multipliers are reset to zero.
     */
    void
    setup(const Mapping<dim>              &mapping,
          const DoFHandler<dim>           &dof_handler,
          const AffineConstraints<double> &hanging_node_constraints,
          const AffineConstraints<double> &all_constraints,
          const ContactSetup<dim>         &input);

    /**
     * The displacement of local node s relative to what it faces: v(s)
     * against the rigid obstacle, v(s) - sum_j c_sj v_j on the slave side
     * of a pair. `v` must hold the masters' entries: with_masters(v).
     */
    Tensor<1, dim>
    relative_displacement(const TrilinosWrappers::MPI::Vector &v,
                          const unsigned int                   s) const
    {
      Tensor<1, dim> w;
      for (unsigned int c = 0; c < dim; ++c)
        w[c] = v[nodes[s].dofs[c]];
      for (const MasterTerm<dim> &master : nodes[s].masters)
        for (unsigned int c = 0; c < dim; ++c)
          w[c] -= master.coefficient * v[master.dofs[c]];
      return w;
    }

    /**
     * Normal displacement v_n(s) = v(s).n at local node s (relative to the
     * master on a pair; `v` as for relative_displacement()).
     */
    double
    normal_displacement(const TrilinosWrappers::MPI::Vector &v,
                        const unsigned int                   s) const
    {
      return relative_displacement(v, s) * nodes[s].normal;
    }

    /**
     * Tangential displacement v_t(s) at local node s, in the basis of the
     * tangents (one component in 2D); relative to the master on a pair.
     */
    Tensor<1, dim - 1>
    tangential_displacement(const TrilinosWrappers::MPI::Vector &v,
                            const unsigned int                   s) const
    {
      const Tensor<1, dim> w = relative_displacement(v, s);
      Tensor<1, dim - 1>   vt;
      for (unsigned int k = 0; k < dim - 1; ++k)
        vt[k] = w * nodes[s].tangents[k];
      return vt;
    }

    /**
     * `v` with the entries the relative displacements read: v itself
     * without contact pairs, else a copy that also holds the master nodes'
     * entries of this rank's paired nodes (an import; collective).
     */
    const TrilinosWrappers::MPI::Vector &
    with_masters(const TrilinosWrappers::MPI::Vector &v) const
    {
      return pairs_.with_masters(v);
    }

    /**
     * The DoFs of the master nodes of this rank's contact nodes, in an
     * index space of `n_dofs`.
     */
    IndexSet
    master_dofs(const types::global_dof_index n_dofs) const;

    /** Whether some contact node of any rank lies on a contact pair. */
    bool
    has_pairs() const
    {
      return pairs_.active();
    }

    /**
     * Slave nodes (all ranks) that face no master node: not contact nodes.
     */
    types::global_dof_index
    n_uncovered_nodes() const
    {
      return pairs_.n_uncovered_nodes();
    }

    /**
     * The wall time of pairing the surfaces on this mesh [s]: gathering the
     * master surface, the segments and the coupling (zero without pairs).
     */
    double
    pairing_wall_time() const
    {
      return pairs_.wall_time();
    }

    /**
     * The entries the Newton matrix needs beyond the elements': for each
     * paired node, its DoFs and its masters' with each other, each DoF as
     * `constraints` condense it. Rows of other ranks included; the pattern's
     * row set must hold them (coupled_rows()).
     */
    void
    add_pair_couplings(DynamicSparsityPattern          &pattern,
                       const AffineConstraints<double> &constraints) const
    {
      pairs_.add_couplings(pattern, constraints, nodes);
    }

    /** The rows add_pair_couplings() writes (this rank's paired nodes; none
     * without pairs), in an index space of `n_dofs`. */
    IndexSet
    coupled_rows(const AffineConstraints<double> &constraints,
                 const types::global_dof_index    n_dofs) const
    {
      return pairs_.coupled_rows(constraints, nodes, n_dofs);
    }

    /** The contact pairs between bodies and their coupling. */
    const ContactPairs<dim> &
    pairs() const
    {
      return pairs_;
    }

    /**
     * The slip of v at local node s against the slip origin of the load
     * step, v_t(s) - o_t(s) (doc/theory.md §11; o = 0 for a static scene).
     */
    Tensor<1, dim - 1>
    slip(const TrilinosWrappers::MPI::Vector &v, const unsigned int s) const
    {
      return tangential_displacement(v, s) - slip_origin[s];
    }

    /**
     * The slip origin of a load step, o_t(s) = T_s^T (u(s) + dU), from the
     * displacement u of the previous step (ghosted) and the obstacle's
     * translation dU since then (doc/theory.md §11).
     */
    void
    set_slip_origin(const TrilinosWrappers::MPI::Vector &u,
                    const Tensor<1, dim>                &obstacle_step);

    /**
     * The slip origin of the nodes that were apart at the end of the
     * previous step (l1 = 0, gap > 0) and whose free motion u_free over the
     * step (ghosted) closes their gap: their position at the time the gap
     * closes, interpolated between u (the previous step's) and u_free
     * (doc/theory.md §11). Call after set_slip_origin(); the obstacle still.
     */
    void
    set_touch_origin(const TrilinosWrappers::MPI::Vector &u,
                     const TrilinosWrappers::MPI::Vector &u_free);

    /**
     * The gaps g0_s, normals and tangents of the nodes, and the direction of
     * first contact, for the obstacle where the scene has it now (setup()
     * calls it; a load step that moves the obstacle calls it again). The
     * multipliers stay.
     */
    void
    place_obstacle(const PlacedObstacle<dim> &obstacle, MPI_Comm comm);


    /**
     * At every local node the arguments of the positive part and of the
     * projection in the Uzawa updates (doc/theory.md §3.2):
     * z_s = l1_s + r (v_n(s) - g0_s) and, with friction,
     * y_s = l2_s + r_t (v_t(s) - o_t(s)) (r, r_t the normal and tangential
     * augmentation, doc/theory.md §5; o the slip origin, §11).
     */
    void
    augmented_state(const TrilinosWrappers::MPI::Vector &v,
                    const double                         r,
                    const double                         r_t,
                    std::vector<double>                 &z,
                    std::vector<Tensor<1, dim - 1>>     &y) const;

    /** l1 = l2 = 0 and g the threshold at zero pressure: a cold start. */
    void
    reset_multipliers()
    {
      for (unsigned int s = 0; s < nodes.size(); ++s)
        {
          l1[s] = 0.;
          l2[s] = Tensor<1, dim - 1>();
          threshold[s] =
            friction ? law->threshold(friction_parameter[s], 0.) : 0.;
        }
    }

    /**
     * The threshold the friction law gives at local node s for its current
     * pressure l1_s (Coulomb: F_s l1_s).
     */
    double
    threshold_from_pressure(const unsigned int s) const
    {
      return law->threshold(friction_parameter[s], l1[s]);
    }

    /**
     * Status of local node s as the last multiplier update decided it
     * (node_status(), contact_functions.h); separated before the first.
     */
    NodeStatus
    status(const unsigned int s) const
    {
      return statuses[s];
    }

    /**
     * The multipliers as nodal fields of the displacement element, for the
     * transfer to a refined mesh and for error indicators: at the DoFs of
     * each contact node, `multipliers` holds l1 in component 0 and l2 (in
     * the tangent basis) in components 1 .. dim-1, and `threshold_field`
     * holds g in component 0; zero elsewhere. Owned vectors, of the
     * DoFHandler this set was set up on; the caller fills hanging nodes
     * and ghosts.
     */
    void
    write_fields(TrilinosWrappers::MPI::Vector &multipliers,
                 TrilinosWrappers::MPI::Vector &threshold_field) const;

    /**
     * The reverse of write_fields, at the nodes of this set (owned
     * entries), projected onto the admissible set: l1 >= 0, g >= 0 and
     * |l2| <= g. g is read only if the law makes it depend on the pressure
     * (a given threshold is the scene's), l2 only with friction. Returns, over
     * this rank's nodes and before the projection, the smallest l1 and the
     * largest |l2| - g: how far the fields read were from admissible.
     * With `project` false the values are taken as they are: the fields of
     * this very set, written and read back (a checkpoint), where |l2| may
     * exceed g by a rounding error that the next step must see as the
     * run that was not stopped sees it.
     */
    std::pair<double, double>
    read_fields(const TrilinosWrappers::MPI::Vector &multipliers,
                const TrilinosWrappers::MPI::Vector &threshold_field,
                const bool                           project = true);

    /** Number of contact nodes on this rank and on all ranks. */
    unsigned int
    n_local_nodes() const
    {
      return nodes.size();
    }
    types::global_dof_index
    n_global_nodes() const
    {
      return n_global;
    }

    /**
     * Support points on Gamma_C that hang (all ranks): they carry no
     * contact condition of their own, their weight is their masters'.
     */
    types::global_dof_index
    n_hanging_nodes() const
    {
      return n_hanging;
    }

    /**
     * Contact nodes (all ranks) whose nearest obstacle point is a corner or
     * an edge: they take the body's normal (place_obstacle()).
     */
    unsigned int
    n_corner_nodes() const
    {
      return n_corner;
    }

    /** Smallest diameter of a face on Gamma_C (over all ranks). */
    double
    min_face_diameter() const
    {
      return h_min_;
    }

    /** Sum of the weights over all ranks: the measure of Gamma_C. */
    double
    measure() const
    {
      return measure_;
    }

    /**
     * The contact force of node s on the obstacle as a vector,
     * m_s (l1_s n_s + sum_k l2_s,k t_s,k); the obstacle's force on the body
     * is its negative.
     */
    Tensor<1, dim>
    nodal_force(const unsigned int s) const
    {
      Tensor<1, dim> force = l1[s] * nodes[s].normal;
      for (unsigned int k = 0; k < dim - 1; ++k)
        force += l2[s][k] * nodes[s].tangents[k];
      return nodes[s].weight * force;
    }

    /**
     * Add every node's nodal_force() to `forces` at its DoFs, and minus c_sj
     * times it at the DoFs of its masters: B^T lambda, the forces the bodies
     * exert on the contact at their DoFs (owned entries; compressed here).
     */
    void
    add_nodal_forces(TrilinosWrappers::MPI::Vector &forces) const;

    /**
     * n = -m and its tangent basis at a point x of Gamma_C (between nodes,
     * e.g. at quadrature points).
     */
    std::pair<Tensor<1, dim>, std::array<Tensor<1, dim>, dim - 1>>
    basis_at(const Point<dim> &x) const;

    std::vector<ContactNode<dim>> nodes;

    /**
     * The direction of first contact: the mean of the n_s of the nodes
     * closest to the obstacle (smallest g0), over all ranks, normalised (for
     * a plane obstacle the plane's n = -m), and a tangent basis for it. For
     * the equilibrium check, the totals on screen and the order of the
     * nodes along the boundary.
     */
    Tensor<1, dim>                      normal;
    Tensor<1, dim>                      tangent; // the first of the tangents
    std::array<Tensor<1, dim>, dim - 1> tangents;

    /** The obstacle the normals come from (set up by setup()). */
    const PlacedObstacle<dim> *obstacle = nullptr;

    /** Contact pressure multiplier l1 >= 0, one per local node. */
    std::vector<double> l1;

    /**
     * Friction: the law (chosen by the scene), whether the tangential terms
     * run at all (the threshold iteration switches them off for a
     * frictionless first solve), and at every local node the tangential
     * multiplier l2 (|l2| <= g, in the tangent basis), the threshold g and
     * the law's parameter (F for Coulomb, g for a given threshold).
     */
    const FrictionLaw              *law      = nullptr;
    bool                            friction = false;
    std::vector<Tensor<1, dim - 1>> l2;
    std::vector<double>             threshold;
    std::vector<double>             friction_parameter;

    /** Each local node's status after the last multiplier update. */
    std::vector<NodeStatus> statuses;

    /**
     * The slip origin o_t of the load step at each local node, in its
     * tangent basis (set_slip_origin(); zero after setup()).
     */
    std::vector<Tensor<1, dim - 1>> slip_origin;

  private:
    /**
     * The candidate contact nodes: the support points on the faces with
     * the ids of `input`, from the owned and ghost cells, each slave node's
     * id in `slave_id_of`; the weights and body normals they carry from
     * the owned cells, summed over the ranks (setup()).
     */
    std::map<types::global_dof_index, ContactNode<dim>>
    find_candidates(
      const Mapping<dim>                                    &mapping,
      const DoFHandler<dim>                                 &dof_handler,
      const AffineConstraints<double>                       &hanging,
      const std::set<types::boundary_id>                    &contact_ids,
      TrilinosWrappers::MPI::Vector                         &weights,
      TrilinosWrappers::MPI::Vector                         &body_normals,
      std::map<types::global_dof_index, types::boundary_id> &slave_id_of,
      double                                                &h_min) const;

    /**
     * The friction law of `input`, and at every node its parameter and the
     * threshold at zero pressure; throws if the parameter is not finite or
     * negative at some node.
     */
    void
    set_friction(const ContactSetup<dim> &input, MPI_Comm comm);

    // the contact pairs: pairing, mortar coupling, the master entries
    ContactPairs<dim> pairs_;
    // the body's size and centre (place_obstacle())
    double     characteristic_length = 1.;
    Point<dim> center;

    types::global_dof_index n_global  = 0;
    types::global_dof_index n_hanging = 0;
    unsigned int            n_corner  = 0;
    double                  h_min_    = 0.;
    double                  measure_  = 0.;
  };
} // namespace dualcontact

#endif
