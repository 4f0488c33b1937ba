#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <dualcontact/bodies.h>
#include <dualcontact/cell_loads.h>
#include <dualcontact/discretization.h>
#include <dualcontact/elasticity.h>
#include <dualcontact/input_error.h>

#include <Epetra_Map.h>
#include <Teuchos_ParameterList.hpp>

#include <iomanip>
#include <sstream>

namespace dualcontact
{
  namespace
  {
    /**
     * The cell terms of linear elasticity: the stiffness of a(u, v) =
     * int sigma(u):eps(v), and the load and, if asked, the lumped mass of
     * CellLoads.
     */
    template <int dim>
    class CellAssembler
    {
    public:
      CellAssembler(const Mapping<dim>       &mapping,
                    const FiniteElement<dim> &fe,
                    const Scene<dim>         &scene)
          : loads(mapping, fe, scene, update_gradients)
          , mass(loads.mass)
          , rhs(loads.rhs)
          , material(scene.parameters.material)
          , matrix(fe.n_dofs_per_cell(), fe.n_dofs_per_cell())
          , eps(fe.n_dofs_per_cell())
          , div(fe.n_dofs_per_cell())
      {}

      /** Add the resultant of the cell's loads `rhs` to `load`. */
      void
      add_resultant(std::array<double, 3> &load) const
      {
        loads.add_resultant(load);
      }

      /** Fill `matrix`, `rhs` and, with `with_mass`, `mass` for `cell`. */
      void
      assemble(const typename DoFHandler<dim>::active_cell_iterator &cell,
               const bool                                            with_mass)
      {
        loads.reinit(cell, with_mass);
        const FEValues<dim>             &fe_values = loads.fe_values;
        const unsigned int               n_dofs    = loads.fe.n_dofs_per_cell();
        const FEValuesExtractors::Vector displacement(0);
        // each body its material (<Material/Materials by id>)
        // (in the mixed formulation the deviatoric part alone: the
        // pressure carries the rest, mixed_bulk.h)
        const MaterialParameters here   = material.of(cell->material_id());
        const double             lambda = here.block_lambda(), mu = here.mu();
        matrix = 0;
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            for (unsigned int i = 0; i < n_dofs; ++i)
              {
                eps[i] = fe_values[displacement].symmetric_gradient(i, q);
                div[i] = trace(eps[i]);
              }
            const double JxW = fe_values.JxW(q);
            // sigma(u):eps(v) = lambda div u div v + 2 mu eps(u):eps(v)
            for (unsigned int i = 0; i < n_dofs; ++i)
              for (unsigned int j = 0; j <= i; ++j)
                matrix(i, j) +=
                  (lambda * div[i] * div[j] + 2. * mu * (eps[i] * eps[j])) *
                  JxW;
          }
        for (unsigned int i = 0; i < n_dofs; ++i)
          for (unsigned int j = i + 1; j < n_dofs; ++j)
            matrix(i, j) = matrix(j, i);
      }

      CellLoads<dim>            loads;
      const Vector<double>     &mass, &rhs;
      const MaterialParameters &material;
      FullMatrix<double>        matrix;

