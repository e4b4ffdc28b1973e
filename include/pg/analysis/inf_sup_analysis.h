#ifndef pg_analysis_inf_sup_analysis_h
#define pg_analysis_inf_sup_analysis_h

#include <pg/analysis/analysis.h>

#include <functional>
#include <ostream>

namespace pg
{
  namespace Analysis
  {
    /**
     * 'Analysis/Type = inf-sup': the numerical inf-sup test (dissertation
     * section 7.2.5, see namespace InfSup) on the refinement series
     * 'Inf-sup subdivisions' of the unit square (cube), one set-up problem
     * per mesh. Writes summary.inf_sup, inf_sup.txt and summary.json (the
     * summary of the last mesh with the inf-sup table).
     */
    template <int dim>
    class InfSupAnalysis : public Interface<dim>
    {
    public:
      /**
       * Set up a problem of the run's parameters on @p geometry, echoing
       * its set-up to @p out, and call @p work with its Access (view set).
       */
      using SetUpProblem = std::function<
        void(const Parameters::Geometry                     &geometry,
             std::ostream                                   &out,
             const std::function<void(const Access<dim> &)> &work)>;

      /** @p access of the (not set-up) problem of the run. */
      InfSupAnalysis(const Access<dim> &access, const SetUpProblem &set_up);

      void
      run() override;

      /**
       * T_h (pressure projection, eq. 7.13; for 'Pressure space = P0' the
       * condensed P0 projection) and S_h (H1 form, eq. 7.12) of the set-up
       * problem @p level with the element kernels of the real problem, the
       * constrained rows condensed by its homogeneous constraints.
       */
      static void
      assemble_forms(const Access<dim>           &level,
                     LinearAlgebra::SparseMatrix &T,
                     LinearAlgebra::SparseMatrix &S);

    private:
      const SetUpProblem set_up;
    };
  } // namespace Analysis
} // namespace pg

#endif
