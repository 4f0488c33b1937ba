/* step-2: one semi-smooth Newton iteration, written out.
 *
 * step-1 wrote the Uzawa iteration and left each proximal step, the
 * minimisation of M_k(v) for fixed multipliers, to the library's Newton
 * solver. This program writes that minimisation itself, for the
 * frictionless Hertz scene of step-1: the gradient G(v) of M_k node by node,
 * the generalised Hessian H(v) (the system matrix with the contact terms of
 * the active nodes added), the Newton direction from H d = -G by CG with
 * algebraic multigrid, and the line search along d (the full step if it
 * passes Armijo's sufficient-decrease test, else the minimiser along d).
 * At every iterate it compares with the library's NewtonSolver, run on the
 * same system from the same start: gradient norms, active counts, step
 * lengths and iterates must agree to round-off (doc/theory.md §3.3).
 *
 * The README has the derivation, the results and tasks for the reader.
 */

// @sect3{Include files}
//
// The library brings the mesh, the matrices K = A + chi M, M, the load b and
// the contact nodes (ContactProblem), the CG + AMG solver (ElasticSolver) and
// the Newton iteration we compare with (NewtonSolver, observed through an
// IterationObserver).
#include <deal.II/base/array_view.h>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <dualcontact/contact_functions.h>
#include <dualcontact/contact_problem.h>
#include <dualcontact/input_error.h>
#include <dualcontact/newton_solver.h>
#include <dualcontact/parameters.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "../common/tutorial_tools.h"

namespace Step2
{
  using namespace dealii;
  using namespace dualcontact;

  using tutorial::format;

  // The agreement asked of the two Newton iterations (relative): gradient
  // norms against the force scale, step lengths, iterates against |v|.
  constexpr double agreement = 1e-10;

  // The Newton tolerance of both: |G| <= tolerance x the force scale.
  constexpr double newton_tolerance = 1e-10;

  // @sect3{One Newton iterate}
  //
  // What either iteration records at its iterate j: |G(v_j)| relative to the
  // force scale, the active nodes (z_s >= 0), the step length alpha_j of the
  // step taken from there (0 at the last iterate), and v_{j+1} (v_j at the
  // last).
  struct Iterate
  {
    double                        gradient    = 0.;
    types::global_dof_index       n_active    = 0;
    double                        step_length = 0.;
    TrilinosWrappers::MPI::Vector v;
  };

  // @sect3{The proximal step}
  //
  // The data of one proximal step k (README, "The functional"):
  //
  //   M_k(v) = 1/2 v^T K v - v^T (b + chi M v^k)
  //            + sum_s m_s/(2r) ((z_s)^+)^2,   z_s = l1_s + r (v_n(s) - g0_s),
  //
  // with K = A + chi M. `rhs` holds b + chi M v^k; `reference` is the force
  // scale the gradient is measured against: |b| while there is no pressure,
  // then the smaller of |b| and the contact forces (sum_s (m_s l1_s)^2)^1/2,
  // which set how far a leftover gradient moves the next multipliers
  // (doc/theory.md §6). The library measures it the same way.
  template <int dim>
  struct ProximalStep
  {
    const ContactSystem          &system;
    const ContactSet<dim>        &contact;
    TrilinosWrappers::MPI::Vector rhs;
    double                        reference = 0.;

    ProximalStep(const ContactSystem                 &system,
                 const ContactSet<dim>               &contact,
                 const TrilinosWrappers::MPI::Vector &v_previous)
        : system(system)
        , contact(contact)
        , rhs(system.load)
    {
      TrilinosWrappers::MPI::Vector Mv(system.load);
      system.mass.vmult(Mv, v_previous);
      rhs.add(system.proximal_weight(), Mv);

      const MPI_Comm comm   = rhs.get_mpi_communicator();
      double         forces = 0.;
      for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
        forces += std::pow(contact.nodes[s].weight, 2) *
                  (contact.l1[s] * contact.l1[s]);
      forces         = std::sqrt(Utilities::MPI::sum(forces, comm));
      const double b = system.load.l2_norm();
      reference      = forces > 0. ? std::min(b, forces) : b;
    }

