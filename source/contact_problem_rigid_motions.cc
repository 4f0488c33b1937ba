// ContactProblem, the rigid motions that nothing holds: combinations of
// the rigid motions of the bodies that no prescribed displacement and no
// contact node resists. The proximal term holds them in each Uzawa step; the
// measures of convergence leave them out (doc/theory.md §6).
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
#include <limits>

namespace dualcontact
{
  namespace
  {
    /**
     * The rigid motions of the bodies as vectors of nodal values: motion i
     * of the whole mesh times the indicator of body b, for each body b.
     */
    template <int dim>
    std::vector<TrilinosWrappers::MPI::Vector>
    rigid_motions_of_bodies(const Mapping<dim>                  &mapping,
                            const DoFHandler<dim>               &dof_handler,
                            const Scene<dim>                    &scene,
                            const TrilinosWrappers::MPI::Vector &body_plus_one,
                            const unsigned int                   n_bodies,
                            const IndexSet &locally_owned_dofs,
                            const MPI_Comm  mpi_communicator)
    {
      const unsigned int n_per_body = Scene<dim>::n_rigid_motions;
      std::vector<TrilinosWrappers::MPI::Vector> motions;
      for (unsigned int b = 0; b < n_bodies; ++b)
        for (unsigned int i = 0; i < n_per_body; ++i)
          {
            TrilinosWrappers::MPI::Vector w(locally_owned_dofs,
                                            mpi_communicator);
            interpolate_field<dim>(
              mapping,
              dof_handler,
              [&](const Point<dim> &x) { return scene.rigid_motion(i, x); },
              w);
            for (const types::global_dof_index dof : locally_owned_dofs)
              if (static_cast<unsigned int>(body_plus_one[dof]) != b + 1)
                w[dof] = 0.;
            w.compress(VectorOperation::insert);
            motions.push_back(std::move(w));
          }
      return motions;
    }

    /**
     * The contact nodes' Gram matrices: how far a combination of the
     * `motions` moves the contact nodes' constraints (`contact_held`, along
     * n_s without friction, whole with it), and how far it moves them at
     * all (`contact_moved`, the relative motion whole). Returns the
     * measure of the contact nodes.
     */
    template <int dim>
    double
    contact_gram_matrices(
      const ContactSet<dim>                            &contact_set,
      const std::vector<TrilinosWrappers::MPI::Vector> &motions,
      const MPI_Comm                                    mpi_communicator,
      FullMatrix<double>                               &contact_held,
      FullMatrix<double>                               &contact_moved)
    {
      const unsigned int n = motions.size();
      contact_held.reinit(n, n);
      contact_moved.reinit(n, n);
      double                                     area = 0.;
      std::vector<Tensor<1, dim>>                relative(n);
      std::vector<TrilinosWrappers::MPI::Vector> ghosted;
      for (const TrilinosWrappers::MPI::Vector &w : motions)
        ghosted.push_back(contact_set.with_masters(w));
      for (unsigned int s = 0; s < contact_set.n_local_nodes(); ++s)
        {
          const ContactNode<dim> &node = contact_set.nodes[s];
          area += node.weight;
          for (unsigned int k = 0; k < n; ++k)
            for (unsigned int c = 0; c < dim; ++c)
              {
                relative[k][c] = ghosted[k][node.dofs[c]];
                for (const MasterTerm<dim> &master : node.masters)
                  relative[k][c] -=
                    master.coefficient * ghosted[k][master.dofs[c]];
              }
          for (unsigned int k = 0; k < n; ++k)
            for (unsigned int l = 0; l < n; ++l)
              {
                const double whole = node.weight * (relative[k] * relative[l]);
                contact_moved(k, l) += whole;
                contact_held(k, l) += contact_set.friction ?
                                        whole :
                                        node.weight *
                                          (relative[k] * node.normal) *
                                          (relative[l] * node.normal);
              }
        }
      Utilities::MPI::sum(contact_held, mpi_communicator, contact_held);
      Utilities::MPI::sum(contact_moved, mpi_communicator, contact_moved);
      return Utilities::MPI::sum(area, mpi_communicator);
    }

    /** All eigenvalues and eigenvectors of the symmetric `matrix`. */
    void
    all_eigen(const FullMatrix<double> &matrix,
              Vector<double>           &values,
              FullMatrix<double>       &vectors)
    {
      LAPACKFullMatrix<double> m(matrix.m());
      m = matrix;
      m.compute_eigenvalues_symmetric(-std::numeric_limits<double>::max(),
                                      std::numeric_limits<double>::max(),
                                      0.,
                                      values,
                                      vectors);
    }

