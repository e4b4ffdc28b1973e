#ifndef pg_base_parameter_file_h
#define pg_base_parameter_file_h

#include <pg/base/global.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace pg
{
  namespace Parameters
  {
    /**
     * prm.parse_input(@p filename), with a suggestion when an entry is
     * unknown: deal.II says "No entry with name <Hourglass Coefficient> was
     * declared in the current subsection"; this adds the subsection, the
     * declared entry the name most likely means ("did you mean 'Hourglass
     * coefficient'?", by case and edit distance), or the subsections that
     * declare it. Other errors pass unchanged.
     */
    void
    parse_parameter_file(ParameterHandler &prm, const std::string &filename);
  } // namespace Parameters
} // namespace pg

#endif
