#ifndef pg_materials_neo_hooke_h
#define pg_materials_neo_hooke_h

#include <pg/materials/material.h>

namespace pg
{
  namespace Materials
  {
    /**
     * The compressible neo-Hooke material of eq. (2.42), with the strain
     * energy density (energy per reference volume)
     * @f[ W = \frac{\mu}{2} (\mathrm{tr} C - 3 - 2 \ln J)
     *       + \frac{\lambda}{4} (J^2 - 1 - 2 \ln J), @f]
     * where C = F^T F and J = det F. The first Piola-Kirchhoff stress is
     * @f[ P = \mu (F - F^{-T}) + \frac{\lambda}{2} (J^2 - 1) F^{-T}, @f]
     * the tangent
     * @f[ A_{ABCD} = \mu \delta_{AC} \delta_{BD}
     *     + \left[\mu - \frac{\lambda}{2} (J^2 - 1)\right]
     *       F^{-1}_{BC} F^{-1}_{DA}
     *     + \lambda J^2 F^{-1}_{BA} F^{-1}_{DC} @f]
     * and the Cauchy stress
     * @f[ \sigma = \frac1J \left[\mu (b - 1)
     *       + \frac{\lambda}{2} (J^2 - 1) 1\right], \quad b = F F^T. @f]
     * Stresses and moduli are in units of force per area. W, P and sigma
     * vanish at F = I.
     *
     * In 2-D only plane strain is available (C_33 = 1, so tr C - 3 is the
     * in-plane trace minus 2; tau_33 = lambda/2 (J^2 - 1)). All functions
     * throw if J <= 0 (an inverted element).
     */
    template <int dim>
    class NeoHooke : public Material<dim>
    {
    public:
      /**
       * Store the Lame constants of @p parameters. Throws for 2-D plane
       * stress, which this model does not support.
       */
      NeoHooke(const Parameters::Material &parameters);

      void
      evaluate(const Tensor<2, dim> &F,
               Tensor<2, dim>       &P,
               Tensor<4, dim>       &A) const final;

      Tensor<2, dim>
      first_piola_stress(const Tensor<2, dim> &F) const final;

      /** sigma embedded in 3x3, with sigma_33 = lambda/2 (J^2 - 1) / J. */
      Tensor<2, 3>
      cauchy_stress(const Tensor<2, dim> &F) const final;

      double
      strain_energy_density(const Tensor<2, dim> &F) const final;

    private:
      /** Lame's first parameter. */
      const double lambda;
      /** Shear modulus. */
      const double mu;
    };
  } // namespace Materials
} // namespace pg

#endif
