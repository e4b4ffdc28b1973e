// pg_study: run one problem over refinement levels x configurations x
// distortions (x horizon factors) and collect the results.
//
//   pg_study study.prm             run the study of subsection 'Study'
//   pg_study --print-parameters    print the 'Study' parameters with their
//                                  documentation and exit
//   pg_study --help

#include <pg/analysis/study.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <iostream>
#include <string>

namespace
{
  void
  print_usage(std::ostream &out)
  {
    out << "Usage: pg_study <study.prm>\n"
        << "       pg_study --print-parameters\n"
        << "       pg_study --help\n"
        << "Runs the pg_solve problem of the parameter file once for every "
           "combination of\nthe lists in subsection 'Study' and writes "
           "study.txt, rates.txt, series/*.dat\nand study.gp (error against "
           "wall time and against DoFs) to its 'Directory'.\nExit code 1 if "
           "a run failed.\n";
  }
} // namespace



int
main(int argc, char *argv[])
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  try
    {
      const std::vector<std::string> args(argv + 1, argv + argc);
      if (args.empty() || args[0] == "--help" || args[0] == "-h")
        {
          if (root)
            print_usage(std::cout);
          return args.empty() ? 1 : 0;
        }
      if (args[0] == "--print-parameters")
        {
          ParameterHandler prm;
          pg::Analysis::Study::Parameters::declare_parameters(prm);
          if (root)
            prm.print_parameters(std::cout, ParameterHandler::PRM);
          return 0;
        }
      const auto runs =
        pg::Analysis::Study::run_study_file(args[0], MPI_COMM_WORLD, std::cout);
      const bool failed =
        std::any_of(runs.begin(), runs.end(), [](const auto &run) {
          return !run.ok && !run.skipped;
        });
      return failed ? 1 : 0;
    }
  catch (std::exception &exc)
    {
      std::cerr << std::endl
                << "----------------------------------------------------"
                << std::endl
                << "Exception on processing: " << std::endl
                << exc.what() << std::endl
                << "Aborting!" << std::endl
                << "----------------------------------------------------"
                << std::endl;
      if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
        MPI_Abort(MPI_COMM_WORLD, 1);
      return 1;
    }
  catch (...)
    {
      std::cerr << std::endl << "Unknown exception! Aborting!" << std::endl;
      if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
        MPI_Abort(MPI_COMM_WORLD, 1);
      return 1;
    }
  return 0;
}
