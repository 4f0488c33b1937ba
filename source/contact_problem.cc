#include <deal.II/base/utilities.h>

#include <deal.II/dofs/dof_accessor.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <dualcontact/contact_functions.h>
#include <dualcontact/contact_output.h>
#include <dualcontact/contact_problem.h>
#include <dualcontact/input_error.h>
#include <dualcontact/output_directory.h>
#include <dualcontact/plausibility.h>
#include <dualcontact/postprocess.h>
#include <dualcontact/refinement.h>
#include <dualcontact/refinement_indicator.h>
#include <dualcontact/run_size.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>

namespace dualcontact
{
  template <int dim>
  ContactProblem<dim>::ContactProblem(const Parameters &given_parameters,
                                      MPI_Comm          mpi_communicator,
                                      std::ostream     &out)
      : mpi_communicator(mpi_communicator)
      , pcout(out, Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      , parameters(given_parameters)
      // the scene reads the coarse mesh of a mesh file: its size is
      // checked against the memory before it is built, as in make_grid()
      , scene(parameters,
              [this](const double n_cells) {
                RunSizeCheck(parameters, this->mpi_communicator)
                  .check(n_cells, false);
              })
      , computing_timer(mpi_communicator,
                        pcout,
                        TimerOutput::never,
                        TimerOutput::wall_times)
      , report(parameters, scene, computing_timer, mpi_communicator, out)
      // Mesh smoothing: only the 2:1 balance at vertices, which p4est
      // enforces on the whole forest. deal.II's other smoothing flags act
      // on the refinement flags each rank sees, so they would make the
      // adaptive meshes depend on the number of ranks.
      , triangulation(mpi_communicator,
                      Triangulation<dim>::limit_level_difference_at_vertices)
      , mapping(1)
      , fe(FE_Q<dim>(1), dim)
      , dof_handler(triangulation)
      , elastic_solver(parameters.solver, parameters.material.poissons_ratio)
      , newton(parameters.solver, elastic_solver)
      , uzawa(parameters.solver, newton)
      , threshold_iteration(parameters.friction, uzawa)
      , probes(parameters.output.probe_points)
  {}

  // The algorithm: on each mesh of a nested sequence, set up, carry the
  // previous mesh's fields over, assemble, solve, measure, write; then
  // refine. Each phase times itself and returns its figures; the report
  // prints them and writes the tables.
  template <int dim>
  void
  ContactProblem<dim>::run()
  {
    // The output folder first: one that cannot be made is bad input, found
    // before the mesh is built. A run that fails before it wrote anything
    // removes it again.
    const OutputDirectory output(parameters.output.directory, mpi_communicator);
    try
      {
        make_grid(); // checks the input first: nothing is written before
        report.print_scene();

        for (unsigned int cycle = 0; cycle < parameters.refinement.n_cycles;
             ++cycle)
          {
            if (cycle > 0)
              refine_mesh();

            CycleResult result;
            result.mesh     = setup_system(cycle);
            result.transfer = transfer_fields();
            report.start_cycle(result.mesh, result.transfer);

            assemble_system();
            result.solve    = solve();
            result.position = check_position();
            if (scene.effects().contact)
              {
                result.zone = measure_contact_zone();
                result.cold = compare_with_cold_start();
              }
            result.errors    = postprocess();
            result.reactions = compute_reactions(result.zone);
            check_balance(result.reactions);

            output_results(cycle);
            report.end_cycle(result);
          }
        report.finish();
      }
    catch (...)
      {
        output.remove_if_unused();
        throw;
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::make_grid()
  {
    TimerOutput::Scope t(computing_timer, "make grid");
    // The size of the finest mesh is checked against the memory before
    // the coarse mesh is built (a box here, a mesh file's mesh in the
    // constructor), before each refinement that builds the initial mesh,
    // and once it is built: a scene refined far too often, or a box of far
    // too many cells, stops at once, not with std::bad_alloc after minutes.
    const RunSizeCheck size(parameters, mpi_communicator);
    scene.create_mesh(triangulation, [&size](const double n_cells) {
      size.check(n_cells, false);
    });
    size.check(triangulation.n_global_active_cells(), true);
    size.warn(triangulation.n_global_active_cells());
    scene.check_rigid_motions(triangulation);
    check_initial_position(triangulation, scene);
    // a probe outside the body is bad input: found before the first solve
    probes.check_inside(mapping, triangulation);
  }

  template <int dim>
  MeshFigures
  ContactProblem<dim>::setup_system(const unsigned int cycle)
  {
    TimerOutput::Scope t(computing_timer, "setup system");
    dof_handler.distribute_dofs(fe);
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);

    hanging_node_constraints.clear();
    hanging_node_constraints.reinit(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler,
                                            hanging_node_constraints);
    hanging_node_constraints.close();

    // Hanging nodes first, then Dirichlet, then sliders: later ones do not
    // overwrite earlier ones, which keeps the space conforming.
    const Functions::ZeroFunction<dim> zero(dim);
    const auto sliders = scene.ids_with(BoundaryCondition::normal_fixed);
    for (const bool homogeneous : {false, true})
      {
        AffineConstraints<double> &c =
          homogeneous ? homogeneous_constraints : constraints;
        c.clear();
        c.reinit(locally_relevant_dofs);
        c.merge(hanging_node_constraints);
        for (const types::boundary_id id :
             scene.ids_with(BoundaryCondition::fixed))
          VectorTools::interpolate_boundary_values(
            mapping,
            dof_handler,
            id,
            homogeneous ? static_cast<const Function<dim> &>(zero) :
                          scene.displacement(id),
            c);
        if (!sliders.empty())
          VectorTools::compute_no_normal_flux_constraints(
            dof_handler, 0, sliders, c, mapping);
        c.close();
      }

    DynamicSparsityPattern dsp(locally_relevant_dofs);
    DoFTools::make_sparsity_pattern(dof_handler,
                                    dsp,
                                    constraints,
                                    /*keep_constrained_dofs=*/false);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               locally_owned_dofs,
                                               mpi_communicator,
                                               locally_relevant_dofs);
    system_matrix.reinit(locally_owned_dofs,
                         locally_owned_dofs,
                         dsp,
                         mpi_communicator);
    if (scene.effects().contact)
      mass.diagonal.reinit(locally_owned_dofs, mpi_communicator);
    system_rhs.reinit(locally_owned_dofs, mpi_communicator);
    solution.reinit(locally_owned_dofs,
                    locally_relevant_dofs,
                    mpi_communicator);

    // the contact nodes, their weights and gaps (doc/theory.md §4)
    if (scene.effects().contact)
      {
        contact_set.setup(
          mapping, dof_handler, hanging_node_constraints, constraints, scene);
        AssertThrow(contact_set.n_global_nodes() > 0,
                    ExcMessage("The contact boundary has no contact nodes."));
      }
    return {cycle, triangulation.n_global_active_cells(), dof_handler.n_dofs()};
  }

  template <int dim>
  TransferFigures
  ContactProblem<dim>::transfer_fields()
  {
    TransferFigures figures;
    carried = false;
    if (!transfer)
      return figures;
    TimerOutput::Scope t(computing_timer, "refine mesh");
    carried_v.reinit(locally_owned_dofs, mpi_communicator);
    std::vector<TrilinosWrappers::MPI::Vector *> fields = {&carried_v};
    if (scene.effects().contact)
      {
        carried_multipliers.reinit(locally_owned_dofs, mpi_communicator);
        carried_threshold.reinit(locally_owned_dofs, mpi_communicator);
        fields.push_back(&carried_multipliers);
        fields.push_back(&carried_threshold);
      }
    transfer->interpolate(fields);
    transfer.reset();
    constraints.distribute(carried_v);
    carried            = true;
    figures.warm_start = true;
    if (scene.effects().contact)
      {
        // the multipliers onto the contact nodes, projected onto the
        // admissible set; how far they were from it (doc/theory.md §7)
        const auto [smallest_l1, excess] =
          contact_set.read_fields(carried_multipliers, carried_threshold);
        const double l1_max = std::max(carried_multipliers.linfty_norm(),
                                       std::numeric_limits<double>::min());
        const double g_max  = std::max(carried_threshold.linfty_norm(),
                                      std::numeric_limits<double>::min());
        figures.carried_min_l1 =
          Utilities::MPI::min(smallest_l1, mpi_communicator) / l1_max;
        // without friction there is no l2 and no excess
        if (contact_set.friction)
          figures.carried_max_excess =
            Utilities::MPI::max(excess, mpi_communicator) / g_max;
      }
    return figures;
  }

  template <int dim>
  void
  ContactProblem<dim>::assemble_system()
  {
    TimerOutput::Scope t(computing_timer, "assemble system");
    const bool         contact = scene.effects().contact;
    assemble_elasticity(mapping,
                        dof_handler,
                        scene,
                        constraints,
                        system_matrix,
                        system_rhs,
                        contact ? &mass : nullptr,
                        &applied_load);
    // An expression may evaluate to NaN or infinity somewhere (sqrt of a
    // negative number, log of zero): stop here, naming the suspects, rather
    // than solve with it.
    if (!std::isfinite(system_rhs.l2_norm()))
      throw InputError(
        "The loads are not finite numbers at some point of the body or its "
        "boundary (NaN or infinity): check the expressions of <Loads/Body "
        "force>, <Boundary conditions/Tractions> and <Boundary "
        "conditions/Displacements> over the whole body (e.g. sqrt or log of "
        "a negative number).",
        exit_invalid_value);
    if (contact)
      {
        // The Uzawa steps minimise with the proximal term (chi/2)|v - v^k|^2
        // (doc/theory.md §3.2), so their matrix is K = A + chi M. chi is
        // relative to E / L^2 so that the scene's units do not matter
        // (doc/theory.md §5).
        chi = parameters.solver.proximal * parameters.material.youngs_modulus /
              std::pow(scene.characteristic_length(), 2);
        mass.add_to(system_matrix, chi);
      }
    // the rigid-body modes of this mesh, for the algebraic multigrid
    elastic_solver.set_near_null_space(mapping,
                                       dof_handler,
                                       system_matrix,
                                       scene.center(),
                                       scene.characteristic_length());
  }

  template <int dim>
  SolveFigures
  ContactProblem<dim>::solve()
  {
    TimerOutput::Scope t(computing_timer, "solve");
    indicator_valid = false; // a new solution
    TrilinosWrappers::MPI::Vector v(locally_owned_dofs, mpi_communicator);
    SolveFigures                  figures =
      scene.effects().contact ? solve_contact(v) : solve_linear_elasticity(v);
    solution = v;
    t.stop();

    // What the contact solve is compared with, timed apart from it
    if (scene.effects().contact && parameters.solver.time_reference_solve)
      {
        TimerOutput::Scope r(computing_timer, "reference linear solve");
        figures.time_reference = newton.time_reference_solve(
          contact_system(), contact_set, v, figures.reference_iterations);
      }
    return figures;
  }

  template <int dim>
  SolveFigures
  ContactProblem<dim>::solve_linear_elasticity(TrilinosWrappers::MPI::Vector &v)
  {
    SolveFigures figures;
    if (carried) // nested iteration: the coarse solution is a first guess
      v = carried_v;
    elastic_solver.initialize(system_matrix);
    figures.cg_iterations = elastic_solver.solve(system_matrix, v, system_rhs);
    constraints.distribute(v);
    return figures;
  }

  template <int dim>
  SolveFigures
  ContactProblem<dim>::prepare_contact_solve()
  {
    SolveFigures figures;
    held_by_friction_pressure = check_equilibrium();

    // r is relative to (lambda + 2 mu) / h_C, so that the Uzawa steps do
    // not depend on the units or on the mesh size; the P-wave modulus
    // lambda + 2 mu rather than E, because it follows the stiffness of a
    // nearly incompressible (locked) material, for which r_rel E / h_C is
    // far too small (doc/theory.md §5).
    // The friction terms have their own r_t, scaled alike: by default r in
    // 2D and r / 4 in 3D, where friction terms as large as r make the Newton
    // matrices hard (doc/theory.md §5).
    const double r_t_rel =
      parameters.solver.tangential_augmentation > 0. ?
        parameters.solver.tangential_augmentation :
        (dim == 2 ? 1. : 0.25) * parameters.solver.augmentation;
    const double modulus =
      parameters.material.lambda() + 2. * parameters.material.mu();
    const double h_C          = contact_set.min_face_diameter();
    r                         = parameters.solver.augmentation * modulus / h_C;
    r_t                       = r_t_rel * modulus / h_C;
    figures.r                 = r;
    figures.r_t               = contact_set.friction ? r_t : 0.;
    figures.chi               = chi;
    figures.n_contact_nodes   = contact_set.n_global_nodes();
    figures.n_hanging_contact = contact_set.n_hanging_nodes();
    // the applied load toward the obstacle, which the contact force
    // balances when nothing else holds the body in that direction (not
    // b . n: b also holds the lifting of prescribed displacements)
    for (unsigned int c = 0; c < dim; ++c)
      figures.normal_load += applied_load[c] * contact_set.normal[c];
    find_free_motions();
    return figures;
  }

  template <int dim>
  void
  ContactProblem<dim>::find_free_motions()
  {
    // Which combinations c of the rigid motions m_i does nothing hold? The
    // prescribed displacements hold those with G_D c != 0 (Scene), the
    // contact those with a normal component at a contact node (frictionless:
    // the obstacle pushes along n_s only) or any component there (friction
    // holds the tangential ones too, also where a body near its sliding
    // limit slips). A combination is free iff c^T (G_D + G_C) c = 0.
    const unsigned int n       = Scene<dim>::n_rigid_motions;
    double             measure = 0.;
    FullMatrix<double> gram = scene.rigid_motion_gram(triangulation, measure);
    FullMatrix<double> contact_gram(n, n);
    const bool         tangential = contact_set.friction;
    double             area       = 0.;
    for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
      {
        const ContactNode<dim> &node = contact_set.nodes[s];
        area += node.weight;
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            {
              const Tensor<1, dim> mi = scene.rigid_motion(i, node.position);
              const Tensor<1, dim> mj = scene.rigid_motion(j, node.position);
              contact_gram(i, j) +=
                node.weight * (tangential ?
                                 mi * mj :
                                 (mi * node.normal) * (mj * node.normal));
            }
      }
    Utilities::MPI::sum(contact_gram, mpi_communicator, contact_gram);
    gram.add(1., contact_gram);
    measure += Utilities::MPI::sum(area, mpi_communicator);

    LAPACKFullMatrix<double> g(n);
    g = gram;
    Vector<double>     eigenvalues;
    FullMatrix<double> eigenvectors;
    g.compute_eigenvalues_symmetric(
      -1., 1e-10 * measure, 0., eigenvalues, eigenvectors);

    // each free combination as a vector of the condensed space (its nodal
    // values), improved by one step of inverse iteration with K = A + chi M,
    // then orthonormal in the Euclidean inner product of the vectors, the
    // one d(v) is measured in (Gram-Schmidt). The inverse iteration matters
    // where hanging nodes lie on a curved boundary: a hanging node sits on
    // the curve, not at the middle of its parents, so the interpolated
    // rotation is not in the constrained space, and the motion nothing holds
    // is a rotation plus a small deformation near those nodes, which K^-1
    // brings out (a translation is kept exactly: K w = chi M w).
    free_motions.clear();
    std::unique_ptr<ElasticSolver<dim>> solver;
    for (unsigned int k = 0; k < eigenvalues.size(); ++k)
      {
        TrilinosWrappers::MPI::Vector w(locally_owned_dofs, mpi_communicator);
        std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(dofs);
              for (const unsigned int v : cell->vertex_indices())
                {
                  Tensor<1, dim> m;
                  for (unsigned int i = 0; i < n; ++i)
                    m += eigenvectors(i, k) *
                         scene.rigid_motion(i, cell->vertex(v));
                  for (unsigned int c = 0; c < dim; ++c)
                    {
                      const types::global_dof_index dof =
                        dofs[fe.component_to_system_index(c, v)];
                      if (locally_owned_dofs.is_element(dof))
                        w[dof] = m[c];
                    }
                }
            }
        w.compress(VectorOperation::insert);
        homogeneous_constraints.distribute(w);
        // a translation is exact in the constrained space: no solve
        double rotation = 0.;
        for (unsigned int i = dim; i < n; ++i)
          rotation += std::abs(eigenvectors(i, k));
        if (rotation > 1e-12 && !solver)
          {
            solver = std::make_unique<ElasticSolver<dim>>(parameters.solver);
            solver->set_near_null_space(mapping,
                                        dof_handler,
                                        system_matrix,
                                        scene.center(),
                                        scene.characteristic_length());
            solver->initialize(system_matrix);
          }
        if (rotation > 1e-12)
          {
            TrilinosWrappers::MPI::Vector rhs(w);
            mass.vmult(rhs, w);
            rhs *= chi;
            // (a direction is what is wanted, not a solution: 1e-2 is
            // enough, 10-20 CG iterations in the 3D half ball)
            solver->solve(system_matrix, w, rhs, 1e-2);
            homogeneous_constraints.distribute(w);
          }
        for (const TrilinosWrappers::MPI::Vector &u : free_motions)
          w.add(-(u * w), u);
        const double norm = w.l2_norm();
        if (norm > 0.)
          {
            w /= norm;
            free_motions.push_back(std::move(w));
          }
      }
  }

