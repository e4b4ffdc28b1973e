#ifndef pg_tests_problem_fixture_h
#define pg_tests_problem_fixture_h

// Run pg's Problem from a parameter text, as pg_solve does from a file.

#include <pg/base/parameters.h>
#include <pg/problem.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

/** The text of the file @p name (a parameter file of prm/). */
inline std::string
read_file(const std::string &name)
{
  std::ifstream     file(name);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

/** The columns of a run's statistics.txt by name (without the wall time). */
inline std::map<std::string, std::vector<double>>
read_statistics(const std::string &file_name)
{
  std::ifstream                              file(file_name);
  std::vector<std::string>                   names;
  std::map<std::string, std::vector<double>> columns;
  std::string                                line;
  while (std::getline(file, line))
    {
      if (line.rfind("# ", 0) == 0)
        {
          names.push_back(line.substr(line.find(':') + 2));
          continue;
        }
      std::istringstream values(line);
      double             v;
      for (unsigned int c = 0; values >> v && c < names.size(); ++c)
        if (names[c] != "wall time")
          columns[names[c]].push_back(v);
    }
  return columns;
}



/** Run the parameters @p parameters (with @p restart: pg_solve --restart). */
template <int dim>
pg::RunSummary
run_problem(const std::string &parameters,
            std::ostream      &screen,
            const bool         restart = false)
{
  dealii::ParameterHandler prm;
  pg::declare_all_parameters<dim>(prm);
  prm.parse_input_from_string(parameters);
  pg::Parameters::AllParameters<dim> all;
  all.parse_parameters(prm);
  pg::Problem<dim> problem(all, MPI_COMM_WORLD, screen, restart);
  problem.run();
  return problem.summary();
}



/**
 * max over the 'Output/Points' and components |u - u_reference| / max
 * |u_reference| of two runs with the same points (e.g. a symmetric part
 * against the full body).
 */
inline double
point_difference(const pg::RunSummary &run, const pg::RunSummary &reference)
{
  double largest = 0, scale = 0;
  for (unsigned int p = 0; p < reference.points.size(); ++p)
    for (unsigned int c = 0; c < reference.points[p].second.size(); ++c)
      {
        largest = std::max(largest,
                           std::abs(run.points[p].second[c] -
                                    reference.points[p].second[c]));
        scale   = std::max(scale, std::abs(reference.points[p].second[c]));
      }
  return largest / scale;
}

#endif