    private:
      std::vector<SymmetricTensor<2, dim>> eps;
      std::vector<double>                  div;
    };
  } // namespace

  template <int dim>
  void
  assemble_elasticity(const Mapping<dim>              &mapping,
                      const DoFHandler<dim>           &dof_handler,
                      const Scene<dim>                &scene,
                      const AffineConstraints<double> &constraints,
                      TrilinosWrappers::SparseMatrix  &system_matrix,
                      TrilinosWrappers::MPI::Vector   &system_rhs,
                      LumpedMass                      *mass,
                      std::array<double, 3>           *applied_load)
  {
    CellAssembler<dim> local(mapping, dof_handler.get_fe(), scene);
    std::vector<types::global_dof_index> dof_indices(
      dof_handler.get_fe().n_dofs_per_cell());
    system_matrix = 0;
    system_rhs    = 0;
    if (mass != nullptr)
      mass->diagonal = 0;
    std::array<double, 3> load{};
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          local.assemble(cell, mass != nullptr);
          local.add_resultant(load);
          cell->get_dof_indices(dof_indices);
          constraints.distribute_local_to_global(
            local.matrix, local.rhs, dof_indices, system_matrix, system_rhs);
          // (the vector alone: constraints act as homogeneous ones, so a
          // constrained DoF gets nothing and a hanging node's share goes to
          // its masters)
          if (mass != nullptr)
            constraints.distribute_local_to_global(local.mass,
                                                   dof_indices,
                                                   mass->diagonal);
        }
    system_matrix.compress(VectorOperation::add);
    system_rhs.compress(VectorOperation::add);
    if (mass != nullptr)
      mass->diagonal.compress(VectorOperation::add);
    if (applied_load != nullptr)
      for (unsigned int c = 0; c < 3; ++c)
        (*applied_load)[c] = Utilities::MPI::sum(
          load[c], dof_handler.get_triangulation().get_communicator());
  }

  void
  LumpedMass::vmult(TrilinosWrappers::MPI::Vector       &dst,
                    const TrilinosWrappers::MPI::Vector &src) const
  {
    dst = src;
    dst.scale(diagonal);
  }

  void
  LumpedMass::add_to(TrilinosWrappers::SparseMatrix &matrix,
                     const double                    factor) const
  {
    for (const types::global_dof_index i : diagonal.locally_owned_elements())
      if (diagonal[i] != 0.)
        matrix.add(i, i, factor * diagonal[i]);
    matrix.compress(VectorOperation::add);
  }

  namespace
  {
    /**
     * The residual of the unconstrained equations, R = A u - f, plus the
     * contact forces, the resultant of the loads, each body's loads (bodies.h)
     * and each owned DoF's body and component, from a locally owned cell
     * that holds it.
     */
    struct BodyResiduals
    {
      TrilinosWrappers::MPI::Vector      residual;
      std::array<double, 3>              load{};
      unsigned int                       n_bodies = 1;
      std::vector<std::array<double, 3>> load_on_body;
      std::vector<unsigned int>          body_of_dof, component_of_dof;
    };

    template <int dim>
    BodyResiduals
    body_residuals(const Mapping<dim>                  &mapping,
                   const DoFHandler<dim>               &dof_handler,
                   const Scene<dim>                    &scene,
                   const TrilinosWrappers::MPI::Vector &solution,
                   const TrilinosWrappers::MPI::Vector *contact_forces,
                   const TrilinosWrappers::MPI::Vector *pressure_forces)
    {
      const MPI_Comm comm = dof_handler.get_triangulation().get_communicator();
      CellAssembler<dim> local(mapping, dof_handler.get_fe(), scene);
      const unsigned int n_dofs = dof_handler.get_fe().n_dofs_per_cell();
      std::vector<types::global_dof_index> dof_indices(n_dofs);
      BodyResiduals                        result;
      result.residual.reinit(dof_handler.locally_owned_dofs(), comm);
      Vector<double>    u(n_dofs), r(n_dofs);
      const IndexSet   &owned = dof_handler.locally_owned_dofs();
      const Bodies<dim> bodies(dof_handler.get_triangulation());
      result.n_bodies = bodies.size();
      result.load_on_body.resize(result.n_bodies);
      result.body_of_dof.assign(owned.n_elements(), 0);
      result.component_of_dof.assign(owned.n_elements(), 0);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            local.assemble(cell, false);
            cell->get_dof_values(solution, u);
            local.matrix.vmult(r, u);
            r -= local.rhs;
            cell->get_dof_indices(dof_indices);
            result.residual.add(dof_indices, r);
            local.add_resultant(result.load);
            const unsigned int body = bodies.of(cell);
            local.add_resultant(result.load_on_body[body]);
            for (unsigned int k = 0; k < n_dofs; ++k)
              if (owned.is_element(dof_indices[k]))
                {
                  const auto index = owned.index_within_set(dof_indices[k]);
                  result.body_of_dof[index] = body;
                  result.component_of_dof[index] =
                    dof_handler.get_fe().system_to_component_index(k).first;
                }
          }
      result.residual.compress(VectorOperation::add);
      if (contact_forces != nullptr)
        result.residual += *contact_forces;
      if (pressure_forces != nullptr)
        result.residual += *pressure_forces;
      return result;
    }

    /**
     * The reaction of support id along e_c is R . w, w = 1 at the DoFs of
     * component c the support constrains and 0 at the other DoFs that are
     * not hanging; at a hanging DoF w interpolates its masters, so that w
     * is a finite element function: R vanishes against every such function
     * that is zero on the supports and the contact nodes (the equations),
     * which makes the reactions, the contact force and the loads balance
     * exactly. A DoF two supports constrain counts for the first ('fixed'
     * before 'normal fixed', the order the constraints were made in).
     * Fills record.on_id and adds each owned DoF's share to its body's
     * `reaction_on_body`.
     */
    template <int dim>
    void
    support_reactions(const DoFHandler<dim>           &dof_handler,
                      const Scene<dim>                &scene,
                      const AffineConstraints<double> &constraints,
                      const AffineConstraints<double> &hanging_node_constraints,
                      const BodyResiduals             &residuals,
                      ReactionRecord                  &record,
                      std::vector<std::array<double, 3>> &reaction_on_body)
    {
      const MPI_Comm  comm = dof_handler.get_triangulation().get_communicator();
      const IndexSet &owned = dof_handler.locally_owned_dofs();
      const TrilinosWrappers::MPI::Vector &residual = residuals.residual;
      IndexSet                             relevant;
      DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
      std::set<types::global_dof_index> claimed;
      TrilinosWrappers::MPI::Vector     w(owned, comm),
        w_ghosted(owned, relevant, comm);
      for (const BoundaryCondition condition :
           {BoundaryCondition::fixed, BoundaryCondition::normal_fixed})
        for (const types::boundary_id id : scene.ids_with(condition))
          {
            std::array<double, 3> &reaction = record.on_id[id];
            for (unsigned int c = 0; c < dim; ++c)
              {
                ComponentMask mask(dim, false);
                mask.set(c, true);
                w = 0.;
                for (const auto i :
                     DoFTools::extract_boundary_dofs(dof_handler, mask, {id}))
                  if (owned.is_element(i) && constraints.is_constrained(i) &&
                      !hanging_node_constraints.is_constrained(i) &&
                      claimed.insert(i).second)
                    w[i] = 1.;
                w.compress(VectorOperation::insert);
                w_ghosted  = w;
                double sum = 0.;
                for (const auto i : owned)
                  {
                    double wi = w[i];
                    if (const auto *entries =
                          hanging_node_constraints.get_constraint_entries(i))
                      {
                        wi = 0.;
                        for (const auto &[j, weight] : *entries)
                          wi += weight * w_ghosted[j];
                      }
                    sum += wi * residual[i];
                    reaction_on_body
                      [residuals.body_of_dof[owned.index_within_set(i)]][c] +=
                      wi * residual[i];
                  }
                reaction[c] = Utilities::MPI::sum(sum, comm);
              }
          }
    }

    /**
     * Each body's reaction, load and contact force (-B^T lambda on its
     * DoFs), summed over the ranks, into `record`; a scene of one body
     * balances as a whole (the record's totals), and records none.
     */
    void
    add_body_balances(
      ReactionRecord                           &record,
      const BodyResiduals                      &residuals,
      const std::vector<std::array<double, 3>> &reaction_on_body,
      const TrilinosWrappers::MPI::Vector      *contact_forces,
      const IndexSet                           &owned,
      const unsigned int                        dim,
      const MPI_Comm                            comm)
    {
      const unsigned int n_bodies = residuals.n_bodies;
      if (n_bodies == 1)
        return;
      std::vector<std::array<double, 3>> contact_on_body(n_bodies);
      if (contact_forces != nullptr)
        for (unsigned int k = 0; k < owned.n_elements(); ++k)
          contact_on_body[residuals.body_of_dof[k]]
                         [residuals.component_of_dof[k]] -=
            (*contact_forces)[owned.nth_index_in_set(k)];
      for (unsigned int b = 0; b < n_bodies; ++b)
        {
          record.on_body.emplace_back();
          record.load_on_body.emplace_back();
          record.contact_on_body.emplace_back();
          for (unsigned int c = 0; c < dim; ++c)
            {
              record.on_body[b][c] =
                Utilities::MPI::sum(reaction_on_body[b][c], comm);
              record.load_on_body[b][c] =
                Utilities::MPI::sum(residuals.load_on_body[b][c], comm);
              record.contact_on_body[b][c] =
                Utilities::MPI::sum(contact_on_body[b][c], comm);
            }
        }
    }
  } // namespace

  template <int dim>
  ReactionRecord
  compute_reactions(const Mapping<dim>              &mapping,
                    const DoFHandler<dim>           &dof_handler,
                    const Scene<dim>                &scene,
                    const AffineConstraints<double> &constraints,
                    const AffineConstraints<double> &hanging_node_constraints,
                    const TrilinosWrappers::MPI::Vector &solution,
                    const TrilinosWrappers::MPI::Vector *contact_forces,
                    const TrilinosWrappers::MPI::Vector *pressure_forces)
  {
    // The residual of the unconstrained equations, R = A u - f, is zero at
    // every free DoF; at a constrained one it is the force the support
    // exerts on the body there. Summed over the DoFs of a boundary id it is
    // that boundary's reaction. Only constrained DoFs count: a slider's
    // tangential DoFs are free, and at a node shared with the contact
    // boundary the free components carry the contact force, not a reaction.
    const MPI_Comm comm = dof_handler.get_triangulation().get_communicator();
    const BodyResiduals residuals = body_residuals(
      mapping, dof_handler, scene, solution, contact_forces, pressure_forces);
    ReactionRecord record;
    for (unsigned int c = 0; c < dim; ++c)
      record.applied_load[c] = Utilities::MPI::sum(residuals.load[c], comm);
    std::vector<std::array<double, 3>> reaction_on_body(residuals.n_bodies);
    support_reactions(dof_handler,
                      scene,
                      constraints,
                      hanging_node_constraints,
                      residuals,
                      record,
                      reaction_on_body);
    add_body_balances(record,
                      residuals,
                      reaction_on_body,
                      contact_forces,
                      dof_handler.locally_owned_dofs(),
                      dim,
                      comm);
    return record;
  }

  template <int dim>
  double
  potential_energy(const Mapping<dim>                  &mapping,
                   const DoFHandler<dim>               &dof_handler,
                   const Scene<dim>                    &scene,
                   const TrilinosWrappers::MPI::Vector &solution)
  {
    // J(u) = sum over the cells K of 1/2 u_K.A_K u_K - b_K.u_K, with the
    // cell matrices and loads of the assembly (no global matrix needed)
    CellAssembler<dim> local(mapping, dof_handler.get_fe(), scene);
    const unsigned int n_dofs = dof_handler.get_fe().n_dofs_per_cell();
    Vector<double>     u(n_dofs), Au(n_dofs);
    double             energy = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          local.assemble(cell, false);
          cell->get_dof_values(solution, u);
          local.matrix.vmult(Au, u);
          energy += 0.5 * (u * Au) - local.rhs * u;
        }
    return Utilities::MPI::sum(
      energy, dof_handler.get_triangulation().get_communicator());
  }

  namespace
  {
    /**
     * FEValues whose quadrature points are the cell's support points (one per
     * DoF, in the element's order): the mapped positions of all of them from
     * one evaluation of the mapping per cell. Mapping::
     * transform_unit_to_real_cell() per point would evaluate the cell's
     * manifold afresh for each, which at degree k >= 2 on a curved
     * (transfinite) manifold costs more than the solve.
     */
    template <int dim>
    FEValues<dim>
    support_point_values(const Mapping<dim>       &mapping,
                         const FiniteElement<dim> &fe)
    {
      return FEValues<dim>(mapping,
                           fe,
                           Quadrature<dim>(fe.get_unit_support_points()),
                           update_quadrature_points);
    }
  } // namespace

  template <int dim>
  void
  interpolate_field(
    const Mapping<dim>                                      &mapping,
    const DoFHandler<dim>                                   &dof_handler,
    const std::function<Tensor<1, dim>(const Point<dim> &)> &field,
    TrilinosWrappers::MPI::Vector                           &v)
  {
    const FiniteElement<dim> &fe    = dof_handler.get_fe();
    const IndexSet           &owned = v.locally_owned_elements();
    FEValues<dim> at_support_points = support_point_values(mapping, fe);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          at_support_points.reinit(cell);
          const std::vector<Point<dim>> &x =
            at_support_points.get_quadrature_points();
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (owned.is_element(dofs[i]))
              v[dofs[i]] = field(x[i])[fe.system_to_component_index(i).first];
        }
    v.compress(VectorOperation::insert);
  }

  template <int dim>
  std::unique_ptr<Epetra_MultiVector>
  rigid_body_modes(const Mapping<dim>                   &mapping,
                   const DoFHandler<dim>                &dof_handler,
                   const TrilinosWrappers::SparseMatrix &matrix,
                   const bool                            with_rotations,
                   const Point<dim>                     &center,
                   const double                          length)
  {
    const unsigned int n_rotations = with_rotations ? dim * (dim - 1) / 2 : 0;
    const unsigned int n_modes     = dim + n_rotations;
    const Epetra_Map  &map         = matrix.trilinos_matrix().RowMap();
    auto modes = std::make_unique<Epetra_MultiVector>(map, n_modes);

    const FiniteElement<dim> &fe    = dof_handler.get_fe();
    FEValues<dim> at_support_points = support_point_values(mapping, fe);
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dof_indices);
          at_support_points.reinit(cell);
          const std::vector<Point<dim>> &x =
            at_support_points.get_quadrature_points();
          for (unsigned int i = 0; i < dof_indices.size(); ++i)
            {
              const int local = map.LID(
                static_cast<TrilinosWrappers::types::int_type>(dof_indices[i]));
              if (local < 0)
                continue; // owned by another rank
              const unsigned int   c = fe.system_to_component_index(i).first;
              const Tensor<1, dim> r = (x[i] - center) / length;
              (*modes)[c][local]     = 1.;
              // rotation k in the plane (a, b): u_a = -r_b, u_b = r_a
              for (unsigned int k = 0; k < n_rotations; ++k)
                {
                  const unsigned int a     = (dim == 2) ? 0 : (k == 2 ? 1 : 0);
                  const unsigned int b     = (dim == 2) ? 1 : (k == 0 ? 1 : 2);
                  (*modes)[dim + k][local] = (c == a) ? -r[b] :
                                             (c == b) ? r[a] :
                                                        0.;
                }
            }
        }
    return modes;
  }

  template <int dim>
  ElasticSolver<dim>::ElasticSolver(const SolverParameters &parameters,
                                    const double            poisson_ratio)
      : parameters(parameters)
      , poisson_ratio(poisson_ratio)
  {}

  template <int dim>
  void
  ElasticSolver<dim>::set_near_null_space(
    const Mapping<dim>                   &mapping,
    const DoFHandler<dim>                &dof_handler,
    const TrilinosWrappers::SparseMatrix &matrix,
    const Point<dim>                     &center,
    const double                          length)
  {
    higher_order = dof_handler.get_fe().degree > 1;
    modes        = rigid_body_modes(mapping,
                             dof_handler,
                             matrix,
                             parameters.amg_rotation_modes,
                             center,
                             length);
  }

  template <int dim>
  void
  ElasticSolver<dim>::initialize(const TrilinosWrappers::SparseMatrix &matrix)
  {
    Assert(modes != nullptr, ExcMessage("set_near_null_space() first"));
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = higher_order;
    data.smoother_sweeps       = 2;
    // No connection is dropped when aggregating: dropping the weak ones
    // (threshold 0.02) more than doubles the CG iterations on the Hertz
    // meshes and takes more memory (doc/performance.md, "What was tried and
    // not kept").
    data.aggregation_threshold = 0.;

    // deal.II 9.4 only hands ML the translations; give it the rotations too
    // through ML's own "null space" parameters ("null space: type" =
    // "pre-computed"): elasticity AMG converges much faster with them.
    Teuchos::ParameterList              list;
    std::unique_ptr<Epetra_MultiVector> unused;
    data.set_parameters(list, unused, matrix);
    list.set("null space: type", "pre-computed");
    list.set("null space: dimension", modes->NumVectors());
    list.set("null space: vectors", modes->Values());

    // The dim DoFs of a node are consecutive in deal.II's numbering of
    // FESystem(FE_Q, dim): ML aggregates nodes, not single DoFs, as it
    // should for elasticity (otherwise an aggregate may hold the x DoF of a
    // node and not its y DoF). On the Hertz meshes it takes a quarter fewer
    // CG iterations (118 against 154 at 1.2e6 DoFs, doc/performance.md).
    AssertThrow(matrix.local_size() % dim == 0,
                ExcMessage("The AMG needs whole nodes on each rank."));
    list.set("PDE equations", dim);

    preconditioner = std::make_unique<TrilinosWrappers::PreconditionAMG>();
    preconditioner->initialize(matrix, list);
  }

  template <int dim>
  unsigned int
  ElasticSolver<dim>::solve(const TrilinosWrappers::SparseMatrix &matrix,
                            TrilinosWrappers::MPI::Vector        &x,
                            const TrilinosWrappers::MPI::Vector  &rhs,
                            const double tolerance) const
  {
    Assert(preconditioner != nullptr, ExcMessage("initialize() first"));
    const double relative =
      tolerance > 0 ? tolerance : parameters.linear_tolerance;
    const double rhs_norm = rhs.l2_norm();
    if (rhs_norm == 0.)
      {
        x = 0;
        return 0;
      }
    SolverControl control(parameters.max_linear_iterations,
                          relative * rhs_norm,
                          /*log_history=*/false,
                          /*log_result=*/false);
    SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
    try
      {
        cg.solve(matrix, x, rhs, *preconditioner);
      }
    catch (const SolverControl::NoConvergence &exc)
      {
        // the likely causes, most likely first
        std::vector<std::string> causes;
        if (poisson_ratio > 0.499)
          causes.push_back(
            "a nearly incompressible material (<Material/Poisson's ratio> = " +
            [this]() {
              std::ostringstream nu;
              nu << std::setprecision(10) << poisson_ratio;
              return nu.str();
            }() +
            ", lambda/mu = " +
            format_number(2. * poisson_ratio / (1. - 2. * poisson_ratio)) +
            "): the displacement elements lock and the matrix is nearly "
            "singular; nu <= 0.49 is what they can resolve");
        causes.emplace_back(
          "a body that the scene does not hold (a rigid motion that only the "
          "contact or the proximal term stops): check the boundary "
          "conditions");
        causes.emplace_back("too few iterations allowed: raise <Solver/Maximum "
                            "linear iterations>");
        std::string text =
          "CG did not converge in " + std::to_string(exc.last_step) +
          " iterations (residual " + format_number(exc.last_residual) +
          ", wanted " + format_number(relative * rhs_norm) +
          "). Likely causes, most likely first: ";
        for (std::size_t i = 0; i < causes.size(); ++i)
          text +=
            (i > 0 ? "; (" : "(") + std::to_string(i + 1) + ") " + causes[i];
        AssertThrow(false, ExcMessage(text + "."));
      }
    return control.last_step();
  }

  template <int dim>
  std::pair<bool, unsigned int>
  ElasticSolver<dim>::try_solve(const TrilinosWrappers::SparseMatrix &matrix,
                                TrilinosWrappers::MPI::Vector        &x,
                                const TrilinosWrappers::MPI::Vector  &rhs,
                                const double                          tolerance,
                                const unsigned int max_iterations) const
  {
    Assert(preconditioner != nullptr, ExcMessage("initialize() first"));
    const double rhs_norm = rhs.l2_norm();
    if (rhs_norm == 0.)
      {
        x = 0;
        return {true, 0};
      }
    SolverControl                           control(std::min(max_iterations,
                                   parameters.max_linear_iterations),
                          tolerance * rhs_norm,
                          /*log_history=*/false,
                          /*log_result=*/false);
    SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
    try
      {
        cg.solve(matrix, x, rhs, *preconditioner);
      }
    catch (const SolverControl::NoConvergence &exc)
      {
        return {false, exc.last_step};
      }
    return {true, control.last_step()};
  }

