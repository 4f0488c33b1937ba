#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <dualcontact/input_error.h>
#include <dualcontact/uzawa_solver.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace dualcontact
{
  namespace
  {
    // |difference| / |reference|, with 0/0 = 0 and x/0 = 1.
    double
    relative(const double difference, const double reference)
    {
      if (reference > 0.)
        return difference / reference;
      return difference > 0. ? 1. : 0.;
    }

    double
    positive_part(const double x)
    {
      return x > 0. ? x : 0.;
    }

    // Projection onto the disc of radius g (an interval in 2D).
    template <int n>
    Tensor<1, n>
    project(const Tensor<1, n> &y, const double g)
    {
      const double norm = y.norm();
      return norm <= g ? y : (g / norm) * y;
    }

    // psi_g(y) = |y|^2/2 for |y| <= g, g|y| - g^2/2 beyond: C^1, convex,
    // with gradient project(y, g) (the tangential part of DESIGN.md §2).
    template <int n>
    double
    huber(const Tensor<1, n> &y, const double g)
    {
      const double norm = y.norm();
      return norm <= g ? 0.5 * norm * norm : g * norm - 0.5 * g * g;
    }

    // d . D(y) d, D the derivative of project(., g) at y: the identity when
    // sticking (|y| < g), (g/|y|)(I - y y^T/|y|^2) when slipping.
    template <int n>
    double
    huber_curvature(const Tensor<1, n> &y,
                    const double        g,
                    const Tensor<1, n> &d)
    {
      const double norm = y.norm();
      if (norm < g)
        return d * d;
      if (norm == 0.)
        return 0.;
      const double along = (d * y) / norm;
      return g / norm * (d * d - along * along);
    }

    // Status of a contact node for the AMG-reuse test and the output:
    // 0 separated, 1 in contact and sticking, 2 in contact and slipping.
    unsigned char
    node_status(const double z, const bool friction, const bool stick)
    {
      if (z < 0.)
        return 0;
      return (!friction || stick) ? 1 : 2;
    }
  } // namespace

  template <int dim>
  UzawaSolver<dim>::UzawaSolver(const SolverParameters &parameters,
                                ElasticSolver<dim>     &linear_solver,
                                ConditionalOStream     &pcout,
                                const bool              print_timing)
      : parameters(parameters)
      , linear_solver(linear_solver)
      , pcout(pcout)
      , print_timing(print_timing)
  {}

  template <int dim>
  void
  UzawaSolver<dim>::nodal_state(const ContactSet<dim>               &contact,
                                const TrilinosWrappers::MPI::Vector &v,
                                const double                         r,
                                std::vector<double>                 &z,
                                std::vector<Tensor<1, dim - 1>>     &y) const
  {
    const unsigned int n_nodes = contact.n_local_nodes();
    z.resize(n_nodes);
    y.resize(n_nodes);
    for (unsigned int s = 0; s < n_nodes; ++s)
      {
        z[s] = contact.l1[s] +
               r * (contact.normal_displacement(v, s) - contact.nodes[s].gap0);
        if (contact.friction)
          y[s] = contact.l2[s] + r * contact.tangential_displacement(v, s);
      }
  }

  template <int dim>
  void
  UzawaSolver<dim>::assemble_newton_matrix(
    const ContactSystem                   &system,
    const ContactSet<dim>                 &contact,
    const std::vector<double>             &z,
    const std::vector<Tensor<1, dim - 1>> &y)
  {
    const Tensor<1, dim>                &n = contact.normal;
    FullMatrix<double>                   local_matrix(dim, dim);
    std::vector<types::global_dof_index> local_dofs(dim);
    newton_matrix.copy_from(system.stiffness);
    for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
      {
        const double m_r = contact.nodes[s].weight * system.r;
        local_matrix     = 0;
        // normal part, where z >= 0 (at z = 0 the generalised derivative may
        // take either branch; the active one spares a free fall)
        if (z[s] >= 0.)
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              local_matrix(a, b) += m_r * n[a] * n[b];
        // tangential part: T D(y) T^T, column by column
        if (contact.friction)
          for (unsigned int b = 0; b < dim; ++b)
            {
              // e_b in the tangent basis, and D(y) applied to it
              Tensor<1, dim - 1> eb;
              for (unsigned int k = 0; k < dim - 1; ++k)
                eb[k] = contact.tangents[k][b];
              const double       g    = contact.threshold[s];
              const double       norm = y[s].norm();
              Tensor<1, dim - 1> Deb;
              if (norm < g)
                Deb = eb;
              else if (norm > 0.)
                {
                  const Tensor<1, dim - 1> yhat = y[s] / norm;
                  Deb = g / norm * (eb - (eb * yhat) * yhat);
                }
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int k = 0; k < dim - 1; ++k)
                  local_matrix(a, b) += m_r * contact.tangents[k][a] * Deb[k];
            }
        if (local_matrix.frobenius_norm() == 0.)
          continue;
        for (unsigned int a = 0; a < dim; ++a)
          local_dofs[a] = contact.nodes[s].dofs[a];
        system.homogeneous_constraints.distribute_local_to_global(
          local_matrix, local_dofs, newton_matrix);
      }
    newton_matrix.compress(VectorOperation::add);
  }

  template <int dim>
  double
  UzawaSolver<dim>::time_reference_solve(const ContactSystem   &system,
                                         const ContactSet<dim> &contact,
                                         const TrilinosWrappers::MPI::Vector &v,
                                         unsigned int &iterations)
  {
    std::vector<double>             z;
    std::vector<Tensor<1, dim - 1>> y;
    nodal_state(contact, v, system.r, z, y);
    assemble_newton_matrix(system, contact, z, y);

    Timer timer(v.get_mpi_communicator(), true);
    linear_solver.initialize(newton_matrix);
    TrilinosWrappers::MPI::Vector x(system.load);
    x          = 0;
    iterations = linear_solver.solve(newton_matrix, x, system.load);
    timer.stop();
    amg_valid = false; // the preconditioner now belongs to another matrix
    return timer.wall_time();
  }

  template <int dim>
  ContactStatistics
  UzawaSolver<dim>::solve(const ContactSystem           &system,
                          ContactSet<dim>               &contact,
                          TrilinosWrappers::MPI::Vector &v,
                          std::vector<IterationRecord>  &log,
                          const bool                     update_threshold,
                          const double                   threshold_tolerance)
  {
    const MPI_Comm comm      = v.get_mpi_communicator();
    const double   tolerance = parameters.uzawa_tolerance;
    const double   final_inner_tolerance =
      parameters.newton_tolerance_factor * tolerance;

    ContactStatistics statistics;
    amg_valid         = false; // a new system: build the preconditioner afresh
    roundoff_reported = false;
    roundoff_floor    = 0.;

    TrilinosWrappers::MPI::Vector   v_previous(v);
    std::vector<double>             z;
    std::vector<Tensor<1, dim - 1>> y;
    double                          previous_change = 0.;

    for (unsigned int k = 1; k <= parameters.max_uzawa_steps; ++k)
      {
        Timer timer(comm, true);
        v_previous = v;

        // Loop 3's tolerance shrinks geometrically (an envelope that keeps
        // the errors summable, as the convergence theorem needs); minimise()
        // also stops once the gradient fell by the inner tolerance factor,
        // never before the final tolerance.
        const double inner_tolerance =
          std::max(final_inner_tolerance,
                   parameters.initial_inner_tolerance *
                     std::pow(parameters.inner_tolerance_reduction, k - 1.));
        IterationRecord record;
        record.loop       = "uzawa";
        record.uzawa_step = k;
        minimise(system,
                 contact,
                 v_previous,
                 v,
                 inner_tolerance,
                 final_inner_tolerance,
                 k,
                 record,
                 log);

        // Multiplier updates l1 <- (l1 + r (v_n - g0))^+ and
        // l2 <- proj_[-g,g](l2 + r v_t), with merged loop 1 also g <- F l1,
        // and the measures of convergence, all reduced over the ranks.
        nodal_state(contact, v, system.r, z, y);
        // sums: |dl1|^2, |l1|^2, |dl2|^2, |l2|^2, |dg|^2, |g|^2
        double                  sums[6] = {0, 0, 0, 0, 0, 0};
        double                  l1_max = 0, violation = 0, complementarity = 0;
        types::global_dof_index counts[3] = {0, 0, 0}; // active, stick, slip
        for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
          {
            const double l1_new = positive_part(z[s]);
            const double gap =
              contact.nodes[s].gap0 - contact.normal_displacement(v, s);
            sums[0] += std::pow(l1_new - contact.l1[s], 2);
            sums[1] += l1_new * l1_new;
            l1_max          = std::max(l1_max, l1_new);
            violation       = std::max(violation, positive_part(-gap));
            complementarity = std::max(complementarity, l1_new * std::abs(gap));
            counts[0] += (l1_new > 0.);
            contact.l1[s] = l1_new;
            if (contact.friction)
              {
                // merged loop 1: g = F l1 first, so that |l2| <= g holds
                if (update_threshold)
                  {
                    const double g_new = contact.coefficient[s] * l1_new;
                    sums[4] += std::pow(g_new - contact.threshold[s], 2);
                    sums[5] += g_new * g_new;
                    contact.threshold[s] = g_new;
                  }
                const Tensor<1, dim - 1> l2_new =
                  project(y[s], contact.threshold[s]);
                sums[2] += (l2_new - contact.l2[s]).norm_square();
                sums[3] += l2_new.norm_square();
                contact.l2[s] = l2_new;
                if (l1_new > 0.)
                  ++counts[y[s].norm() < contact.threshold[s] ? 1 : 2];
              }
          }
        Utilities::MPI::sum(ArrayView<const double>(sums, 6),
                            comm,
                            ArrayView<double>(sums, 6));
        Utilities::MPI::sum(ArrayView<const types::global_dof_index>(counts, 3),
                            comm,
                            ArrayView<types::global_dof_index>(counts, 3));
        l1_max          = Utilities::MPI::max(l1_max, comm);
        violation       = Utilities::MPI::max(violation, comm);
        complementarity = Utilities::MPI::max(complementarity, comm);
        const types::global_dof_index n_active   = counts[0];
        const double                  l1_change2 = sums[0], l1_norm2 = sums[1];
        record.change_l2 = relative(std::sqrt(sums[2]), std::sqrt(sums[3]));
        record.change_g  = relative(std::sqrt(sums[4]), std::sqrt(sums[5]));
        record.n_stick   = counts[1];
        record.n_slip    = counts[2];

        const double v_norm_inf = v.linfty_norm();
        v_previous.sadd(-1., 1., v); // now v - v_previous
        record.change_l1 = relative(std::sqrt(l1_change2), std::sqrt(l1_norm2));
        record.change_v  = relative(v_previous.l2_norm(), v.l2_norm());
        record.violation = relative(violation, v_norm_inf);
        record.complementarity = relative(complementarity, l1_max * v_norm_inf);
        record.n_active        = n_active;
        timer.stop();
        record.time = timer.wall_time();
        log.push_back(record);

        statistics.uzawa_steps = k;
        statistics.newton_steps += record.newton_steps;
        statistics.cg_iterations += record.cg_iterations;
        statistics.amg_setups += record.amg_setups;
        statistics.n_active = n_active;
        statistics.n_stick  = record.n_stick;
        statistics.n_slip   = record.n_slip;
        statistics.change_g = record.change_g;

        std::ostringstream line;
        line << "   Uzawa " << std::setw(4) << k << ": Newton " << std::setw(2)
             << record.newton_steps << ", CG " << std::setw(4)
             << record.cg_iterations << ", active " << std::setw(6) << n_active
             << std::scientific << std::setprecision(2) << ", d(l1) "
             << record.change_l1 << ", d(v) " << record.change_v
             << ", violation " << record.violation << ", compl. "
             << record.complementarity;
        if (contact.friction)
          line << ", d(l2) " << record.change_l2 << ", stick/slip "
               << record.n_stick << "/" << record.n_slip;
        if (update_threshold)
          line << ", d(g) " << record.change_g;
        if (print_timing)
          line << std::fixed << std::setprecision(3) << "  (" << record.time
               << " s)";
        pcout << line.str() << std::endl;

        if (k > 1 && previous_change > 0.)
          statistics.rate = std::min(record.change_l1 / previous_change, 0.999);
        statistics.estimated_l1_error =
          record.change_l1 * statistics.rate / (1. - statistics.rate);
        previous_change = record.change_l1;

        if (record.change_l1 <= tolerance && record.change_v <= tolerance &&
            record.violation <= tolerance &&
            (!contact.friction || record.change_l2 <= tolerance) &&
            (!update_threshold || record.change_g <= threshold_tolerance))
          return statistics;
      }

    AssertThrow(false,
                ExcMessage("The Uzawa method did not converge in " +
                           std::to_string(parameters.max_uzawa_steps) +
                           " steps (<Solver/Maximum Uzawa steps>). Raise the "
                           "limit or <Solver/Augmentation parameter>, or check "
                           "that the foundation can hold the load."));
    return statistics;
  }

  template <int dim>
  void
  UzawaSolver<dim>::minimise(const ContactSystem                 &system,
                             const ContactSet<dim>               &contact,
                             const TrilinosWrappers::MPI::Vector &v_previous,
                             TrilinosWrappers::MPI::Vector       &v,
                             const double                         envelope,
                             const double                  final_tolerance,
                             const unsigned int            uzawa_step,
                             IterationRecord              &step_record,
                             std::vector<IterationRecord> &log)
  {
    const MPI_Comm comm        = v.get_mpi_communicator();
    const auto    &K           = system.stiffness;
    const auto    &constraints = system.homogeneous_constraints;
    const double   r           = system.r;
    const unsigned n_nodes     = contact.n_local_nodes();
    const double   load_norm   = system.load.l2_norm();
    const double   reference   = load_norm > 0. ? load_norm : 1.;

    // The smooth part's gradient is K v - rhs with rhs = b + chi M v^k.
    TrilinosWrappers::MPI::Vector rhs(system.load), tmp(system.load);
    system.mass.vmult(tmp, v_previous);
    rhs.add(system.chi, tmp);

    TrilinosWrappers::MPI::Vector smooth_gradient(rhs), gradient(rhs),
      direction(rhs), direction_free(rhs), newton_rhs(rhs);
    std::vector<double>                  z, dn(n_nodes);
    std::vector<Tensor<1, dim - 1>>      y, dt(n_nodes);
    std::vector<unsigned char>           status(n_nodes);
    Vector<double>                       local_vector(dim);
    std::vector<types::global_dof_index> local_dofs(dim);
    const Tensor<1, dim>                &n = contact.normal;

    double target = 0.; // absolute gradient tolerance of this Uzawa step
    // for the round-off test: the previous step's statuses, step length
    // and gradient, and how many steps in a row have stalled
    std::vector<unsigned char> previous_status(n_nodes);
    double                     previous_alpha = 0., previous_gradient = 0.;
    unsigned int               stalled = 0;
    for (unsigned int j = 0;; ++j)
      {
        Timer timer(comm, true);
        // gradient of M_k (constrained rows are zero: they are not unknowns)
        nodal_state(contact, v, r, z, y);
        K.vmult(smooth_gradient, v);
        smooth_gradient -= rhs;
        constraints.set_zero(smooth_gradient);
        gradient = smooth_gradient;
        // contact terms m_s ((z_s)^+ n + T proj_g(y_s))
        for (unsigned int s = 0; s < n_nodes; ++s)
          {
            const double   m     = contact.nodes[s].weight;
            Tensor<1, dim> force = (m * positive_part(z[s])) * n;
            if (contact.friction)
              {
                const Tensor<1, dim - 1> q =
                  project(y[s], contact.threshold[s]);
                for (unsigned int k = 0; k < dim - 1; ++k)
                  force += (m * q[k]) * contact.tangents[k];
              }
            if (force.norm() == 0.)
              continue;
            for (unsigned int c = 0; c < dim; ++c)
              {
                local_vector(c) = force[c];
                local_dofs[c]   = contact.nodes[s].dofs[c];
              }
            constraints.distribute_local_to_global(local_vector,
                                                   local_dofs,
                                                   gradient);
          }
        gradient.compress(VectorOperation::add);

        IterationRecord record;
        record.loop       = "newton";
        record.uzawa_step = uzawa_step;
        record.index      = j;
        record.gradient   = gradient.l2_norm() / reference;

        // Status of each node (separated, stick, slip) as the generalised
        // Hessian sees it.
        types::global_dof_index n_active = 0;
        for (unsigned int s = 0; s < n_nodes; ++s)
          {
            status[s] = node_status(z[s],
                                    contact.friction,
                                    contact.friction &&
                                      y[s].norm() < contact.threshold[s]);
            n_active += (status[s] > 0);
          }
        record.n_active = Utilities::MPI::sum(n_active, comm);

        // Stop when the gradient is below the envelope and has fallen by the
        // inner tolerance factor within this Uzawa step (each step is then
        // solved as accurately as the Uzawa iteration can use, and no more),
        // or when it is below the final tolerance.
        const double gradient_norm = gradient.l2_norm();
        if (j == 0)
          target = std::max(
            {final_tolerance * reference,
             std::min(envelope * reference,
                      parameters.inner_tolerance_factor * gradient_norm),
             1.5 * roundoff_floor * reference});
        // With the node statuses fixed M_k is quadratic, and a full Newton
        // step ends at its minimiser up to the CG tolerance. If full steps
        // at unchanged statuses stop reducing the gradient, it has reached
        // the round-off floor of K (which rises with lambda/mu, i.e. as nu
        // -> 1/2): accept that floor when it is within 10^3 of the target.
        bool unchanged = j > 0;
        for (unsigned int s = 0; unchanged && s < n_nodes; ++s)
          unchanged = status[s] == previous_status[s];
        unchanged           = Utilities::MPI::min(unchanged ? 1 : 0, comm) == 1;
        stalled             = (unchanged && previous_alpha == 1. &&
                   gradient_norm > 0.5 * previous_gradient) ?
                                stalled + 1 :
                                0;
        const bool at_floor = stalled >= 3 && gradient_norm <= 1e3 * target;
        if (at_floor)
          roundoff_floor = std::max(roundoff_floor, gradient_norm / reference);
        if (at_floor && !roundoff_reported)
          {
            pcout << "   Newton: the gradient stagnates at "
                  << format_number(gradient_norm / reference)
                  << " |b| (round-off of this matrix) above the target "
                  << format_number(target / reference)
                  << " |b|; accepted, and the later Uzawa steps of this "
                     "solve stop there at once"
                  << std::endl;
            roundoff_reported = true;
          }
        if (gradient_norm <= target || at_floor)
          {
            timer.stop();
            record.time = timer.wall_time();
            log.push_back(record);
            break;
          }
        previous_status   = status;
        previous_gradient = gradient_norm;
        AssertThrow(j < parameters.max_newton_steps,
                    ExcMessage(
                      "Newton's method (loop 3) did not converge in " +
                      std::to_string(parameters.max_newton_steps) +
                      " steps in Uzawa step " + std::to_string(uzawa_step) +
                      " (relative gradient " + format_number(record.gradient) +
                      ", wanted " + format_number(target / reference) +
                      "). Raise <Solver/Maximum Newton steps>."));

        // Generalised Hessian H = K + contact terms.
        assemble_newton_matrix(system, contact, z, y);

        // Rebuild the AMG only when the node statuses moved enough, measured
        // against the size of the active set (the part of H that changes).
        types::global_dof_index n_changed = 0, n_active_built = 0;
        if (amg_valid)
          for (unsigned int s = 0; s < n_nodes; ++s)
            {
              n_changed += (status[s] != amg_status[s]);
              n_active_built += (amg_status[s] > 0);
            }
        n_changed      = Utilities::MPI::sum(n_changed, comm);
        n_active_built = Utilities::MPI::sum(n_active_built, comm);
        // ... or when the last CG solve needed clearly more iterations than
        // the first one after the set-up (a set-up costs about 20 of them).
        const bool rebuild =
          !amg_valid || parameters.amg_rebuild_fraction == 0. ||
          n_changed > parameters.amg_rebuild_fraction *
                        std::max(n_active_built, record.n_active) ||
          last_cg_iterations > 1.5 * cg_iterations_after_setup + 10;
        if (rebuild)
          {
            linear_solver.initialize(newton_matrix);
            amg_status        = status;
            amg_valid         = true;
            record.amg_setups = 1;
          }

        // Inexact Newton: solve only as accurately as the target needs.
        const double forcing =
          std::min(0.1, std::max(1e-12, 0.5 * target / gradient_norm));
        newton_rhs.equ(-1., gradient);
        direction = 0;
        record.cg_iterations =
          linear_solver.solve(newton_matrix, direction, newton_rhs, forcing);
        last_cg_iterations = record.cg_iterations;
        if (record.amg_setups > 0)
          cg_iterations_after_setup = record.cg_iterations;
        constraints.distribute(direction);

        // Line search on M_k along the direction. The smooth part is
        // exactly quadratic and each contact term a 1D piecewise quadratic,
        // so phi(a) = M_k(v + a d) is a convex piecewise quadratic with
        //   phi'(a) = q1 + a q2 + sum_s m_s (z_s + a r dn_s)^+ dn_s,
        // and its minimiser is found exactly (DESIGN.md §2: the line search
        // makes Newton globally convergent; an exact one also lets a step
        // that meets many new contact nodes go as far as it should).
        direction_free = direction;
        constraints.set_zero(direction_free);
        K.vmult(tmp, direction_free);
        const double q2 = direction_free * tmp;
        const double q1 = smooth_gradient * direction;
        for (unsigned int s = 0; s < n_nodes; ++s)
          {
            dn[s] = contact.normal_displacement(direction, s);
            if (contact.friction)
              dt[s] = contact.tangential_displacement(direction, s);
          }
        // phi'(a) and phi''(a) (the latter from the right), summed over ranks
        const auto derivatives = [&](const double alpha) {
          double local[2] = {0., 0.};
          for (unsigned int s = 0; s < n_nodes; ++s)
            {
              const double m  = contact.nodes[s].weight;
              const double zs = z[s] + alpha * r * dn[s];
              if (zs > 0. || (zs == 0. && dn[s] > 0.))
                {
                  local[0] += m * zs * dn[s];
                  local[1] += m * r * dn[s] * dn[s];
                }
              if (contact.friction)
                {
                  const Tensor<1, dim - 1> ys = y[s] + alpha * r * dt[s];
                  const double             g  = contact.threshold[s];
                  local[0] += m * (project(ys, g) * dt[s]);
                  local[1] += m * r * huber_curvature(ys, g, dt[s]);
                }
            }
          double global[2];
          Utilities::MPI::sum(ArrayView<const double>(local, 2),
                              comm,
                              ArrayView<double>(global, 2));
          return std::make_pair(q1 + alpha * q2 + global[0], q2 + global[1]);
        };
        // phi(a) - phi(0), for the sufficient-decrease test of the full step
        const auto merit_change = [&](const double alpha) {
          double local = 0;
          for (unsigned int s = 0; s < n_nodes; ++s)
            {
              const double m = contact.nodes[s].weight;
              local += m / (2. * r) *
                       (std::pow(positive_part(z[s] + alpha * r * dn[s]), 2) -
                        std::pow(positive_part(z[s]), 2));
              if (contact.friction)
                local += m / r *
                         (huber(Tensor<1, dim - 1>(y[s] + alpha * r * dt[s]),
                                contact.threshold[s]) -
                          huber(y[s], contact.threshold[s]));
            }
          return alpha * q1 + 0.5 * alpha * alpha * q2 +
                 Utilities::MPI::sum(local, comm);
        };
        double alpha = 1.;
        // The full step is taken when it decreases M_k enough (Armijo);
        // otherwise the exact minimiser along the direction.
        if (parameters.line_search &&
            merit_change(1.) > 1e-4 * derivatives(0.).first)
          {
            // phi' is increasing, negative at 0: bracket its root, then
            // Newton steps on phi' kept inside the bracket (bisection when
            // they leave it); phi' is piecewise linear, so this ends in a few
            // steps.
            double lower = 0., upper = 1.;
            while (derivatives(upper).first < 0. && upper < 1e6)
              {
                lower = upper;
                upper *= 4.;
              }
            alpha = upper;
            for (unsigned int it = 0; it < 50; ++it)
              {
                const auto [d1, d2] = derivatives(alpha);
                if (std::abs(d1) <= 1e-12 * std::abs(q1) ||
                    upper - lower <= 1e-12 * upper)
                  break;
                (d1 > 0. ? upper : lower) = alpha;
                const double next         = alpha - d1 / d2;
                alpha =
                  (next > lower && next < upper) ? next : 0.5 * (lower + upper);
              }
          }
        v.add(alpha, direction);
        record.step_length = alpha;
        previous_alpha     = alpha;

        timer.stop();
        record.time = timer.wall_time();
        log.push_back(record);
        step_record.newton_steps += 1;
        step_record.cg_iterations += record.cg_iterations;
        step_record.amg_setups += record.amg_setups;
      }
  }

  template class UzawaSolver<2>;
  template class UzawaSolver<3>;
} // namespace dualcontact
