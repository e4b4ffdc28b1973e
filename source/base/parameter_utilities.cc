#include <pg/base/exceptions.h>
#include <pg/base/parameter_utilities.h>

#include <deal.II/base/utilities.h>

namespace pg
{
  namespace Parameters
  {
    std::vector<double>
    parse_doubles(const std::string &text, const std::string &entry)
    {
      std::vector<double> values;
      for (const std::string &word : Utilities::split_string_list(text, ','))
        {
          try
            {
              values.push_back(Utilities::string_to_double(word));
            }
          catch (...)
            {
              AssertThrow(false,
                          ExcBadParameter(entry,
                                          text,
                                          "it must be a comma-separated "
                                          "list of numbers."));
            }
        }
      return values;
    }



    std::vector<types::boundary_id>
    parse_ids(const std::string &text, const std::string &entry)
    {
      std::vector<types::boundary_id> ids;
      for (const std::string &word : Utilities::split_string_list(text, ','))
        {
          int id = -1;
          try
            {
              id = Utilities::string_to_int(word);
            }
          catch (const ExceptionBase &)
            {
              // not a number: reported below, with the entry
            }
          AssertThrow(id >= 0 && id < 255,
                      ExcBadParameter(entry,
                                      text,
                                      "boundary ids must be integers "
                                      "between 0 and 254."));
          ids.push_back(static_cast<types::boundary_id>(id));
        }
      return ids;
    }



    std::vector<bool>
    parse_components(const std::string &letters,
                     const unsigned int dim,
                     const std::string &entry,
                     const std::string &text,
                     const std::string &example)
    {
      std::vector<bool> mask(dim, false);
      for (const char c : letters)
        {
          const unsigned int component = (c == 'x' ? 0 :
                                          c == 'y' ? 1 :
                                          c == 'z' ? 2 :
                                                     99);
          AssertThrow(component < dim,
                      ExcBadParameter(entry,
                                      text,
                                      "components are written with the "
                                      "letters x, y" +
                                        std::string(dim == 3 ? ", z" : "") +
                                        example));
          mask[component] = true;
        }
      return mask;
    }



    std::vector<std::vector<std::string>>
    parse_items(const std::string &text,
                const char         separator,
                const unsigned int n_parts,
                const std::string &entry,
                const std::string &form)
    {
      std::vector<std::vector<std::string>> items;
      for (const std::string &item :
           Utilities::split_string_list(text, separator))
        {
          items.push_back(Utilities::split_string_list(item, ':'));
          AssertThrow(items.back().size() == n_parts,
                      ExcBadParameter(entry, text, form));
        }
      return items;
    }



    std::vector<double>
    parse_coordinates(const std::string &part,
                      const unsigned int dim,
                      const std::string &entry,
                      const std::string &text,
                      const std::string &what)
    {
      const std::vector<double> coordinates = parse_doubles(part, entry);
      AssertThrow(coordinates.size() == dim,
                  ExcBadParameter(entry,
                                  text,
                                  what + " needs " + std::to_string(dim) +
                                    " coordinates."));
      return coordinates;
    }
  } // namespace Parameters
} // namespace pg
