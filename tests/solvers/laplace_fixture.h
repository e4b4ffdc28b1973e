#ifndef pg_tests_solvers_laplace_fixture_h
#define pg_tests_solvers_laplace_fixture_h

// The linear system of the solver tests (amg_cache_01, amg_operator_01): a
// scalar Laplace-plus-mass matrix, Q1 on 48 x 48 cells of the unit square
// (2,401 DoFs: above ML's coarse size of 2000), b_i = 1 + 0.001 i, and CG
// with ML to 1e-10 ('Reuse AMG' on, translations as near-null space).

#include <pg/solvers/linear_solver.h>
#include <pg/solvers/solver_parameters.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/numerics/matrix_creator.h>

struct LaplaceFixture
{
  LaplaceFixture()
    : fe(1)
    , dof_handler(triangulation)
  {
    using namespace dealii;
    GridGenerator::subdivided_hyper_cube(triangulation, 48);
    dof_handler.distribute_dofs(fe);
    const IndexSet         owned = dof_handler.locally_owned_dofs();
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp);
    for (auto *M : {&matrix, &laplace, &mass})
      M->reinit(owned, owned, dsp, MPI_COMM_WORLD);
    MatrixCreator::create_laplace_matrix(dof_handler, QGauss<2>(2), laplace);
    MatrixCreator::create_mass_matrix(dof_handler, QGauss<2>(2), mass);
    matrix.copy_from(laplace);
    matrix.add(1., mass);

    rhs.reinit(owned, MPI_COMM_WORLD);
    for (const auto i : owned)
      rhs[i] = 1. + 0.001 * i;
    rhs.compress(VectorOperation::insert);

    parameters.type            = "cg";
    parameters.tolerance       = 1e-10;
    parameters.near_null_space = "translations";
    parameters.vc_solver       = "automatic";
    parameters.reuse_amg       = true;
  }

  /** |b - M x| / |b| */
  double
  relative_residual(const pg::LinearAlgebra::SparseMatrix &M,
                    const pg::LinearAlgebra::Vector       &x) const
  {
    pg::LinearAlgebra::Vector r(rhs);
    M.vmult(r, x);
    r -= rhs;
    return r.l2_norm() / rhs.l2_norm();
  }

  dealii::Triangulation<2> triangulation;
  dealii::FE_Q<2>          fe;
  dealii::DoFHandler<2>    dof_handler;
  /** matrix = laplace + mass */
  pg::LinearAlgebra::SparseMatrix matrix, laplace, mass;
  pg::LinearAlgebra::Vector       rhs;
  pg::Parameters::LinearSolver    parameters;
};

#endif
