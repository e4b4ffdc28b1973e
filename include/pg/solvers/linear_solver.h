#ifndef pg_solvers_linear_solver_h
#define pg_solvers_linear_solver_h

#include <pg/base/global.h>
#include <pg/base/linear_algebra.h>
#include <pg/solvers/solver_parameters.h>

#include <deal.II/dofs/dof_handler.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace Teuchos
{
  class ParameterList;
}

namespace dealii::TrilinosWrappers
{
  class PreconditionAMG;
}

namespace pg
{
  /**
   * Sets Trilinos ML's parameter @p name in @p list from the text @p value
   * (an item of 'Linear solver/AMG parameters'), with the type that ML
   * reads it as (int, double, bool or string, from ML's own list of valid
   * parameters). Throws ExcBadParameter, naming the entry, for a name that
   * ML does not know and for a value of the wrong type.
   */
  void
  set_ml_parameter(Teuchos::ParameterList &list,
                   const std::string      &name,
                   const std::string      &value);

  class AMGCache;

  /**
   * Solve K du = b with the solver of subsection 'Linear solver': Amesos
   * MUMPS (direct; KLU if Trilinos was built without MUMPS), or CG / GMRES
   * preconditioned by ML algebraic multigrid with the near-null space of
   * 'AMG near-null space' (the rigid body modes by default). Returns the number
   * of Krylov iterations (0 for the direct solver). Throws
   * SolverControl::NoConvergence if the Krylov method does not converge.
   *
   * With @p cache and 'Reuse AMG', a hierarchy in @p cache built from the
   * same matrix object is applied to @p matrix's current values; it is
   * rebuilt when the solve does not converge (the solve is repeated) or
   * needs more than 1.5 times (plus 5) the iterations of its first solve
   * (for the next one).
   *
   * With @p amg_operator, a new hierarchy is built from the matrix it
   * returns ('AMG operator = Q1 cells'; it must outlive the hierarchy, i.e.
   * the cache), and from @p matrix where it returns nullptr or where the
   * solve with it does not converge in 1000 iterations (the solve is then
   * repeated). With 'AMG operator = automatic' and a cache, the first solve
   * whose Q1 hierarchy needs more than #operator_trial_iterations
   * iterations is repeated once with the tangent's hierarchy (at most as
   * many iterations), and the faster of the two in wall time is kept for
   * the rest of the run (AMGCache::operator_rejected).
   */
  /**
   * Iterations of a first solve with the Q1 cells' hierarchy above which
   * 'AMG operator = automatic' tries the tangent's: on the cantilevers and
   * the tensile bar the Q1 hierarchy needed at most 219 and was faster; on
   * B-12's irregular particles 486 per solve, and the tangent's (85) was
   * 1.9 times faster (doc/benchmarks/amg_operator.md).
   */
  constexpr unsigned int operator_trial_iterations = 250;

  template <int dim>
  unsigned int
  solve_linear_system(const Parameters::LinearSolver    &parameters,
                      const DoFHandler<dim>             &dof_handler,
                      const LinearAlgebra::SparseMatrix &matrix,
                      LinearAlgebra::Vector             &solution,
                      const LinearAlgebra::Vector       &rhs,
                      AMGCache                          *cache = nullptr,
                      const std::function<const LinearAlgebra::SparseMatrix *()>
                        &amg_operator = {});

  /**
   * An ML hierarchy kept from one solve_linear_system() to the next
   * ('Linear solver/Reuse AMG'). ML's finest level wraps the Epetra matrix
   * it was built from without copying it (an old hierarchy smooths with
   * the matrix's current values), so the cache must be cleared (or destroyed)
   * before that matrix is reinitialized or destroyed.
   */
  class AMGCache
  {
  public:
    AMGCache();
    ~AMGCache();

    /** Forget the hierarchy: the next solve builds a new one. */
    void
    clear();

    /** Hierarchies built since construction (for the summary). */
    unsigned int n_builds = 0;

    /**
     * 'AMG operator = automatic': whether a trial solve found the tangent's
     * hierarchy faster than the Q1 cells' (solve_linear_system()); then
     * every later hierarchy is the tangent's.
     */
    bool operator_rejected = false;