  template <int dim>
  ContactSystem
  ContactProblem<dim>::contact_system()
  {
    ContactSystem system{
      system_matrix, mass, system_rhs, homogeneous_constraints, r, r_t, chi};
    system.free_motions = &free_motions;
    return system;
  }

  template <int dim>
  TrilinosWrappers::MPI::Vector
  ContactProblem<dim>::initial_displacement() const
  {
    TrilinosWrappers::MPI::Vector v(locally_owned_dofs, mpi_communicator);
    if (carried)
      v = carried_v;
    constraints.distribute(v);
    return v;
  }

  template <int dim>
  void
  ContactProblem<dim>::set_displacement(const TrilinosWrappers::MPI::Vector &v)
  {
    solution        = v;
    indicator_valid = false;
  }

  template <int dim>
  SolveFigures
  ContactProblem<dim>::solve_contact(TrilinosWrappers::MPI::Vector &v)
  {
    SolveFigures figures = prepare_contact_solve();
    report.start_contact_solve(figures);

    // from the previous mesh's solution (nested iteration), or from v = 0
    // with the prescribed boundary values and l1 = l2 = 0
    v = initial_displacement();
    static_cast<ContactStatistics &>(figures) =
      threshold_iteration.solve(contact_system(),
                                contact_set,
                                v,
                                &report,
                                held_by_friction_pressure,
                                carried);
    return figures;
  }

