#ifndef pg_analysis_eigenmode_analysis_h
#define pg_analysis_eigenmode_analysis_h

#include <pg/analysis/analysis.h>

namespace pg
{
  namespace Analysis
  {
    /**
     * 'Analysis/Type = eigenmodes': all eigenvalues of the tangent in the
     * undeformed state (dissertation section 7.2.1) by dense_eigenvalues();
     * the largest one, the number below 1e-10 times it (the zero-energy
     * modes, rigid-body motions included) and the lowest 'Number of
     * eigenvalues' go to the summary and to eigenvalues.txt.
     */
    template <int dim>
    class EigenmodeAnalysis : public Interface<dim>
    {
    public:
      using Interface<dim>::Interface;

      void
      run() override;
    };
  } // namespace Analysis
} // namespace pg

#endif
