// solve_by_gmres(), the solver of the VC system, on the Laplace-plus-mass
// matrix of laplace_fixture.h (2,401 DoFs), to |b - A x| <= 1e-13 |b|:
//  1. with ILU(0) and with ML AMG it converges; the true residual meets
//     the tolerance (checked by solve_by_gmres itself, and here);
//  2. with a stagnation limit of 3 iterations (the automatic VC choice
//     gives the AMG 100 to reach 1e-4 |b|) it throws NoConvergence at
//     iteration 3, before the ILU solve's own count;
//  3. a limit above that count changes nothing;
//  4. max_iterations below it throws NoConvergence.

#include <pg/solvers/linear_solver.h>

#include <deal.II/lac/solver_control.h>

#include "../tests.h"
#include "laplace_fixture.h"

using namespace pg;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  LaplaceFixture                       problem;
  pg::LinearAlgebra::Vector            x(problem.rhs);
  const std::vector<std::vector<bool>> one_mode(
    1,
    std::vector<bool>(problem.rhs.locally_owned_size(), true));

  const auto solve = [&](const GMRESPreconditioner preconditioner,
                         const unsigned int        max_iterations,
                         const unsigned int        stagnation) {
    return solve_by_gmres(problem.matrix,
                          x,
                          problem.rhs,
                          preconditioner,
                          preconditioner == GMRESPreconditioner::amg ?
                            one_mode :
                            std::vector<std::vector<bool>>(),
                          1e-13,
                          max_iterations,
                          stagnation);
  };

  const unsigned int ilu = solve(GMRESPreconditioner::ilu, 2000, 0);
  deallog << "ILU(0): converged, iterations > 3: " << (ilu > 3 ? "yes" : "no")
          << std::endl;
  print_bound("  |b - A x| / |b|",
              problem.relative_residual(problem.matrix, x),
              1e-12);
  const unsigned int amg = solve(GMRESPreconditioner::amg, 2000, 100);
  deallog << "AMG: converged in fewer iterations than ILU(0): "
          << (amg < ilu ? "yes" : "no") << std::endl;
  print_bound("  |b - A x| / |b|",
              problem.relative_residual(problem.matrix, x),
              1e-12);

  try
    {
      solve(GMRESPreconditioner::ilu, 2000, 3);
      deallog << "stagnation limit 3: NO exception" << std::endl;
    }
  catch (const SolverControl::NoConvergence &failure)
    {
      deallog << "stagnation limit 3: NoConvergence at iteration "
              << failure.last_step << std::endl;
    }
  deallog << "a stagnation limit above the ILU(0) count changes nothing: "
          << (solve(GMRESPreconditioner::ilu, 2000, ilu + 1) == ilu ? "yes" :
                                                                      "no")
          << std::endl;
  try
    {
      solve(GMRESPreconditioner::ilu, ilu / 2, 0);
      deallog << "max_iterations " << ilu / 2 << ": NO exception" << std::endl;
    }
  catch (const SolverControl::NoConvergence &failure)
    {
      deallog << "max_iterations below the count: NoConvergence, |b - A x| / "
                 "|b| > 1e-13: "
              << (failure.last_residual > 1e-13 * problem.rhs.l2_norm() ?
                    "yes" :
                    "no")
              << std::endl;
    }
}