  template <int dim>
  double
  ContactProblem<dim>::net_load(const Tensor<1, dim> &direction) const
  {
    // b . E, E the nodal vector of the rigid translation along `direction`
    TrilinosWrappers::MPI::Vector translation(locally_owned_dofs,
                                              mpi_communicator);
    for (unsigned int c = 0; c < dim; ++c)
      {
        ComponentMask mask(dim, false);
        mask.set(c, true);
        for (const auto i : DoFTools::extract_dofs(dof_handler, mask))
          translation[i] = direction[c];
      }
    translation.compress(VectorOperation::insert);
    return system_rhs * translation;
  }

  template <int dim>
  double
  ContactProblem<dim>::check_equilibrium() const
  {
    // A translation that only the contact can stop must be balanced by
    // contact forces: they push along m (never pull) and their tangential
    // part is at most what the friction law can resist. Necessary
    // conditions, checked before solving so that an impossible load never
    // loops (doc/theory.md §8).
    const Tensor<1, dim> m = -contact_set.normal; // into the body
    LoadBalance          balance;
    Tensor<1, dim>       resultant;
    for (unsigned int d = 0; d < dim; ++d)
      {
        Tensor<1, dim> e;
        e[d]         = 1.;
        resultant[d] = net_load(e);
      }
    balance.resultant   = resultant.norm();
    balance.normal_free = scene.translation_is_free(m, triangulation);
    balance.load_away   = net_load(m);

    // N / |Gamma_C| if only friction holds a tangential load and N is known
    // (on a plane: a curved obstacle also holds tangential loads by its
    // normal pressure)
    double     pressure = 0.;
    const bool plane    = scene.obstacle()->is_plane();
    for (const Tensor<1, dim> &t : contact_set.tangents)
      if (plane && scene.translation_is_free(t, triangulation))
        {
          const double load = std::abs(net_load(t));
          balance.tangential_loads.push_back(load);
          if (balance.normal_free && load > 1e-10 * balance.resultant)
            pressure = -balance.load_away / contact_set.measure();
        }

    // what the friction law can resist: from sum_s m_s p_s, max_s p_s (p
    // its parameter) and the normal load
    double weighted = 0., largest = 0.;
    for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
      {
        weighted +=
          contact_set.nodes[s].weight * contact_set.friction_parameter[s];
        largest = std::max(largest, contact_set.friction_parameter[s]);
      }
    std::string  why;
    const double capacity = scene.effects().friction_law().capacity(
      Utilities::MPI::sum(weighted, mpi_communicator),
      Utilities::MPI::max(largest, mpi_communicator),
      balance.normal_free ? -balance.load_away : -1.,
      why);
    dualcontact::check_equilibrium(balance, capacity, why);
    if (balance.normal_free && plane)
      check_moment(balance);
    return pressure;
  }

