#ifndef pg_base_shared_libraries_h
#define pg_base_shared_libraries_h

#include <pg/base/global.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace pg
{
  namespace Parameters
  {
    /**
     * Declare the top-level entry 'Additional shared libraries' (as
     * ASPECT's): shared libraries that register their own materials (or
     * other plugins) with pg's registries when they are loaded.
     */
    void
    declare_additional_shared_libraries(ParameterHandler &prm);

    /**
     * Read 'Additional shared libraries' from the parameter file
     * @p filename (skipping every other entry, as read_dimension() does)
     * and load each library with dlopen(), before the parameters are
     * declared: a library's registration objects then add its materials
     * to 'Model' in subsection 'Material' (its selection and documentation)
     * like the built-in ones. Relative paths start in the working
     * directory; a name without '/' is searched as dlopen() does
     * (LD_LIBRARY_PATH, the system's paths). Loading a library twice does
     * nothing. Throws ExcBadParameter with the loader's message if a
     * library cannot be loaded. Returns the libraries loaded.
     */
    std::vector<std::string>
    load_additional_shared_libraries(const std::string &filename);
  } // namespace Parameters
} // namespace pg

#endif
