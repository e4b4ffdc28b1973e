#ifndef pg_base_interruption_h
#define pg_base_interruption_h

#include <pg/base/global.h>

#include <deal.II/base/mpi.h>

#include <stdexcept>
#include <string>

namespace pg
{
  /**
   * SIGINT and SIGTERM during a run: the handlers only record the signal;
   * the analyses ask for it after every accepted load step or time step
   * (received(), collective), write a checkpoint and the files of that
   * step, and stop with RunInterrupted. A second signal of the same kind
   * ends the process at once (the default action is restored by the
   * first).
   */
  namespace Interruption
  {
    /** Install the handlers for SIGINT and SIGTERM (pg_solve, pg_study). */
    void
    install_handlers();

    /**
     * The signal received by any rank of @p comm since the start (the
     * largest number if they differ), 0 if none. Collective.
     */
    int
    received(const MPI_Comm comm);

    /** Record @p signal as if it had arrived (tests). */
    void
    request(const int signal);

    /** Forget a recorded signal (tests). */
    void
    clear();

    /** "SIGINT", "SIGTERM" or "signal <n>". */
    std::string
    signal_name(const int signal);
  } // namespace Interruption

  /**
   * A run stopped by a signal after writing a checkpoint and the files of
   * its last accepted step. The application exits with 128 + signal(), as
   * a shell reports a process killed by that signal.
   */
  class RunInterrupted : public std::runtime_error
  {
  public:
    RunInterrupted(const int signal, const std::string &message)
      : std::runtime_error(message)
      , signal_number(signal)
    {}

    int
    signal() const
    {
      return signal_number;
    }

  private:
    int signal_number;
  };
} // namespace pg

#endif
