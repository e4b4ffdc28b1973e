#ifndef pg_solvers_newton_solver_h
#define pg_solvers_newton_solver_h

#include <pg/base/global.h>
#include <pg/base/parameters.h>

#include <deal.II/base/conditional_ostream.h>

#include <functional>
#include <string>
#include <vector>

namespace pg
{
  /**
   * Newton's method on a residual R(u) = 0 whose assembly, linear solve and
   * update live elsewhere (the Assembler and the problem's state): the one
   * loop behind the quasi-static load steps and the implicit Newmark steps.
   *
   * Iteration i assembles R_i, then stops when
   *  - |R_i| <= 'Absolute tolerance' or |R_i| <= 'Relative tolerance' |R_0|
   *    (converged), or
   *  - the residual stagnates at the round-off floor (converged at
   *    round-off): i >= 2, |R_i| <= 'Stagnation tolerance' |R_0|, the last
   *    update decreased |R| by less than a factor 2, and its energy
   *    |du_{i-1} . R_{i-1}| is at most 'Stagnation tolerance'^2 times the
   *    first update's |du_0 . R_0|. Quadratic convergence never keeps
   *    |R| flat that far below |R_0|, but the assembly and the direct
   *    solver do, at eps times the size of the element forces: Cook's
   *    membrane at nu = 0.4999 stalls at 2e-9 to 1e-7 |R_0| (doc/solvers.md),
   *  - or it fails: the assembly or the linear solver fails, |R| is not
   *    finite, or 'Maximum iterations' updates did not converge.
   * Otherwise it assembles the tangent K (with R, unless the caller has no
   * residual-only assembly), solves K du = R and applies du.
   */
  class NewtonSolver
  {
  public:
    /** What one solve ended with. */
    enum class Outcome
    {
      converged,
      converged_at_round_off,
      assembly_failed,
      linear_solver_failed,
      not_finite,
      too_many_iterations
    };

    /** The operations Newton's method is made of (set by the caller). */
    struct Operations
    {
      /**
       * Assemble R and the tangent at the current state; return an empty
       * string on success, or why it failed (already reduced over all MPI
       * ranks: every rank returns the same verdict).
       */
      std::function<std::string()> assemble;
      /**
       * Optional: assemble R alone (no tangent), with the same failure
       * verdicts. If set, every iteration first assembles R alone for the
       * convergence test and calls assemble() only when an update follows:
       * the tangent at the converged state is then never built. It pays
       * where R costs far less than R and K: about 1/16 of it for Q1 cells
       * and for VCBCPBG V5sn Unl families (3-D cantilever, 4 Newton steps:
       * assembly 14 % shorter, doc/benchmarks/vc_solve.md).
       */
      std::function<std::string()> assemble_residual;
      /** |R| of the last assembly (the l2 norm over all ranks). */
      std::function<double()> residual_norm;
      /**
       * Optional: the reference of the relative test from |R_0|
       * (default |R_0|; Newmark also counts the inertia and static forces).
       */
      std::function<double(const double first_residual)> reference;
      /**
       * Solve K du = R, apply du (with the homogeneous constraints) to the
       * state and return du . R (for the stagnation test); false if the
       * linear solver failed (it has printed why).
       */
      std::function<bool(double &update_energy)> solve_and_update;
      /**
       * Optional: called after every update, e.g. to recover condensed local
       * fields or to update a contact active set.
       */
      std::function<void()> after_update;
    };

    /** How one solve went. */
    struct Result
    {
      Outcome             outcome = Outcome::too_many_iterations;
      unsigned int        updates = 0;
      std::vector<double> residuals;
      /** |R_i| / reference of every iteration, formatted (%.2e). */
      std::string history;
      /** Why it failed (empty on success). */
      std::string failure;

      bool
      converged() const
      {
        return outcome == Outcome::converged ||
               outcome == Outcome::converged_at_round_off;
      }
    };

    explicit NewtonSolver(const Parameters::Newton &parameters);

    /**
     * Iterate from the current state. Prints nothing; report() gives the
     * line the load stepper shows.
     */
    Result
    solve(const Operations &operations) const;

    /**
     * "    Newton <n>: |R|/|R_0| = ..." for a converged solve (with
     * "(stagnated at round-off)" where that test stopped it), "    Newton did
     * not converge: ..." otherwise, "    assembly failed: ..." for a failed
     * assembly; nothing for a failed linear solve (the callback printed it).
     */
    static void
    report(const Result &result, const ConditionalOStream &out);

    /**
     * Whether @p failure (a Result::failure) says that the residual stalled
     * at a small level, i.e. on the round-off floor that a smaller load
     * step does not lower.
     */
    static bool
    stalled(const std::string &failure);

  private:
    /**
     * For a solve that ran out of iterations: if its residual has stalled at
     * a small level, the message that says so and names 'Stagnation
     * tolerance'; otherwise empty.
     */
    std::string
    stall_diagnosis(const std::vector<double> &residuals,
                    double                     reference) const;

    const Parameters::Newton &parameters;
  };
} // namespace pg

#endif