    /**
     * The combinations Z that no support moves (G_D z = 0, `gram` = G_D),
     * orthonormal.
     */
    std::vector<Vector<double>>
    unsupported_combinations(const FullMatrix<double> &gram,
                             const double              support_measure)
    {
      const unsigned int          n = gram.m();
      std::vector<Vector<double>> unsupported;
      Vector<double>              values;
      FullMatrix<double>          vectors;
      all_eigen(gram, values, vectors);
      for (unsigned int k = 0; k < values.size(); ++k)
        if (values[k] <= 1e-10 * std::max(support_measure, 1e-300))
          {
            Vector<double> z(n);
            for (unsigned int i = 0; i < n; ++i)
              z[i] = vectors(i, k);
            unsupported.push_back(z);
          }
      return unsupported;
    }

    /**
     * The free combinations among Z = `unsupported`, and whether they keep
     * the start's value (find_free_motions() says which and why).
     */
    std::vector<std::pair<Vector<double>, bool>>
    free_combinations_of(const std::vector<Vector<double>> &unsupported,
                         const FullMatrix<double>          &contact_held,
                         const FullMatrix<double>          &contact_moved,
                         const double                       measure,
                         const bool                         several_bodies)
    {
      const unsigned int n   = contact_held.m();
      const unsigned int n_z = unsupported.size();
      // the contact's Gram matrices on Z (z_k orthonormal)
      const auto on_unsupported = [&](const FullMatrix<double> &matrix) {
        FullMatrix<double> reduced(n_z, n_z);
        Vector<double>     mz(n);
        for (unsigned int k = 0; k < n_z; ++k)
          {
            matrix.vmult(mz, unsupported[k]);
            for (unsigned int l = 0; l < n_z; ++l)
              reduced(l, k) = unsupported[l] * mz;
          }
        return reduced;
      };
      const auto combination = [&](const auto &coefficient) {
        Vector<double> c(n);
        for (unsigned int k = 0; k < n_z; ++k)
          c.add(coefficient(k), unsupported[k]);
        return c;
      };

      // A combination of Z that moves no contact node (H c = 0) is free;
      // among the others (H^(-1/2) whitened, so that each eigenvalue is the
      // held fraction of a motion, the mean of cos^2 of the angle between it
      // and n_s) those that G holds by less than 5 %: they move the contact
      // nodes at right angles to n_s, to within about 13 degrees on average.
      // That is a rigid plane's tangential motion (exactly at right angles),
      // and between two bodies the sideways motions that only the
      // discretisation error of the normals holds: two identical balls press
      // along their plane of symmetry, whose normal the bisector n_s gives up
      // to that error, and in the linear model (small sliding) the upper
      // ball's sideways translations and its rotation about the axis are
      // free. Held by that error (0.02-0.6 % of them in prm/two_spheres.prm;
      // the motions that the contact holds, 94-100 %), they would take a step
      // of F / chi in each Uzawa step along the force F that the same error
      // leaves, and d(v) would not fall.
      // The free combinations, and whether they keep the start's value:
      // those that something holds weakly, and between bodies all (a body's
      // motion relative to another, which the first Newton solve leaves as
      // inexact as its tolerance, would stay there)
      std::vector<std::pair<Vector<double>, bool>> free_combinations;
      if (n_z > 0)
        {
          Vector<double>     h_values;
          FullMatrix<double> h_vectors;
          all_eigen(on_unsupported(contact_moved), h_values, h_vectors);
          std::vector<Vector<double>> whitened; // in the coordinates of Z
          for (unsigned int k = 0; k < n_z; ++k)
            {
              const auto column = [&](const unsigned int i) {
                return h_vectors(i, k);
              };
              if (h_values[k] <= 1e-10 * measure)
                free_combinations.emplace_back(combination(column),
                                               several_bodies);
              else
                {
                  Vector<double> c(n_z);
                  for (unsigned int i = 0; i < n_z; ++i)
                    c[i] = column(i) / std::sqrt(h_values[k]);
                  whitened.push_back(c);
                }
            }
          const unsigned int r = whitened.size();
          if (r > 0)
            {
              const FullMatrix<double> held = on_unsupported(contact_held);
              FullMatrix<double>       reduced(r, r);
              Vector<double>           gc(n_z);
              for (unsigned int k = 0; k < r; ++k)
                {
                  held.vmult(gc, whitened[k]);
                  for (unsigned int l = 0; l < r; ++l)
                    reduced(l, k) = whitened[l] * gc;
                }
              LAPACKFullMatrix<double> g(r);
              g = reduced;
              Vector<double>     values;
              FullMatrix<double> vectors;
              g.compute_eigenvalues_symmetric(
                -std::numeric_limits<double>::max(), 0.05, 0., values, vectors);
              for (unsigned int e = 0; e < values.size(); ++e)
                {
                  Vector<double> c_z(n_z);
                  for (unsigned int k = 0; k < r; ++k)
                    c_z.add(vectors(k, e), whitened[k]);
                  free_combinations.emplace_back(
                    combination([&](const unsigned int i) { return c_z[i]; }),
                    several_bodies || values[e] > 1e-10);
                }
            }
        }
      return free_combinations;
    }
    /**
     * The combination sum_k c_k m_k of the bodies' rigid `motions`, and how
     * much of it is rotation: sum_k |c_k| over the rotations.
     */
    template <int dim>
    std::pair<TrilinosWrappers::MPI::Vector, double>
    combine_motions(const Vector<double>                             &c,
                    const std::vector<TrilinosWrappers::MPI::Vector> &motions,
                    const IndexSet &locally_owned_dofs,
                    const MPI_Comm  mpi_communicator)
    {
      const unsigned int            n_per_body = Scene<dim>::n_rigid_motions;
      const unsigned int            n          = motions.size();
      TrilinosWrappers::MPI::Vector w(locally_owned_dofs, mpi_communicator);
      double                        rotation = 0.;
      for (unsigned int k = 0; k < n; ++k)
        {
          w.add(c[k], motions[k]);
          if (k % n_per_body >= dim)
            rotation += std::abs(c[k]);
        }
      return {std::move(w), rotation};
    }
  } // namespace

