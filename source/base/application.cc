#include <pg/base/application.h>
#include <pg/base/exceptions.h>
#include <pg/base/interruption.h>

#include <deal.II/base/mpi.h>

#include <cstdlib>
#include <iostream>

namespace pg
{
  int
  run_application(
    int                                                               argc,
    char                                                            **argv,
    const std::string                                                &usage,
    const std::function<void(ParameterHandler &)>                    &declare,
    const std::function<int(const std::vector<std::string> &, bool)> &run)
  {
    // threads: all cores not taken by other MPI ranks of the node, at most
    // DEAL_II_NUM_THREADS (deal.II's rule)
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv);
    const bool root  = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    const auto abort = []() {
      if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
        MPI_Abort(MPI_COMM_WORLD, 1);
      return 1;
    };
    try
      {
        const std::vector<std::string> args(argv + 1, argv + argc);
        if (args.empty() || args[0] == "--help" || args[0] == "-h")
          {
            if (root)
              std::cout << usage;
            return args.empty() ? 1 : 0;
          }
        if (args[0] == "--print-parameters")
          {
            ParameterHandler prm;
            declare(prm);
            if (root)
              prm.print_parameters(std::cout, ParameterHandler::PRM);
            return 0;
          }
        Interruption::install_handlers();
        return run(args, root);
      }
    catch (const RunInterrupted &exc)
      {
        // every rank stops here together (the signal was shared): no abort
        if (root)
          std::cerr << std::endl << exc.what() << std::endl;
        return 128 + exc.signal();
      }
    catch (std::exception &exc)
      {
        // A user reads what went wrong and how to fix it; the source
        // location and deal.II's stack trace only on request.
        std::cerr << std::endl
                  << "----------------------------------------------------"
                  << std::endl
                  << "Exception on processing: " << std::endl
                  << user_message(exc) << std::endl;
        if (std::getenv("PG_ERROR_DETAILS") != nullptr)
          std::cerr << std::endl
                    << "Details (PG_ERROR_DETAILS is set):" << std::endl
                    << exc.what() << std::endl;
        std::cerr << "Aborting!" << std::endl
                  << "----------------------------------------------------"
                  << std::endl;
        return abort();
      }
    catch (...)
      {
        std::cerr << std::endl << "Unknown exception! Aborting!" << std::endl;
        return abort();
      }
  }
} // namespace pg
