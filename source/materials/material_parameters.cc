#include <pg/base/exceptions.h>
#include <pg/materials/material_parameters.h>
#include <pg/materials/material_registry.h>

#include <deal.II/base/utilities.h>

#include <cmath>

namespace pg
{
  namespace Parameters
  {
    namespace
    {
      /**
       * The declared defaults of 'Young's modulus' and 'Poisson's ratio'
       * (keep equal to the strings in declare_parameters()).
       */
      constexpr double default_youngs_modulus = 1.;
      constexpr double default_poissons_ratio = 0.3;

      /**
       * The modulus @p text of the entry 'Material/<entry>' as a number;
       * throws ExcBadParameter unless it is a number.
       */
      double
      modulus_from_text(const std::string &text, const std::string &entry)
      {
        try
          {
            std::size_t  end   = 0;
            const double value = std::stod(text, &end);
            if (Utilities::trim(text.substr(end)).empty())
              return value;
          }
        catch (...)
          {}
        AssertThrow(false,
                    ExcBadParameter("Material/" + entry,
                                    text,
                                    "it must be a number (or empty)."));
        return 0.;
      }
    } // namespace



    double
    Material::lambda() const
    {
      AssertThrow(bulk_modulus.has_value() == shear_modulus.has_value(),
                  ExcMessage("Parameters::Material: bulk_modulus and "
                             "shear_modulus must be given both or neither."));
      if (bulk_modulus)
        return *bulk_modulus - 2. / 3. * *shear_modulus;
      return youngs_modulus * poissons_ratio /
             ((1. + poissons_ratio) * (1. - 2. * poissons_ratio));
    }



    double
    Material::mu() const
    {
      AssertThrow(bulk_modulus.has_value() == shear_modulus.has_value(),
                  ExcMessage("Parameters::Material: bulk_modulus and "
                             "shear_modulus must be given both or neither."));
      if (shear_modulus)
        return *shear_modulus;
      return youngs_modulus / (2. * (1. + poissons_ratio));
    }



    bool
    Material::incompressible() const
    {
      return !bulk_modulus && poissons_ratio == 0.5;
    }



    Material
    Material::without_volumetric_energy() const
    {
      Material result      = *this;
      result.shear_modulus = mu();
      result.bulk_modulus  = 0.;
      return result;
    }