  template <int dim>
  void
  ContactProblem<dim>::check_moment(const LoadBalance &balance) const
  {
    // Where only the contact holds the body (no prescribed displacement
    // holds any rigid motion), the contact forces must also balance the
    // loads' moment. On a plane they push along m at the nodes of Gamma_C;
    // their friction parts lie in the plane, and where the nodes lie on it
    // their moment about a point O of the plane is normal to it. So the
    // loads' moment M about O, normal part aside, is balanced by pressures
    // alone: their centre c = O + (M x m) / N must lie in the convex hull
    // of the nodes, N the load toward the plane. Without friction the
    // nodes may lie anywhere on Gamma_C (only their projections count);
    // with friction off the plane a tangential force has a lever arm, and
    // the check cannot decide (doc/theory.md §8).
    double     measure = 0.;
    const auto gram    = scene.rigid_motion_gram(triangulation, measure);
    if (gram.frobenius_norm() > 1e-12 * std::max(measure, 1e-300))
      return;
    const double N = -balance.load_away;
    if (!(N > 1e-10 * balance.resultant))
      return;
    const double         length = scene.characteristic_length();
    const double         flat   = 1e-8 * length;
    const Tensor<1, dim> m      = -contact_set.normal; // into the body
    // O: the body's centre moved onto the plane along m
    Point<dim> origin = scene.center();
    origin -= scene.initial_gap(origin) * m;
    bool                               off_plane = false;
    std::vector<std::array<double, 2>> points;
    for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
      {
        const ContactNode<dim> &node = contact_set.nodes[s];
        off_plane                    = off_plane || node.gap0 > flat;
        std::array<double, 2> p{};
        for (unsigned int k = 0; k < dim - 1; ++k)
          p[k] = contact_set.tangents[k] * (node.position - origin);
        points.push_back(p);
      }
    if (Utilities::MPI::logical_or(off_plane, mpi_communicator) &&
        contact_set.friction)
      return;
    // each rank's hull, then the hull of theirs
    std::vector<double> local;
    for (const auto &p : convex_hull(points, dim - 1))
      local.insert(local.end(), p.begin(), p.end());
    std::vector<std::array<double, 2>> hull;
    for (const auto &part : Utilities::MPI::all_gather(mpi_communicator, local))
      for (std::size_t i = 0; i + 1 < part.size(); i += 2)
        hull.push_back(std::array<double, 2>{{part[i], part[i + 1]}});
    hull = convex_hull(hull, dim - 1);

    // M about O: b . R_k for the rigid rotations R_k(x) = e_k x (x - O)
    // (in 2D the one about the normal of the plane)
    const unsigned int n_rotations = dim == 2 ? 1 : 3;
    Tensor<1, 3>       moment;
    const IndexSet    &owned = locally_owned_dofs;
    for (unsigned int k = 0; k < n_rotations; ++k)
      {
        TrilinosWrappers::MPI::Vector rotation(owned, mpi_communicator);
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const unsigned int v : cell->vertex_indices())
              {
                const Tensor<1, dim> r = cell->vertex(v) - origin;
                Tensor<1, 3>         u; // (e_k x r), r in 3D
                const unsigned int   axis = dim == 2 ? 2 : k;
                const unsigned int   a = (axis + 1) % 3, b = (axis + 2) % 3;
                const double r3[3] = {r[0], r[1], dim == 3 ? r[dim - 1] : 0.};
                u[a]               = -r3[b];
                u[b]               = r3[a];
                for (unsigned int c = 0; c < dim; ++c)
                  {
                    const auto dof = cell->vertex_dof_index(v, c);
                    if (owned.is_element(dof))
                      rotation[dof] = u[c];
                  }
              }
        rotation.compress(VectorOperation::insert);
        moment[dim == 2 ? 2 : k] = system_rhs * rotation;
      }
    Tensor<1, 3> m3;
    for (unsigned int c = 0; c < dim; ++c)
      m3[c] = m[c];
    const Tensor<1, 3>    offset = cross_product_3d(moment, m3) / N;
    std::array<double, 2> centre{};
    for (unsigned int k = 0; k < dim - 1; ++k)
      for (unsigned int c = 0; c < dim; ++c)
        centre[k] += contact_set.tangents[k][c] * offset[c];
    const double outside = distance_outside_hull(hull, centre, dim - 1);
    if (!(outside > flat))
      return;

