#ifndef pg_materials_material_registry_h
#define pg_materials_material_registry_h

#include <pg/base/plugin_registry.h>
#include <pg/materials/material.h>
#include <pg/materials/material_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <memory>
#include <string>
#include <type_traits>

namespace pg
{
  namespace Materials
  {
    /**
     * What a material registers (doc/adding-a-material.md): its name (the
     * value of 'Model'), a one-phrase description for the documentation of
     * 'Model', a factory for each dimension, and optionally a declare and a
     * parse function for its own entries, which live in the nested
     * subsection "Material/<name>".
     */
    struct MaterialPlugin
    {
      /** Listing position of plugins that do not ask for one. */
      static constexpr unsigned int default_listing_position = 1000;

      std::string  name;
      std::string  description;
      unsigned int listing_position = default_listing_position;

      std::function<std::unique_ptr<Material<2>>(const Parameters::Material &)>
        create_2d;
      std::function<std::unique_ptr<Material<3>>(const Parameters::Material &)>
        create_3d;

      /**
       * Declares the material's own entries; called inside the subsection
       * "Material/<name>" for every registered material before a file is
       * parsed. Empty: the material has no own entries (no subsection).
       */
      std::function<void(ParameterHandler &)> declare_parameters;
      /**
       * Reads them into Parameters::Material::model_entries; called inside
       * "Material/<name>" for the selected material only.
       */
      std::function<void(ParameterHandler &, Parameters::Material &)>
        parse_parameters;

      /** The factory of dimension @p dim. */
      template <int dim>
      std::unique_ptr<Material<dim>>
      create(const Parameters::Material &parameters) const
      {
        if constexpr (dim == 2)
          return create_2d(parameters);
        else
          return create_3d(parameters);
      }
    };

    /**
     * The registry of materials: a function-local static, so it exists
     * before the first registration object in any translation unit (of the
     * library or of an executable) adds to it.
     */
    PluginRegistry<MaterialPlugin> &
    material_registry();

    namespace internal
    {
      template <typename T, typename = void>
      struct HasDeclareParameters : std::false_type
      {};
      template <typename T>
      struct HasDeclareParameters<T,
                                  std::void_t<decltype(T::declare_parameters(
                                    std::declval<ParameterHandler &>()))>>
        : std::true_type
      {};
    } // namespace internal

    /**
     * The plugin of the class template @p MaterialClass (constructed as
     * MaterialClass<dim>(const Parameters::Material &)); the constructor
     * does the model's own checks of the parameters. If MaterialClass<2>
     * has static functions
     *   void declare_parameters(ParameterHandler &prm);
     *   void parse_parameters(ParameterHandler &prm,
     *                         Parameters::Material &parameters);
     * they become the plugin's declare and parse functions.
     */
    template <template <int> class MaterialClass>
    MaterialPlugin
    make_material_plugin(const std::string &name,
                         const std::string &description,
                         const unsigned int listing_position =
                           MaterialPlugin::default_listing_position)
    {
      MaterialPlugin plugin;
      plugin.name             = name;
      plugin.description      = description;
      plugin.listing_position = listing_position;
      plugin.create_2d        = [](const Parameters::Material &parameters)
        -> std::unique_ptr<Material<2>> {
        return std::make_unique<MaterialClass<2>>(parameters);
      };
      plugin.create_3d = [](const Parameters::Material &parameters)
        -> std::unique_ptr<Material<3>> {
        return std::make_unique<MaterialClass<3>>(parameters);
      };
      if constexpr (internal::HasDeclareParameters<MaterialClass<2>>::value)
        {
          plugin.declare_parameters = &MaterialClass<2>::declare_parameters;
          plugin.parse_parameters   = &MaterialClass<2>::parse_parameters;
        }
      return plugin;
    }

    /** Adds a plugin to material_registry() on construction. */
    struct MaterialRegistration
    {
      MaterialRegistration(const MaterialPlugin &plugin)
      {
        material_registry().add(plugin);
      }
    };
  } // namespace Materials
} // namespace pg

/**
 * Register the material class template @p Class (namespace-scope, in the
 * .cc file that defines it):
 *   PG_REGISTER_MATERIAL(MyModel, "my model", "what it is, eq. (x)");
 * An optional fourth argument is the listing position (default
 * MaterialPlugin::default_listing_position; equal positions are listed by
 * name). The class must be instantiated for dim = 2 and 3.
 */
#define PG_REGISTER_MATERIAL(Class, ...)                            \
  namespace                                                         \
  {                                                                 \
    const ::pg::Materials::MaterialRegistration                     \
      pg_material_registration_##Class(                             \
        ::pg::Materials::make_material_plugin<Class>(__VA_ARGS__)); \
  }

#endif
