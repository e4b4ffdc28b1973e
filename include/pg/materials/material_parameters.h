#ifndef pg_materials_material_parameters_h
#define pg_materials_material_parameters_h

#include <pg/base/global.h>

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <string>

namespace pg
{
  namespace Parameters
  {
    /**
     * Subsection "Material": the entries common to every material, and the
     * entries a registered material declares for itself (in its nested
     * subsection "Material/<Model>", see Materials::MaterialPlugin).
     */
    struct Material
    {
      /** A registered name: linear elastic | saint venant kirchhoff | ... */
      std::string model;
      double      youngs_modulus;
      double      poissons_ratio;
      double      density;
      /** strain | stress (2-D only) */
      std::string plane;
      /**
       * The entries of the selected model's own subsection, name -> value
       * as written (filled by the model's parse function; empty for the
       * models without own entries).
       */
      std::map<std::string, std::string> model_entries;

      /** Lame's first parameter of the 3-D material. */
      double
      lambda() const;
      /** Shear modulus. */
      double
      mu() const;

      /**
       * The entry @p name of model_entries as a number; throws with a clear
       * message if it is missing or not a number.
       */
      double
      model_double(const std::string &name) const;

      /**
       * Declare the common entries, 'Model' (its selection and documentation
       * built from the registered materials) and every registered
       * material's own entries.
       */
      static void
      declare_parameters(ParameterHandler &prm);
      /** Read the common entries and those of the selected model. */
      void
      parse_parameters(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace pg

#endif
