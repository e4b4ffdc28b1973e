#include <pg/analysis/study.h>
#include <pg/analysis/study_report.h>

#include <deal.II/base/table_handler.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>
#include <tuple>

namespace pg
{
  namespace Analysis
  {
    namespace Study
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
      format(const double x, const int digits)
      {
        std::ostringstream s;
        s << std::setprecision(digits) << x;
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
       * The wall time to the solution: everything but the post-processing
       * (error norms, statistics, output files), which every
       * configuration does alike.
       */
      double
      solution_time(const RunSummary &s)
      {
        return s.timing.at("total") - s.timing.at("postprocess");
      }



      // named, not anonymous: SeriesKey is used by the lambdas of the
      // template write_results(), which GCC rejects for a type with
      // internal linkage when this file is compiled inside a unity batch
      // (-Wsubobject-linkage)
      namespace report_details
      {
        std::string
        fixed(const double x)
        {
          std::ostringstream s;
          s << std::fixed << std::setprecision(2) << x;
          return s.str();
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
      } // namespace report_details
      using namespace report_details;



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
                      << rate_L2 << "  " << scientific(s.energy_relative) << " "
                      << std::setw(5) << rate_energy;
                if (with_stress)
                  block << "  " << std::setw(stress_name.size() + 6)
                        << scientific(list[i]->stress_error);
                block << "  " << scientific(s.max_interface_stress_jump)
                      << "\n";
                data << list[i]->level << " " << s.n_dofs << " "
                     << s.L2_relative << " " << s.H1_relative << " "
                     << s.energy_relative << " " << list[i]->stress_error << " "
                     << solution_time(s) << " " << step_time(s) << " "
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
                table.add_value("interface jump", s.max_interface_stress_jump);
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
                                1e-6 * per_second(c.fe_entries, c.fe_seconds));
                table.add_value("PG Mentries/s",
                                1e-6 * per_second(c.family_entries,
                                                  c.family_seconds));
                table.add_value("FE Gflop/s",
                                1e-9 * per_second(c.fe_flops, c.fe_seconds));
                table.add_value("PG Gflop/s",
                                1e-9 *
                                  per_second(c.family_flops, c.family_seconds));
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
                              std::log(study.target_error / p.energy_relative) /
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
                   << "'\nset xlabel '" << xlabel << "'\nset ylabel '" << error
                   << "'\nplot";
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



      template void
      write_results<2>(const std::vector<Run> &,
                       const Study::Parameters &,
                       const std::vector<double> &,
                       std::ostream &);
      template void
      write_results<3>(const std::vector<Run> &,
                       const Study::Parameters &,
                       const std::vector<double> &,
                       std::ostream &);
    } // namespace Study
  }   // namespace Analysis
} // namespace pg
