#ifndef pg_analysis_analysis_h
#define pg_analysis_analysis_h

#include <pg/analysis/checkpoint.h>
#include <pg/base/formulation_code.h>
#include <pg/base/global.h>
#include <pg/base/parameters.h>
#include <pg/history/quadrature_point_history.h>
#include <pg/postprocess/problem_view.h>
#include <pg/postprocess/run_summary.h>
#include <pg/solvers/mechanical_system.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/table_handler.h>
#include <deal.II/base/timer.h>

#include <functional>

namespace pg
{
  /**
   * Analyses: what a run does with a set-up problem ('Analysis/Type' and
   * 'Time/Integrator'). Problem::run() sets the problem up, creates the
   * analysis the parameters name and runs it:
   * - StaticAnalysis: load steps with step cuts (LoadStepper),
   * - DynamicAnalysis: leapfrog or Newmark in time (TimeStepper),
   * - EigenmodeAnalysis: the eigenvalues of the initial tangent,
   * - InfSupAnalysis: the inf-sup test on a series of meshes, each one a
   *   problem of its own (so it runs before any set-up).
   * A study (Study::run_study_file(), pg_study) is one level above: it
   * runs many problems, each with its own analysis, and compares their
   * summaries.
   */
  namespace Analysis
  {
    /**
     * What an analysis may use of the problem, in the spirit of ASPECT's
     * SimulatorAccess but as one small aggregate: the parameters, the
     * MechanicalSystem (displacement, constraints, residual, tangent,
     * solver), the read-only ProblemView (mesh, particles, families, u),
     * the results it may write (summary, statistics table, the material
     * history it commits and reverts) and the postprocessors of the problem.
     */
    template <int dim>
    struct Access
    {
      const Parameters::AllParameters<dim> &parameters;
      const FormulationCode                &formulation;
      const ConditionalOStream             &pcout;
      /** Rank 0 (which writes the text files). */
      const bool root;
      /** Wall time since the start of the run. */
      const Timer &total_timer;

      MechanicalSystem &system;
      /**
       * The read-only view of the set-up problem; null where the analysis
       * runs before the set-up (InfSupAnalysis sets up problems of its own).
       */
      const Postprocess::ProblemView<dim> *view;

      RunSummary             &summary;
      TableHandler           &statistics;
      QuadraturePointHistory &history;

      /**
       * The postprocessors' execute() at step @p step, time (or load
       * factor) @p t, timed as postprocessing.
       */
      std::function<void(const unsigned int step,
                         const double       t,
                         const unsigned int newton_iterations)>
        postprocess;
      /** statistics.txt, summary.json, timing.txt and the VTU/PVD files. */
      std::function<void(const unsigned int step, const double t)> write_files;
      /**
       * The postprocessors' finalize() after the last step (particle fields,
       * nodal stresses, the final report and the files).
       */
      std::function<void(const unsigned int step, const double t)> finalize;
      /**
       * After the accepted step @p step at @p t (its files written): a
       * checkpoint if 'Output/Checkpoint interval' asks for one or SIGINT
       * or SIGTERM arrived, with the problem's state and what
       * @p analysis_state writes; after a signal it stops the run
       * (throws RunInterrupted). Collective.
       */
      std::function<void(const unsigned int        step,
                         const double              t,
                         const Checkpoint::Writer &analysis_state)>
        checkpoint;
      /**
       * With `pg_solve --restart`: read the checkpoint into the problem
       * (displacement, history, summary, statistics, PVD records) and
       * @p analysis_state, set @p step and @p t to the step it was written
       * after and return true; otherwise false. Collective.
       */
      std::function<bool(unsigned int             &step,
                         double                   &t,
                         const Checkpoint::Reader &analysis_state)>
        restart;
    };



    /**
     * An analysis: constructed with the Access to the problem (and what
     * else it needs), run once.
     */
    template <int dim>
    class Interface
    {
    public:
      explicit Interface(const Access<dim> &access)
        : access(access)
      {}

      virtual ~Interface() = default;

      virtual void
      run() = 0;

    protected:
      const Access<dim> access;

      /** The view of the set-up problem (throws if there is none). */
      const Postprocess::ProblemView<dim> &
      view() const
      {
        Assert(access.view != nullptr, ExcInternalError());
        return *access.view;
      }
    };
  } // namespace Analysis
} // namespace pg

#endif
