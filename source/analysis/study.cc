#include <pg/analysis/study.h>
#include <pg/analysis/study_report.h>
#include <pg/base/exceptions.h>
#include <pg/base/parameter_file.h>
#include <pg/base/parameters.h>
#include <pg/base/shared_libraries.h>
#include <pg/problem.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/patterns.h>
#include <deal.II/base/table_handler.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

namespace pg
{
  namespace Analysis
  {
    namespace Study
    {
      void
      Parameters::declare_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("Study");
        {
          prm.declare_entry(
            "Problem file",
            "",
            Patterns::Anything(),
            "The pg_solve parameter file of the problem studied (a relative "
            "path starts in the directory of the study file). Entries of the "
            "study file outside subsection 'Study' override it. Empty: the "
            "study file holds the whole problem.");
          prm.declare_entry(
            "Refinement levels",
            "1, 2, 3",
            Patterns::List(Patterns::Integer(0, 12), 1),
            "'Global refinement' (subsection 'Geometry') of the runs of "
            "every series, coarse to fine.");
          prm.declare_entry("Distortions",
                            "0",
                            Patterns::List(Patterns::Double(0., 0.45), 1),
                            "'Distortion' (subsection 'Geometry') values; "
                            "each gives its own series and plot panel.");
          prm.declare_entry(
            "Horizon factors",
            "",
            Patterns::List(Patterns::Double(0.), 0),
            "'Horizon factor' (subsection 'Discretization') values; empty: "
            "the file's value. Each gives its own series (cost against "
            "horizon).");
          prm.declare_entry(
            "Configurations",
            "FEM | FEM | none",
            Patterns::Anything(),
            "The discretisations compared, separated by ';', each "
            "'label | Formulation | Meshfree region' with the values of "
            "'Formulation' (subsection 'Discretization') and 'Meshfree "
            "region' (subsection 'Geometry'). E.g. 'FEM | FEM | none; "
            "coupled 2R | VCBCPPG V3sn Unl | ball 0, 0 : 2'.");
          prm.declare_entry(
            "Stress point",
            "",
            Patterns::Anything(),
            "A name from 'Points' (subsection 'Output'): the relative error "
            "of 'Stress component' at the mesh vertex nearest that point is "
            "a column of the table (needs 'Compute errors'). Empty: none.");
          prm.declare_entry("Stress component",
                            "xx",
                            Patterns::Selection("xx|yy|zz|xy|xz|yz"),
                            "The Cauchy stress component of 'Stress point'.");
          prm.declare_entry(
            "Directory",
            "study",
            Patterns::Anything(),
            "Where study.txt, rates.txt, series/*.dat, study.gp and the "
            "runs/ directories (one per run, with its usual files and "
            "log.txt) go. Created if missing; 'Directory' of subsection "
            "'Output' is replaced.");
          prm.declare_entry("Report wall times",
                            "true",
                            Patterns::Bool(),
                            "Print each run's wall time in the progress "
                            "lines (the tables always have them). Tests "
                            "switch this off to compare the screen output.");
          prm.declare_entry(
            "Time limit per run",
            "0",
            Patterns::Double(0.),
            "Once a run of a series takes longer than this (seconds, total "
            "wall time), the finer levels of that series are skipped. 0: no "
            "limit. A failed run also ends its series.");
          prm.declare_entry(
            "Target error",
            "0",
            Patterns::Double(0.),
            "A relative energy-norm error: the wall time each series needs "
            "to reach it, interpolated log-log between the levels that "
            "bracket it, goes to time_to_error.txt (and to the screen with "
            "'Report wall times'). 0: off.");
        }
        prm.leave_subsection();
      }



      void
      Parameters::parse_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("Study");
        {
          problem_file = prm.get("Problem file");
          refinement_levels.clear();
          for (const int level : Utilities::string_to_int(
                 Utilities::split_string_list(prm.get("Refinement levels"))))
            refinement_levels.push_back(level);
          std::sort(refinement_levels.begin(), refinement_levels.end());
          distortions = Utilities::string_to_double(
            Utilities::split_string_list(prm.get("Distortions")));
          horizon_factors = Utilities::string_to_double(
            Utilities::split_string_list(prm.get("Horizon factors")));

          configurations.clear();
          const std::string text = prm.get("Configurations");
          for (const std::string &item :
               Utilities::split_string_list(text, ';'))
            {
              const std::vector<std::string> fields =
                Utilities::split_string_list(item, '|');
              AssertThrow(
                fields.size() == 3 && !fields[0].empty() && !fields[1].empty(),
                ExcBadParameter("Study/Configurations",
                                text,
                                "each configuration must read 'label | "
                                "Formulation | Meshfree region', e.g. 'coupled "
                                "2R | VCBCPPG V3sn Unl | ball 0, 0 : 2'."));
              configurations.push_back({fields[0], fields[1], fields[2]});
            }
          AssertThrow(!configurations.empty(),
                      ExcBadParameter("Study/Configurations",
                                      text,
                                      "at least one configuration is needed."));

          stress_point                 = prm.get("Stress point");
          const std::string component  = prm.get("Stress component");
          const auto        axis_index = [](const char c) {
            return static_cast<unsigned int>(c - 'x');
          };
          stress_row        = axis_index(component[0]);
          stress_column     = axis_index(component[1]);
          directory         = prm.get("Directory");
          report_wall_times = prm.get_bool("Report wall times");
          time_limit        = prm.get_double("Time limit per run");
          target_error      = prm.get_double("Target error");
        }
        prm.leave_subsection();
      }