    // z_s = l1_s + r (v_n(s) - g0_s) at this rank's contact nodes: the
    // argument of the positive part, the pressure the node would feel.
    std::vector<double>
    augmented_pressure(const TrilinosWrappers::MPI::Vector &v) const
    {
      std::vector<double> z(contact.n_local_nodes());
      for (unsigned int s = 0; s < z.size(); ++s)
        z[s] = contact.l1[s] + system.r * (contact.normal_displacement(v, s) -
                                           contact.nodes[s].gap0);
      return z;
    }
  };

  // @sect3{The gradient}
  //
  //   G(v) = K v - b - chi M v^k + sum_s m_s (z_s)^+ N_s,
  //
  // N_s the vector that picks v_n(s) = N_s^T v out of v: n at the d DoFs of
  // node s. The smooth part K v - rhs comes from the matrix; its entries at
  // constrained DoFs (hanging nodes) are set to zero: the condensed
  // problem has no equation there. The contact part is assembled node by
  // node over this rank's contact nodes, through the constraints like any
  // local vector. `smooth` keeps the first part: the line search needs it.
  template <int dim>
  void
  compute_gradient(const ProximalStep<dim>             &step,
                   const std::vector<double>           &z,
                   const TrilinosWrappers::MPI::Vector &v,
                   TrilinosWrappers::MPI::Vector       &smooth,
                   TrilinosWrappers::MPI::Vector       &gradient)
  {
    const AffineConstraints<double> &constraints =
      step.system.homogeneous_constraints;
    step.system.stiffness.vmult(smooth, v);
    smooth -= step.rhs;
    constraints.set_zero(smooth);
    gradient = smooth;

    Vector<double>                       force(dim);
    std::vector<types::global_dof_index> dofs(dim);
    for (unsigned int s = 0; s < step.contact.n_local_nodes(); ++s)
      {
        if (!(z[s] > 0.)) // (z_s)^+ = 0: the node feels nothing
          continue;
        const ContactNode<dim> &node = step.contact.nodes[s];
        for (unsigned int c = 0; c < dim; ++c)
          {
            force(c) = node.weight * z[s] * node.normal[c];
            dofs[c]  = node.dofs[c];
          }
        constraints.distribute_local_to_global(force, dofs, gradient);
      }
    gradient.compress(VectorOperation::add);
  }

  // @sect3{The generalised Hessian}
  //
  //   H(v) = K + r sum_{s: z_s >= 0} m_s N_s N_s^T.
  //
  // The derivative of (z_s)^+ jumps from 0 to 1 at z_s = 0; there either
  // value is a generalised derivative, and the active one (z_s >= 0) is
  // taken: a node at zero gap then holds the body in the first step (step-1,
  // README). H is a copy of K, with the same sparsity pattern, to which the
  // d x d block m_s r n n^T of each active node is added: its rows and
  // columns are the node's own DoFs, which this rank owns. (The library
  // adds the same terms to K in place and takes them off after the solve,
  // to hold one matrix only.) The scene's contact nodes carry no
  // constraint: the program checks that, so the block goes in as it is.
  template <int dim>
  types::global_dof_index
  assemble_hessian(const ProximalStep<dim>        &step,
                   const std::vector<double>      &z,
                   TrilinosWrappers::SparseMatrix &H)
  {
    H.copy_from(step.system.stiffness);
    types::global_dof_index n_active = 0;
    for (unsigned int s = 0; s < step.contact.n_local_nodes(); ++s)
      {
        if (!(z[s] >= 0.))
          continue;
        ++n_active;
        const ContactNode<dim> &node = step.contact.nodes[s];
        const double            m_r  = node.weight * step.system.r;
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            if (m_r * node.normal[a] * node.normal[b] != 0.)
              H.add(node.dofs[a],
                    node.dofs[b],
                    m_r * node.normal[a] * node.normal[b]);
      }
    H.compress(VectorOperation::add);
    return Utilities::MPI::sum(n_active, step.rhs.get_mpi_communicator());
  }

