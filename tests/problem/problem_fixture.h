#ifndef pg_tests_problem_fixture_h
#define pg_tests_problem_fixture_h

// Run pg's Problem from a parameter text, as pg_solve does from a file.

#include <pg/base/parameters.h>
#include <pg/problem.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <fstream>
#include <sstream>
#include <string>

/** The text of the file @p name (a parameter file of prm/). */
inline std::string
read_file(const std::string &name)
{
  std::ifstream     file(name);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
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

#endif
