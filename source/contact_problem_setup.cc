// ContactProblem: the mesh and the system on it. make_grid() builds and
// checks the initial mesh; setup_system() numbers the DoFs, makes the
// constraints (hanging nodes, Dirichlet, sliders, and on a pair of bodies
// the master couplings), the contact set and the sparsity pattern.
#include <deal.II/base/utilities.h>

#include <deal.II/dofs/dof_renumbering.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <deal.II/numerics/vector_tools.h>

#include <dualcontact/contact_problem.h>
#include <dualcontact/input_error.h>
#include <dualcontact/plausibility.h>
#include <dualcontact/run_size.h>

#include <algorithm>
#include <iostream>

namespace dualcontact
{
  namespace
  {
    // What the contact set reads of the scene: the contact ids, the pairs,
    // the obstacle, the friction and the body's size and centre.
    template <int dim>
    ContactSetup<dim>
    contact_setup(const Scene<dim> &scene)
    {
      ContactSetup<dim> input;
      input.contact_ids           = scene.contact_ids();
      input.pairs                 = scene.contact_pairs();
      input.node_to_segment       = scene.pairs_node_to_segment();
      input.obstacle              = &scene.obstacle();
      input.friction_law          = &scene.effects().friction_law();
      input.friction_parameter    = scene.friction_function();
      input.characteristic_length = scene.characteristic_length();
      input.center                = scene.center();
      return input;
    }
  } // namespace

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
    const RunSizeCheck size(parameters, mpi_communicator, scene.cell_kind());
    scene.create_mesh(triangulation, [&size](const double n_cells) {
      size.check(n_cells, false);
    });
    size.check(triangulation.n_global_active_cells(), true);
    size.warn(triangulation.n_global_active_cells());
    // a mapping of degree k follows the boundary where the shape names
    // its curved parts
    const std::string warning =
      scene.geometry().mapping_warning(parameters.discretization.degree);
    if (!warning.empty() &&
        Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      std::cerr << "dualcontact: warning: " << warning << std::endl;
    scene.check_rigid_motions(triangulation);
    check_initial_position(triangulation, scene);
    // a checkpoint keeps the mesh as p4est's forest
    if (parameters.output.checkpoint_interval > 0 && step_times.size() > 1 &&
        scene.discretization().mesh_is_replicated())
      throw InputError(
        "<Output/Checkpoint interval> needs a mesh of quadrilaterals or "
        "hexahedra (a checkpoint keeps p4est's forest); this scene's mesh is "
        "of triangles or tetrahedra: set it to 0.",
        exit_inconsistent);
    // every cell has a material: once <Material/Materials by id> lists
    // some, a cell of an id it does not name (and not 0) is bad input
    types::material_id missing = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() &&
          !parameters.material.has(cell->material_id()))
        missing = std::max<types::material_id>(missing, cell->material_id());
    missing = Utilities::MPI::max(missing, mpi_communicator);
    if (missing > 0)
      throw InputError("The mesh has cells of material id " +
                         std::to_string(missing) +
                         ", which <Material/Materials by id> does not list "
                         "(id 0 takes <Material/Young's modulus> and "
                         "<Poisson's ratio>): give it its 'E, nu'.",
                       exit_inconsistent);
    // a probe outside the body is bad input: found before the first solve
    probes.check_inside(mapping, triangulation);
  }

  template <int dim>
  MeshRecord
  ContactProblem<dim>::setup_system(const unsigned int cycle)
  {
    TimerOutput::Scope t(computing_timer, "setup system");
    dof_handler.distribute_dofs(fe);
    // the dim DoFs of each support point next to each other, as the AMG
    // takes them (elasticity.cc); FE_Q(1) numbers them so already, FE_Q(k)
    // numbers an edge's or face's inner DoFs component by component
    if (fe.degree > 1)
      DoFRenumbering::support_point_wise(dof_handler);
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);

    make_constraints();

    // the contact nodes, their weights and gaps (doc/theory.md §4), and on
    // a pair of bodies their master nodes (doc/two_bodies.md)
    if (scene.effects().contact)
      {
        contact_set.setup(mapping,
                          dof_handler,
                          hanging_node_constraints,
                          constraints,
                          contact_setup(scene));
        AssertThrow(contact_set.n_global_nodes() > 0,
                    ExcMessage("The contact boundary has no contact nodes."));
        make_constraints(/*contact_set_built=*/true);
      }

    // The elements' couplings, and on a pair those of each slave node with
    // its master nodes, rows of other ranks included: the Newton matrix
    // adds its contact terms there (newton_solver.cc).
    IndexSet rows = locally_relevant_dofs;
    rows.add_indices(
      contact_set.coupled_rows(constraints, dof_handler.n_dofs()));
    DynamicSparsityPattern dsp(rows);
    DoFTools::make_sparsity_pattern(dof_handler,
                                    dsp,
                                    constraints,
                                    /*keep_constrained_dofs=*/false);
    contact_set.add_pair_couplings(dsp, constraints);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               locally_owned_dofs,
                                               mpi_communicator,
                                               rows);
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
    if (mixed)
      mixed->setup(dof_handler, constraints);
    return {cycle, triangulation.n_global_active_cells(), dof_handler.n_dofs()};
  }

  template <int dim>
  void
  ContactProblem<dim>::make_constraints(const bool contact_set_built)
  {
    // A slave node's coupling adds its forces and its Newton terms at the
    // master DoFs through these constraints. A master DoF off this rank's
    // cells that a slider or a clamp holds (the master body's end on a
    // symmetry plane) must be known as constrained here too, or its force
    // goes into an equation that the solve does not have: the Newton
    // gradient then keeps a part that no step reduces. Its owner has the
    // constraint and sends it.
    const bool couple_masters =
      contact_set_built && scene.effects().contact && contact_set.has_pairs();
    IndexSet relevant = locally_relevant_dofs;
    if (couple_masters)
      relevant.add_indices(contact_set.master_dofs(dof_handler.n_dofs()));
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
        c.reinit(relevant);
        c.merge(hanging_node_constraints,
                AffineConstraints<double>::no_conflicts_allowed,
                /*allow_different_local_lines=*/couple_masters);
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
        if (couple_masters)
          c.make_consistent_in_parallel(locally_owned_dofs,
                                        relevant,
                                        mpi_communicator);
        c.close();
      }
  }

  template void
  ContactProblem<2>::make_grid();
  template MeshRecord
  ContactProblem<2>::setup_system(const unsigned int cycle);
  template void
  ContactProblem<2>::make_constraints(const bool contact_set_built);
  template void
  ContactProblem<3>::make_grid();
  template MeshRecord
  ContactProblem<3>::setup_system(const unsigned int cycle);
  template void
  ContactProblem<3>::make_constraints(const bool contact_set_built);
} // namespace dualcontact
