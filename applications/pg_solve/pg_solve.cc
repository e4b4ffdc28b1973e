// pg_solve: run a pg parameter file.
//
//   pg_solve file.prm              solve
//   pg_solve --print-parameters    print every parameter with its
//                                  documentation (2-D defaults) and exit
//   pg_solve --validate file.prm   parse the file and exit
//   pg_solve --help

#include <pg/base/parameters.h>
#include <pg/problem.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <iostream>
#include <string>

namespace
{
  void
  print_usage(std::ostream &out)
  {
    out << "Usage: pg_solve <file.prm>\n"
        << "       pg_solve --validate <file.prm>\n"
        << "       pg_solve --print-parameters\n"
        << "       pg_solve --help\n"
        << "Solves the quasi-static problem described by the parameter file "
           "and writes\nVTU/PVD files, statistics.txt and summary.json to "
           "'Directory' in subsection\n'Output' (default: results).\n";
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
          pg::declare_all_parameters<2>(prm);
          if (root)
            prm.print_parameters(std::cout, ParameterHandler::PRM);
          return 0;
        }
      if (args[0] == "--validate")
        {
          AssertThrow(args.size() == 2,
                      ExcMessage("--validate needs a parameter file."));
          const unsigned int dim = pg::Parameters::read_dimension(args[1]);
          ParameterHandler   prm;
          if (dim == 2)
            pg::declare_all_parameters<2>(prm);
          else
            pg::declare_all_parameters<3>(prm);
          prm.parse_input(args[1]);
          if (root)
            std::cout << args[1] << ": valid" << std::endl;
          return 0;
        }
      pg::run_parameter_file(args[0], MPI_COMM_WORLD, std::cout);
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
