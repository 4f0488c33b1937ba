#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <dualcontact/contact_functions.h>
#include <dualcontact/input_error.h>
#include <dualcontact/newton_solver.h>
#include <dualcontact/parameters.h>
#include <dualcontact/pressure_coupling.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <tuple>

namespace dualcontact
{
  namespace
  {
    // The branch of the generalised Hessian at a contact node: the normal
    // term where z >= 0 (at z = 0, a node that touches with no force, the
    // active branch, so that the step sees it), and the friction term of
    // a sticking or a slipping node (sticks(), as the multiplier update
    // decides it).
    template <int n>
    NodeStatus
    hessian_branch(const double        z,
                   const bool          friction,
                   const Tensor<1, n> &y,
                   const double        g)
    {
      if (z < 0.)
        return separated;
      return (!friction || sticks(y, g)) ? stick : slip;
    }

    // seconds since `start` on this rank's clock, and restart it
    double
    lap(std::chrono::steady_clock::time_point &start)
    {
      const auto   now = std::chrono::steady_clock::now();
      const double t   = std::chrono::duration<double>(now - start).count();
      start            = now;
      return t;
    }
  } // namespace

  template <int dim>
  NewtonSolver<dim>::NewtonSolver(const SolverParameters &parameters,
                                  ElasticSolver<dim>     &linear_solver)
      : parameters(parameters)
      , linear_solver(linear_solver)
  {}

  template <int dim>
  void
  NewtonSolver<dim>::reset(const bool keep_preconditioner)
  {
    amg_valid         = amg_valid && keep_preconditioner;
    roundoff_floor    = 0.;
    roundoff_reported = false;
  }

  template <int dim>
  void
  NewtonSolver<dim>::compute_gradient(
    const ContactSet<dim>               &contact,
    const TrilinosWrappers::MPI::Vector &v,
    TrilinosWrappers::MPI::Vector       &smooth,
    TrilinosWrappers::MPI::Vector       &gradient) const
  {
    const auto &constraints = system->homogeneous_constraints;
    system->stiffness.vmult(smooth, v);
    if (system->pressure != nullptr)
      system->pressure->add_pressure_forces(smooth);
    if (system->chi_scale != 1.)
      {
        TrilinosWrappers::MPI::Vector Mv(v);
        system->mass.vmult(Mv, v);
        smooth.add(system->proximal_correction(), Mv);
      }
    smooth -= rhs;
    constraints.set_zero(smooth);
    gradient = smooth;
    // contact terms m_s ((z_s)^+ n + T proj_g(y_s)) at the node, and on a
    // pair their share -c_sj of them at each master node j
    Vector<double>                       local_vector;
    std::vector<types::global_dof_index> local_dofs;
    for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
      {
        const double   m = contact.nodes[s].weight;
        Tensor<1, dim> force =
          (m * positive_part(z[s])) * contact.nodes[s].normal;
        if (contact.friction)
          {
            const Tensor<1, dim - 1> q =
              project_onto_disc(y[s], contact.threshold[s]);
            for (unsigned int k = 0; k < dim - 1; ++k)
              force += (m * q[k]) * contact.nodes[s].tangents[k];
          }
        if (force.norm() == 0.)
          continue;
        const auto &masters = contact.nodes[s].masters;
        local_vector.reinit(dim * (1 + masters.size()));
        local_dofs.resize(dim * (1 + masters.size()));
        for (unsigned int c = 0; c < dim; ++c)
          {
            local_vector(c) = force[c];
            local_dofs[c]   = contact.nodes[s].dofs[c];
            for (unsigned int j = 0; j < masters.size(); ++j)
              {
                local_vector(dim * (j + 1) + c) =
                  -masters[j].coefficient * force[c];
                local_dofs[dim * (j + 1) + c] = masters[j].dofs[c];
              }
          }
        constraints.distribute_local_to_global(local_vector,
                                               local_dofs,
                                               gradient);
      }
    gradient.compress(VectorOperation::add);
  }