      namespace
      {
        /**
         * 'Problem file' of the study file @p filename, resolved against the
         * study file's directory; empty if not given.
         */
        std::string
        problem_file(const std::string &filename)
        {
          ParameterHandler prm;
          Study::Parameters::declare_parameters(prm);
          prm.parse_input(filename, "", true);
          prm.enter_subsection("Study");
          const std::filesystem::path file = prm.get("Problem file");
          prm.leave_subsection();
          if (file.empty() || file.is_absolute())
            return file.string();
          const std::filesystem::path resolved =
            std::filesystem::path(filename).parent_path() / file;
          AssertThrow(std::filesystem::exists(resolved),
                      ExcBadParameter("Study/Problem file",
                                      file.string(),
                                      "the file <" + resolved.string() +
                                        "> does not exist (a relative path "
                                        "starts in the directory of the "
                                        "study file)."));
          return resolved.string();
        }



        template <int dim>
        std::vector<Run>
        run_dim(const std::string &filename,
                const MPI_Comm     comm,
                std::ostream      &out)
        {
          ParameterHandler prm;
          pg::Parameters::AllParameters<dim>::declare_parameters(prm);
          Study::Parameters::declare_parameters(prm);
          if (const std::string problem = problem_file(filename);
              !problem.empty())
            pg::Parameters::parse_parameter_file(prm, problem);
          pg::Parameters::parse_parameter_file(prm, filename);
          Study::Parameters study;
          study.parse_parameters(prm);
          const bool         root = Utilities::MPI::this_mpi_process(comm) == 0;
          ConditionalOStream pout(out, root);

          std::vector<double> horizons = study.horizon_factors;
          {
            pg::Parameters::AllParameters<dim> base;
            base.parse_parameters(prm);
            if (horizons.empty())
              horizons.push_back(base.discretization.horizon_factor);
            if (!study.stress_point.empty())
              {
                const auto &points = base.output.points;
                AssertThrow(
                  std::any_of(points.begin(),
                              points.end(),
                              [&](const auto &p) {
                                return p.first == study.stress_point;
                              }),
                  ExcBadParameter("Study/Stress point",
                                  study.stress_point,
                                  "it must be one of the names of 'Points' "
                                  "in subsection 'Output'."));
                AssertThrow(base.compute_errors,
                            ExcBadParameter(
                              "Study/Stress point",
                              study.stress_point,
                              "its error needs the exact solution: set "
                              "'Compute errors = true' in subsection 'Exact "
                              "solution'."));
                AssertThrow(std::max(study.stress_row, study.stress_column) <
                              dim,
                            ExcBadParameter("Study/Stress component",
                                            "z",
                                            "a 2-D study has the components "
                                            "xx, yy and xy."));
              }
          }

          const unsigned int n_runs =
            study.configurations.size() * study.distortions.size() *
            horizons.size() * study.refinement_levels.size();
          pout << "pg_study: " << n_runs << " runs ("
               << study.configurations.size() << " configurations x "
               << study.distortions.size() << " distortions x "
               << horizons.size() << " horizon factors x "
               << study.refinement_levels.size() << " levels) into "
               << study.directory << "/" << std::endl;

          std::vector<Run> runs;
          unsigned int     index = 0;
          for (unsigned int c = 0; c < study.configurations.size(); ++c)
            for (const double distortion : study.distortions)
              for (const double horizon : horizons)
                {
                  const Configuration &configuration = study.configurations[c];
                  bool                 end_series    = false;
                  for (const unsigned int level : study.refinement_levels)
                    {
                      Run run;
                      run.configuration  = c;
                      run.distortion     = distortion;
                      run.horizon_factor = horizon;
                      run.level          = level;
                      std::ostringstream head;
                      head << "[" << std::setw(3) << ++index << "/" << n_runs
                           << "] " << configuration.label << ", distortion "
                           << distortion
                           << (horizons.size() > 1 ?
                                 ", horizon " + format(horizon) :
                                 "")
                           << ", refinement " << level << ": ";
                      if (end_series)
                        {
                          run.skipped = true;
                          pout << head.str() << "skipped" << std::endl;
                          runs.push_back(run);
                          continue;
                        }
                      const std::string run_directory =
                        study.directory + "/runs/" + slug(configuration.label) +
                        "_d" + format(distortion) + "_h" + format(horizon) +
                        "_r" + std::to_string(level);
                      prm.enter_subsection("Geometry");
                      prm.set("Global refinement", std::to_string(level));
                      prm.set("Distortion", distortion);
                      prm.set("Meshfree region", configuration.meshfree_region);
                      prm.leave_subsection();
                      prm.enter_subsection("Discretization");
                      prm.set("Formulation", configuration.formulation);
                      // 0: the base file gives an absolute 'Horizon'
                      if (horizon > 0)
                        prm.set("Horizon factor", horizon);
                      prm.leave_subsection();
                      prm.enter_subsection("Output");
                      prm.set("Directory", run_directory);
                      prm.leave_subsection();

                      if (root)
                        std::filesystem::create_directories(run_directory);
                      MPI_Barrier(comm);
                      std::ofstream log;
                      if (root)
                        log.open(run_directory + "/log.txt");
                      try
                        {
                          pg::Parameters::AllParameters<dim> parameters;
                          parameters.parse_parameters(prm);
                          Problem<dim> problem(parameters, comm, log);
                          problem.run();
                          run.summary = problem.summary();
                          run.ok      = run.summary.converged;
                          if (!run.ok)
                            run.failure = "did not converge";
                        }
                      catch (const std::exception &e)
                        {
                          run.failure = one_line(user_message(e));
                          log << e.what() << std::endl;
                        }

                      if (run.ok && !study.stress_point.empty())
                        {
                          const auto find = [&](const auto &list) {
                            for (const auto &[name, values] : list)
                              if (name == study.stress_point)
                                return values[study.stress_row * dim +
                                              study.stress_column];
                            return std::numeric_limits<double>::quiet_NaN();
                          };
                          const double h = find(run.summary.point_stresses);
                          const double e =
                            find(run.summary.point_exact_stresses);
                          run.stress_error =
                            std::abs(h - e) / (e != 0. ? std::abs(e) : 1.);
                        }

                      pout << head.str();
                      if (run.ok)
                        {
                          const RunSummary &s = run.summary;
                          pout << s.n_dofs << " DoFs, " << s.newton_iterations
                               << " Newton its., L2 "
                               << scientific(s.L2_relative) << ", energy "
                               << scientific(s.energy_relative);
                          if (!study.stress_point.empty())
                            pout << ", stress " << scientific(run.stress_error);
                          if (study.report_wall_times)
                            pout << ", " << format(solution_time(s)) << " s";
                        }
                      else
                        pout << "FAILED (" << run.failure
                             << "); finer levels of this series are skipped";
                      pout << std::endl;
                      end_series = !run.ok || (study.time_limit > 0 &&
                                               run.summary.timing.at("total") >
                                                 study.time_limit);
                      runs.push_back(run);
                    }
                }

          if (root)
            write_results<dim>(runs, study, horizons, out);
          const unsigned int n_failed =
            std::count_if(runs.begin(), runs.end(), [](const Run &r) {
              return !r.ok && !r.skipped;
            });
          pout << "Wrote " << study.directory
               << "/study.txt, rates.txt, series/*.dat and study.gp"
               << (study.target_error > 0 ? ", time_to_error.txt" : "")
               << "; plots: cd " << study.directory << " && gnuplot study.gp"
               << std::endl;
          if (n_failed > 0)
            pout << n_failed << " run(s) failed; see log.txt in their "
                 << "directories under " << study.directory << "/runs/"
                 << std::endl;
          return runs;
        }
      } // namespace



      std::vector<Run>
      run_study_file(const std::string &filename,
                     const MPI_Comm     comm,
                     std::ostream      &out)
      {
        const std::string  problem = problem_file(filename);
        const unsigned int dim =
          pg::Parameters::read_dimension(problem.empty() ? filename : problem);
        pg::Parameters::load_additional_shared_libraries(
          problem.empty() ? filename : problem);
        return (dim == 2) ? run_dim<2>(filename, comm, out) :
                            run_dim<3>(filename, comm, out);
      }
    } // namespace Study
  }   // namespace Analysis
} // namespace pg
