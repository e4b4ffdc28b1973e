#ifndef pg_analysis_study_h
#define pg_analysis_study_h

#include <pg/base/global.h>
#include <pg/postprocess/run_summary.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <ostream>
#include <string>
#include <vector>

namespace pg
{
  namespace Analysis
  {
    /**
     * A convergence and cost study (what `pg_study file.prm` does): one
     * problem, given by the pg_solve parameters of the file, is solved for
     * every combination of the lists in subsection 'Study' (configurations
     * x distortions x horizon factors x refinement levels). Every run writes
     * its usual files into its own directory; the study collects their
     * summaries into one table (study.txt), convergence rates (rates.txt,
     * also printed), one data file per series (series/<series>.dat) and a
     * gnuplot script (study.gp) that draws error against wall time and against
     * DoFs.
     *
     * A study is not an Analysis::Interface but one level above the
     * analyses: it builds the parameters of every run, runs a Problem for
     * each (whose run() creates and runs the analysis 'Analysis/Type'
     * names, usually a StaticAnalysis) and compares their RunSummary.
     * Running is in study.cc, the report (write_results()) in
     * study_report.cc.
     */
    namespace Study
    {
      /** One line of 'Configurations': label | Formulation | Meshfree region.
       */
      struct Configuration
      {
        std::string label;
        std::string formulation;
        std::string meshfree_region;
      };

      /** The entries of subsection 'Study'. */
      struct Parameters
      {
        std::string                problem_file;
        std::vector<unsigned int>  refinement_levels;
        std::vector<double>        distortions;
        std::vector<double>        horizon_factors; //!< empty: the file's
        std::vector<Configuration> configurations;
        std::string                stress_point;
        unsigned int               stress_row = 0, stress_column = 0;
        std::string                directory;
        bool                       report_wall_times = true;
        double                     time_limit        = 0;
        double                     target_error      = 0;

        static void
        declare_parameters(ParameterHandler &prm);
        void
        parse_parameters(ParameterHandler &prm);
      };

      /** One run of the study and what it measured. */
      struct Run
      {
        unsigned int configuration = 0;
        double       distortion = 0, horizon_factor = 0;
        unsigned int level   = 0;
        bool         ok      = false;
        bool         skipped = false;
        std::string  failure;
        RunSummary   summary;
        /** Relative error of the chosen stress component at the point. */
        double stress_error = 0;
      };

      /**
       * Run the study of @p filename (pg_solve parameters plus subsection
       * 'Study'). Progress goes to @p out (without wall times if 'Report
       * wall times' is false, so that tests can compare it). Returns the
       * runs; failed runs are reported and do not stop the study.
       */
      std::vector<Run>
      run_study_file(const std::string &filename,
                     const MPI_Comm     mpi_communicator,
                     std::ostream      &out);
    } // namespace Study
  }   // namespace Analysis
} // namespace pg

#endif
