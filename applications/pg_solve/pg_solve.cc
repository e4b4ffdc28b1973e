// pg_solve: run a pg parameter file.
//
//   pg_solve file.prm              solve
//   pg_solve --restart file.prm    continue from the checkpoint in the
//                                  output directory
//   pg_solve --print-parameters    print every parameter with its
//                                  documentation (2-D defaults) and exit
//   pg_solve --validate file.prm   parse and check the file, and exit
//   pg_solve --help

#include <pg/base/application.h>
#include <pg/base/parameter_file.h>
#include <pg/base/parameters.h>
#include <pg/base/shared_libraries.h>
#include <pg/problem.h>

#include <iostream>
#include <string>

int
main(int argc, char *argv[])
{
  using namespace dealii;
  return pg::run_application(
    argc,
    argv,
    "Usage: pg_solve <file.prm>\n"
    "       pg_solve --restart <file.prm>\n"
    "       pg_solve --validate <file.prm>\n"
    "       pg_solve --print-parameters\n"
    "       pg_solve --help\n"
    "Solves the quasi-static problem described by the parameter file and "
    "writes\nVTU/PVD files, statistics.txt and summary.json to 'Directory' in "
    "subsection\n'Output' (default: results). With --restart it continues "
    "from the checkpoint\nthere (written every 'Checkpoint interval' steps "
    "and when SIGINT or SIGTERM\nstops a run), with the same parameter file "
    "on the same number of MPI ranks.\n",
    pg::declare_all_parameters<2>,
    [](const std::vector<std::string> &args, const bool root) {
      if (args[0] == "--validate")
        {
          AssertThrow(args.size() == 2,
                      ExcMessage("--validate needs a parameter file."));
          const unsigned int dim = pg::Parameters::read_dimension(args[1]);
          pg::Parameters::load_additional_shared_libraries(args[1]);
          ParameterHandler prm;
          if (dim == 2)
            pg::declare_all_parameters<2>(prm);
          else
            pg::declare_all_parameters<3>(prm);
          pg::Parameters::parse_parameter_file(prm, args[1]);
          // the checks a run makes before it reads a mesh: entries that
          // contradict each other (a mixed code on a material without the
          // volumetric split, an hourglass coefficient on Unl, ...)
          if (dim == 2)
            pg::Parameters::AllParameters<2>().parse_parameters(prm);
          else
            pg::Parameters::AllParameters<3>().parse_parameters(prm);
          if (root)
            std::cout << args[1] << ": valid" << std::endl;
          return 0;
        }
      if (args[0] == "--restart")
        {
          AssertThrow(args.size() == 2,
                      ExcMessage("--restart needs a parameter file: "
                                 "pg_solve --restart file.prm"));
          pg::run_parameter_file(args[1], MPI_COMM_WORLD, std::cout, true);
          return 0;
        }
      pg::run_parameter_file(args[0], MPI_COMM_WORLD, std::cout);
      return 0;
    });
}