  // @sect3{The line search}
  //
  // Along d, phi(alpha) = M_k(v + alpha d) is convex and piecewise
  // quadratic:
  //
  //   phi'(alpha) = q1 + alpha q2 + sum_s m_s (z_s + alpha r dn_s)^+ dn_s,
  //   q1 = (K v - b - chi M v^k) . d,  q2 = d^T K d,  dn_s = N_s^T d.
  //
  // phi' is continuous, non-decreasing and linear between the breakpoints
  // alpha_s = -z_s / (r dn_s) > 0 where a node enters or leaves contact. The
  // minimiser is the root of phi'. The search is not exact: first the full
  // step alpha = 1 if it decreases M_k enough (phi(1) - phi(0) <= 1e-4
  // phi'(0), Armijo's sufficient-decrease test: near the solution Newton's
  // step is right and needs no search), whether or not 1 is the minimiser;
  // only if that fails, the minimiser: the breakpoints of all ranks, sorted;
  // the first breakpoint where phi' >= 0, found by bisection over the list (one
  // reduction per evaluation); and on the piece to its left, where phi' is
  // linear, its root
  //   alpha = alpha_lo - phi'(alpha_lo) / phi''
  // with phi'' = q2 + r sum_{active on the piece} m_s dn_s^2, evaluated in the
  // middle of the piece, where no node is at its breakpoint.
  template <int dim>
  double
  line_search(const ProximalStep<dim>             &step,
              const std::vector<double>           &z,
              const TrilinosWrappers::MPI::Vector &smooth_gradient,
              const TrilinosWrappers::MPI::Vector &d)
  {
    const MPI_Comm     comm = d.get_mpi_communicator();
    const double       r    = step.system.r;
    const unsigned int n    = step.contact.n_local_nodes();

    // q2 = d^T K d on the free DoFs (K is condensed: a constrained DoF's row
    // and column hold only a diagonal entry, which is no energy)
    TrilinosWrappers::MPI::Vector free_d(d), Kd(d);
    step.system.homogeneous_constraints.set_zero(free_d);
    step.system.stiffness.vmult(Kd, free_d);
    const double        q2 = free_d * Kd;
    const double        q1 = smooth_gradient * d;
    std::vector<double> dn(n);
    for (unsigned int s = 0; s < n; ++s)
      dn[s] = step.contact.normal_displacement(d, s);

    // phi'(alpha) and phi''(alpha), summed over the ranks
    const auto derivatives = [&](const double alpha) {
      double local[2] = {0., 0.};
      for (unsigned int s = 0; s < n; ++s)
        {
          const double zs = z[s] + alpha * r * dn[s];
          if (zs > 0.)
            {
              local[0] += step.contact.nodes[s].weight * zs * dn[s];
              local[1] += step.contact.nodes[s].weight * r * dn[s] * dn[s];
            }
        }
      Utilities::MPI::sum(ArrayView<const double>(local, 2),
                          comm,
                          ArrayView<double>(local, 2));
      return std::make_pair(q1 + alpha * q2 + local[0], q2 + local[1]);
    };

    // The full step: phi(1) - phi(0) = q1 + q2/2 + the change of the
    // contact terms sum_s m_s/(2r) (((z_s + r dn_s)^+)^2 - ((z_s)^+)^2).
    double contact_change = 0., slope = 0.;
    for (unsigned int s = 0; s < n; ++s)
      {
        const double m = step.contact.nodes[s].weight;
        contact_change += m / (2. * r) *
                          (std::pow(positive_part(z[s] + r * dn[s]), 2) -
                           std::pow(positive_part(z[s]), 2));
        slope += m * positive_part(z[s]) * dn[s];
      }
    contact_change = Utilities::MPI::sum(contact_change, comm);
    slope          = q1 + Utilities::MPI::sum(slope, comm); // phi'(0) < 0
    if (q1 + 0.5 * q2 + contact_change <= 1e-4 * slope)
      return 1.;

    // The breakpoints of all ranks ahead of alpha = 0, sorted.
    std::vector<double> local_breakpoints;
    for (unsigned int s = 0; s < n; ++s)
      if (dn[s] != 0. && -z[s] / (r * dn[s]) > 0.)
        local_breakpoints.push_back(-z[s] / (r * dn[s]));
    std::vector<double> breakpoints;
    for (const std::vector<double> &part :
         Utilities::MPI::all_gather(comm, local_breakpoints))
      breakpoints.insert(breakpoints.end(), part.begin(), part.end());
    std::sort(breakpoints.begin(), breakpoints.end());

    // The first breakpoint with phi' >= 0 (breakpoints.size() if none):
    // phi' is non-decreasing, so bisection over the list finds it.
    std::size_t lower = 0, upper = breakpoints.size();
    while (lower < upper)
      {
        const std::size_t middle = (lower + upper) / 2;
        if (derivatives(breakpoints[middle]).first >= 0.)
          upper = middle;
        else
          lower = middle + 1;
      }
    // The root lies on the piece [alpha_lo, alpha_hi] to its left.
    const double alpha_lo = lower == 0 ? 0. : breakpoints[lower - 1];
    const double alpha_hi =
      lower < breakpoints.size() ? breakpoints[lower] : alpha_lo + 1.;
    const double first  = derivatives(alpha_lo).first;
    const double second = derivatives(0.5 * (alpha_lo + alpha_hi)).second;
    return alpha_lo - first / second;
  }

