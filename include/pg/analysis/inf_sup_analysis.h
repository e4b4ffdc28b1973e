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

      /**
       * The dense T_h and S_h of the nodal pressure spaces, 'Pressure space
       * = P1C' or (@p bubble) 'P1C+bubble': the unknowns are the free
       * displacement DoFs of @p level, then (@p bubble) dim bubble
       * coefficients per family (eqs. 6.12-6.16). S_h is the H1 form of
       * the Q1 cells and of the families' tables (with the bubble node);
       * T_h = B^T M^-1 B with B_{k,i} = sum over the families of sum_q w_q
       * pi_qk div N_i and M_{kl} = sum sum_q w_q pi_qk pi_ql (pi of eq.
       * 6.11, nodal_field_interpolation()), plus the P0 projection of the
       * Q1 cells. Returns the number of pressures n_p (particles and Q1
       * cells).
       */
      static unsigned int
      assemble_nodal_forms(const Access<dim>        &level,
                           const bool                bubble,
                           const unsigned int        max_size,
                           LAPACKFullMatrix<double> &T,
                           LAPACKFullMatrix<double> &S);

    private:
      const SetUpProblem set_up;
    };
  } // namespace Analysis
} // namespace pg

#endif