  template <int dim>
  void
  NewtonSolver<dim>::add_contact_terms(const ContactSet<dim> &contact)
  {
    Assert(contact_terms.empty() && proximal_added == 0.,
           ExcMessage("The contact terms are in K already."));
    TrilinosWrappers::SparseMatrix  &H = system->stiffness;
    const AffineConstraints<double> &constraints =
      system->homogeneous_constraints;
    FullMatrix<double> local_matrix(dim, dim);
    // a DoF as the condensed space sees it: itself, or the masters of a
    // hanging node with their weights, or nothing (a prescribed DoF); for
    // each of the node's DoFs, then each of its master nodes' on a pair
    std::vector<std::vector<std::pair<types::global_dof_index, double>>> rows;
    std::vector<double> coefficient; // of each node: 1, then -c_sj
    for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
      {
        const double m_a =
          contact.nodes[s].weight * contact.nodes[s].augmentation;
        const double                               m_r  = m_a * system->r;
        const double                               m_rt = m_a * system->r_t;
        const Tensor<1, dim>                      &n = contact.nodes[s].normal;
        const std::array<Tensor<1, dim>, dim - 1> &t =
          contact.nodes[s].tangents;
        local_matrix = 0;
        // normal part, where z >= 0 (at z = 0 the generalised derivative may
        // take either branch; the active one spares a free fall)
        if (z[s] >= 0.)
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              local_matrix(a, b) += m_r * n[a] * n[b];
        // tangential part T D(y) T^T, column by column: e_b in the tangent
        // basis, and D(y) applied to it
        if (contact.friction)
          for (unsigned int b = 0; b < dim; ++b)
            {
              Tensor<1, dim - 1> eb;
              for (unsigned int k = 0; k < dim - 1; ++k)
                eb[k] = t[k][b];
              const Tensor<1, dim - 1> Deb =
                projection_derivative(y[s], contact.threshold[s], eb);
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int k = 0; k < dim - 1; ++k)
                  local_matrix(a, b) += m_rt * t[k][a] * Deb[k];
            }
        if (local_matrix.frobenius_norm() == 0.)
          continue;
        // condensed by hand rather than by distribute_local_to_global, which
        // also puts a positive diagonal entry on constrained rows: those
        // would not come off again in remove_contact_terms()
        // the node's terms act on B v = v_s - sum_j c_sj v_j (v_s alone
        // against the obstacle): B^T (local matrix) B
        const auto        &masters = contact.nodes[s].masters;
        const unsigned int n_nodes = 1 + masters.size();
        rows.assign(dim * n_nodes, {});
        coefficient.assign(n_nodes, 1.);
        for (unsigned int i = 0; i < n_nodes; ++i)
          for (unsigned int a = 0; a < dim; ++a)
            {
              const types::global_dof_index dof =
                i == 0 ? contact.nodes[s].dofs[a] : masters[i - 1].dofs[a];
              if (i > 0)
                coefficient[i] = -masters[i - 1].coefficient;
              if (!constraints.is_constrained(dof))
                rows[dim * i + a].emplace_back(dof, 1.);
              else if (const auto *entries =
                         constraints.get_constraint_entries(dof))
                rows[dim * i + a] = *entries;
            }
        for (unsigned int i = 0; i < n_nodes; ++i)
          for (unsigned int k = 0; k < n_nodes; ++k)
            for (unsigned int a = 0; a < dim; ++a)
              for (unsigned int b = 0; b < dim; ++b)
                if (local_matrix(a, b) != 0.)
                  for (const auto &[row, row_weight] : rows[dim * i + a])
                    for (const auto &[column, column_weight] :
                         rows[dim * k + b])
                      contact_terms.push_back({row,
                                               column,
                                               coefficient[i] * coefficient[k] *
                                                 row_weight * column_weight *
                                                 local_matrix(a, b)});
      }
    for (const ContactEntry &entry : contact_terms)
      H.add(entry.row, entry.column, entry.value);
    H.compress(VectorOperation::add);
    if (system->chi_scale != 1.)
      {
        proximal_added = system->proximal_correction();
        system->mass.add_to(H, proximal_added);
      }
  }

  template <int dim>
  void
  NewtonSolver<dim>::remove_contact_terms()
  {
    TrilinosWrappers::SparseMatrix &H = system->stiffness;
    for (const ContactEntry &entry : contact_terms)
      H.add(entry.row, entry.column, -entry.value);
    H.compress(VectorOperation::add);
    contact_terms.clear();
    if (proximal_added != 0.)
      system->mass.add_to(H, -proximal_added);
    proximal_added = 0.;
  }

  template <int dim>
  bool
  NewtonSolver<dim>::update_preconditioner(
    const std::vector<unsigned char> &status,
    const types::global_dof_index     n_active)
  {
    // Rebuild the AMG only when the node statuses moved enough, measured
    // against the size of the active set (the part of H that changes) ...
    const MPI_Comm          comm      = rhs.get_mpi_communicator();
    types::global_dof_index n_changed = 0, n_active_built = 0, n_stiffer = 0;
    if (amg_valid)
      for (unsigned int s = 0; s < status.size(); ++s)
        {
          n_changed += (status[s] != amg_status[s]);
          n_active_built += (amg_status[s] != separated);
          // a node whose contact terms grew: newly in contact, or from
          // slip to stick (the full r_t instead of its projection)
          n_stiffer += (amg_status[s] == separated && status[s] != separated) ||
                       (amg_status[s] == slip && status[s] == stick);
        }
    n_changed      = Utilities::MPI::sum(n_changed, comm);
    n_active_built = Utilities::MPI::sum(n_active_built, comm);
    n_stiffer      = Utilities::MPI::sum(n_stiffer, comm);
    // ... or when the last CG solve needed clearly more iterations than the
    // first one after the set-up (a set-up costs about 20 of them), unless
    // the matrix is the one the hierarchy was built for (the same statuses
    // and no slipping node, whose term depends on v): a rebuild would give
    // the same hierarchy (doc/performance.md).
    types::global_dof_index n_slipping = 0;
    for (const unsigned char s : status)
      n_slipping += (s == slip);
    const bool same_matrix = amg_valid && n_changed == 0 &&
                             amg_chi_scale == system->chi_scale &&
                             Utilities::MPI::sum(n_slipping, comm) == 0;
    // ... or when more than 20 nodes got stiffer terms than the hierarchy
    // knows: each such term (r m_s, about r_rel times the element's
    // stiffness) puts an outlying eigenvalue into the preconditioned
    // matrix, and CG spends about one iteration on each, so beyond about a
    // set-up's worth of iterations (~20) a new set-up is cheaper. Terms
    // that shrank do not do that (doc/contact_solver.md).
    const bool rebuild =
      !amg_valid || parameters.amg_rebuild_fraction == 0. || n_stiffer > 20 ||
      n_changed >
        parameters.amg_rebuild_fraction * std::max(n_active_built, n_active) ||
      (!same_matrix &&
       last_cg_iterations > 1.5 * cg_iterations_after_setup + 10);
    if (rebuild)
      {
        linear_solver.initialize(system->stiffness);
        amg_status    = status;
        amg_valid     = true;
        amg_chi_scale = system->chi_scale;
      }
    return rebuild;
  }

  template <int dim>
  double
  NewtonSolver<dim>::line_search(
    const ContactSet<dim>               &contact,
    const TrilinosWrappers::MPI::Vector &smooth_gradient,
    const TrilinosWrappers::MPI::Vector &direction)
  {
    // The smooth part of M_k is exactly quadratic and each contact term a
    // 1D piecewise quadratic, so phi(a) = M_k(v + a d) is a convex piecewise
    // quadratic with
    //   phi'(a) = q1 + a q2 + sum_s m_s ((z_s + a r dn_s)^+ dn_s
    //                                   + proj_g(y_s + a r dt_s).dt_s),
    // The full step is taken when it passes Armijo's sufficient-decrease
    // test, else the minimiser of phi, found by safeguarded Newton steps on
    // phi' (doc/theory.md §3.3: the line search makes Newton globally
    // convergent; the minimiser lets a step that meets many new contact
    // nodes go as far as it should).
    const MPI_Comm                  comm = rhs.get_mpi_communicator();
    const double                    r    = system->r;
    const double                    r_t  = system->r_t;
    const unsigned int              n    = contact.n_local_nodes();
    std::vector<double>             dn(n);
    std::vector<Tensor<1, dim - 1>> dt(n);
    TrilinosWrappers::MPI::Vector   free_direction(direction), tmp(direction);
    system->homogeneous_constraints.set_zero(free_direction);
    system->stiffness.vmult(tmp, free_direction);
    double q2 = free_direction * tmp;
    // in the mixed formulation the pressure takes its whole step, and the
    // merit function has an exact penalty on the incompressibility
    // constraint (pressure_coupling.h)
    const PressureCoupling::LineTerms pressure =
      system->pressure != nullptr ?
        system->pressure->update_pressure(direction) :
        PressureCoupling::LineTerms();
    if (system->chi_scale != 1.)
      {
        system->mass.vmult(tmp, free_direction);
        q2 += system->proximal_correction() * (free_direction * tmp);
      }
    const double q1 = smooth_gradient * direction + pressure.slope;
    const TrilinosWrappers::MPI::Vector &d = contact.with_masters(direction);
    for (unsigned int s = 0; s < n; ++s)
      {
        dn[s] = contact.normal_displacement(d, s);
        if (contact.friction)
          dt[s] = contact.tangential_displacement(d, s);
      }
    // phi'(a) and phi''(a) (the latter from the right), summed over ranks
    const auto derivatives = [&](const double alpha) {
      double local[2] = {0., 0.};
      for (unsigned int s = 0; s < n; ++s)
        {
          const double m  = contact.nodes[s].weight;
          const double a  = contact.nodes[s].augmentation;
          const double zs = z[s] + alpha * a * r * dn[s];
          if (zs > 0. || (zs == 0. && dn[s] > 0.))
            {
              local[0] += m * zs * dn[s];
              local[1] += m * a * r * dn[s] * dn[s];
            }
          if (contact.friction)
            {
              const Tensor<1, dim - 1> ys = y[s] + alpha * a * r_t * dt[s];
              const double             g  = contact.threshold[s];
              local[0] += m * (project_onto_disc(ys, g) * dt[s]);
              local[1] += m * a * r_t * huber_curvature(ys, g, dt[s]);
            }
        }
      double global[2];
      Utilities::MPI::sum(ArrayView<const double>(local, 2),
                          comm,
                          ArrayView<double>(global, 2));
      const auto penalty = pressure.penalty(alpha);
      return std::make_pair(q1 + alpha * q2 + global[0] + penalty[1],
                            q2 + global[1] + penalty[2]);
    };
    // phi(1) - phi(0), for the sufficient-decrease (Armijo) test of the
    // full step
    const auto merit_change = [&]() {
      double local = 0;
      for (unsigned int s = 0; s < n; ++s)
        {
          const double m = contact.nodes[s].weight;
          const double a = contact.nodes[s].augmentation;
          local += m / (2. * a * r) *
                   (std::pow(positive_part(z[s] + a * r * dn[s]), 2) -
                    std::pow(positive_part(z[s]), 2));
          if (contact.friction)
            local += m / (a * r_t) *
                     (huber(Tensor<1, dim - 1>(y[s] + a * r_t * dt[s]),
                            contact.threshold[s]) -
                      huber(y[s], contact.threshold[s]));
        }
      return q1 + 0.5 * q2 + Utilities::MPI::sum(local, comm) +
             pressure.penalty(1.)[0] - pressure.penalty(0.)[0];
    };
    // The full step when it decreases M_k enough, else the minimiser.
    if (!parameters.line_search ||
        merit_change() <= 1e-4 * derivatives(0.).first)
      return 1.;
    return exact_line_search(derivatives);
  }

  template <int dim>
  double
  NewtonSolver<dim>::force_reference(const ContactSet<dim> &contact) const
  {
    // The force scale the gradient is measured against. A gradient g left
    // at a contact node moves its multipliers in the next update by about
    // g_s / m_s (doc/theory.md §6), so the Newton tolerance must be
    // relative to the contact forces m_s (l1_s, l2_s), not only to the load
    // b: when displacements are prescribed, b holds their lifting, which
    // can be far larger than the contact forces, and a tolerance relative
    // to it leaves the Uzawa iteration asking for changes of the
    // multipliers that no proximal step resolves.
    const MPI_Comm comm    = system->load.get_mpi_communicator();
    const unsigned n_nodes = contact.n_local_nodes();
    const double   load    = system->load.l2_norm();
    double         local   = 0.;
    for (unsigned int s = 0; s < n_nodes; ++s)
      local += std::pow(contact.nodes[s].weight, 2) *
               (contact.l1[s] * contact.l1[s] +
                (contact.friction ? contact.l2[s].norm_square() : 0.));
    const double contact_forces = std::sqrt(Utilities::MPI::sum(local, comm));
    // Without loads (an obstacle pressed in by a prescribed displacement)
    // and before the first pressure, the force the augmented term exerts on
    // the initial overlap, m_s r (g0_s)^-, sets the scale.
    double overlap = 0.;
    for (unsigned int s = 0; s < n_nodes; ++s)
      overlap +=
        std::pow(contact.nodes[s].weight * contact.nodes[s].augmentation *
                   system->r * std::max(-contact.nodes[s].gap0, 0.),
                 2);
    overlap          = std::sqrt(Utilities::MPI::sum(overlap, comm));
    double reference = load > 0. ? load : overlap;
    if (contact_forces > 0.)
      reference =
        reference > 0. ? std::min(reference, contact_forces) : contact_forces;
    // along a load path, not below the previous step's contact forces: a
    // step that unloads everything stops at the round-off of the path
    reference = std::max(reference, system->previous.force_norm);
    return reference > 0. ? reference : 1.; // no load at all: v = 0 at once
  }

  template <int dim>
  double
  NewtonSolver<dim>::evaluate(const ContactSet<dim>               &contact,
                              const TrilinosWrappers::MPI::Vector &v,
                              IterationRecord                     &record)
  {
    contact.augmented_state(v, system->r, system->r_t, z, y);
    compute_gradient(contact, v, smooth_gradient, gradient);
    previous_status = status;
    status.resize(contact.n_local_nodes());
    types::global_dof_index n_active = 0;
    for (unsigned int s = 0; s < status.size(); ++s)
      {
        status[s] =
          hessian_branch(z[s], contact.friction, y[s], contact.threshold[s]);
        n_active += (status[s] != separated);
      }
    record.n_active =
      Utilities::MPI::sum(n_active, gradient.get_mpi_communicator());
    return gradient.l2_norm();
  }

  template <int dim>
  bool
  NewtonSolver<dim>::at_roundoff_floor(const unsigned int j,
                                       const double       gradient_norm,
                                       const double       target,
                                       const double       reference,
                                       IterationObserver *observer)
  {
    // With the node statuses fixed M_k is quadratic (in 3D only without
    // slipping nodes: the projection onto the disc), and a full Newton
    // step ends at its minimiser up to the CG tolerance. If full steps
    // at unchanged statuses stop reducing the gradient, it has reached
    // the round-off floor of K (which rises with lambda/mu, i.e. as nu
    // -> 1/2): accept that floor when it is within 10^3 of the target.
    bool unchanged = j > 0;
    for (unsigned int s = 0; unchanged && s < status.size(); ++s)
      unchanged = status[s] == previous_status[s];
    const MPI_Comm comm = gradient.get_mpi_communicator();
    unchanged           = Utilities::MPI::min(unchanged ? 1 : 0, comm) == 1;
    // A node whose status flips at round-off of its z or y (on 2 ranks
    // the sums are taken in another order) changes the matrix by one
    // contact term and leaves the floor where it is: five stalled full
    // steps in a row count as at the floor whatever the statuses do.
    // A step counts as full when the line search takes (nearly) all of
    // it: at the floor the sufficient-decrease test sees only round-off
    // and the exact minimiser lies a rounding error away from 1. A step
    // the line search cannot take at all (alpha below 1e-6: M_k falls
    // along the direction by less than its round-off) stalls as well.
    const double alpha    = progress.previous_alpha;
    const bool   stalling = j > 0 && (alpha > 0.9 || alpha < 1e-6) &&
                          gradient_norm > 0.5 * progress.previous_gradient;
    progress.stalled = (stalling && unchanged) ? progress.stalled + 1 : 0;
    progress.stalled_switching = stalling ? progress.stalled_switching + 1 : 0;
    progress.previous_gradient = gradient_norm;
    // (Round-off of K leaves about 1e-10 |b| even at nu = 0.49999,
    // doc/robustness.md; a stall far above that is not round-off: in 3D
    // the projection onto the friction disc is not linear at fixed
    // statuses, and a few full steps can stall at 1e-2 |b|.)
    // A stall within 10^3 of the target, or below 1e-9 F_ref (round-off
    // for any matrix the scenes meet, however far below it a tolerance
    // asks), is accepted.
    const bool at_floor =
      (progress.stalled >= 3 || progress.stalled_switching >= 5) &&
      gradient_norm <= std::max(1e3 * target, 1e-9 * reference) &&
      gradient_norm <= 1e-6 * reference;
    if (at_floor)
      roundoff_floor = std::max(roundoff_floor, gradient_norm / reference);
    if (at_floor && !roundoff_reported && observer != nullptr)
      observer->note(
        "Newton: the gradient stagnates at " +
        format_number(gradient_norm / reference) +
        " |b| (round-off of this matrix) above the target " +
        format_number(target / reference) +
        " |b|; accepted, and the later Uzawa steps of this solve stop "
        "there at once");
    roundoff_reported |= at_floor;
    return at_floor;
  }

  template <int dim>
  void
  NewtonSolver<dim>::check_step_limit(const unsigned int     j,
                                      const ContactSet<dim> &contact,
                                      const IterationRecord &record,
                                      const double relative_target) const
  {
    // <Solver/Maximum Newton steps> counts the full steps. A step that the
    // line search cuts short ends at a kink of M_k, where a node changes
    // its status (or its direction of slip): with gross slip and a large r
    // the Newton iteration crosses many of them one by one, and M_k still
    // falls at every step (piecewise quadratic and strictly convex:
    // finitely many such steps). Such steps are allowed on top, up to one
    // per contact node.
    const double       alpha = progress.previous_alpha;
    const unsigned int limit =
      parameters.max_newton_steps +
      static_cast<unsigned int>(
        std::min<types::global_dof_index>(progress.short_steps,
                                          contact.n_global_nodes()));
    AssertThrow(
      j < limit,
      ExcMessage(
        "The Newton iteration (loop 3) did not converge in " +
        std::to_string(j) + " steps in Uzawa step " +
        std::to_string(record.uzawa_step) + " (relative gradient " +
        format_number(record.gradient) + ", wanted " +
        format_number(relative_target) + ", last step length " +
        format_number(alpha) + "). Likely causes, most likely first: " +
        (alpha < 0.1 ?
           "(1) the contact and stick/slip statuses switch at every step "
           "(short steps of the line search): lower <Solver/"
           "Augmentation parameter>; (2) too few steps allowed: raise "
           "<Solver/Maximum Newton steps>." :
           "(1) too few steps allowed: raise <Solver/Maximum Newton "
           "steps>; (2) a large <Solver/Augmentation parameter>, whose "
           "contact terms make each step harder: lower it.")));
  }

  template <int dim>
  void
  NewtonSolver<dim>::solve_for_direction(const ContactSet<dim> &contact,
                                         const TrilinosWrappers::MPI::Vector &v,
                                         const double      forcing,
                                         IterationRecord  &record,
                                         NewtonStatistics &statistics)
  {
    // The Newton direction: H d = -grad, by CG with AMG, solved only as
    // accurately as the target needs (inexact Newton: `forcing` is the
    // relative CG tolerance). H is K with the contact terms added in
    // place, until remove_contact_terms() below. (If anything between
    // throws, K keeps them: the run ends then.)
    auto clock = std::chrono::steady_clock::now();
    add_contact_terms(contact);
    const TrilinosWrappers::SparseMatrix &H = system->stiffness;
    statistics.times.newton_matrix += lap(clock);
    record.amg_setups = update_preconditioner(status, record.n_active);
    statistics.times.amg_setup += lap(clock);
    newton_rhs.equ(-1., gradient);
    direction            = 0;
    bool solved          = false;
    record.cg_iterations = 0;
    // one linear solve: CG, or in the mixed formulation MINRES on the
    // saddle-point system (pressure_coupling.h), each with the AMG of H
    const auto linear_solve = [&](const unsigned int max_iterations) {
      if (system->pressure == nullptr)
        return linear_solver.try_solve(
          H, direction, newton_rhs, forcing, max_iterations);
      // (at the same forcing, and on until the second row is accurate
      // enough for the line search: MixedBulk::solve())
      return system->pressure->solve(H,
                                     linear_solver.amg(),
                                     v,
                                     newton_rhs,
                                     direction,
                                     forcing,
                                     max_iterations);
    };
    if (record.amg_setups == 0)
      {
        // The AMG of an earlier Newton matrix. The contact terms r m_s
        // of the nodes whose status changed since are large (about
        // r_rel times the stiffness), and a preconditioner without them
        // can make CG take a hundred times the iterations it took after
        // the set-up (766 against 9 on the 3D ball with friction at 2.3e5
        // DoFs; no convergence in 2000 at 6.8e5). So CG stops at three
        // times those plus 30, and the AMG is built for this matrix; CG
        // goes on from where it stopped.
        const auto [converged, iterations] =
          linear_solve(3 * cg_iterations_after_setup + 30);
        record.cg_iterations = iterations;
        solved               = converged;
        statistics.times.cg += lap(clock);
        if (!solved)
          {
            linear_solver.initialize(H);
            statistics.times.amg_setup += lap(clock);
            amg_status        = status;
            amg_valid         = true;
            amg_chi_scale     = system->chi_scale;
            record.amg_setups = 1;
          }
      }
    unsigned int final_iterations = record.cg_iterations;
    if (!solved && system->pressure == nullptr)
      final_iterations = linear_solver.solve(H, direction, newton_rhs, forcing);
    else if (!solved)
      {
        bool converged;
        std::tie(converged, final_iterations) =
          linear_solve(parameters.max_linear_iterations);
        AssertThrow(converged,
                    ExcMessage(
                      "MINRES did not solve the mixed saddle-point system in " +
                      std::to_string(final_iterations) +
                      " iterations: raise <Solver/Maximum linear "
                      "iterations>, or check that the scene holds the "
                      "body (a pressure that nothing determines: an "
                      "incompressible body held on its whole boundary)."));
      }
    if (!solved)
      record.cg_iterations += final_iterations;
    statistics.times.cg += lap(clock);
    remove_contact_terms();
    statistics.times.newton_matrix += lap(clock);
    last_cg_iterations = final_iterations;
    if (record.amg_setups > 0)
      cg_iterations_after_setup = final_iterations;
    system->homogeneous_constraints.distribute(direction);
  }

  template <int dim>
  NewtonStatistics
  NewtonSolver<dim>::minimise(const ContactSystem                 &system_,
                              const ContactSet<dim>               &contact,
                              const TrilinosWrappers::MPI::Vector &v_previous,
                              TrilinosWrappers::MPI::Vector       &v,
                              const double                         envelope,
                              const double       final_tolerance,
                              const unsigned int uzawa_step,
                              IterationObserver *observer)
  {
    system                   = &system_;
    const MPI_Comm comm      = v.get_mpi_communicator();
    const double   reference = force_reference(contact);

    // The smooth part's gradient is K v - rhs with rhs = b + chi M v^k
    // (chi the step's proximal weight).
    rhs.reinit(system->load);
    system->mass.vmult(rhs, v_previous);
    rhs.sadd(system->proximal_weight(), 1., system->load);
    for (auto *vector : {&smooth_gradient, &gradient, &direction, &newton_rhs})
      vector->reinit(rhs);
    status.clear();
    progress = Progress();

    NewtonStatistics statistics;
    double           target = 0.; // absolute gradient tolerance of this call
    for (unsigned int j = 0;; ++j)
      {
        Timer timer(comm, true);
        auto  clock = std::chrono::steady_clock::now();

        IterationRecord record;
        record.loop                = Loop::newton;
        record.uzawa_step          = uzawa_step;
        record.index               = j;
        const double gradient_norm = evaluate(contact, v, record);
        record.gradient            = gradient_norm / reference;

        // Stop when the gradient is below the envelope and has fallen by the
        // Newton gradient reduction within this Uzawa step (each step is then
        // solved as accurately as the Uzawa iteration can use, and no more),
        // or when it is below the final tolerance (doc/theory.md §6), or at
        // the round-off floor of the matrix.
        if (j == 0)
          {
            target = std::max(final_tolerance * reference,
                              std::min(envelope * reference,
                                       parameters.newton_gradient_reduction *
                                         gradient_norm));
            // a floor found earlier in this solve: the later Newton
            // iterations stop there at once
            statistics.at_floor = 1.5 * roundoff_floor * reference > target;
            target = std::max(target, 1.5 * roundoff_floor * reference);
          }
        const bool at_floor =
          at_roundoff_floor(j, gradient_norm, target, reference, observer);
        statistics.times.gradient += lap(clock);
        if (gradient_norm <= target || at_floor)
          {
            statistics.at_floor |= at_floor;
            timer.stop();
            record.time = timer.wall_time();
            if (observer != nullptr)
              observer->newton_step(record);
            return statistics;
          }
        check_step_limit(j, contact, record, target / reference);

        solve_for_direction(
          contact,
          v,
          std::min(0.1, std::max(1e-12, 0.5 * target / gradient_norm)),
          record,
          statistics);
        clock              = std::chrono::steady_clock::now();
        const double alpha = line_search(contact, smooth_gradient, direction);
        v.add(alpha, direction);
        record.step_length      = alpha;
        progress.previous_alpha = alpha;
        progress.short_steps += (alpha < 1.);
        statistics.times.gradient += lap(clock);

        timer.stop();
        record.time = timer.wall_time();
        if (observer != nullptr)
          observer->newton_step(record);
        statistics.newton_steps += 1;
        statistics.cg_iterations += record.cg_iterations;
        statistics.amg_setups += record.amg_setups;
      }
  }

  template <int dim>
  double
  NewtonSolver<dim>::time_reference_solve(
    const ContactSystem                 &system_,
    const ContactSet<dim>               &contact,
    const TrilinosWrappers::MPI::Vector &v,
    ElasticSolver<dim>                  &solver,
    unsigned int                        &iterations)
  {
    system = &system_;
    contact.augmented_state(v, system->r, system->r_t, z, y);
    add_contact_terms(contact);

    Timer timer(v.get_mpi_communicator(), true);
    solver.initialize(system->stiffness);
    TrilinosWrappers::MPI::Vector x(system->load);
    x = 0;
    if (system->pressure == nullptr)
      iterations = solver.solve(system->stiffness, x, system->load);
    else
      iterations = system->pressure
                     ->solve(system->stiffness,
                             solver.amg(),
                             v,
                             system->load,
                             x,
                             parameters.linear_tolerance,
                             parameters.max_linear_iterations)
                     .second;
    timer.stop();
    remove_contact_terms();
    return timer.wall_time();
  }

  template class NewtonSolver<2>;
  template class NewtonSolver<3>;
} // namespace dualcontact
