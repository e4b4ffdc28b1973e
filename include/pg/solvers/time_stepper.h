#ifndef pg_solvers_time_stepper_h
#define pg_solvers_time_stepper_h

#include <pg/base/global.h>
#include <pg/base/parameters.h>
#include <pg/solvers/mechanical_system.h>
#include <pg/solvers/time_integration.h>
#include <pg/solvers/time_integrator.h>

#include <deal.II/base/conditional_ostream.h>

#include <functional>
#include <vector>

namespace pg
{
  /**
   * The time loop of 'Time/Integrator' leapfrog or newmark: the stable step
   * 2 / omega_max of leapfrog from the tangent of the initial state (and
   * again every 'Stable step update interval' steps), the step size (cut
   * and grown with 'Time step control = adaptive'), the initial
   * acceleration, the steps of the integrator and
   * the energy account (kinetic energy, the work of the internal forces,
   * of the external loads and of the supports, each by the trapezoidal
   * rule), with a progress line at every output time.
   */
  class TimeStepper
  {
  public:
    /** What the loop found out, for the summary. */
    struct Result
    {
      /**
       * The first step, the stable leapfrog step (the last estimate), and
       * the smallest and largest accepted steps.
       */
      double       time_step = 0, stable_time_step = 0;
      double       smallest_time_step = 0, largest_time_step = 0;
      unsigned int n_steps = 0, newton_iterations = 0;
      /** Failed steps redone with half the step ('adaptive'). */
      unsigned int step_cuts  = 0;
      double       final_time = 0;
    };

    /**
     * The loop's state after a step, all a checkpoint needs besides the
     * displacement and the velocity: the step, its time, the next output
     * time, the acceleration, the external and internal forces and the
     * reaction of the step (the trapezoidal rule of the next step starts
     * from them).
     */
    struct State
    {
      Result       result;
      unsigned int step = 0;
      double       t = 0, next_output = 0;
      double       kinetic_constrained = 0;
      /**
       * The size of the next step, the easy steps since the last growth
       * ('adaptive'), and whether every step so far had the first one's
       * size (then t = step * dt, bit for bit as before).
       */
      double                dt         = 0;
      unsigned int          easy_steps = 0;
      bool                  uniform    = true;
      LinearAlgebra::Vector a, f_ext, f_int, r_old;

      /** Size the vectors for the owned DoFs @p owned. */
      void
      reinit(const IndexSet &owned, const MPI_Comm comm);

      /** The scalars (boost serialization). */
      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int /*version*/)
      {
        archive &result.time_step &result.stable_time_step &result
          .n_steps &result.newton_iterations &result
          .final_time &step &t &next_output  &kinetic_constrained;
        archive                              &result.smallest_time_step;
        archive                              &result.largest_time_step;
        archive                              &result.step_cuts;
        archive                              &dt;
        archive                              &easy_steps;
        archive                              &uniform;
      }
    };

    struct Operations
    {
      /** Step @p step converged after @p iterations Newton updates. */
      std::function<void(const unsigned int step,
                         const unsigned int iterations)>
        step_done;
      /** The step is chosen (before the output at t = 0). */
      std::function<void(const Result &)> started;
      /** Output at step @p step, time @p t (energies already updated). */
      std::function<void(const unsigned int step,
                         const double       t,
                         const unsigned int iterations)>
        output;
      /**
       * A step failed (or the motion became unbounded): write what has been
       * computed up to step @p last_step at time @p t.
       */
      std::function<void(const unsigned int last_step, const double t)> give_up;
      /**
       * A step failed and is redone with a smaller one ('adaptive'): the
       * trial point history goes back to the committed one.
       */
      std::function<void()> step_rejected;
      /** After every step and its output: the state (for a checkpoint). */
      std::function<void(const State &)> step_accepted;
    };

    TimeStepper(const Parameters::Time   &time,
                const std::string        &output_directory,
                const ConditionalOStream &out);

    /**
     * Run from the system's current displacement and the velocity @p v,
     * at the start (@p restarted false: @p state as State::reinit() left
     * it) or after the step of @p state (a restart: @p state, @p v and
     * @p energies as a checkpoint left them). @p energies is updated at every
     * step;
     * @p disorder (the particles' disorder indicator, filled by the output)
     * is shown in the progress line if not empty.
     */
    Result
    run(MechanicalSystem          &system,
        TimeIntegrator            &integrator,
        const MassMatrices        &masses,
        LinearAlgebra::Vector     &v,
        TimeIntegration::Energies &energies,
        const std::vector<double> &disorder,
        const Operations          &operations,
        State                     &state,
        const bool                 restarted = false) const;

  private:
    /**
     * 2 / omega_max of leapfrog from the tangent of the current state
     * (omega_max^2 the largest eigenvalue of M^-1 K, power iteration).
     */
    double
    stable_step(MechanicalSystem &system, const MassMatrices &masses) const;

    /**
     * 'Stable step update interval': 2 / omega_max again at the current
     * state; an automatic step becomes 'Safety factor' times it (reported
     * if it changes by more than 1 %), a fixed 'Time step' above it, or an
     * automatic one below @p dt_min, ends the run (operations.give_up(),
     * then an exception).
     */
    void
    update_stable_step(MechanicalSystem   &system,
                       const MassMatrices &masses,
                       State              &state,
                       const double        dt_min,
                       const Operations   &operations) const;

    /**
     * The stable step 2 / omega_max of leapfrog from the tangent of the
     * current (initial) state, checked against 'Time step' for leapfrog,
     * and the step and the number of steps to 'End time', into @p result.
     */
    void
    choose_time_step(MechanicalSystem   &system,
                     const MassMatrices &masses,
                     const bool          explicit_,
                     Result             &result) const;

    const Parameters::Time   &time;
    const std::string         output_directory;
    const ConditionalOStream &out;
  };
} // namespace pg

#endif
