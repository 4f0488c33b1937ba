#include <deal.II/base/utilities.h>

#include <deal.II/distributed/grid_refinement.h>

#include <deal.II/dofs/dof_accessor.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <dualcontact/contact_problem.h>
#include <dualcontact/input_error.h>
#include <dualcontact/postprocess.h>
#include <dualcontact/refinement.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>

namespace dualcontact
{
  template <int dim>
  ContactProblem<dim>::ContactProblem(const Parameters &parameters,
                                      MPI_Comm          mpi_communicator,
                                      std::ostream     &out)
      : mpi_communicator(mpi_communicator)
      , pcout(out, Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      , parameters(parameters)
      , scene(parameters)
      , computing_timer(mpi_communicator,
                        pcout,
                        TimerOutput::never,
                        TimerOutput::wall_times)
      , triangulation(mpi_communicator,
                      typename Triangulation<dim>::MeshSmoothing(
                        Triangulation<dim>::smoothing_on_refinement |
                        Triangulation<dim>::smoothing_on_coarsening))
      , mapping(1)
      , fe(FE_Q<dim>(1), dim)
      , dof_handler(triangulation)
      , elastic_solver(parameters.solver)
      , uzawa_solver(parameters.solver,
                     elastic_solver,
                     pcout,
                     parameters.output.print_timing)
      , friction_iteration(parameters.friction, uzawa_solver, pcout)
  {}

  template <int dim>
  void
  ContactProblem<dim>::print_header() const
  {
    pcout << "dualcontact: " << dim << "D, "
          << to_string(parameters.geometry.type)
          << ", E = " << parameters.material.youngs_modulus
          << ", nu = " << parameters.material.poissons_ratio << ", "
          << Utilities::MPI::n_mpi_processes(mpi_communicator)
          << " MPI rank(s)\n";
    pcout << "Boundary parts:\n";
    for (const auto &[id, condition] : parameters.boundary.conditions)
      pcout << "  id " << static_cast<unsigned int>(id) << ": "
            << to_string(condition) << '\n';
    pcout << "Effects composed for this scene:\n" << scene.effects().describe();
  }

  template <int dim>
  void
  ContactProblem<dim>::make_grid()
  {
    scene.create_mesh(triangulation);
    scene.check_rigid_motions(triangulation);
  }

  template <int dim>
  void
  ContactProblem<dim>::setup_system()
  {
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
      mass_matrix.reinit(locally_owned_dofs,
                         locally_owned_dofs,
                         dsp,
                         mpi_communicator);
    system_rhs.reinit(locally_owned_dofs, mpi_communicator);
    solution.reinit(locally_owned_dofs,
                    locally_relevant_dofs,
                    mpi_communicator);
  }

  template <int dim>
  void
  ContactProblem<dim>::assemble_system()
  {
    const bool contact = scene.effects().contact;
    assemble_elasticity(mapping,
                        dof_handler,
                        scene,
                        constraints,
                        system_matrix,
                        system_rhs,
                        contact ? &mass_matrix : nullptr);
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
        // (DESIGN.md §2), so their matrix is K = A + chi M. chi is relative
        // to E / L^2 so that the scene's units do not matter.
        const double chi = parameters.solver.proximal *
                           parameters.material.youngs_modulus /
                           std::pow(scene.characteristic_length(), 2);
        system_matrix.add(chi, mass_matrix);
        cycle_results.back().chi = chi;
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::solve()
  {
    elastic_solver.set_near_null_space(mapping,
                                       dof_handler,
                                       system_matrix,
                                       scene.center(),
                                       scene.characteristic_length());
    indicator_valid = false; // a new solution
    TrilinosWrappers::MPI::Vector v(locally_owned_dofs, mpi_communicator);
    if (scene.effects().contact)
      solve_contact(v);
    else
      solve_linear_elasticity(v);
    solution = v;
  }

  template <int dim>
  void
  ContactProblem<dim>::solve_linear_elasticity(TrilinosWrappers::MPI::Vector &v)
  {
    if (carried) // nested iteration: the coarse solution is a first guess
      v = carried_v;
    elastic_solver.initialize(system_matrix);
    cycle_results.back().linear_iterations =
      elastic_solver.solve(system_matrix, v, system_rhs);
    constraints.distribute(v);
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
    // part is at most the friction capacity. Necessary conditions, checked
    // before solving so that an impossible load never loops.
    const Tensor<1, dim> m = -contact_set.normal; // into the body
    Tensor<1, dim>       resultant;
    for (unsigned int d = 0; d < dim; ++d)
      {
        Tensor<1, dim> e;
        e[d]         = 1.;
        resultant[d] = net_load(e);
      }
    const double scale = 1e-10 * resultant.norm();

    const bool   normal_free = scene.translation_is_free(m, triangulation);
    const double load_away   = net_load(m); // > 0: pulls off the foundation
    if (normal_free && load_away > scale)
      throw InputError(
        "No equilibrium: the net load pulls the body away from the foundation "
        "(" +
          std::to_string(load_away) +
          " along the foundation normal) and only the contact could hold it "
          "in that direction.",
        exit_no_equilibrium);

    // returned: N / |Gamma_C| if only friction holds a tangential load
    // and N is known (see FrictionIteration::solve), else 0
    double held_by_friction_pressure = 0.;
    for (unsigned int k = 0; k < dim - 1; ++k)
      {
        const Tensor<1, dim> &t = contact_set.tangents[k];
        if (!scene.translation_is_free(t, triangulation))
          continue;
        const double tangential = std::abs(net_load(t));
        if (normal_free && tangential > scale)
          held_by_friction_pressure = -load_away / contact_set.measure();
        double      capacity = 0.; // what friction can resist at most
        std::string bound    = "0 (frictionless contact)";
        if (scene.effects().friction == FrictionLaw::given)
          {
            double local = 0;
            for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
              local += contact_set.nodes[s].weight * contact_set.threshold[s];
            capacity = Utilities::MPI::sum(local, mpi_communicator);
            bound    = std::to_string(capacity) + " (the sum of the given "
                                                  "threshold over Gamma_C)";
          }
        else if (scene.effects().friction == FrictionLaw::coulomb)
          {
            if (!normal_free)
              continue; // N is not known from the load alone
            double largest = 0;
            for (const double F : contact_set.coefficient)
              largest = std::max(largest, F);
            largest  = Utilities::MPI::max(largest, mpi_communicator);
            capacity = largest * (-load_away);
            bound    = std::to_string(capacity) +
                    " (F N, N = " + std::to_string(-load_away) +
                    " the normal load)";
          }
        if (tangential > capacity * (1. + 1e-10) + scale)
          throw InputError(
            "No equilibrium: the net tangential load " +
              std::to_string(tangential) +
              " exceeds what friction can resist, " + bound +
              ", and only friction holds the body along the foundation.",
            exit_no_equilibrium);
      }
    return held_by_friction_pressure;
  }

  template <int dim>
  void
  ContactProblem<dim>::solve_contact(TrilinosWrappers::MPI::Vector &v)
  {
    CycleResult &result = cycle_results.back();
    contact_set.setup(
      mapping, dof_handler, hanging_node_constraints, constraints, scene);
    AssertThrow(contact_set.n_global_nodes() > 0,
                ExcMessage("The contact boundary has no contact nodes."));
    const double held_by_friction_pressure = check_equilibrium();
    // the net load toward the foundation, which the contact force balances
    // when nothing else holds the body in that direction
    result.normal_load = net_load(contact_set.normal);

    // r is relative to (lambda + 2 mu) / h_C, so that the Uzawa steps do
    // not depend on the units or on the mesh size (DESIGN.md §3); the
    // P-wave modulus lambda + 2 mu rather than E, because it follows the
    // stiffness of a nearly incompressible (locked) material, for which
    // r_rel E / h_C is far too small (doc/robustness.md §3).
    result.r = parameters.solver.augmentation *
               (parameters.material.lambda() + 2. * parameters.material.mu()) /
               contact_set.min_face_diameter();
    result.n_contact_nodes = contact_set.n_global_nodes();
    pcout << "   contact: " << result.n_contact_nodes
          << " nodes, r = " << result.r << ", chi = " << result.chi << '\n';

    result.n_hanging_contact = contact_set.n_hanging_nodes();
    const ContactSystem system{system_matrix,
                               mass_matrix,
                               system_rhs,
                               homogeneous_constraints,
                               result.r,
                               result.chi};

    // For the comparison of nested iteration with a cold start: the same
    // mesh solved from v = 0, l1 = l2 = 0 first (its log is not kept).
    TrilinosWrappers::MPI::Vector v_cold;
    ContactSet<dim>               cold_set;
    result.warm_start = carried;
    if (carried && parameters.refinement.compare_cold_start)
      {
        pcout << "   cold start, for comparison with nested iteration:\n";
        cold_set = contact_set;
        v_cold.reinit(locally_owned_dofs, mpi_communicator);
        constraints.distribute(v_cold);
        std::vector<IterationRecord> cold_log;
        Timer                        timer(mpi_communicator, true);
        const ContactStatistics      cold = friction_iteration.solve(
          system, cold_set, v_cold, cold_log, held_by_friction_pressure);
        timer.stop();
        result.cold_uzawa_steps    = cold.uzawa_steps;
        result.cold_newton_steps   = cold.newton_steps;
        result.cold_friction_steps = cold.friction_steps;
        result.cold_time_solve     = timer.wall_time();
        pcout << "   nested start from the previous mesh:\n";
      }

    // Start from the previous mesh's solution (nested iteration), or from
    // v = 0 with the prescribed boundary values and l1 = l2 = 0.
    if (carried)
      {
        v = carried_v;
        const auto [smallest_l1, excess] =
          contact_set.read_fields(carried_multipliers, carried_threshold);
        const double l1_max = std::max(carried_multipliers.linfty_norm(),
                                       std::numeric_limits<double>::min());
        const double g_max  = std::max(carried_threshold.linfty_norm(),
                                      std::numeric_limits<double>::min());
        result.carried_min_l1 =
          Utilities::MPI::min(smallest_l1, mpi_communicator) / l1_max;
        result.carried_max_excess =
          Utilities::MPI::max(excess, mpi_communicator) / g_max;
      }
    else
      v = 0;
    constraints.distribute(v);

    const std::size_t       first = iteration_log.size();
    const ContactStatistics statistics =
      friction_iteration.solve(system,
                               contact_set,
                               v,
                               iteration_log,
                               held_by_friction_pressure,
                               carried);
    for (std::size_t i = first; i < iteration_log.size(); ++i)
      iteration_log[i].cycle = result.cycle;

    if (v_cold.size() > 0)
      {
        // in the energy norm a(e, e) = e.(K - chi M)e, blind to the rigid
        // motions that only the proximal term fixes (a semi-coercive scene
        // keeps the one its start selects)
        // (on the condensed matrices: over the unconstrained DoFs)
        const auto energy = [&](TrilinosWrappers::MPI::Vector e) {
          homogeneous_constraints.set_zero(e);
          TrilinosWrappers::MPI::Vector Ke(e), Me(e);
          system_matrix.vmult(Ke, e);
          mass_matrix.vmult(Me, e);
          return std::sqrt(std::max(e * Ke - result.chi * (e * Me), 0.));
        };
        TrilinosWrappers::MPI::Vector difference(v);
        difference -= v_cold;
        const double reference = energy(v_cold);
        result.cold_difference_v =
          reference > 0. ? energy(difference) / reference : energy(difference);
        double sums[2] = {0., 0.};
        for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
          {
            const double m = contact_set.nodes[s].weight;
            sums[0] += m * std::pow(contact_set.l1[s] - cold_set.l1[s], 2);
            sums[1] += m * cold_set.l1[s] * cold_set.l1[s];
          }
        Utilities::MPI::sum(ArrayView<const double>(sums, 2),
                            mpi_communicator,
                            ArrayView<double>(sums, 2));
        result.cold_difference_l1 =
          sums[1] > 0. ? std::sqrt(sums[0] / sums[1]) : std::sqrt(sums[0]);
      }

    if (parameters.solver.time_reference_solve)
      result.time_reference = uzawa_solver.time_reference_solve(
        system, contact_set, v, result.reference_iterations);

    result.uzawa_steps       = statistics.uzawa_steps;
    result.newton_steps      = statistics.newton_steps;
    result.linear_iterations = statistics.cg_iterations;
    result.amg_setups        = statistics.amg_setups;
    result.uzawa_rate        = statistics.rate;
    result.l1_error_estimate = statistics.estimated_l1_error;
    result.n_active          = statistics.n_active;
    result.n_stick           = statistics.n_stick;
    result.n_slip            = statistics.n_slip;
    result.friction_steps    = statistics.friction_steps;

    measure_contact_zone(result);
  }

  template <int dim>
  void
  ContactProblem<dim>::measure_contact_zone(CycleResult &result) const
  {
    // Figures of the contact zone: total force, peak pressure, half-width
    // along t, and the L2 error against an exact pressure.
    const Function<dim> *exact = scene.exact_pressure();
    double               force = 0, peak = 0;
    double               t_min = std::numeric_limits<double>::max();
    double               t_max = -std::numeric_limits<double>::max();
    for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
      {
        const ContactNode<dim> &node = contact_set.nodes[s];
        const double            l1   = contact_set.l1[s];
        force += node.weight * l1;
        peak = std::max(peak, l1);
        if (l1 > 0.)
          {
            const double t = node.position * contact_set.tangent;
            t_min          = std::min(t_min, t);
            t_max          = std::max(t_max, t);
          }
      }
    result.contact_force = Utilities::MPI::sum(force, mpi_communicator);
    Tensor<1, dim - 1> tangential;
    for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
      tangential += contact_set.nodes[s].weight * contact_set.l2[s];
    for (unsigned int k = 0; k < dim - 1; ++k)
      tangential[k] = Utilities::MPI::sum(tangential[k], mpi_communicator);
    result.tangential_force = tangential.norm();
    result.max_pressure     = Utilities::MPI::max(peak, mpi_communicator);
    t_min                   = Utilities::MPI::min(t_min, mpi_communicator);
    t_max                   = Utilities::MPI::max(t_max, mpi_communicator);
    if (dim == 2 && t_max >= t_min)
      {
        result.contact_half_width = 0.5 * (t_max - t_min);
        // A sharper estimate of the zone's edges: near an edge of a smooth
        // contact the pressure vanishes like sqrt(distance), so l1^2 is
        // linear there; extrapolate it from the two outermost active nodes
        // on each side to zero, staying before the first separated node.
        // Where the zone reaches the end of Gamma_C there is no such edge,
        // and the outermost node is kept.
        std::vector<std::pair<double, double>> local;
        for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
          local.emplace_back(contact_set.nodes[s].position *
                               contact_set.tangent,
                             contact_set.l1[s]);
        std::vector<std::pair<double, double>> nodes; // (t, l1), all nodes
        for (const auto &part :
             Utilities::MPI::all_gather(mpi_communicator, local))
          nodes.insert(nodes.end(), part.begin(), part.end());
        std::sort(nodes.begin(), nodes.end());
        std::size_t first = 0, last = nodes.size();
        while (first < nodes.size() && !(nodes[first].second > 0.))
          ++first;
        while (last > first && !(nodes[last - 1].second > 0.))
          --last;
        // edge beyond `outer` (active) toward `beyond` (separated)
        const auto edge = [](const std::pair<double, double> &outer,
                             const std::pair<double, double> &inner,
                             const std::pair<double, double> &beyond) {
          const double p2_outer = outer.second * outer.second;
          const double p2_inner = inner.second * inner.second;
          if (!(p2_inner > p2_outer))
            return outer.first;
          const double t = outer.first + (outer.first - inner.first) *
                                           p2_outer / (p2_inner - p2_outer);
          return std::clamp(t,
                            std::min(outer.first, beyond.first),
                            std::max(outer.first, beyond.first));
        };
        if (last - first >= 2)
          {
            const double lower =
              first > 0 ?
                edge(nodes[first], nodes[first + 1], nodes[first - 1]) :
                nodes[first].first;
            const double upper =
              last < nodes.size() ?
                edge(nodes[last - 1], nodes[last - 2], nodes[last]) :
                nodes[last - 1].first;
            result.contact_edge_half_width = 0.5 * (upper - lower);
          }
        else
          result.contact_edge_half_width = result.contact_half_width;
      }
    if (exact != nullptr)
      {
        TrilinosWrappers::MPI::Vector multipliers, threshold;
        multiplier_fields(multipliers, threshold);
        result.pressure_error =
          compute_pressure_error(mapping,
                                 dof_handler,
                                 multipliers,
                                 scene.ids_with(BoundaryCondition::contact),
                                 *exact);
      }
    if (parameters.exact.contact_half_width > 0.)
      result.half_width_error =
        result.contact_edge_half_width / parameters.exact.contact_half_width -
        1.;
    if (parameters.exact.peak_pressure > 0.)
      result.peak_pressure_error =
        result.max_pressure / parameters.exact.peak_pressure - 1.;
  }

  template <int dim>
  void
  ContactProblem<dim>::postprocess(CycleResult &result)
  {
    const ErrorNorms norms = compute_error_norms(mapping,
                                                 dof_handler,
                                                 solution,
                                                 scene.exact_displacement());
    result.u_l2            = norms.u_l2;
    result.l2_error        = norms.l2;
    result.h1_error        = norms.h1_semi;
    if (cycle_results.size() > 1 && scene.exact_displacement() != nullptr)
      {
        // meshes are halved between cycles: the rate is log2 of the ratio
        const CycleResult &previous = cycle_results[cycle_results.size() - 2];
        result.l2_rate = std::log2(previous.l2_error / result.l2_error);
        result.h1_rate = std::log2(previous.h1_error / result.h1_error);
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::output_results(const unsigned int cycle)
  {
    if (!parameters.output.write_vtu)
      return;

    StressPostprocessor<dim> stress(parameters.material);
    DataOut<dim>             data_out;
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
    if (parameters.refinement.strategy != RefinementStrategy::global)
      data_out.add_data_vector(refinement_indicator(), "refinement_indicator");

    // Nodal fields on Gamma_C, on a scalar copy of the element: contact
    // pressure l1, gap g0 - u_n, status (-1 not a contact node, 0 separated,
    // 1 in contact and sticking, 2 slipping), tangential traction l2,
    // friction threshold g, tangential slip u_t (2D: along t; 3D: their
    // magnitudes). Zero away from Gamma_C.
    DoFHandler<dim> scalar_dof_handler(triangulation);
    const FE_Q<dim> scalar_fe(fe.degree);
    std::array<TrilinosWrappers::MPI::Vector, 6> contact_fields;
    if (scene.effects().contact)
      {
        scalar_dof_handler.distribute_dofs(scalar_fe);
        const IndexSet owned = scalar_dof_handler.locally_owned_dofs();
        IndexSet       relevant;
        DoFTools::extract_locally_relevant_dofs(scalar_dof_handler, relevant);
        std::array<TrilinosWrappers::MPI::Vector, 6> owned_fields;
        for (auto &f : owned_fields)
          f.reinit(owned, mpi_communicator);
        owned_fields[2] = -1.;

        std::map<types::global_dof_index, unsigned int> node_of_dof;
        for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
          node_of_dof[contact_set.nodes[s].dofs[0]] = s;
        std::vector<types::global_dof_index> vector_dofs(fe.n_dofs_per_cell());
        std::vector<types::global_dof_index> scalar_dofs(
          scalar_fe.n_dofs_per_cell());
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(vector_dofs);
              typename DoFHandler<dim>::active_cell_iterator(
                &triangulation,
                cell->level(),
                cell->index(),
                &scalar_dof_handler)
                ->get_dof_indices(scalar_dofs);
              for (unsigned int i = 0; i < scalar_dofs.size(); ++i)
                {
                  const auto it = node_of_dof.find(
                    vector_dofs[fe.component_to_system_index(0, i)]);
                  if (it == node_of_dof.end() ||
                      !owned.is_element(scalar_dofs[i]))
                    continue;
                  const unsigned int s            = it->second;
                  const double       l1           = contact_set.l1[s];
                  owned_fields[0][scalar_dofs[i]] = l1;
                  owned_fields[1][scalar_dofs[i]] =
                    contact_set.nodes[s].gap0 -
                    contact_set.normal_displacement(solution, s);
                  owned_fields[2][scalar_dofs[i]] = contact_set.status(s);
                  const Tensor<1, dim - 1> vt =
                    contact_set.tangential_displacement(solution, s);
                  owned_fields[3][scalar_dofs[i]] =
                    dim == 2 ? contact_set.l2[s][0] : contact_set.l2[s].norm();
                  owned_fields[4][scalar_dofs[i]] = contact_set.threshold[s];
                  owned_fields[5][scalar_dofs[i]] =
                    dim == 2 ? vt[0] : vt.norm();
                }
            }
        const char *names[] = {"contact_pressure",
                               "gap",
                               "contact_status",
                               "tangential_traction",
                               "friction_threshold",
                               "tangential_slip"};
        for (unsigned int f = 0; f < owned_fields.size(); ++f)
          {
            owned_fields[f].compress(VectorOperation::insert);
            contact_fields[f].reinit(owned, relevant, mpi_communicator);
            contact_fields[f] = owned_fields[f];
            data_out.add_data_vector(scalar_dof_handler,
                                     contact_fields[f],
                                     names[f]);
          }
      }
    data_out.build_patches(mapping, fe.degree);

    const std::string pvtu =
      data_out.write_vtu_with_pvtu_record(parameters.output.directory + "/",
                                          "solution",
                                          cycle,
                                          mpi_communicator,
                                          2);

    // a .pvd record over all cycles so ParaView shows them as a sequence
    pvtu_records.emplace_back(cycle, pvtu);
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      {
        std::ofstream pvd(parameters.output.directory + "/solution.pvd");
        DataOutBase::write_pvd_record(pvd, pvtu_records);
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::write_cycle_table() const
  {
    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return;
    std::ofstream csv(parameters.output.directory + "/cycles.csv");
    csv << "cycle,cells,dofs,contact_nodes,active_nodes,uzawa_steps,"
           "newton_steps,linear_iterations,amg_setups,contact_force,"
           "max_pressure,contact_half_width,pressure_error,u_l2,"
           "l2_error,h1_error,l2_rate,h1_rate,time_setup,time_assembly,"
           "time_solve,time_output,time_reference,memory_mb,"
           "friction_steps,stick_nodes,slip_nodes,tangential_force,"
           "contact_edge_half_width,half_width_error,peak_pressure_error,"
           "hanging_contact_nodes,warm_start,cold_uzawa_steps,"
           "cold_newton_steps,cold_friction_steps,cold_time_solve,"
           "cold_difference_v,cold_difference_l1,time_refine,time_total,"
           "carried_min_l1,carried_max_excess\n";
    csv << std::setprecision(10);
    for (const CycleResult &r : cycle_results)
      csv << r.cycle << ',' << r.n_cells << ',' << r.n_dofs << ','
          << r.n_contact_nodes << ',' << r.n_active << ',' << r.uzawa_steps
          << ',' << r.newton_steps << ',' << r.linear_iterations << ','
          << r.amg_setups << ',' << r.contact_force << ',' << r.max_pressure
          << ',' << r.contact_half_width << ',' << r.pressure_error << ','
          << r.u_l2 << ',' << r.l2_error << ',' << r.h1_error << ','
          << r.l2_rate << ',' << r.h1_rate << ',' << r.time_setup << ','
          << r.time_assembly << ',' << r.time_solve << ',' << r.time_output
          << ',' << r.time_reference << ',' << r.memory_mb << ','
          << r.friction_steps << ',' << r.n_stick << ',' << r.n_slip << ','
          << r.tangential_force << ',' << r.contact_edge_half_width << ','
          << r.half_width_error << ',' << r.peak_pressure_error << ','
          << r.n_hanging_contact << ',' << r.warm_start << ','
          << r.cold_uzawa_steps << ',' << r.cold_newton_steps << ','
          << r.cold_friction_steps << ',' << r.cold_time_solve << ','
          << r.cold_difference_v << ',' << r.cold_difference_l1 << ','
          << r.time_refine << ',' << r.time_total << ',' << r.carried_min_l1
          << ',' << r.carried_max_excess << '\n';
  }

  template <int dim>
  void
  ContactProblem<dim>::print_convergence_table() const
  {
    if (!scene.effects().contact)
      return;
    // one line per cycle: mesh, errors, iterations of each loop, wall times
    const bool    friction = scene.effects().friction != FrictionLaw::none;
    const auto    column   = [](const int w) { return std::setw(w); };
    std::ostream &out      = pcout.get_stream();
    if (!pcout.is_active())
      return;
    out << "\nConvergence table (" << to_string(parameters.refinement.strategy)
        << " refinement"
        << (parameters.refinement.nested_iteration ? ", nested iteration" :
                                                     ", cold starts")
        << "; errors relative; times in s):\n"
        << "cycle    cells     DoFs  Gamma_C(hang)  p L2 err   a err     "
           "p0 err   "
        << (friction ? " loop1" : "")
        << " Uzawa Newton     CG   refine  assemble    solve   total\n";
    for (const CycleResult &r : cycle_results)
      {
        std::ostringstream nodes;
        nodes << r.n_contact_nodes << "(" << r.n_hanging_contact << ")";
        // an error is '-' where the scene gives nothing to compare with
        const auto error = [](const bool known, const double value) {
          std::ostringstream s;
          if (known)
            s << std::scientific << std::setprecision(2) << value;
          else
            s << '-';
          return s.str();
        };
        out << column(5) << r.cycle << column(9) << r.n_cells << column(9)
            << r.n_dofs << column(15) << nodes.str() << column(10)
            << error(scene.exact_pressure() != nullptr, r.pressure_error)
            << column(10)
            << error(parameters.exact.contact_half_width > 0.,
                     r.half_width_error)
            << column(10)
            << error(parameters.exact.peak_pressure > 0.,
                     r.peak_pressure_error);
        if (friction)
          out << column(6) << r.friction_steps;
        out << column(6) << r.uzawa_steps << column(7) << r.newton_steps
            << column(7) << r.linear_iterations << std::fixed
            << std::setprecision(3) << column(9) << r.time_refine << column(10)
            << r.time_assembly << column(9) << r.time_solve << column(8)
            << r.time_total << std::defaultfloat << '\n';
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::write_iteration_table() const
  {
    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0 ||
        !scene.effects().contact)
      return;
    std::ofstream csv(parameters.output.directory + "/iterations.csv");
    csv << "cycle,loop,uzawa_step,newton_step,newton_steps,cg_iterations,"
           "amg_setups,n_active,n_stick,n_slip,gradient,step_length,"
           "change_l1,change_l2,change_g,change_v,violation,complementarity,"
           "time\n";
    csv << std::setprecision(8);
    for (const IterationRecord &r : iteration_log)
      csv << r.cycle << ',' << r.loop << ',' << r.uzawa_step << ',' << r.index
          << ',' << r.newton_steps << ',' << r.cg_iterations << ','
          << r.amg_setups << ',' << r.n_active << ',' << r.n_stick << ','
          << r.n_slip << ',' << r.gradient << ',' << r.step_length << ','
          << r.change_l1 << ',' << r.change_l2 << ',' << r.change_g << ','
          << r.change_v << ',' << r.violation << ',' << r.complementarity << ','
          << r.time << '\n';
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
    indicator_valid                        = true;
    const RefinementParameters &refinement = parameters.refinement;
    indicator = kelly_indicator(mapping, dof_handler, solution);
    if (refinement.strategy == RefinementStrategy::contact &&
        scene.effects().contact)
      {
        TrilinosWrappers::MPI::Vector multipliers, threshold;
        multiplier_fields(multipliers, threshold);
        add_contact_indicator(mapping,
                              dof_handler,
                              solution,
                              multipliers,
                              contact_set,
                              scene.ids_with(BoundaryCondition::contact),
                              parameters.material,
                              refinement.contact_weight,
                              indicator);
      }
    return indicator;
  }

  template <int dim>
  void
  ContactProblem<dim>::mark_cells_for_refinement()
  {
    const RefinementParameters &refinement = parameters.refinement;
    if (refinement.strategy == RefinementStrategy::global)
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            cell->set_refine_flag();
        return;
      }
    parallel::distributed::GridRefinement::refine_and_coarsen_fixed_number(
      triangulation,
      refinement_indicator(),
      refinement.refine_fraction,
      refinement.coarsen_fraction);
  }

  template <int dim>
  void
  ContactProblem<dim>::refine_mesh()
  {
    mark_cells_for_refinement();

    // Nested iteration: v and the multiplier fields go with the cells.
    // The inputs must live until the refinement is executed.
    carried = false;
    TrilinosWrappers::MPI::Vector multipliers, threshold;
    if (parameters.refinement.nested_iteration)
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

  template <int dim>
  void
  ContactProblem<dim>::interpolate_carried_fields()
  {
    if (!transfer)
      return;
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
    carried = true;
  }

  template <int dim>
  void
  ContactProblem<dim>::run()
  {
    // Everything about the input is checked before anything is written.
    {
      TimerOutput::Scope t(computing_timer, "make grid");
      make_grid();
    }
    print_header();

    const bool timing = parameters.output.print_timing;
    const auto timed  = [&](const char *name, const auto &phase) {
      TimerOutput::Scope t(computing_timer, name);
      Timer              timer(mpi_communicator, /*sync_lap_times=*/true);
      phase();
      timer.stop();
      return timer.wall_time();
    };
    const auto seconds = [timing](const double t) {
      std::ostringstream s;
      if (timing)
        s << "  (" << std::fixed << std::setprecision(3) << t << " s)";
      return s.str();
    };

    for (unsigned int cycle = 0; cycle < parameters.refinement.n_cycles;
         ++cycle)
      {
        const double time_refine =
          cycle > 0 ? timed("refine mesh", [&] { refine_mesh(); }) : 0.;

        cycle_results.emplace_back();
        CycleResult &result = cycle_results.back();
        result.cycle        = cycle;
        result.time_setup   = timed("setup system", [&] { setup_system(); });
        result.time_refine  = time_refine + timed("refine mesh", [&] {
                               interpolate_carried_fields();
                             });
        result.n_cells      = triangulation.n_global_active_cells();
        result.n_dofs       = dof_handler.n_dofs();
        pcout << "Cycle " << cycle << ": " << result.n_cells << " cells, "
              << result.n_dofs << " DoFs" << seconds(result.time_setup);
        if (cycle > 0)
          pcout << ", refined (" << to_string(parameters.refinement.strategy)
                << (!carried ? "" :
                    scene.effects().contact ?
                               ", v and multipliers carried over" :
                               ", v carried over")
                << ")" << seconds(result.time_refine);
        pcout << '\n';

        result.time_assembly = timed("assemble", [&] { assemble_system(); });
        pcout << "   assembled A and b" << seconds(result.time_assembly)
              << '\n';
        // the time of the cold start for comparison is reported apart
        result.time_solve = timed("solve", [&] { solve(); });
        result.time_solve -= result.cold_time_solve;
        if (scene.effects().contact)
          pcout << "   contact solved: " << result.uzawa_steps
                << " Uzawa steps, " << result.newton_steps << " Newton steps, "
                << result.linear_iterations << " CG iterations, "
                << result.amg_setups << " AMG set-ups, " << result.n_active
                << " of " << result.n_contact_nodes << " nodes in contact"
                << seconds(result.time_solve) << '\n'
                << std::setprecision(8) << "   total contact force "
                << result.contact_force << " (net load toward the foundation "
                << result.normal_load << "), peak pressure "
                << result.max_pressure << ", contact half-width "
                << result.contact_half_width << " (nodes), "
                << result.contact_edge_half_width << " (edges extrapolated)";
        if (scene.exact_pressure() != nullptr)
          pcout << ", pressure error (rel. L2) " << result.pressure_error;
        if (parameters.exact.contact_half_width > 0.)
          pcout << ", half-width error " << result.half_width_error;
        if (parameters.exact.peak_pressure > 0.)
          pcout << ", peak error " << result.peak_pressure_error;
        if (result.n_hanging_contact > 0)
          pcout << "\n   " << result.n_hanging_contact
                << " hanging nodes on Gamma_C (no contact condition of their "
                   "own)";
        if (result.cold_uzawa_steps > 0)
          pcout << "\n   nested iteration against a cold start: Uzawa "
                << result.uzawa_steps << " vs " << result.cold_uzawa_steps
                << ", Newton " << result.newton_steps << " vs "
                << result.cold_newton_steps << ", loop 1 "
                << result.friction_steps << " vs " << result.cold_friction_steps
                << ", time " << result.time_solve << " s vs "
                << result.cold_time_solve << " s; solutions differ by "
                << result.cold_difference_v << " (v, energy norm), "
                << result.cold_difference_l1 << " (l1)";
        if (scene.effects().friction != FrictionLaw::none)
          pcout << "\n   friction: " << result.n_stick << " stick, "
                << result.n_slip << " slip nodes, total tangential force "
                << result.tangential_force
                << (result.friction_steps > 0 ?
                      ", " + std::to_string(result.friction_steps) +
                        " threshold (loop 1) steps" :
                      std::string());
        if (scene.effects().contact)
          pcout << std::scientific << std::setprecision(2)
                << "\n   Uzawa contraction rate " << result.uzawa_rate
                << ": the last change of l1 understates its error, estimated "
                << result.l1_error_estimate;
        if (scene.effects().contact)
          pcout << std::defaultfloat << '\n';
        else
          pcout << "   one linear elasticity solve: "
                << result.linear_iterations << " CG iterations"
                << seconds(result.time_solve) << '\n';

        if (parameters.solver.time_reference_solve && scene.effects().contact)
          pcout << "   reference: one linear solve on this mesh "
                << result.reference_iterations << " CG iterations"
                << seconds(result.time_reference)
                << ", contact / linear = " << std::fixed << std::setprecision(2)
                << (result.time_assembly + result.time_solve) /
                     (result.time_assembly + result.time_reference)
                << std::defaultfloat << " (assembly included)\n";
        {
          Utilities::System::MemoryStats stats;
          Utilities::System::get_memory_stats(stats);
          result.memory_mb =
            Utilities::MPI::sum(static_cast<double>(stats.VmHWM),
                                mpi_communicator) /
            1024.;
        }
        timed("postprocess", [&] { postprocess(result); });
        pcout << std::scientific << std::setprecision(6)
              << "   ||u||_L2 = " << result.u_l2;
        if (scene.exact_displacement() != nullptr)
          pcout << ", error L2 = " << result.l2_error
                << ", H1 = " << result.h1_error;
        pcout << std::defaultfloat << '\n';

        // The output folder is made only now: a run that fails on its first
        // mesh (bad input found late, no equilibrium) writes nothing.
        if (cycle == 0)
          {
            if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
              std::filesystem::create_directories(parameters.output.directory);
            MPI_Barrier(mpi_communicator);
          }
        result.time_output = timed("output", [&] { output_results(cycle); });
        result.time_total =
          (cycle > 0 ? cycle_results[cycle - 1].time_total : 0.) +
          result.time_refine + result.time_setup + result.time_assembly +
          result.time_solve + result.time_output;
        write_cycle_table();
        write_iteration_table();
      }

    print_convergence_table();
    if (scene.exact_displacement() != nullptr)
      {
        pcout << "\nConvergence (rates for h halved per cycle):\n"
              << "cycle       DoFs     L2 error  rate     H1 error  rate\n";
        for (const CycleResult &r : cycle_results)
          pcout << std::setw(5) << r.cycle << std::setw(11) << r.n_dofs
                << std::scientific << std::setprecision(4) << std::setw(13)
                << r.l2_error << std::fixed << std::setprecision(2)
                << std::setw(6) << r.l2_rate << std::scientific
                << std::setprecision(4) << std::setw(13) << r.h1_error
                << std::fixed << std::setprecision(2) << std::setw(6)
                << r.h1_rate << std::defaultfloat << '\n';
      }
    pcout << "Output written to " << parameters.output.directory << "/\n";
    if (parameters.output.print_timing)
      computing_timer.print_summary();
  }

  template class ContactProblem<2>;
  template class ContactProblem<3>;
} // namespace dualcontact