  // @sect3{The Newton iteration, by hand}
  //
  // From v, until |G(v)| <= newton_tolerance x the force scale:
  //   1. z_s, G(v) and the active set {s: z_s >= 0};
  //   2. H d = -G by CG, preconditioned by AMG built for this H, to the
  //      relative residual min(0.1, max(1e-12, 0.5 target / |G|)) (inexact
  //      Newton: no more accuracy than the target needs; the library's
  //      choice);
  //   3. alpha by the line search (1 if Armijo accepts the full step,
  //      else the minimiser along d), v <- v + alpha d.
  // The CG + AMG solver is the library's ElasticSolver (smoothed aggregation
  // with the rigid-body modes as near-null space): the one a linear
  // elasticity solve of the problem uses.
  template <int dim>
  std::vector<Iterate>
  newton_by_hand(const ProximalStep<dim>       &step,
                 ElasticSolver<dim>            &linear_solver,
                 TrilinosWrappers::MPI::Vector &v,
                 const unsigned int             max_steps)
  {
    const double                  target = newton_tolerance * step.reference;
    TrilinosWrappers::MPI::Vector smooth(step.rhs), gradient(step.rhs),
      direction(step.rhs), minus_gradient(step.rhs);
    TrilinosWrappers::SparseMatrix H;
    std::vector<Iterate>           iterates;
    for (unsigned int j = 0;; ++j)
      {
        const std::vector<double> z = step.augmented_pressure(v);
        compute_gradient(step, z, v, smooth, gradient);
        const double gradient_norm = gradient.l2_norm();
        Iterate      iterate;
        iterate.gradient = gradient_norm / step.reference;
        iterate.n_active = assemble_hessian(step, z, H);
        if (gradient_norm <= target)
          {
            iterate.v = v;
            iterates.push_back(iterate);
            return iterates;
          }
        AssertThrow(j < max_steps,
                    ExcMessage("The Newton iteration by hand did not "
                               "converge in <Solver/Maximum Newton steps>."));

        const double forcing =
          std::min(0.1, std::max(1e-12, 0.5 * target / gradient_norm));
        minus_gradient.equ(-1., gradient);
        direction = 0;
        linear_solver.initialize(H);
        linear_solver.solve(H, direction, minus_gradient, forcing);
        // the hanging DoFs follow their masters
        step.system.homogeneous_constraints.distribute(direction);

        iterate.step_length = line_search(step, z, smooth, direction);
        v.add(iterate.step_length, direction);
        iterate.v = v;
        iterates.push_back(iterate);
      }
  }

  // @sect3{The library's Newton iteration, observed}
  //
  // NewtonSolver::minimise reports each Newton step to an observer, after
  // the step is taken: |G|/(force scale) and the active count at the iterate
  // the step started from, and its step length. The observer also keeps a
  // reference to the v that minimise() works on, so that it can copy the
  // new iterate at each report.
  class Recorder : public IterationObserver
  {
  public:
    explicit Recorder(const TrilinosWrappers::MPI::Vector &v)
        : v(v)
    {}

    void
    newton_step(const IterationRecord &record) override
    {
      Iterate iterate;
      iterate.gradient    = record.gradient;
      iterate.n_active    = record.n_active;
      iterate.step_length = record.step_length;
      iterate.v           = v;
      iterates.push_back(iterate);
    }

    std::vector<Iterate> iterates;

  private:
    const TrilinosWrappers::MPI::Vector &v;
  };

