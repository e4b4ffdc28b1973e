#ifndef pg_analysis_study_report_h
#define pg_analysis_study_report_h

#include <pg/analysis/study.h>
#include <pg/postprocess/run_summary.h>

#include <ostream>
#include <string>
#include <vector>

namespace pg
{
  namespace Analysis
  {
    namespace Study
    {
      /**
       * The report of a finished study (rank 0 only): study.txt (every
       * successful run with errors, cost and rates), rates.txt (relative
       * errors and convergence rates in h ~ N^(-1/dim), N the DoFs, between
       * successive levels, also printed to @p out), series/<series>.dat,
       * time_to_error.txt (with 'Target error') and the gnuplot script
       * study.gp. @p horizons are the horizon factors the runs used.
       */
      template <int dim>
      void
      write_results(const std::vector<Run>    &runs,
                    const Study::Parameters   &study,
                    const std::vector<double> &horizons,
                    std::ostream              &out);

      /** @name Formatting shared by the progress lines and the report */
      /** @{ */
      /** "coupled 2R" -> "coupled_2r": a file name. */
      std::string
      slug(const std::string &text);

      /** @p x with @p digits significant digits. */
      std::string
      format(const double x, const int digits = 3);

      /** @p x in scientific notation with two decimals. */
      std::string
      scientific(const double x);

      /**
       * The wall time (s) to the solution: everything but the
       * post-processing (error norms, statistics, output files), which
       * every configuration does alike.
       */
      double
      solution_time(const RunSummary &s);
      /** @} */
    } // namespace Study
  }   // namespace Analysis
} // namespace pg

#endif
