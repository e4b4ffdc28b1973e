#ifndef pg_analysis_analysis_parameters_h
#define pg_analysis_analysis_parameters_h

#include <pg/base/global.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

// Which analysis a run performs (subsection "Analysis"): static,
// eigenmodes or inf-sup.

namespace pg
{
  namespace Parameters
  {
    /** Subsection "Analysis". */
    struct Analysis
    {
      /** static | eigenmodes | inf-sup */
      std::string type;
      /** How many of the smallest eigenvalues are reported. */
      unsigned int n_eigenvalues;
      /** inf-sup: displacement | P0 (one condensed pressure per element). */
      std::string pressure_space;
      /** inf-sup: the N of every N x N (x N) mesh of the unit square. */
      std::vector<unsigned int> inf_sup_subdivisions;
      /** inf-sup: eigenvalues below this times the largest are zero. */
      double inf_sup_zero_tolerance;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace pg

#endif
