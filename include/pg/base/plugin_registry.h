#ifndef pg_base_plugin_registry_h
#define pg_base_plugin_registry_h

#include <pg/base/exceptions.h>
#include <pg/base/global.h>

#include <algorithm>
#include <string>
#include <tuple>
#include <vector>

namespace pg
{
  /**
   * A list of named plugins of one kind (materials now; postprocessors and
   * element groups later), filled by static registration objects in the
   * plugins' own .cc files (style-and-architecture.md section 3.2).
   *
   * @p Plugin is a struct with at least the members
   *   std::string  name;             // the value of the selecting entry
   *   std::string  description;      // one phrase, for the documentation
   *   unsigned int listing_position; // where the name is listed
   * and whatever the kind needs (factories, declare functions). Plugins are
   * listed by (listing_position, name), so the listing (the
   * Patterns::Selection, the documentation and the error messages) does not
   * depend on the order in which the static objects are initialised.
   *
   * A registry is meant to live in a function-local static (constructed on
   * first use, so before the first registration whatever the static
   * initialisation order), see Materials::material_registry().
   */
  template <typename Plugin>
  class PluginRegistry
  {
  public:
    /** Add @p plugin; throws if its name is taken or contains '|'. */
    void
    add(const Plugin &plugin)
    {
      AssertThrow(!plugin.name.empty() &&
                    plugin.name.find('|') == std::string::npos,
                  ExcMessage("A plugin name must be non-empty and must not "
                             "contain '|': <" +
                             plugin.name + ">."));
      AssertThrow(find(plugin.name) == nullptr,
                  ExcMessage("A plugin named <" + plugin.name +
                             "> is registered twice."));
      const auto position =
        std::upper_bound(entries.begin(),
                         entries.end(),
                         plugin,
                         [](const Plugin &a, const Plugin &b) {
                           return std::tie(a.listing_position, a.name) <
                                  std::tie(b.listing_position, b.name);
                         });
      entries.insert(position, plugin);
    }

    /** The plugin named @p name, or nullptr. */
    const Plugin *
    find(const std::string &name) const
    {
      for (const Plugin &plugin : entries)
        if (plugin.name == name)
          return &plugin;
      return nullptr;
    }

    /**
     * The plugin named @p name; throws ExcBadParameter(@p entry, @p name,
     * "it must be one of 'a', 'b' or 'c'.") if there is none.
     */
    const Plugin &
    get(const std::string &name, const std::string &entry) const
    {
      const Plugin *plugin = find(name);
      AssertThrow(plugin != nullptr,
                  ExcBadParameter(entry,
                                  name,
                                  "it must be one of " + listing() + "."));
      return *plugin;
    }

    /** All plugins, in listing order. */
    const std::vector<Plugin> &
    plugins() const
    {
      return entries;
    }

    /** The names, in listing order. */
    std::vector<std::string>
    names() const
    {
      std::vector<std::string> result;
      for (const Plugin &plugin : entries)
        result.push_back(plugin.name);
      return result;
    }

    /** "a|b|c", the argument of Patterns::Selection. */
    std::string
    selection() const
    {
      std::string result;
      for (const Plugin &plugin : entries)
        result += (result.empty() ? "" : "|") + plugin.name;
      return result;
    }

    /** "'a', 'b' or 'c'", for messages. */
    std::string
    listing() const
    {
      return enumerate(false);
    }

    /** "'a' (description a), 'b' (description b) or 'c' (...)". */
    std::string
    documentation() const
    {
      return enumerate(true);
    }

  private:
    std::string
    enumerate(const bool with_descriptions) const
    {
      std::string result;
      for (unsigned int i = 0; i < entries.size(); ++i)
        {
          if (i > 0)
            result += (i + 1 == entries.size()) ? " or " : ", ";
          result += "'" + entries[i].name + "'";
          if (with_descriptions && !entries[i].description.empty())
            result += " (" + entries[i].description + ")";
        }
      return result;
    }

    /** Sorted by (listing_position, name). */
    std::vector<Plugin> entries;
  };
} // namespace pg

#endif