  // @sect3{The comparison}
  //
  // The largest differences over the iterates, each relative: |G| against
  // the force scale (both are relative to it already), alpha against alpha,
  // v_hand - v_lib against |v_lib|. And whether the counts agree.
  struct Agreement
  {
    bool   same_steps  = true;
    bool   same_active = true;
    double gradient = 0., step_length = 0., iterate = 0., final_v = 0.;
    double time_hand = 0., time_library = 0.;
  };

  // @sect3{One proximal step, both ways}
  //
  // Solve the proximal step from `v` by hand and by the library, print one
  // row per Newton iterate (and write it to `csv`, for plot.gp), and return
  // the agreement. `v` gets the hand's minimiser.
  template <int dim>
  Agreement
  compare(const unsigned int                   k,
          const std::string                   &title,
          const ContactSystem                 &system,
          const ContactSet<dim>               &contact,
          const TrilinosWrappers::MPI::Vector &v_previous,
          TrilinosWrappers::MPI::Vector       &v,
          ElasticSolver<dim>                  &linear_solver,
          const SolverParameters              &solver_parameters,
          const bool                           timing,
          ConditionalOStream                  &pcout,
          std::ofstream                       &csv)
  {
    const MPI_Comm          comm = v.get_mpi_communicator();
    const ProximalStep<dim> step(system, contact, v_previous);
    Agreement               agreement;

    // By hand.
    TrilinosWrappers::MPI::Vector v_hand(v);
    Timer                         timer(comm, true);
    const std::vector<Iterate>    hand = newton_by_hand(
      step, linear_solver, v_hand, solver_parameters.max_newton_steps);
    timer.stop();
    agreement.time_hand = timer.wall_time();

    // The library, on the same system from the same v. The envelope and the
    // final tolerance are both newton_tolerance, so that it stops where the
    // hand does. Its AMG is rebuilt for every Newton matrix
    // (amg_rebuild_fraction = 0; by default it reuses one while the active
    // set hardly moves), so that both precondition CG alike.
    SolverParameters newton_parameters     = solver_parameters;
    newton_parameters.amg_rebuild_fraction = 0.;
    NewtonSolver<dim>             newton(newton_parameters, linear_solver);
    TrilinosWrappers::MPI::Vector v_library(v);
    Recorder                      library(v_library);
    timer.restart();
    newton.minimise(system,
                    contact,
                    v_previous,
                    v_library,
                    newton_tolerance,
                    newton_tolerance,
                    1,
                    &library);
    timer.stop();
    agreement.time_library = timer.wall_time();

    pcout << "\n"
          << title << ": force scale " << format("%.6g", step.reference)
          << ", Newton tolerance " << format("%.0e", newton_tolerance)
          << "\n   Newton  |G|/scale   active  step length  "
             "|v_hand - v_lib|/|v|\n";
    agreement.same_steps = hand.size() == library.iterates.size();
    for (unsigned int j = 0; j < std::min(hand.size(), library.iterates.size());
         ++j)
      {
        const Iterate                &h = hand[j], &l = library.iterates[j];
        TrilinosWrappers::MPI::Vector difference(h.v);
        difference -= l.v;
        const double v_difference = difference.l2_norm() / l.v.l2_norm();
        agreement.same_active &= h.n_active == l.n_active;
        agreement.gradient =
          std::max(agreement.gradient, std::abs(h.gradient - l.gradient));
        if (l.step_length > 0.)
          agreement.step_length =
            std::max(agreement.step_length,
                     std::abs(h.step_length / l.step_length - 1.));
        agreement.iterate = std::max(agreement.iterate, v_difference);
        if (j + 1 == hand.size())
          agreement.final_v = v_difference;
        pcout << format("   %6.0f", j) << format("  %9.3e", h.gradient)
              << format("  %7.0f", h.n_active)
              << (h.step_length > 0. ? format("  %11.6f", h.step_length) :
                                       std::string("  (converged)"))
              << format("  %10.1e", v_difference) << "\n";
        csv << k << ',' << j << ',' << h.gradient << ',' << l.gradient << ','
            << h.n_active << ',' << h.step_length << ',' << l.step_length << ','
            << v_difference << '\n';
      }
    pcout << "   Newton steps: by hand " << hand.size() - 1
          << (timing ? format(" (%.3f s)", agreement.time_hand) : "")
          << ", library " << library.iterates.size() - 1
          << (timing ? format(" (%.3f s)", agreement.time_library) : "")
          << "\n";
    v = v_hand;
    return agreement;
  }

