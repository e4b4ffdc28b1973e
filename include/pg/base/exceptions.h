#ifndef pg_base_exceptions_h
#define pg_base_exceptions_h

#include <pg/base/global.h>

#include <deal.II/base/exceptions.h>

#include <string>

namespace pg
{
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
