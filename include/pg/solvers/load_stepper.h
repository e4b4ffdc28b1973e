#ifndef pg_solvers_load_stepper_h
#define pg_solvers_load_stepper_h

#include <pg/base/global.h>
#include <pg/base/parameters.h>

#include <deal.II/base/conditional_ostream.h>

#include <functional>
#include <string>

namespace pg
{
  /**
   * Quasi-static load stepping: 'Load steps' equal steps of the load factor
   * t from 0 to 1, each reached by one or more sub-steps. A sub-step whose
   * Newton solve fails is reverted and halved (at most 'Maximum step cuts'
   * times per load step); after a cut, a sub-step that converged in at most
   * 'Easy step iterations' Newton iterations doubles the next one again, up
   * to the rest of the load step. Two failed sub-steps in a row whose
   * residual stalled on its round-off floor (NewtonSolver::stalled()) end
   * the run at once: a cut cannot lower that floor. So does a NaN or inf
   * that the loads give at the sub-step's load factor
   * (Operations::load_is_finite).
   *
   * The stepper knows nothing of the discretization: the problem gives it
   * the operations below. The state (solution, point history) is committed
   * after every converged sub-step and reverted after every failed one.
   */
  class LoadStepper
  {
  public:
    struct Operations
    {
      /**
       * Solve the sub-step to load factor @p t from the committed state;
       * return whether it converged, and its Newton updates in
       * @p iterations.
       */
      std::function<bool(const double t, unsigned int &iterations)> solve;
      /** The sub-step converged: make its state the committed one. */
      std::function<void()> commit;
      /** The sub-step failed: return to the committed state. */
      std::function<void()> revert;
      /** Load step @p step reached @p t after @p iterations updates. */
      std::function<void(const unsigned int step,
                         const double       t,
                         const unsigned int iterations)>
        step_done;
      /**
       * Load step @p step failed at load factor @p t: called before the
       * exception, e.g. to write what has been computed.
       */
      std::function<void(const unsigned int step, const double t)> give_up;
      /** Why the last failed sub-step failed (for the message). */
      std::function<std::string()> last_failure;
      /**
       * Optional, called (on every rank) after a sub-step to load factor
       * @p t failed: false if the sub-step failed with a NaN or inf and
       * the residual of the undeformed state (u = 0) at @p t is not
       * finite either. Then the NaN or inf comes from the loads (a
       * 'Traction' or 'Body force' that is NaN or inf at @p t), not from
       * the size of the step: no cut can remove it, and the run stops at
       * once.
       */
      std::function<bool(const double t)> load_is_finite;
    };

    /**
     * @p output_directory is named in the message of a failed run.
     */
    LoadStepper(const Parameters::Loading &parameters,
                const std::string         &output_directory,
                const ConditionalOStream  &out);

    /**
     * The load steps from @p first_step on (a restart: the steps before it
     * are done, the load factor is (first_step - 1) / n). Throws
     * ExcMessage naming the load step, the load factor reached and the
     * last failure if a load step does not converge after 'Maximum step
     * cuts' cuts.
     */
    void
    run(const Operations &operations, const unsigned int first_step = 1) const;

  private:
    const Parameters::Loading &parameters;
    const std::string          output_directory;
    const ConditionalOStream  &out;
  };
} // namespace pg

#endif