  // @sect3{The whole step}
  //
  // The program in the shape of deal.II's steps: a class whose run() reads
  // as its stages, one member function each, and members for what a later
  // stage needs of an earlier one (the problem and its system, v, the
  // agreement of each proximal step).
  template <int dim>
  class ProximalStepByHand
  {
  public:
    explicit ProximalStepByHand(const Parameters &parameters);

    tutorial::Checks
    run();

  private:
    void
    set_up_system();
    void
    open_figure_file();
    void
    check_free_contact_dofs();
    void
    compare_proximal_step(const unsigned int k, const std::string &title);
    void
    update_multipliers();
    tutorial::Checks
    check_results() const;

    // The scene, the screen (rank 0 prints) and whether it shows times.
    const Parameters  &parameters;
    const MPI_Comm     comm;
    ConditionalOStream pcout;
    const bool         timing;

    // The library's problem, the system it set up (K, M, b, r, chi), v and
    // v^k, every Newton iterate's row for the figure (rank 0), and the
    // agreement of each proximal step.
    ContactProblem<dim>           problem;
    std::optional<ContactSystem>  system;
    TrilinosWrappers::MPI::Vector v, v_previous;
    std::ofstream                 csv;
    std::vector<Agreement>        agreements;
  };


  template <int dim>
  ProximalStepByHand<dim>::ProximalStepByHand(const Parameters &parameters)
      : parameters(parameters)
      , comm(MPI_COMM_WORLD)
      , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
      , timing(parameters.output.print_timing)
      , problem(parameters, comm, std::cout)
  {}


  // The library's phases up to the solve, as in step-1; then proximal step
  // k = 1 from v = 0 with l1 = 0, the multiplier update of step-1, and
  // proximal step k = 2 from there; then the checks.
  template <int dim>
  tutorial::Checks
  ProximalStepByHand<dim>::run()
  {
    set_up_system();
    open_figure_file();
    check_free_contact_dofs();
    // Proximal step 1: v^k = v = 0, l1 = 0.
    compare_proximal_step(1, "Proximal step 1 (from v = 0, l1 = 0)");
    update_multipliers();
    compare_proximal_step(2, "Proximal step 2 (from v^1, l1^1)");
    return check_results();
  }


  // The library's phases up to the solve, as in step-1: the mesh, the
  // degrees of freedom and contact nodes, the matrices, r and chi; v
  // starts from zero.
  template <int dim>
  void
  ProximalStepByHand<dim>::set_up_system()
  {
    problem.make_grid();
    problem.get_report().print_scene();
    const MeshRecord mesh = problem.setup_system(0);
    problem.transfer_fields();
    problem.assemble_system();
    const SolveRecord constants = problem.prepare_contact_solve();
    pcout << "Mesh: " << mesh.n_cells << " cells, " << mesh.n_dofs << " DoFs, "
          << constants.n_contact_nodes
          << " contact nodes; r = " << format("%.6g", constants.r)
          << ", chi = " << format("%.6g", constants.chi) << "\n";

    system.emplace(problem.contact_system());
    v          = problem.initial_displacement();
    v_previous = v;
  }