    Material
    Material::with_poissons_ratio(const double nu) const
    {
      Material result       = *this;
      result.poissons_ratio = nu;
      if (bulk_modulus)
        {
          result.bulk_modulus  = youngs_modulus / (3. * (1. - 2. * nu));
          result.shear_modulus = youngs_modulus / (2. * (1. + nu));
        }
      return result;
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
                          "E. Units: force per area. With 'Poisson's ratio' "
                          "the default way to give the elastic constants; "
                          "alternatively give 'Bulk modulus' and 'Shear "
                          "modulus' and leave E and nu at their defaults.");
        prm.declare_entry("Poisson's ratio",
                          "0.3",
                          Patterns::Double(-1., 0.5),
                          "nu, -1 < nu < 0.5; 0.5 (incompressible) only "
                          "with the formulation IUnlP0.");
        prm.declare_entry("Bulk modulus",
                          "",
                          Patterns::Anything(),
                          "K > 0, with 'Shear modulus' an alternative to "
                          "'Young's modulus' and 'Poisson's ratio' (which "
                          "then must keep their defaults): give both or "
                          "neither. Empty: not given, E and nu define the "
                          "material. K = lambda + 2/3 mu = E / (3 (1 - 2 "
                          "nu)). Units: force per area.");
        prm.declare_entry("Shear modulus",
                          "",
                          Patterns::Anything(),
                          "mu > 0, the second Lame constant, with 'Bulk "
                          "modulus' (see there; give both or neither). "
                          "Empty: not given. mu = E / (2 (1 + nu)). Units: "
                          "force per area.");
        prm.declare_entry("Density",
                          "1",
                          Patterns::Double(0.),
                          "Reference density rho_0. Units: mass per volume.");
        prm.declare_entry("Initial yield stress",
                          "1",
                          Patterns::Double(),
                          "sigma_y0 > 0 of 'Model = J2 plasticity' (used "
                          "by that model only): the yield stress "
                          "sigma_y(alpha) = sigma_y0 + H alpha + (sigma_yinf "
                          "- sigma_y0) (1 - exp(-delta alpha)) of the "
                          "equivalent plastic strain alpha, eq. 2.49, bounds "
                          "the von Mises Kirchhoff stress. Units: force per "
                          "area.");
        prm.declare_entry("Saturation yield stress",
                          "1",
                          Patterns::Double(),
                          "sigma_yinf >= sigma_y0 of 'Model = J2 "
                          "plasticity' (see 'Initial yield stress'; equal "
                          "to it: no saturation hardening). Units: force per "
                          "area.");
        prm.declare_entry("Linear hardening modulus",
                          "0",
                          Patterns::Double(),
                          "H >= 0 of 'Model = J2 plasticity' (see 'Initial "
                          "yield stress'). Units: force per area.");
        prm.declare_entry("Saturation exponent",
                          "0",
                          Patterns::Double(),
                          "delta >= 0 of 'Model = J2 plasticity' (see "
                          "'Initial yield stress'). Dimensionless.");
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
      std::string bulk_text, shear_text;
      prm.enter_subsection("Material");
      {
        model                    = prm.get("Model");
        youngs_modulus           = prm.get_double("Young's modulus");
        poissons_ratio           = prm.get_double("Poisson's ratio");
        density                  = prm.get_double("Density");
        plane                    = prm.get("Plane");
        initial_yield_stress     = prm.get_double("Initial yield stress");
        saturation_yield_stress  = prm.get_double("Saturation yield stress");
        linear_hardening_modulus = prm.get_double("Linear hardening modulus");
        saturation_exponent      = prm.get_double("Saturation exponent");
        bulk_text                = Utilities::trim(prm.get("Bulk modulus"));
        shear_text               = Utilities::trim(prm.get("Shear modulus"));
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
      // (nu = 0.5 only with the incompressible formulation IUnlP0:
      // AllParameters::parse_parameters() checks the pair)
      AssertThrow(poissons_ratio > -1. && poissons_ratio <= 0.5,
                  ExcBadParameter("Material/Poisson's ratio",
                                  std::to_string(poissons_ratio),
                                  "it must lie in (-1, 0.5]."));

      // The alternative pair: K and mu, both or neither.
      bulk_modulus.reset();
      shear_modulus.reset();
      if (bulk_text.empty() && shear_text.empty())
        return;
      const std::string either_or =
        "give both 'Bulk modulus' and 'Shear modulus' in subsection "
        "'Material', or neither (then 'Young's modulus' and 'Poisson's "
        "ratio' define the material).";
      AssertThrow(!bulk_text.empty(),
                  ExcBadParameter("Material/Bulk modulus",
                                  bulk_text,
                                  "'Shear modulus' is given (<" + shear_text +
                                    ">) and needs it: " + either_or));
      AssertThrow(!shear_text.empty(),
                  ExcBadParameter("Material/Shear modulus",
                                  shear_text,
                                  "'Bulk modulus' is given (<" + bulk_text +
                                    ">) and needs it: " + either_or));
      const double K  = modulus_from_text(bulk_text, "Bulk modulus");
      const double mu = modulus_from_text(shear_text, "Shear modulus");
      AssertThrow(K > 0. && std::isfinite(K),
                  ExcBadParameter("Material/Bulk modulus",
                                  bulk_text,
                                  "it must be positive. (K > 0 and mu > 0 are "
                                  "equivalent to E > 0 and -1 < nu < 0.5; K = "
                                  "0 means nu = -1.)"));
      AssertThrow(mu > 0. && std::isfinite(mu),
                  ExcBadParameter("Material/Shear modulus",
                                  shear_text,
                                  "it must be positive. (K > 0 and mu > 0 are "
                                  "equivalent to E > 0 and -1 < nu < 0.5; mu "
                                  "= 0 means nu = 0.5, an incompressible "
                                  "fluid.)"));
      const std::string both =
        "'Bulk modulus' and 'Shear modulus' are given too; give either "
        "'Young's modulus' and 'Poisson's ratio' or 'Bulk modulus' and "
        "'Shear modulus' in subsection 'Material', and leave the other pair "
        "at its defaults (E = 1, nu = 0.3; also after an 'include').";
      AssertThrow(youngs_modulus == default_youngs_modulus,
                  ExcBadParameter("Material/Young's modulus",
                                  Utilities::to_string(youngs_modulus),
                                  both));
      AssertThrow(poissons_ratio == default_poissons_ratio,
                  ExcBadParameter("Material/Poisson's ratio",
                                  Utilities::to_string(poissons_ratio),
                                  both));
      bulk_modulus   = K;
      shear_modulus  = mu;
      youngs_modulus = 9. * K * mu / (3. * K + mu);
      poissons_ratio = (3. * K - 2. * mu) / (2. * (3. * K + mu));
    }
  } // namespace Parameters
} // namespace pg