    // points of the plane as coordinates, for the message
    const auto on_plane = [&](const std::array<double, 2> &p) {
      Point<dim> x = origin;
      for (unsigned int k = 0; k < dim - 1; ++k)
        x += p[k] * contact_set.tangents[k];
      std::ostringstream out;
      out << "(";
      for (unsigned int c = 0; c < dim; ++c)
        out << (c > 0 ? ", " : "") << std::setprecision(4)
            << (std::abs(x[c]) < flat ? 0. : x[c]);
      return out.str() + ")";
    };
    std::ostringstream text;
    text << "No equilibrium: the loads tip the body over. Only the contact "
            "holds the body, and it can only push: the loads press it onto "
            "the foundation with "
         << format_number(N)
         << ", but the line of action of their resultant meets the "
            "foundation at "
         << on_plane(centre) << ", " << format_number(outside)
         << " outside the contact boundary's "
         << (dim == 2 ? "extent on it, from " + on_plane(hull.front()) +
                          " to " + on_plane(hull.back()) :
                        std::string("convex hull on it"))
         << ", so no contact pressure balances their moment. Reduce the "
            "tangential loads or their lever arm, or hold the body "
            "(<Boundary conditions/Conditions>).";
    throw InputError(text.str(), exit_no_equilibrium);
  }

  template <int dim>
  ContactZoneFigures
  ContactProblem<dim>::measure_contact_zone() const
  {
    TimerOutput::Scope    t(computing_timer, "measure contact zone");
    ContactZoneFigures    figures;
    double                force = 0, peak = 0;
    Tensor<1, dim>        on_obstacle;
    std::vector<ZoneNode> local;
    for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
      {
        force += contact_set.nodes[s].weight * contact_set.l1[s];
        on_obstacle += contact_set.nodal_force(s);
        peak = std::max(peak, contact_set.l1[s]);
        ZoneNode node;
        for (unsigned int k = 0; k < dim - 1; ++k)
          node.t[k] = contact_set.nodes[s].position * contact_set.tangents[k];
        node.weight = contact_set.nodes[s].weight;
        node.gap0   = contact_set.nodes[s].gap0;
        node.l1     = contact_set.l1[s];
        node.status = contact_set.status(s);
        local.push_back(node);
      }
    figures.contact_force = Utilities::MPI::sum(force, mpi_communicator);
    for (unsigned int c = 0; c < dim; ++c)
      on_obstacle[c] = Utilities::MPI::sum(on_obstacle[c], mpi_communicator);
    // the force of the obstacle on the body, -sum_s m_s (l1_s n_s + T_s l2_s),
    // and its part in the tangent plane of Gamma_C's mean direction
    const Tensor<1, dim> resultant = -on_obstacle;
    figures.tangential_force =
      (resultant - (resultant * contact_set.normal) * contact_set.normal)
        .norm();
    figures.max_pressure = Utilities::MPI::max(peak, mpi_communicator);
    for (unsigned int c = 0; c < dim; ++c)
      figures.resultant[c] = resultant[c];

    // the half-width (2D) or radius (3D) of the zone and of its stick zone
    std::vector<ZoneNode> nodes;
    for (const auto &part : Utilities::MPI::all_gather(mpi_communicator, local))
      nodes.insert(nodes.end(), part.begin(), part.end());
    const ContactZoneShape shape =
      contact_zone_shape(nodes,
                         dim - 1,
                         0.25 * contact_set.min_face_diameter());
    figures.half_width      = shape.width.nodes;
    figures.edge_half_width = shape.width.extrapolated;
    figures.area            = shape.area;
    figures.extent          = shape.extent;
    figures.mirrored        = shape.mirrored;
    if (contact_set.friction)
      figures.stick_half_width = shape.stick_width;

    // errors against what the scene knows
    if (const Function<dim> *exact = scene.exact_pressure())
      {
        TrilinosWrappers::MPI::Vector multipliers, threshold;
        multiplier_fields(multipliers, threshold);
        figures.pressure_error =
          compute_pressure_error(mapping,
                                 dof_handler,
                                 multipliers,
                                 scene.ids_with(BoundaryCondition::contact),
                                 *exact);
        if (!std::isfinite(figures.pressure_error))
          throw InputError("The entry <Exact solution/Contact pressure> is "
                           "not a finite number (NaN or infinity) at some "
                           "point of Gamma_C: '" +
                             parameters.exact.contact_pressure + "'.",
                           exit_invalid_value);
      }
    if (parameters.exact.contact_half_width > 0.)
      figures.half_width_error =
        figures.edge_half_width / parameters.exact.contact_half_width - 1.;
    if (parameters.exact.stick_half_width > 0.)
      figures.stick_half_width_error =
        figures.stick_half_width / parameters.exact.stick_half_width - 1.;
    if (parameters.exact.peak_pressure > 0.)
      figures.peak_pressure_error =
        figures.max_pressure / parameters.exact.peak_pressure - 1.;
    return figures;
  }

  template <int dim>
  ColdStartFigures
  ContactProblem<dim>::compare_with_cold_start()
  {
    ColdStartFigures figures;
    if (!carried || !parameters.refinement.compare_cold_start)
      return figures;
    TimerOutput::Scope t(computing_timer, "cold start (comparison)");
    report.start_cold_start();
    ContactSet<dim> cold_set = contact_set;
    cold_set.reset_multipliers();
    TrilinosWrappers::MPI::Vector v_cold(locally_owned_dofs, mpi_communicator);
    constraints.distribute(v_cold);
    // its steps are neither printed nor logged
    const ContactStatistics cold = threshold_iteration.solve(
      contact_system(), cold_set, v_cold, nullptr, held_by_friction_pressure);
    report.end_cold_start();
    figures.uzawa_steps     = cold.uzawa_steps;
    figures.newton_steps    = cold.newton_steps;
    figures.threshold_steps = cold.threshold_steps;

    // in the energy norm a(e, e) = e.(K - chi M)e, blind to the rigid
    // motions that only the proximal term fixes (a semi-coercive scene
    // keeps the one its start selects); on the condensed matrices, i.e.
    // over the unconstrained DoFs
    const auto energy = [&](TrilinosWrappers::MPI::Vector e) {
      homogeneous_constraints.set_zero(e);
      TrilinosWrappers::MPI::Vector Ke(e), Me(e);
      system_matrix.vmult(Ke, e);
      mass.vmult(Me, e);
      return std::sqrt(std::max(e * Ke - chi * (e * Me), 0.));
    };
    TrilinosWrappers::MPI::Vector difference(locally_owned_dofs,
                                             mpi_communicator);
    difference = solution;
    difference -= v_cold;
    figures.difference_v = relative_change(energy(difference), energy(v_cold));
    double sums[2]       = {0., 0.};
    for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
      {
        const double m = contact_set.nodes[s].weight;
        sums[0] += m * std::pow(contact_set.l1[s] - cold_set.l1[s], 2);
        sums[1] += m * cold_set.l1[s] * cold_set.l1[s];
      }
    Utilities::MPI::sum(ArrayView<const double>(sums, 2),
                        mpi_communicator,
                        ArrayView<double>(sums, 2));
    figures.difference_l1 =
      relative_change(std::sqrt(sums[0]), std::sqrt(sums[1]));
    return figures;
  }

  template <int dim>
  ReactionFigures
  ContactProblem<dim>::compute_reactions(const ContactZoneFigures &zone) const
  {
    TimerOutput::Scope t(computing_timer, "postprocess");
    // one more pass over the cells: only where there are supports
    ReactionFigures figures;
    if (scene.ids_with(BoundaryCondition::fixed).empty() &&
        scene.ids_with(BoundaryCondition::normal_fixed).empty())
      figures.applied_load = applied_load;
    else
      figures = dualcontact::compute_reactions(mapping,
                                               dof_handler,
                                               scene,
                                               constraints,
                                               hanging_node_constraints,
                                               solution);

    // Equilibrium of the whole body: contact force, reactions and applied
    // loads sum to zero, up to the solver tolerances.
    std::array<double, 3> sum   = figures.applied_load;
    double                scale = std::sqrt(norm_square(figures.applied_load));
    for (const auto &[id, force] : figures.on_id)
      {
        for (unsigned int c = 0; c < dim; ++c)
          sum[c] += force[c];
        scale = std::max(scale, std::sqrt(norm_square(force)));
      }
    for (unsigned int c = 0; c < dim; ++c)
      sum[c] += zone.resultant[c];
    scale             = std::max(scale, std::sqrt(norm_square(zone.resultant)));
    figures.imbalance = scale > 0. ? std::sqrt(norm_square(sum)) / scale : 0.;
    return figures;
  }

  template <int dim>
  void
  ContactProblem<dim>::check_balance(const ReactionFigures &reactions) const
  {
    // The converged solution balances the loads up to the solver
    // tolerances (1e-14 to 1e-10 on the shipped scenes, doc/theory.md §8);
    // a solve that stopped on its tests without balancing them (a proximal
    // weight so large that v never moves, say) is not a solution.
    const double tolerance =
      std::clamp(1e2 * parameters.solver.uzawa_tolerance, 1e-6, 1e-2);
    if (!(reactions.imbalance <= tolerance))
      AssertThrow(
        false,
        ExcMessage("The solution does not balance the loads: contact "
                   "force, reactions and applied loads sum to " +
                   format_number(reactions.imbalance) +
                   " of the largest of them (at most " +
                   format_number(tolerance) + " for <Solver/Uzawa tolerance> " +
                   format_number(parameters.solver.uzawa_tolerance) +
                   "). The solver stopped without a solution: check "
                   "<Solver/Proximal parameter> and <Solver/Augmentation "
                   "parameter> (their defaults suit every scene)."));
  }

  template <int dim>
  PositionFigures
  ContactProblem<dim>::check_position()
  {
    TimerOutput::Scope    t(computing_timer, "postprocess");
    const PositionFigures figures =
      check_deformed_position(dof_handler, solution, scene);
    for (const std::string &warning : figures.warnings)
      report.warning(warning);
    return figures;
  }

  template <int dim>
  ErrorNorms
  ContactProblem<dim>::postprocess() const
  {
    TimerOutput::Scope t(computing_timer, "postprocess");
    const ErrorNorms   norms = compute_error_norms(mapping,
                                                 dof_handler,
                                                 solution,
                                                 scene.exact_displacement());
    if (!std::isfinite(norms.l2) || !std::isfinite(norms.h1_semi))
      throw InputError("The entry <Exact solution/Displacement> is not a "
                       "finite number (NaN or infinity) at some point of "
                       "the body: '" +
                         parameters.exact.displacement + "'.",
                       exit_invalid_value);
    return norms;
  }

  template <int dim>
  void
  ContactProblem<dim>::output_results(const unsigned int cycle)
  {
    TimerOutput::Scope t(computing_timer, "output results");
    const std::string &directory = parameters.output.directory;
    const bool root = Utilities::MPI::this_mpi_process(mpi_communicator) == 0;

    // The first file is written only now: a run that fails on its first
    // mesh (bad input found late, no equilibrium) writes nothing. run()
    // made the folder; a program that calls the phases itself may not have.
    // The files of an earlier run go first: the last cycles of a longer run
    // must not stand next to this run's.
    if (cycle == 0)
      {
        if (root)
          {
            std::filesystem::create_directories(directory);
            OutputDirectory::remove_earlier_results(directory);
            if (!recorded_parameters.empty())
              std::ofstream(directory + "/parameters.prm")
                << recorded_parameters;
          }
        MPI_Barrier(mpi_communicator);
        pvtu_records.clear();
        contact_pvtu_records.clear();
      }

    // the probes: all cycles so far
    probes.evaluate(cycle, mapping, dof_handler, solution, parameters.material);
    if (root && !probes.empty())
      probes.write_csv(directory + "/probes.csv");

    // one row per contact node, gathered on rank 0
    const bool contact = scene.effects().contact;
    if (contact)
      {
        const std::vector<ContactNodeRow<dim>> rows =
          gather_contact_rows(contact_set, solution, mpi_communicator);
        if (root)
          write_contact_csv(directory + "/contact_" +
                              Utilities::int_to_string(cycle, 2) + ".csv",
                            rows,
                            contact_set.law->has_friction(),
                            scene.exact_pressure());
      }

    if (!parameters.output.write_vtu)
      return;
    // zlib's fastest level: best_compression (deal.II's default) took
    // most of the output's time for files a few percent smaller
    DataOutBase::VtkFlags flags;
    flags.compression_level = DataOutBase::VtkFlags::best_speed;

    // The volume: displacement, stress and von Mises stress (from one
    // evaluation of the gradient per point), the owning rank, and the
    // refinement indicator with adaptive refinement. The contact fields
    // live on Gamma_C only, in the boundary output below.
    StressPostprocessor<dim> stress(parameters.material);
    DataOut<dim>             data_out;
    data_out.set_flags(flags);
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(
      solution,
      std::vector<std::string>(dim, "displacement"),
      DataOut<dim>::type_dof_data,
      std::vector<DataComponentInterpretation::DataComponentInterpretation>(
        dim, DataComponentInterpretation::component_is_part_of_vector));
    data_out.add_data_vector(solution, stress);

    Vector<float> subdomain(triangulation.n_active_cells());
    subdomain = static_cast<float>(triangulation.locally_owned_subdomain());
    data_out.add_data_vector(subdomain, "subdomain");

    // what the adaptive strategies rank the cells by (the cells refined
    // next are those with the largest values)
    if (!refinement_indicator_kind(parameters.refinement.strategy)
           .refines_every_cell())
      data_out.add_data_vector(refinement_indicator(), "refinement_indicator");
    data_out.build_patches(mapping, fe.degree);

    // a .pvd record over all cycles so that ParaView shows them as a
    // sequence
    const auto add_to_pvd =
      [&](const std::string &name, const std::string &pvtu, auto &records) {
        records.emplace_back(cycle, pvtu);
        if (root)
          {
            std::ofstream pvd(directory + "/" + name + ".pvd");
            DataOutBase::write_pvd_record(pvd, records);
          }
      };
    add_to_pvd("solution",
               data_out.write_vtu_with_pvtu_record(
                 directory + "/", "solution", cycle, mpi_communicator, 2),
               pvtu_records);

    // Gamma_C: the contact fields on its faces (contact_output.h)
    if (contact)
      {
        ContactBoundaryOutput<dim> boundary;
        boundary.set_flags(flags);
        boundary.build_patches(dof_handler,
                               scene.ids_with(BoundaryCondition::contact),
                               contact_set,
                               solution,
                               hanging_node_constraints,
                               locally_relevant_dofs);
        add_to_pvd("contact",
                   boundary.write_vtu_with_pvtu_record(
                     directory + "/", "contact", cycle, mpi_communicator, 2),
                   contact_pvtu_records);
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::multiplier_fields(
    TrilinosWrappers::MPI::Vector &multipliers,
    TrilinosWrappers::MPI::Vector &threshold) const
  {
    // nodal values at the contact nodes, then at the hanging nodes on
    // Gamma_C (interpolated from their masters, so l1 >= 0 and |l2| <= g
    // hold there too), then ghosted
    TrilinosWrappers::MPI::Vector owned_multipliers(locally_owned_dofs,
                                                    mpi_communicator);
    TrilinosWrappers::MPI::Vector owned_threshold(locally_owned_dofs,
                                                  mpi_communicator);
    contact_set.write_fields(owned_multipliers, owned_threshold);
    hanging_node_constraints.distribute(owned_multipliers);
    hanging_node_constraints.distribute(owned_threshold);
    multipliers.reinit(locally_owned_dofs,
                       locally_relevant_dofs,
                       mpi_communicator);
    threshold.reinit(locally_owned_dofs,
                     locally_relevant_dofs,
                     mpi_communicator);
    multipliers = owned_multipliers;
    threshold   = owned_threshold;
  }

  template <int dim>
  const Vector<float> &
  ContactProblem<dim>::refinement_indicator()
  {
    // computed once per solution: the output and the marking both use it
    if (indicator_valid)
      return indicator;
    indicator_valid = true;
    const std::set<types::boundary_id> contact_ids =
      scene.effects().contact ? scene.ids_with(BoundaryCondition::contact) :
                                std::set<types::boundary_id>();
    indicator =
      compute_indicator<dim>({mapping,
                              dof_handler,
                              solution,
                              contact_set,
                              contact_ids,
                              parameters,
                              parameters.refinement.values,
                              [this] {
                                TrilinosWrappers::MPI::Vector multipliers,
                                  threshold;
                                multiplier_fields(multipliers, threshold);
                                return multipliers;
                              }});
    return indicator;
  }

  template <int dim>
  void
  ContactProblem<dim>::refine_mesh()
  {
    TimerOutput::Scope          t(computing_timer, "refine mesh");
    const RefinementParameters &refinement = parameters.refinement;
    if (refinement_indicator_kind(refinement.strategy).refines_every_cell())
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            cell->set_refine_flag();
      }
    else // the same cells on any number of ranks
      mark_fixed_number(triangulation,
                        refinement_indicator(),
                        indicator_scale(mapping, dof_handler, solution),
                        refinement.refine_fraction,
                        refinement.coarsen_fraction);

    // Nested iteration: v and the multiplier fields go with the cells.
    // The inputs must live until the refinement is executed.
    TrilinosWrappers::MPI::Vector multipliers, threshold;
    if (refinement.nested_iteration)
      {
        std::vector<const TrilinosWrappers::MPI::Vector *> fields = {&solution};
        if (scene.effects().contact)
          {
            multiplier_fields(multipliers, threshold);
            fields.push_back(&multipliers);
            fields.push_back(&threshold);
          }
        transfer = std::make_unique<parallel::distributed::SolutionTransfer<
          dim,
          TrilinosWrappers::MPI::Vector>>(dof_handler);
        triangulation.prepare_coarsening_and_refinement();
        transfer->prepare_for_coarsening_and_refinement(fields);
      }
    triangulation.execute_coarsening_and_refinement();
  }

  template class ContactProblem<2>;
  template class ContactProblem<3>;
} // namespace dualcontact