  // Every Newton iterate of both iterations, for the figure (rank 0).
  template <int dim>
  void
  ProximalStepByHand<dim>::open_figure_file()
  {
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::filesystem::create_directories(parameters.output.directory);
        csv.open(parameters.output.directory + "/newton.csv");
        csv << "proximal_step,newton_step,gradient_hand,gradient_library,"
               "active,step_length_hand,step_length_library,v_difference\n";
        csv.precision(10);
      }
  }


  // The contact terms go into H and G at the node's own DoFs: check that
  // none of them is constrained (true of every scene whose contact
  // boundary has no Dirichlet or slider part).
  template <int dim>
  void
  ProximalStepByHand<dim>::check_free_contact_dofs()
  {
    const ContactSet<dim> &contact    = problem.contact();
    bool                   free_nodes = true;
    for (const ContactNode<dim> &node : contact.nodes)
      for (const types::global_dof_index dof : node.dofs)
        free_nodes &= !system->homogeneous_constraints.is_constrained(dof);
    AssertThrow(Utilities::MPI::min(free_nodes ? 1 : 0, comm) == 1,
                ExcMessage("step-2 adds the contact terms at the nodes' own "
                           "DoFs: no contact DoF may be constrained."));
  }


  // Proximal step k from v^k = v_previous, by hand and by the library
  // (compare() above); v gets the hand's minimiser.
  template <int dim>
  void
  ProximalStepByHand<dim>::compare_proximal_step(const unsigned int k,
                                                 const std::string &title)
  {
    agreements.push_back(compare(k,
                                 title,
                                 *system,
                                 problem.contact(),
                                 v_previous,
                                 v,
                                 problem.linear_solver(),
                                 parameters.solver,
                                 timing,
                                 pcout,
                                 csv));
  }


  // The multiplier update of step-1: l1_s <- (l1_s + r (v_n(s) - g0_s))^+,
  // the pressure v^1 felt; then proximal step 2 from v^1 with it.
  template <int dim>
  void
  ProximalStepByHand<dim>::update_multipliers()
  {
    ContactSet<dim>        &contact   = problem.contact();
    types::global_dof_index n_pressed = 0;
    for (unsigned int s = 0; s < contact.n_local_nodes(); ++s)
      {
        contact.l1[s] =
          std::max(0.,
                   contact.l1[s] +
                     system->r * (contact.normal_displacement(v, s) -
                                  contact.nodes[s].gap0));
        n_pressed += (contact.l1[s] > 0.);
      }
    pcout << "\nMultiplier update: " << Utilities::MPI::sum(n_pressed, comm)
          << " nodes with l1 > 0\n";
    v_previous = v;
  }


  // @sect4{The checks}
  //
  // The two iterations do the same arithmetic in the same order except
  // the line search (a different algorithm for the same root), so every
  // figure must agree to round-off: `agreement` = 1e-10 relative, with
  // room for the line search's last digits. Each check prints a line;
  // main() ends with one message naming the failed ones and exit status 1.
  template <int dim>
  tutorial::Checks
  ProximalStepByHand<dim>::check_results() const
  {
    Agreement worst;
    for (const Agreement &a : agreements)
      {
        worst.same_steps &= a.same_steps;
        worst.same_active &= a.same_active;
        worst.gradient    = std::max(worst.gradient, a.gradient);
        worst.step_length = std::max(worst.step_length, a.step_length);
        worst.iterate     = std::max(worst.iterate, a.iterate);
        worst.final_v     = std::max(worst.final_v, a.final_v);
      }
    tutorial::Checks check;
    pcout << "\nChecks:\n";
    check(worst.same_steps && worst.same_active,
          "the same Newton steps and active counts at every iterate");
    check(worst.gradient <= agreement,
          "|G| agrees to 1e-10 of the force scale (largest difference " +
            format("%.1e", worst.gradient) + ")");
    check(worst.step_length <= agreement,
          "step lengths agree to 1e-10 (relative; largest " +
            format("%.1e", worst.step_length) + ")");
    check(worst.iterate <= agreement,
          "every iterate v agrees to 1e-10 (relative; largest " +
            format("%.1e", worst.iterate) + ", final v " +
            format("%.1e", worst.final_v) + ")");
    return check;
  }


  // The step as main() calls it: the program on the scene.
  template <int dim>
  tutorial::Checks
  run(const Parameters &parameters)
  {
    return ProximalStepByHand<dim>(parameters).run();
  }
} // namespace Step2

// @sect3{The main function}
//
// As in step-1: MPI, the parameter file (default step-2.prm) and `--set`
// overrides after it; one message and a non-zero exit status if anything
// goes wrong (tutorials/common/tutorial_tools.h). The hand-written Newton
// step is for the frictionless 2D scene.
int
main(int argc, char *argv[])
{
  using namespace dualcontact;
  return tutorial::run_tutorial(
    argc, argv, "step-2", "step-2.prm", [](Parameters &parameters) {
      tutorial::require(
        parameters.geometry.dimension == 2,
        "step-2 runs the 2D half disc: <Geometry/Dimension> must be 2.");
      tutorial::require(parameters.friction.law == "none",
                        "step-2 is frictionless: <Friction/Law> must be none.");
      return Step2::run<2>(parameters);
    });
}
