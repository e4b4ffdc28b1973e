#ifndef pg_base_application_h
#define pg_base_application_h

#include <pg/base/global.h>

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <string>
#include <vector>

namespace pg
{
  /**
   * The main() that pg_solve and pg_study share: initialize MPI; with no
   * argument or --help (-h) print @p usage (exit code 1 without arguments);
   * with --print-parameters print the entries @p declare declares, with
   * their documentation; otherwise return what @p run returns for the
   * arguments. An exception is reported on std::cerr by its message
   * (user_message(): what went wrong and how to fix it); the source location
   * and deal.II's stack trace follow only where the environment variable
   * PG_ERROR_DETAILS is set. MPI is aborted when several ranks run, and the
   * exit code is 1. Output
   * goes to rank 0 only.
   */
  int
  run_application(
    int                                                               argc,
    char                                                            **argv,
    const std::string                                                &usage,
    const std::function<void(ParameterHandler &)>                    &declare,
    const std::function<int(const std::vector<std::string> &, bool)> &run);
} // namespace pg

#endif
