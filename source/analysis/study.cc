#include <pg/analysis/study.h>
#include <pg/base/exceptions.h>
#include <pg/base/parameters.h>

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
        /** "coupled 2R" -> "coupled_2r": a file name. */
        std::string
        slug(const std::string &text)
        {
          std::string s;
          for (const char c : text)
            if (std::isalnum(static_cast<unsigned char>(c)) || c == '.')
              s += static_cast<char>(std::tolower(c));
            else if (!s.empty() && s.back() != '_')
              s += '_';
          while (!s.empty() && s.back() == '_')
            s.pop_back();
          return s;
        }



        std::string
        format(const double x, const int digits = 3)
        {
          std::ostringstream s;
          s << std::setprecision(digits) << x;
          return s.str();
        }



        std::string
        fixed(const double x)
        {
          std::ostringstream s;
          s << std::fixed << std::setprecision(2) << x;
          return s.str();
        }



        std::string
        scientific(const double x)
        {
          std::ostringstream s;
          s << std::scientific << std::setprecision(2) << x;
          return s.str();
        }



        /**
         * The part of an exception message a user needs: deal.II's
         * "Additional information" (without the stack trace), white space
         * collapsed.
         */
        std::string
        short_message(const std::string &what)
        {
          std::string       text = what;
          const std::string key  = "Additional information:";
          if (const auto at = text.find(key); at != std::string::npos)
            text = text.substr(at + key.size());
          if (const auto at = text.find("Stacktrace:"); at != std::string::npos)
            text = text.substr(0, at);
          std::string s;
          for (const char c : text)
            if (!std::isspace(static_cast<unsigned char>(c)))
              s += c;
            else if (!s.empty() && s.back() != ' ')
              s += ' ';
          while (!s.empty() && (s.back() == ' ' || s.back() == '-'))
            s.pop_back();
          return s;
        }



        /** The series of a run: everything but the refinement level. */
        struct SeriesKey
        {
          unsigned int configuration;
          double       distortion, horizon_factor;
          bool
          operator<(const SeriesKey &o) const
          {
            return std::tie(configuration, distortion, horizon_factor) <
                   std::tie(o.configuration, o.distortion, o.horizon_factor);
          }
        };



        double
        step_time(const RunSummary &s)
        {
          const auto  &c = s.assembly_cost;
          const double assembly =
            c.n_assemblies > 0 ? s.timing.at("assembly") / c.n_assemblies : 0;
          const double solve =
            c.n_solves > 0 ? s.timing.at("solve") / c.n_solves : 0;
          return assembly + solve;
        }



        /**
         * The wall time to the solution: everything but the post-processing
         * (error norms, statistics, output files), which every
         * configuration does alike.
         */
        double
        solution_time(const RunSummary &s)
        {
          return s.timing.at("total") - s.timing.at("postprocess");
        }



        /** Rate in h ~ N^(-1/dim) between two runs. */
        double
        rate(const double       e0,
             const double       e1,
             const double       n0,
             const double       n1,
             const unsigned int dim)
        {
          return -double(dim) * std::log(e1 / e0) / std::log(n1 / n0);
        }



        template <int dim>
        void
        write_results(const std::vector<Run>    &runs,
                      const Study::Parameters   &study,
                      const std::vector<double> &horizons,
                      std::ostream              &out)
        {
          const auto       &configurations = study.configurations;
          const std::string dir            = study.directory + "/";
          const bool        with_stress    = !study.stress_point.empty();
          const std::string stress_name =
            "sigma_" +
            std::string{"xyz"[study.stress_row], "xyz"[study.stress_column]} +
            "(" + study.stress_point + ")";
          const auto series_label = [&](const SeriesKey &key) {
            std::string label = configurations[key.configuration].label +
                                ", distortion " + format(key.distortion);
            if (horizons.size() > 1)
              label += ", horizon " + format(key.horizon_factor);
            return label;
          };
          const auto series_file = [&](const SeriesKey &key) {
            return "series/" + slug(configurations[key.configuration].label) +
                   "_d" + format(key.distortion) + "_h" +
                   format(key.horizon_factor) + ".dat";
          };

          std::map<SeriesKey, std::vector<const Run *>> series;
          for (const Run &run : runs)
            if (run.ok)
              series[{run.configuration, run.distortion, run.horizon_factor}]
                .push_back(&run);

          // study.txt: every successful run with errors, cost and rates
          TableHandler  table;
          std::ofstream rates(dir + "rates.txt");
          rates << "# Relative errors and convergence rates in h ~ "
                   "N^(-1/dim) (N: DoFs) between successive levels\n";
          out << "\nConvergence (relative errors; rates in h ~ N^(-1/dim)):"
              << std::endl;
          std::filesystem::create_directories(dir + "series");
          for (const auto &[key, list] : series)
            {
              std::ostringstream block;
              block << series_label(key) << "\n"
                    << "  level   DoFs      L2  rate   energy  rate"
                    << (with_stress ? "  " + stress_name + " error" : "")
                    << "  interface jump\n";
              std::ofstream data(dir + series_file(key));
              data << "# " << series_label(key) << "\n"
                   << "# level n_dofs L2_relative H1_relative "
                      "energy_relative stress_error solution_seconds "
                      "seconds_per_newton_step interface_jump\n"
                   << std::setprecision(8);
              for (unsigned int i = 0; i < list.size(); ++i)
                {
                  const RunSummary &s       = list[i]->summary;
                  const double      N       = s.n_dofs;
                  std::string       rate_L2 = "-", rate_energy = "-";
                  if (i > 0)
                    {
                      const RunSummary &p = list[i - 1]->summary;
                      rate_L2             = fixed(
                        rate(p.L2_relative, s.L2_relative, p.n_dofs, N, dim));
                      rate_energy = fixed(rate(p.energy_relative,
                                               s.energy_relative,
                                               p.n_dofs,
                                               N,
                                               dim));
                    }
                  block << "  " << std::setw(5) << list[i]->level << " "
                        << std::setw(6) << s.n_dofs << "  "
                        << scientific(s.L2_relative) << " " << std::setw(5)
                        << rate_L2 << "  " << scientific(s.energy_relative)
                        << " " << std::setw(5) << rate_energy;
                  if (with_stress)
                    block << "  " << std::setw(stress_name.size() + 6)
                          << scientific(list[i]->stress_error);
                  block << "  " << scientific(s.max_interface_stress_jump)
                        << "\n";
                  data << list[i]->level << " " << s.n_dofs << " "
                       << s.L2_relative << " " << s.H1_relative << " "
                       << s.energy_relative << " " << list[i]->stress_error
                       << " " << solution_time(s) << " " << step_time(s) << " "
                       << s.max_interface_stress_jump << "\n";

                  const auto &c = s.assembly_cost;
                  table.add_value("configuration",
                                  configurations[key.configuration].label);
                  table.add_value("distortion", key.distortion);
                  table.add_value("horizon", key.horizon_factor);
                  table.add_value("level", list[i]->level);
                  table.add_value("DoFs", s.n_dofs);
                  table.add_value("particles", s.n_particles);
                  table.add_value("nnz/row", double(s.matrix_nonzeros) / N);
                  table.add_value("Newton", s.newton_iterations);
                  table.add_value("L2", s.L2_relative);
                  table.add_value("H1", s.H1_relative);
                  table.add_value("energy", s.energy_relative);
                  table.add_value("rate L2", rate_L2);
                  table.add_value("rate energy", rate_energy);
                  if (with_stress)
                    table.add_value("stress error", list[i]->stress_error);
                  table.add_value("interface jump",
                                  s.max_interface_stress_jump);
                  for (const char *phase : {"mesh",
                                            "setup",
                                            "shape_functions",
                                            "vc",
                                            "assembly",
                                            "solve",
                                            "postprocess",
                                            "total"})
                    table.add_value(std::string(phase) + " s",
                                    s.timing.at(phase));
                  table.add_value("solution s", solution_time(s));
                  table.add_value("s/Newton step", step_time(s));
                  const auto per_second = [&](const double amount,
                                              const double seconds) {
                    return seconds > 0 ? amount * c.n_assemblies / seconds : 0.;
                  };
                  table.add_value("FE Mentries/s",
                                  1e-6 *
                                    per_second(c.fe_entries, c.fe_seconds));
                  table.add_value("PG Mentries/s",
                                  1e-6 * per_second(c.family_entries,
                                                    c.family_seconds));
                  table.add_value("FE Gflop/s",
                                  1e-9 * per_second(c.fe_flops, c.fe_seconds));
                  table.add_value("PG Gflop/s",
                                  1e-9 * per_second(c.family_flops,
                                                    c.family_seconds));
                }
              out << block.str();
              rates << block.str();
            }
          for (const char *column : {"L2",
                                     "H1",
                                     "energy",
                                     "mesh s",
                                     "setup s",
                                     "shape_functions s",
                                     "postprocess s",
                                     "solution s",
                                     "vc s",
                                     "assembly s",
                                     "solve s",
                                     "total s",
                                     "s/Newton step"})
            {
              table.set_scientific(column, true);
              table.set_precision(column, 2);
            }
          table.set_scientific("interface jump", true);
          table.set_precision("interface jump", 2);
          if (with_stress)
            {
              table.set_scientific("stress error", true);
              table.set_precision("stress error", 2);
            }
          for (const char *column : {"nnz/row",
                                     "FE Mentries/s",
                                     "PG Mentries/s",
                                     "FE Gflop/s",
                                     "PG Gflop/s"})
            table.set_precision(column, 3);
          std::ofstream study_table(dir + "study.txt");
          table.write_text(study_table, TableHandler::org_mode_table);

          // time to reach the target error, per distortion
          if (study.target_error > 0)
            {
              std::ofstream target(dir + "time_to_error.txt");
              target << "# wall time (s) to reach a relative energy error of "
                     << study.target_error
                     << " (log-log interpolation between levels)\n";
              for (const double distortion : study.distortions)
                {
                  std::vector<std::pair<double, std::string>> times;
                  for (const auto &[key, list] : series)
                    if (key.distortion == distortion)
                      for (unsigned int i = 0; i < list.size(); ++i)
                        {
                          const RunSummary &s = list[i]->summary;
                          if (s.energy_relative > study.target_error)
                            continue;
                          double t = solution_time(s);
                          if (i > 0)
                            {
                              const RunSummary &p = list[i - 1]->summary;
                              const double      x =
                                std::log(study.target_error /
                                         p.energy_relative) /
                                std::log(s.energy_relative / p.energy_relative);
                              t = std::exp(std::log(solution_time(p)) +
                                           x * std::log(solution_time(s) /
                                                        solution_time(p)));
                            }
                          times.emplace_back(t, series_label(key));
                          break;
                        }
                  std::sort(times.begin(), times.end());
                  target << "distortion " << distortion << ":\n";
                  for (const auto &[t, label] : times)
                    target << "  " << std::setw(10) << format(t) << " s  "
                           << label << "\n";
                  if (study.report_wall_times)
                    {
                      out << "Time to reach a relative energy error of "
                          << study.target_error << " (distortion " << distortion
                          << "):\n";
                      for (const auto &[t, label] : times)
                        out << "  " << std::setw(10) << format(t) << " s  "
                            << label << "\n";
                    }
                }
            }

          // study.gp: energy and L2 error against wall time and DoFs
          std::ofstream gp(dir + "study.gp");
          gp << "# Drawn by pg_study; run 'gnuplot study.gp' in this "
                "directory.\n"
             << "set terminal pngcairo size " << 520 * study.distortions.size()
             << ",900 font ',10'\nset logscale xy\nset grid\n"
             << "set key bottom left font ',8'\nset format y '10^{%T}'\n";
          const auto plot = [&](const std::string &file,
                                const std::string &xlabel,
                                const unsigned int column) {
            gp << "set output '" << file << "'\n"
               << "set multiplot layout 2," << study.distortions.size() << "\n";
            for (const auto &[error, error_column] :
                 std::vector<std::pair<std::string, unsigned int>>{
                   {"relative energy error", 5},
                   {"relative L2 error", 3}})
              for (const double distortion : study.distortions)
                {
                  gp << "set title 'distortion " << distortion
                     << "'\nset xlabel '" << xlabel << "'\nset ylabel '"
                     << error << "'\nplot";
                  bool first = true;
                  for (const auto &[key, list] : series)
                    if (key.distortion == distortion)
                      {
                        gp << (first ? " " : ", \\\n     ") << "'"
                           << series_file(key) << "' using " << column << ":"
                           << error_column << " with linespoints title '"
                           << configurations[key.configuration].label
                           << (horizons.size() > 1 ?
                                 " h" + format(key.horizon_factor) :
                                 "")
                           << "'";
                        first = false;
                      }
                  if (first)
                    gp << " NaN notitle";
                  gp << "\n";
                }
            gp << "unset multiplot\n";
          };
          plot("error_vs_time.png", "wall time to the solution (s)", 7);
          plot("error_vs_dofs.png", "DoFs", 2);
        }



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
            prm.parse_input(problem);
          prm.parse_input(filename);
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
                          run.failure = short_message(e.what());
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
        return (dim == 2) ? run_dim<2>(filename, comm, out) :
                            run_dim<3>(filename, comm, out);
      }
    } // namespace Study
  }   // namespace Analysis
} // namespace pg
