#include <pg/base/exceptions.h>
#include <pg/base/shared_libraries.h>

#include <deal.II/base/utilities.h>

#include <dlfcn.h>

namespace pg
{
  namespace Parameters
  {
    namespace
    {
      const char *const entry = "Additional shared libraries";
    }



    void
    declare_additional_shared_libraries(ParameterHandler &prm)
    {
      prm.declare_entry(
        entry,
        "",
        Patterns::List(Patterns::FileName(), 0),
        "Comma-separated paths of shared libraries to load before the "
        "parameters are read, e.g. './libmooney_rivlin.so': a user's "
        "materials (and other plugins) registered in their own library, "
        "built against this pg (examples/user_material). Their names then "
        "appear in 'Model' of subsection 'Material' like the built-in ones. "
        "Read, like 'Dimension', before everything else; relative paths "
        "start in the working directory.");
    }



    std::vector<std::string>
    load_additional_shared_libraries(const std::string &filename)
    {
      ParameterHandler prm;
      declare_additional_shared_libraries(prm);
      // every other entry is skipped (read_dimension() has checked that
      // the file can be read)
      prm.parse_input(filename, "", true);
      const std::vector<std::string> libraries =
        Utilities::split_string_list(prm.get(entry), ',');
      for (const std::string &library : libraries)
        {
          // RTLD_GLOBAL: the library's symbols resolve against the pg
          // already loaded, so its registrations reach pg's registries
          void *handle = dlopen(library.c_str(), RTLD_NOW | RTLD_GLOBAL);
          if (handle == nullptr)
            {
              const char *error = dlerror();
              AssertThrow(false,
                          ExcBadParameter(
                            entry,
                            library,
                            "it cannot be loaded: " +
                              std::string(error != nullptr ? error :
                                                             "unknown error") +
                              ". Give the path of a shared library built "
                              "against this pg (relative paths start in the "
                              "working directory; examples/user_material "
                              "shows how to build one)."));
            }
        }
      return libraries;
    }
  } // namespace Parameters
} // namespace pg
