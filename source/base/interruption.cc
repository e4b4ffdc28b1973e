#include <pg/base/interruption.h>

#include <unistd.h>

#include <csignal>

namespace pg
{
  namespace Interruption
  {
    namespace
    {
      /** The last signal recorded by the handler (0: none). */
      volatile std::sig_atomic_t recorded_signal = 0;

      extern "C" void
      record_signal(const int signal)
      {
        recorded_signal = signal;
        // a second signal of this kind ends the process as usual
        std::signal(signal, SIG_DFL);
        // write() is async-signal-safe, std::cerr is not
        static const char message[] =
          "\npg: signal received: stopping after the current step with a "
          "checkpoint (send it again to stop at once)\n";
        [[maybe_unused]] const auto n =
          write(STDERR_FILENO, message, sizeof(message) - 1);
      }
    } // namespace



    void
    install_handlers()
    {
      std::signal(SIGINT, record_signal);
      std::signal(SIGTERM, record_signal);
    }



    int
    received(const MPI_Comm comm)
    {
      return Utilities::MPI::max(static_cast<int>(recorded_signal), comm);
    }



    void
    request(const int signal)
    {
      recorded_signal = signal;
    }



    void
    clear()
    {
      recorded_signal = 0;
    }



    std::string
    signal_name(const int signal)
    {
      if (signal == SIGINT)
        return "SIGINT";
      if (signal == SIGTERM)
        return "SIGTERM";
      return "signal " + std::to_string(signal);
    }
  } // namespace Interruption
} // namespace pg
