// pg_study: run one problem over refinement levels x configurations x
// distortions (x horizon factors) and collect the results.
//
//   pg_study study.prm             run the study of subsection 'Study'
//   pg_study --print-parameters    print the 'Study' parameters with their
//                                  documentation and exit
//   pg_study --help

#include <pg/analysis/study.h>
#include <pg/base/application.h>

#include <algorithm>
#include <iostream>
#include <string>

int
main(int argc, char *argv[])
{
  return pg::run_application(
    argc,
    argv,
    "Usage: pg_study <study.prm>\n"
    "       pg_study --print-parameters\n"
    "       pg_study --help\n"
    "Runs the pg_solve problem of the parameter file once for every "
    "combination of\nthe lists in subsection 'Study' and writes study.txt, "
    "rates.txt, series/*.dat\nand study.gp (error against wall time and "
    "against DoFs) to its 'Directory'.\nExit code 1 if a run failed.\n",
    pg::Analysis::Study::Parameters::declare_parameters,
    [](const std::vector<std::string> &args, bool) {
      const auto runs =
        pg::Analysis::Study::run_study_file(args[0], MPI_COMM_WORLD, std::cout);
      return std::any_of(runs.begin(),
                         runs.end(),
                         [](const auto &run) {
                           return !run.ok && !run.skipped;
                         }) ?
               1 :
               0;
    });
}
