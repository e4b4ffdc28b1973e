#ifndef pg_base_parameter_utilities_h
#define pg_base_parameter_utilities_h

#include <pg/base/global.h>

#include <deal.II/base/types.h>

#include <string>
#include <vector>

// Parsers of list-valued parameter entries, shared by the parse_parameters()
// of the parameter structs; every one throws ExcBadParameter naming the
// entry and its value.
namespace pg
{
  namespace Parameters
  {
    /** "a, b, c" -> {a, b, c} with a clear message on a bad number. */
    std::vector<double>
    parse_doubles(const std::string &text, const std::string &entry);

    /** "0, 3" -> the boundary ids {0, 3}, each between 0 and 254. */
    std::vector<types::boundary_id>
    parse_ids(const std::string &text, const std::string &entry);

    /**
     * The component mask of the letters x, y, z in @p letters; a wrong
     * letter is reported for @p entry with its whole value @p text, the
     * message ending in @p example.
     */
    std::vector<bool>
    parse_components(const std::string &letters,
                     const unsigned int dim,
                     const std::string &entry,
                     const std::string &text,
                     const std::string &example);

    /**
     * The items of the @p separator-separated list @p text of @p entry,
     * each split at ':' into exactly @p n_parts parts; otherwise the
     * message @p form (how an item must read).
     */
    std::vector<std::vector<std::string>>
    parse_items(const std::string &text,
                const char         separator,
                const unsigned int n_parts,
                const std::string &entry,
                const std::string &form);

    /**
     * @p part of the value @p text of @p entry as dim coordinates;
     * otherwise the message "<what> needs <dim> coordinates.".
     */
    std::vector<double>
    parse_coordinates(const std::string &part,
                      const unsigned int dim,
                      const std::string &entry,
                      const std::string &text,
                      const std::string &what);
  } // namespace Parameters
} // namespace pg

#endif
