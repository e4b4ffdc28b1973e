#ifndef pg_base_exceptions_h
#define pg_base_exceptions_h

#include <pg/base/global.h>

#include <deal.II/base/exceptions.h>

#include <exception>
#include <string>

namespace pg
{
  /**
   * The text a user reads for @p exc. For a deal.II exception (pg's own
   * included) its message proper, print_info(): what went wrong and how to
   * fix it, without the source location, the violated condition and the
   * stack trace that what() adds. For any other exception what(). Leading
   * and trailing white space removed.
   */
  std::string
  user_message(const std::exception &exc);

  /**
   * user_message() on one line: runs of white space (deal.II wraps long
   * messages) collapsed to one blank.
   */
  std::string
  one_line(const std::string &message);

  /**
   * A parameter has a value that pg cannot work with. The message names the
   * entry with its subsection, the value, and what the value must be.
   */
  DeclException3(ExcBadParameter,
                 std::string,
                 std::string,
                 std::string,
                 << "The entry '" << arg1 << "' has the value <" << arg2
                 << ">, but " << arg3);

  /**
   * A family whose moment matrix cannot be inverted reliably.
   */
  DeclException4(ExcSingularFamily,
                 unsigned int,
                 std::string,
                 unsigned int,
                 std::string,
                 << "The family of particle " << arg1 << " at " << arg2
                 << " (with " << arg3
                 << " neighbours) has a singular or ill-conditioned moment "
                 << "matrix" << arg4
                 << ". Increase 'Horizon factor' or 'Horizon' (or 'Nearest "
                 << "neighbours') "
                 << "in subsection 'Discretization', or reduce 'Distortion' "
                 << "in subsection 'Geometry'.");
} // namespace pg

#endif
