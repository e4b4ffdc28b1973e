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

#include <pg/solvers/linear_solver.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/numerics/matrix_creator.h>

#include "../tests.h"

using namespace pg;

namespace
{
  /** |b - M x| / |b| */
  double
  relative_residual(const pg::LinearAlgebra::SparseMatrix &M,
                    const pg::LinearAlgebra::Vector       &x,
                    const pg::LinearAlgebra::Vector       &b)
  {
    pg::LinearAlgebra::Vector r(b);
    M.vmult(r, x);
    r -= b;
    return r.l2_norm() / b.l2_norm();
  }
} // namespace


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
  pg::LinearAlgebra::SparseMatrix matrix, mass;
  matrix.reinit(owned, owned, dsp, MPI_COMM_WORLD);
  mass.reinit(owned, owned, dsp, MPI_COMM_WORLD);
  MatrixCreator::create_laplace_matrix(dof_handler, QGauss<2>(2), matrix);
  MatrixCreator::create_mass_matrix(dof_handler, QGauss<2>(2), mass);
  matrix.add(1., mass);

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

  AMGCache   cache;
  const auto solve = [&](const pg::LinearAlgebra::SparseMatrix &M) {
    x = 0;
    const unsigned int its =
      solve_linear_system(parameters, dof_handler, M, x, rhs, &cache);
    print_bound("  |b - M x| / |b|", relative_residual(M, x, rhs), 1e-10);
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
