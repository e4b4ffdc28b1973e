#include <pg/base/exceptions.h>
#include <pg/materials/material_parameters.h>
#include <pg/materials/material_registry.h>

#include <deal.II/base/utilities.h>

namespace pg
{
  namespace Parameters
  {
    double
    Material::lambda() const
    {
      return youngs_modulus * poissons_ratio /
             ((1. + poissons_ratio) * (1. - 2. * poissons_ratio));
    }



    double
    Material::mu() const
    {
      return youngs_modulus / (2. * (1. + poissons_ratio));
    }



    double
    Material::model_double(const std::string &name) const
    {
      const auto entry = model_entries.find(name);
      AssertThrow(entry != model_entries.end(),
                  ExcMessage("The material <" + model + "> has no entry <" +
                             name + "> in subsection 'Material/" + model +
                             "'."));
      try
        {
          return Utilities::string_to_double(entry->second);
        }
      catch (...)
        {
          AssertThrow(false,
                      ExcBadParameter("Material/" + model + "/" + name,
                                      entry->second,
                                      "it must be a number."));
        }
      return 0.;
    }



    void
    Material::declare_parameters(ParameterHandler &prm)
    {
      const PluginRegistry<Materials::MaterialPlugin> &registry =
        Materials::material_registry();
      prm.enter_subsection("Material");
      {
        prm.declare_entry("Model",
                          "neo-Hooke",
                          Patterns::Selection(registry.selection()),
                          registry.documentation() + ".");
        prm.declare_entry("Young's modulus",
                          "1",
                          Patterns::Double(0.),
                          "E. Units: force per area.");
        prm.declare_entry("Poisson's ratio",
                          "0.3",
                          Patterns::Double(-1., 0.5),
                          "nu, -1 < nu < 0.5.");
        prm.declare_entry("Density",
                          "1",
                          Patterns::Double(0.),
                          "Reference density rho_0. Units: mass per volume.");
        prm.declare_entry("Plane",
                          "strain",
                          Patterns::Selection("strain|stress"),
                          "2-D only: plane strain or plane stress (plane "
                          "stress for 'linear elastic' and 'saint venant "
                          "kirchhoff').");
        for (const Materials::MaterialPlugin &plugin : registry.plugins())
          if (plugin.declare_parameters)
            {
              prm.enter_subsection(plugin.name);
              plugin.declare_parameters(prm);
              prm.leave_subsection();
            }
      }
      prm.leave_subsection();
    }



    void
    Material::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      {
        model          = prm.get("Model");
        youngs_modulus = prm.get_double("Young's modulus");
        poissons_ratio = prm.get_double("Poisson's ratio");
        density        = prm.get_double("Density");
        plane          = prm.get("Plane");
        model_entries.clear();
        const Materials::MaterialPlugin &plugin =
          Materials::material_registry().get(model, "Material/Model");
        if (plugin.parse_parameters)
          {
            prm.enter_subsection(model);
            plugin.parse_parameters(prm, *this);
            prm.leave_subsection();
          }
      }
      prm.leave_subsection();

      AssertThrow(youngs_modulus > 0.,
                  ExcBadParameter("Material/Young's modulus",
                                  std::to_string(youngs_modulus),
                                  "it must be positive."));
      AssertThrow(
        poissons_ratio > -1. && poissons_ratio < 0.5,
        ExcBadParameter("Material/Poisson's ratio",
                        std::to_string(poissons_ratio),
                        "it must lie in (-1, 0.5): at 0.5 the material is "
                        "incompressible, lambda is infinite, and the "
                        "displacement formulations lock. Use e.g. 0.499 or a "
                        "mixed formulation (not yet available)."));
    }
  } // namespace Parameters
} // namespace pg
