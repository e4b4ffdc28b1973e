#ifndef pg_analysis_static_analysis_h
#define pg_analysis_static_analysis_h

#include <pg/analysis/analysis.h>

#include <functional>
#include <string>

namespace pg
{
  namespace Analysis
  {
    /**
     * 'Analysis/Type = static' without a time integrator: the quasi-static
     * load steps of subsection 'Loading' by LoadStepper (step cuts, growing
     * the step again), with the postprocessors after every step and their
     * finalize() at the end. The material history is committed after every
     * accepted (sub)step and reverted, with the displacement, after a cut.
     */
    template <int dim>
    class StaticAnalysis : public Interface<dim>
    {
    public:
      /**
       * @p solve_step solves one (sub)step to load factor t from the
       * committed state (returns success and the Newton iterations);
       * @p last_failure says why the last failed one failed.
       */
      StaticAnalysis(
        const Access<dim>                                 &access,
        const std::function<bool(double, unsigned int &)> &solve_step,
        const std::function<std::string()>                &last_failure);

      void
      run() override;

    private:
      const std::function<bool(double, unsigned int &)> solve_step;
      const std::function<std::string()>                last_failure;
    };
  } // namespace Analysis
} // namespace pg

#endif
