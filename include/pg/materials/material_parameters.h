#ifndef pg_materials_material_parameters_h
#define pg_materials_material_parameters_h

#include <pg/base/global.h>

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <optional>
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
      /**
       * Young's modulus E and Poisson's ratio nu. They define lambda() and
       * mu() unless bulk_modulus and shear_modulus are given; then they
       * hold the equivalent E = 9 K mu / (3 K + mu) and
       * nu = (3 K - 2 mu) / (2 (3 K + mu)), for output.
       */
      double youngs_modulus;
      double poissons_ratio;
      /**
       * Bulk modulus K and shear modulus mu, if the input gave the elastic
       * constants as 'Bulk modulus' and 'Shear modulus' (both or neither);
       * then they define lambda() = K - 2/3 mu and mu(). Empty (the
       * default): E and nu define them.
       */
      std::optional<double> bulk_modulus;
      std::optional<double> shear_modulus;
      double                density;
      /**
       * @name Hardening of 'J2 plasticity' (eq. 2.49; used by that model
       * only, checked by its constructor)
       *
       * sigma_y(alpha) = sigma_y0 + H alpha + (sigma_yinf - sigma_y0)
       * (1 - exp(-delta alpha)) of the equivalent plastic strain alpha.
       */
      /** @{ */
      /** sigma_y0 > 0, 'Initial yield stress'. Units: force per area. */
      double initial_yield_stress = 1.;
      /**
       * sigma_yinf >= sigma_y0, 'Saturation yield stress'. Units: force per
       * area.
       */
      double saturation_yield_stress = 1.;
      /** H >= 0, 'Linear hardening modulus'. Units: force per area. */
      double linear_hardening_modulus = 0.;
      /** delta >= 0, 'Saturation exponent'. Dimensionless. */
      double saturation_exponent = 0.;
      /** @} */
      /** strain | stress (2-D only) */
      std::string plane;
      /**
       * The entries of the selected model's own subsection, name -> value
       * as written (filled by the model's parse function; empty for the
       * models without own entries).
       */
      std::map<std::string, std::string> model_entries;

      /**
       * Lame's first parameter of the 3-D material: K - 2/3 mu if
       * bulk_modulus and shear_modulus are given, else
       * E nu / ((1 + nu) (1 - 2 nu)).
       */
      double
      lambda() const;
      /** Shear modulus: shear_modulus if given, else E / (2 (1 + nu)). */
      double
      mu() const;

      /**
       * True for nu = 0.5 (given as 'Poisson's ratio'): the material of
       * the incompressible formulation IUnlP0; lambda() is infinite.
       */
      bool
      incompressible() const;

      /**
       * The same shear modulus with the bulk modulus K = 0: the isochoric
       * part alone, for IUnlP0, whose volume is constrained by its pressure
       * (pg-methods.md section 12.2.1) and whose K is infinite.
       */
      Material
      without_volumetric_energy() const;

      /**
       * The same material with Poisson's ratio @p nu and the same Young's
       * modulus (K and mu recomputed from them if they were given): the
       * pseudo-material of U1SUnl, eq. (6.20).
       */
      Material
      with_poissons_ratio(const double nu) const;

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
      /**
       * Read the common entries and those of the selected model. The elastic
       * constants are 'Young's modulus' and 'Poisson's ratio' or, instead,
       * 'Bulk modulus' and 'Shear modulus' (both positive; then E and nu
       * must keep their defaults). Throws ExcBadParameter naming the entry
       * for a single modulus, a modulus that is not a positive number, or
       * both pairs.
       */
      void
      parse_parameters(ParameterHandler &prm);
    };
  } // namespace Parameters
} // namespace pg

#endif