  template <int dim>
  void
  ContactProblem<dim>::find_free_motions()
  {
    // Which combinations c of the rigid motions m_k of the bodies (motion
    // i of body b, zero on the other bodies) does nothing hold? The
    // prescribed displacements hold those with G_D c != 0 (Scene), the
    // contact those that move a contact node's constraint: B_s c, the
    // relative motion of slave node s and the master point it faces (its
    // own motion against the obstacle), along n_s without friction (the
    // contact pushes along n_s only), whole with friction (which holds
    // the tangential motions too, also where a body near its sliding
    // limit slips). A combination is free iff c^T (G_D + G_C) c = 0.
    const Bodies<dim>        bodies(triangulation);
    double                   measure = 0.;
    const FullMatrix<double> gram =
      scene.rigid_motion_gram(triangulation, measure, &bodies);

    // the motions as vectors of nodal values
    const TrilinosWrappers::MPI::Vector body_plus_one =
      bodies.of_dofs_plus_one(dof_handler);
    const std::vector<TrilinosWrappers::MPI::Vector> motions =
      rigid_motions_of_bodies(mapping,
                              dof_handler,
                              scene,
                              body_plus_one,
                              bodies.size(),
                              locally_owned_dofs,
                              mpi_communicator);

    // the contact nodes' Gram matrices
    FullMatrix<double> contact_held, contact_moved;
    const double       area = contact_gram_matrices(
      contact_set, motions, mpi_communicator, contact_held, contact_moved);
    const double support_measure = measure;
    measure += area;

    // The supports first: a prescribed displacement holds every motion it
    // moves at all, however little of it (a hard constraint, against which
    // the body is as stiff as its material). The candidates are the
    // combinations Z that no support moves (G_D z = 0); the contact decides
    // among them.
    const std::vector<Vector<double>> unsupported =
      unsupported_combinations(gram, support_measure);
    const std::vector<std::pair<Vector<double>, bool>> free_combinations =
      free_combinations_of(
        unsupported, contact_held, contact_moved, measure, bodies.size() > 1);

    // each free combination as a vector of the condensed space, improved
    // by one step of inverse iteration with K = A + chi M, then orthonormal
    // in the Euclidean inner product of the vectors, the one d(v) is
    // measured in (Gram-Schmidt). The inverse iteration matters where
    // hanging nodes lie on a curved boundary: a hanging node sits on the
    // curve, not at the middle of its parents, so the interpolated rotation
    // is not in the constrained space, and the motion nothing holds is a
    // rotation plus a small deformation near those nodes, which K^-1
    // brings out (a translation is kept exactly: K w = chi M w).
    free_motions.clear();
    anchored_at_start.clear();
    std::unique_ptr<ElasticSolver<dim>> solver;
    for (const auto &[c, at_start] : free_combinations)
      {
        auto [w, rotation] = combine_motions<dim>(c,
                                                  motions,
                                                  locally_owned_dofs,
                                                  mpi_communicator);
        homogeneous_constraints.distribute(w);
        // a translation is exact in the constrained space: no solve
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
            anchored_at_start.push_back(at_start);
          }
      }
  }

  template void
  ContactProblem<2>::find_free_motions();
  template void
  ContactProblem<3>::find_free_motions();
} // namespace dualcontact