#define DUALCONTACT_INSTANTIATE(dim)                                                  \
  template void           assemble_elasticity<dim>(const Mapping<dim> &,              \
                                         const DoFHandler<dim> &,           \
                                         const Scene<dim> &,                \
                                         const AffineConstraints<double> &, \
                                         TrilinosWrappers::SparseMatrix &,  \
                                         TrilinosWrappers::MPI::Vector &,   \
                                         LumpedMass *,                      \
                                         std::array<double, 3> *);          \
  template ReactionRecord compute_reactions<dim>(                                     \
    const Mapping<dim> &,                                                             \
    const DoFHandler<dim> &,                                                          \
    const Scene<dim> &,                                                               \
    const AffineConstraints<double> &,                                                \
    const AffineConstraints<double> &,                                                \
    const TrilinosWrappers::MPI::Vector &,                                            \
    const TrilinosWrappers::MPI::Vector *,                                            \
    const TrilinosWrappers::MPI::Vector *);                                           \
  template double potential_energy<dim>(                                              \
    const Mapping<dim> &,                                                             \
    const DoFHandler<dim> &,                                                          \
    const Scene<dim> &,                                                               \
    const TrilinosWrappers::MPI::Vector &);                                           \
  template void interpolate_field<dim>(                                               \
    const Mapping<dim> &,                                                             \
    const DoFHandler<dim> &,                                                          \
    const std::function<Tensor<1, dim>(const Point<dim> &)> &,                        \
    TrilinosWrappers::MPI::Vector &);                                                 \
  template std::unique_ptr<Epetra_MultiVector> rigid_body_modes<dim>(                 \
    const Mapping<dim> &,                                                             \
    const DoFHandler<dim> &,                                                          \
    const TrilinosWrappers::SparseMatrix &,                                           \
    const bool,                                                                       \
    const Point<dim> &,                                                               \
    const double);                                                                    \
  template class ElasticSolver<dim>;

  DUALCONTACT_INSTANTIATE(2)
  DUALCONTACT_INSTANTIATE(3)
#undef DUALCONTACT_INSTANTIATE
} // namespace dualcontact
