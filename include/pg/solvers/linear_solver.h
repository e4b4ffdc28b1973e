#ifndef pg_solvers_linear_solver_h
#define pg_solvers_linear_solver_h

#include <pg/base/global.h>
#include <pg/base/linear_algebra.h>
#include <pg/base/parameters.h>

#include <deal.II/dofs/dof_handler.h>

namespace pg
{
  /**
   * Solve K du = b with the solver of subsection 'Linear solver': Amesos
   * KLU (direct), or CG / GMRES preconditioned by ML algebraic multigrid
   * whose near-null space is the rigid translations. Returns the number of
   * Krylov iterations (0 for the direct solver). Throws
   * SolverControl::NoConvergence if the Krylov method does not converge.
   */
  template <int dim>
  unsigned int
  solve_linear_system(const Parameters::LinearSolver    &parameters,
                      const DoFHandler<dim>             &dof_handler,
                      const LinearAlgebra::SparseMatrix &matrix,
                      LinearAlgebra::Vector             &solution,
                      const LinearAlgebra::Vector       &rhs);
} // namespace pg

#endif
