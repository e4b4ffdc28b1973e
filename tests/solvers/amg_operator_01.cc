// 'Linear solver/AMG operator': solve_linear_system() builds ML's hierarchy
// from the matrix that its amg_operator returns, and still solves with the
// given matrix. On a scalar Laplace-plus-mass matrix A (Q1, 48 x 48 cells,
// 2,401 DoFs), against the plain solve (0):
//  1. operator = A itself: the iterations of the plain solve, one call;
//  2. a second solve with the cache: the hierarchy is reused, no call;
//  3. operator = the Laplacian L alone (close to A in energy, like a Q1
//     tangent to a PG tangent): CG on A converges, in at most twice the
//     iterations of A's own hierarchy;
//  4. operator returns nullptr (pg: a Q1 cell failed): built from A;
//  5. operator = D A D with D_ii = 10^(4 frac(0.618 i)) (scattered over
//     four decades, far from A in energy): CG on A does not reach the
//     tolerance within 1000 iterations, so the hierarchy is rebuilt from A
//     and the solve repeated (its count is the 1000 failed iterations plus
//     those of case 1; 2 hierarchies).
// Every solution is checked against its residual |b - M x| <= 1e-10 |b|.

#include <pg/solvers/linear_solver.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/numerics/matrix_creator.h>

#include "../tests.h"

using namespace pg;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  Triangulation<2> tria;
  GridGenerator::subdivided_hyper_cube(tria, 48);
  const FE_Q<2> fe(1);
  DoFHandler<2> dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  const IndexSet owned = dof_handler.locally_owned_dofs();

  DynamicSparsityPattern dsp(dof_handler.n_dofs());
  DoFTools::make_sparsity_pattern(dof_handler, dsp);
  pg::LinearAlgebra::SparseMatrix A, L, mass, scaled;
  for (auto *M : {&A, &L, &mass, &scaled})
    M->reinit(owned, owned, dsp, MPI_COMM_WORLD);
  MatrixCreator::create_laplace_matrix(dof_handler, QGauss<2>(2), L);
  MatrixCreator::create_mass_matrix(dof_handler, QGauss<2>(2), mass);
  A.copy_from(L);
  A.add(1., mass);
  scaled.copy_from(A);
  const auto d = [](const types::global_dof_index i) {
    const double x = 0.618034 * i;
    return std::pow(10., 4. * (x - std::floor(x)));
  };
  for (auto entry = scaled.begin(); entry != scaled.end(); ++entry)
    entry->value() *= d(entry->row()) * d(entry->column());
  pg::LinearAlgebra::Vector rhs(owned, MPI_COMM_WORLD), x(rhs);
  for (const auto i : owned)
    rhs[i] = 1. + 0.001 * i;
  rhs.compress(VectorOperation::insert);

  Parameters::LinearSolver parameters;
  parameters.type            = "cg";
  parameters.tolerance       = 1e-10;
  parameters.near_null_space = "translations";
  parameters.vc_solver       = "automatic";
  parameters.reuse_amg       = true;

  unsigned int calls = 0;
  const auto   solve = [&](const pg::LinearAlgebra::SparseMatrix &M,
                         AMGCache                              &cache,
                         const pg::LinearAlgebra::SparseMatrix *hierarchy,
                         const bool                             with_operator) {
    x = 0;
    std::function<const pg::LinearAlgebra::SparseMatrix *()> amg_operator;
    if (with_operator)
      amg_operator = [&calls, hierarchy]() {
        ++calls;
        return hierarchy;
      };
    const unsigned int        its = solve_linear_system(parameters,
                                                 dof_handler,
                                                 M,
                                                 x,
                                                 rhs,
                                                 &cache,
                                                 amg_operator);
    pg::LinearAlgebra::Vector r(rhs);
    M.vmult(r, x);
    r -= rhs;
    print_bound("  |b - M x| / |b|", r.l2_norm() / rhs.l2_norm(), 1e-10);
    return its;
  };

  deallog << "0. A without an operator" << std::endl;
  AMGCache           plain_cache;
  const unsigned int plain = solve(A, plain_cache, nullptr, false);

  deallog << "1. A with operator A" << std::endl;
  AMGCache           cache;
  const unsigned int first = solve(A, cache, &A, true);
  deallog << "  iterations as without the operator: "
          << (first == plain ? "yes" : "NO") << ", operator calls " << calls
          << ", hierarchies " << cache.n_builds << std::endl;

  deallog << "2. again, reusing the hierarchy" << std::endl;
  const unsigned int second = solve(A, cache, &A, true);
  deallog << "  iterations as solve 1: " << (second == first ? "yes" : "NO")
          << ", operator calls " << calls << ", hierarchies " << cache.n_builds
          << std::endl;

  deallog << "3. A with operator L (the Laplacian alone)" << std::endl;
  AMGCache           laplace_cache;
  const unsigned int third = solve(A, laplace_cache, &L, true);
  deallog << "  at most twice the iterations of A's hierarchy: "
          << (third <= 2 * plain ? "yes" : "NO") << ", operator calls " << calls
          << ", hierarchies " << laplace_cache.n_builds << std::endl;

  deallog << "4. A with an operator that returns nullptr" << std::endl;
  AMGCache           null_cache;
  const unsigned int fourth = solve(A, null_cache, nullptr, true);
  deallog << "  iterations as without the operator: "
          << (fourth == plain ? "yes" : "NO") << ", operator calls " << calls
          << ", hierarchies " << null_cache.n_builds << std::endl;

  deallog << "5. A with operator D A D" << std::endl;
  AMGCache           fallback_cache;
  const unsigned int fifth = solve(A, fallback_cache, &scaled, true);
  deallog << "  iterations = 1000 failed + those of A's hierarchy: "
          << (fifth == 1000 + plain ? "yes" : "NO") << ", operator calls "
          << calls << ", hierarchies " << fallback_cache.n_builds << std::endl;
}
