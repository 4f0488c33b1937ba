// ContactProblem, the rigid motions that nothing holds: combinations of
// the rigid motions that no prescribed displacement and no contact node
// resists. The proximal term holds them in each Uzawa step; the measures
// of convergence leave them out (doc/theory.md §6).
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
        interpolate_field<dim>(
          mapping,
          dof_handler,
          [&](const Point<dim> &x) {
            Tensor<1, dim> m;
            for (unsigned int i = 0; i < n; ++i)
              m += eigenvectors(i, k) * scene.rigid_motion(i, x);
            return m;
          },
          w);
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


  template void
  ContactProblem<2>::find_free_motions();
  template void
  ContactProblem<3>::find_free_motions();
} // namespace dualcontact
