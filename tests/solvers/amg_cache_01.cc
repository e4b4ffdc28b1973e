// 'Linear solver/Reuse AMG': an AMGCache keeps ML's hierarchy between
// solve_linear_system() calls on the same matrix object. On a scalar
// Laplace-plus-mass matrix (Q1, 48 x 48 cells, 2,401 DoFs: above ML's
// coarse size of 2000) the second solve builds nothing and takes the
// iterations of the first. After the matrix is rescaled in place (rows and
// columns of the right half times 30, B = D A D), CG with the old hierarchy
// does not reach the tolerance within its iteration limit (2,401), so the
// solve is repeated with a new hierarchy (2 built after solve 3; its count
// includes the failed iterations), and solve 4 reuses that one with fewer
// iterations. Without a cache, or with 'Reuse AMG' false, every solve
// builds one. Every solution
// is checked against its residual |b - M x| <= 1e-10 |b|.

#include <deal.II/fe/mapping_q1.h>

#include "../tests.h"
#include "laplace_fixture.h"

using namespace pg;


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  LaplaceFixture            problem;
  const auto               &dof_handler = problem.dof_handler;
  const auto               &rhs         = problem.rhs;
  auto                     &matrix      = problem.matrix;
  auto                     &parameters  = problem.parameters;
  pg::LinearAlgebra::Vector x(rhs);

  AMGCache   cache;
  const auto solve = [&](const pg::LinearAlgebra::SparseMatrix &M) {
    x = 0;
    const unsigned int its =
      solve_linear_system(parameters, dof_handler, M, x, rhs, &cache);
    print_bound("  |b - M x| / |b|", problem.relative_residual(M, x), 1e-10);
    return its;
  };

  deallog << "solve 1 (A)" << std::endl;
  const unsigned int first = solve(matrix);
  deallog << "  hierarchies built: " << cache.n_builds << std::endl;

  deallog << "solve 2 (A again)" << std::endl;
  const unsigned int second = solve(matrix);
  deallog << "  hierarchies built: " << cache.n_builds
          << ", iterations as solve 1: " << (second == first ? "yes" : "NO")
          << std::endl;

  // B = D A D in place, D = 30 on the DoFs right of x = 0.5
  std::vector<Point<2>> support(dof_handler.n_dofs());
  DoFTools::map_dofs_to_support_points(MappingQ1<2>(), dof_handler, support);
  for (auto entry = matrix.begin(); entry != matrix.end(); ++entry)
    {
      const double d_row    = support[entry->row()][0] > 0.5 ? 30. : 1.;
      const double d_column = support[entry->column()][0] > 0.5 ? 30. : 1.;
      entry->value() *= d_row * d_column;
    }

  deallog << "solve 3 (B with the hierarchy of A, which fails)" << std::endl;
  const unsigned int third = solve(matrix);
  deallog << "  hierarchies built: " << cache.n_builds
          << ", more than 1.5 x (plus 5) the iterations of solve 1: "
          << (2 * third > 3 * first + 10 ? "yes" : "NO") << std::endl;

  deallog << "solve 4 (B, the hierarchy of solve 3)" << std::endl;
  const unsigned int fourth = solve(matrix);
  deallog << "  hierarchies built: " << cache.n_builds
          << ", fewer iterations than solve 3: "
          << (fourth < third ? "yes" : "NO") << std::endl;

  deallog << "'Reuse AMG' false, two solves" << std::endl;
  parameters.reuse_amg = false;
  solve(matrix);
  solve(matrix);
  deallog << "  hierarchies built: " << cache.n_builds << std::endl;
}