  private:
    template <int dim>
    friend unsigned int
    solve_linear_system(
      const Parameters::LinearSolver &,
      const DoFHandler<dim> &,
      const LinearAlgebra::SparseMatrix &,
      LinearAlgebra::Vector &,
      const LinearAlgebra::Vector &,
      AMGCache *,
      const std::function<const LinearAlgebra::SparseMatrix *()> &);

    std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg;
    /** The matrix the hierarchy was built from. */
    const LinearAlgebra::SparseMatrix *matrix = nullptr;
    /** Krylov iterations of the first solve with the hierarchy. */
    unsigned int first_iterations = 0;
    /** Whether the automatic operator's trial has been made. */
    bool operator_tried = false;
  };

  /**
   * The preconditioner of solve_by_gmres().
   */
  enum class GMRESPreconditioner
  {
    /** Ifpack's ILU(0), block Jacobi over the MPI ranks. */
    ilu,
    /**
     * ML's non-symmetric smoothed aggregation (deal.II's `elliptic =
     * false`: "NSSA") with two ILU(0) sweeps as smoother and the given
     * constant modes as near-null space.
     */
    amg
  };

  /**
   * Solve the non-symmetric A x = b by restarted GMRES (200 vectors, right
   * preconditioning, so the stopping test sees the true residual) with the
   * @p preconditioner, from x = 0, until |b - A x| <= @p tolerance |b|.
   * Every row of A needs a nonzero diagonal. @p constant_modes (one mask
   * over the locally owned rows per near-null vector, as
   * PreconditionAMG::AdditionalData::constant_modes) are used by the AMG
   * only. Returns the number of iterations; throws
   * SolverControl::NoConvergence after @p max_iterations, or when the true
   * residual |b - A x| at GMRES's stop exceeds 100 @p tolerance |b| (its
   * own estimate can be far off when the preconditioner is nearly
   * singular). With @p stagnation_iterations > 0 it also throws when the
   * residual has not fallen below 1e-4 |b| after that many iterations (a
   * preconditioner worth trying first, dropped early where it fails).
   */
  unsigned int
  solve_by_gmres(const LinearAlgebra::SparseMatrix    &matrix,
                 LinearAlgebra::Vector                &solution,
                 const LinearAlgebra::Vector          &rhs,
                 const GMRESPreconditioner             preconditioner,
                 const std::vector<std::vector<bool>> &constant_modes,
                 const double                          tolerance,
                 const unsigned int                    max_iterations,
                 const unsigned int stagnation_iterations = 0);

  /**
   * Solve A x = b for a square @p matrix A that may be singular but whose
   * system is consistent, by iterative refinement with a slightly shifted
   * factorization (Amesos KLU):
   *   x <- x + (A + eps D)^{-1} (b - A x),  x_0 = 0,
   * with D the largest |entry| of each row and eps = @p relative_shift.
   * It converges in a few steps on the regular part (eps << |lambda|) and
   * keeps the null-space part of x at zero.
   *
   * Only the nonzero entries of A (and the diagonal) are factorized: A may
   * be stored in a larger sparsity pattern, e.g. the tangent's, whose other
   * entries are zero, and a direct solver would treat every stored entry as
   * a structural nonzero (fill-in, time). The factorized matrix holds the
   * same values, so only the pivot order can differ.
   *
   * Stops as soon as |b - A x| <= @p tolerance |b|, or at the round-off
   * floor of b - A x: when a correction no longer halves a residual that is
   * already below @p floor_tolerance |b|. The floor grows with the size of
   * the system (plate with hole, VC V3sn: about 1.5e-14 |b| at 12,610
   * DoFs, 2.5e-14 to 6.5e-14 |b| at 50,000), so a fixed 1e-14 alone is met
   * by chance or never. Returns the number of corrections applied;
   * @p max_corrections if neither criterion was met (the caller decides
   * what that means). @p direct_solver names the Amesos factorization of
   * A + eps D (serial "Amesos_Klu", or distributed "Amesos_Mumps", which
   * keeps a share of the factors on every rank).
   */
  unsigned int
  solve_by_shifted_refinement(const LinearAlgebra::SparseMatrix &matrix,
                              LinearAlgebra::Vector             &solution,
                              const LinearAlgebra::Vector       &rhs,
                              const double                       relative_shift,
                              const double                       tolerance,
                              const unsigned int max_corrections,
                              const double       floor_tolerance = 1e-12,
                              const std::string &direct_solver = "Amesos_Klu");
} // namespace pg

#endif
