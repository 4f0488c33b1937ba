// Rigid motions: the scene check that refuses a body nothing holds, and the
// rigid-body modes handed to the AMG, which must span the kernel of the
// unconstrained stiffness matrix.
#include <deal.II/base/mpi.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <dualcontact/elasticity.h>
#include <dualcontact/input_error.h>
#include <dualcontact/parameters.h>
#include <dualcontact/scene.h>

#include <catch2/catch.hpp>

#include <Epetra_MultiVector.h>

#include "test_tools.h"

using namespace dualcontact;
using dualcontact_test::catch_input_error;
using dualcontact_test::CaughtError;

namespace
{
  /** Build the mesh of a 2x1 rectangle with the given conditions and run
   * Scene::check_rigid_motions on it. */
  CaughtError
  check_rectangle(const std::string &conditions)
  {
    Parameters parameters;
    parameters.read_string("subsection Geometry\n"
                           "  set Upper right corner = 2, 1\n"
                           "  set Subdivisions = 2, 1\n"
                           "end\n"
                           "subsection Refinement\n"
                           "  set Initial global refinement = 1\n"
                           "end\n"
                           "subsection Boundary conditions\n"
                           "  set Conditions = " +
                           conditions +
                           "\n"
                           "end\n");
    const Scene<2>                          scene(parameters);
    parallel::distributed::Triangulation<2> triangulation(MPI_COMM_WORLD);
    scene.create_mesh(triangulation);
    return catch_input_error([&] { scene.check_rigid_motions(triangulation); });
  }
} // namespace

TEST_CASE("A rectangle held only by a slider at its bottom is rejected: "
          "it could slide along x",
          "[rigid motions][mpi]")
{
  const CaughtError error = check_rectangle("2: normal fixed");
  REQUIRE(error.thrown);
  CHECK(error.code == exit_inconsistent);
  CHECK(error.message.find("1 rigid-body motion(s)") != std::string::npos);
}

TEST_CASE("A rectangle with no condition at all leaves all 3 rigid motions "
          "free",
          "[rigid motions][mpi]")
{
  const CaughtError error = check_rectangle("");
  REQUIRE(error.thrown);
  CHECK(error.code == exit_inconsistent);
  CHECK(error.message.find("3 rigid-body motion(s)") != std::string::npos);
}

TEST_CASE("A rectangle on sliders at its bottom and its left is held",
          "[rigid motions][mpi]")
{
  CHECK_FALSE(check_rectangle("0: normal fixed, 2: normal fixed").thrown);
}

TEST_CASE("A rectangle fixed on its left is held", "[rigid motions][mpi]")
{
  CHECK_FALSE(check_rectangle("0: fixed").thrown);
}

TEST_CASE("A scene with a contact boundary may leave rigid motions to the "
          "contact (semi-coercive)",
          "[rigid motions][mpi]")
{
  CHECK_FALSE(check_rectangle("2: contact").thrown);
}

TEST_CASE("The rigid-body modes lie in the kernel of the unconstrained "
          "stiffness matrix",
          "[rigid motions][elasticity][mpi]")
{
  const MPI_Comm comm = MPI_COMM_WORLD;
  Parameters     parameters;
  parameters.read_string("subsection Geometry\n"
                         "  set Lower left corner = -1, 0\n"
                         "  set Upper right corner = 2, 1\n"
                         "  set Subdivisions = 3, 1\n"
                         "end\n"
                         "subsection Material\n"
                         "  set Young's modulus = 210e9\n"
                         "  set Poisson's ratio = 0.3\n"
                         "end\n"
                         "subsection Refinement\n"
                         "  set Initial global refinement = 3\n"
                         "end\n");
  const Scene<2>                          scene(parameters);
  parallel::distributed::Triangulation<2> triangulation(comm);
  scene.create_mesh(triangulation);

  const MappingQ<2> mapping(1);
  const FESystem<2> fe(FE_Q<2>(1), 2);
  DoFHandler<2>     dof_handler(triangulation);
  dof_handler.distribute_dofs(fe);
  const IndexSet locally_owned = dof_handler.locally_owned_dofs();
  IndexSet       locally_relevant;
  DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant);

  // no constraints at all: A is singular with the rigid motions as kernel
  AffineConstraints<double> constraints;
  constraints.reinit(locally_relevant);
  constraints.close();

  DynamicSparsityPattern dsp(locally_relevant);
  DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
  SparsityTools::distribute_sparsity_pattern(dsp,
                                             locally_owned,
                                             comm,
                                             locally_relevant);
  TrilinosWrappers::SparseMatrix matrix;
  matrix.reinit(locally_owned, locally_owned, dsp, comm);
  TrilinosWrappers::MPI::Vector rhs(locally_owned, comm);
  assemble_elasticity(mapping, dof_handler, scene, constraints, matrix, rhs);

  for (const bool with_rotations : {true, false})
    {
      const std::unique_ptr<Epetra_MultiVector> modes =
        rigid_body_modes(mapping,
                         dof_handler,
                         matrix,
                         with_rotations,
                         scene.center(),
                         scene.characteristic_length());
      const int n_modes = modes->NumVectors();
      CHECK(n_modes == (with_rotations ? 3 : 2));

      // the scale of A: its action on a vector of entries in [-1, 1]
      Epetra_MultiVector random(modes->Map(), 1);
      random.SetSeed(12345);
      random.Random();
      Epetra_MultiVector a_random(matrix.trilinos_matrix().RangeMap(), 1);
      matrix.trilinos_matrix().Multiply(false, random, a_random);
      double scale = 0;
      a_random.NormInf(&scale); // global over all ranks

      Epetra_MultiVector a_modes(matrix.trilinos_matrix().RangeMap(), n_modes);
      matrix.trilinos_matrix().Multiply(false, *modes, a_modes);
      std::vector<double> residual(n_modes), size(n_modes);
      a_modes.NormInf(residual.data());
      modes->NormInf(size.data());

      INFO("with rotations: " << with_rotations << ", |A r|_inf = " << scale);
      CHECK(scale > 0);
      for (int m = 0; m < n_modes; ++m)
        {
          INFO("mode " << m << ": |m|_inf = " << size[m]
                       << ", |A m|_inf = " << residual[m]);
          // a mode is not zero, and in the kernel up to round-off
          CHECK(size[m] >= 0.5);
          CHECK(residual[m] < 1e-10 * scale);
        }
    }
}
