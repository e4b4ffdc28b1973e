#ifndef pg_materials_isochoric_volumetric_neo_hooke_h
#define pg_materials_isochoric_volumetric_neo_hooke_h

#include <pg/materials/jacobian_volumetric_split.h>
#include <pg/materials/material.h>

namespace pg
{
  namespace Materials
  {
    /**
     * The neo-Hooke material with an isochoric/volumetric split, eqs.
     * (2.43)-(2.44) (pg-methods.md section 3.2), used by the mixed
     * formulations. The strain energy density (energy per reference volume)
     * @f[ W = W_{iso}(b_{iso}) + W_{vol}(J)
     *       = \frac{\mu}{2} (\mathrm{tr}\, b_{iso} - 3)
     *       + \frac{K}{4} (J^2 - 1 - 2 \ln J), \qquad
     *     b_{iso} = J^{-2/3} F F^T, @f]
     * with J = det F, the shear modulus mu and the bulk modulus
     * K = lambda + 2/3 mu. The Kirchhoff and first Piola-Kirchhoff stresses
     * are
     * @f[ \tau = \mu\, \mathrm{dev}\, b_{iso} + \frac{K}{2} (J^2 - 1) 1,
     *     \qquad P = \tau F^{-T}
     *     = \underbrace{\mu J^{-2/3} \left(F - \frac{I_1}{3} F^{-T}\right)}
     *         _{P_{iso}}
     *     + \underbrace{\frac{K}{2} (J^2 - 1) F^{-T}}_{P_{vol}}, @f]
     * I_1 = tr(F F^T), and the tangent A_ABCD = dP_AB / dF_CD is
     * @f[ A^{iso}_{ABCD} = \mu J^{-2/3} \Big[\delta_{AC} \delta_{BD}
     *       - \frac23 (F_{AB} F^{-1}_{DC} + F^{-1}_{BA} F_{CD})
     *       + \frac{I_1}{3} F^{-1}_{BC} F^{-1}_{DA}
     *       + \frac{2 I_1}{9} F^{-1}_{BA} F^{-1}_{DC}\Big], @f]
     * @f[ A^{vol}_{ABCD} = K J^2 F^{-1}_{BA} F^{-1}_{DC}
     *       - \frac{K}{2} (J^2 - 1) F^{-1}_{BC} F^{-1}_{DA}. @f]
     * Stresses and moduli are in units of force per area. W, P and sigma
     * vanish at F = I; for small strains the model is linear elasticity with
     * the Lame constants lambda = K - 2/3 mu and mu.
     *
     * In 2-D only plane strain is available: the 3-D model with F_33 = 1.
     * Then J is the determinant of the 2x2 F, I_1 = tr(F F^T) + 1 (in-plane
     * trace plus b_33 = 1), the exponent stays -2/3, and the formulas above
     * hold as written for the in-plane P and A (F^{-1} is block diagonal).
     * This is not the 2-D split with J^{-1}. The out-of-plane stress is
     * tau_33 = mu J^{-2/3} (1 - I_1/3) + K/2 (J^2 - 1).
     *
     * For the mixed (Hu-Washizu) formulations, eq. (2.59)-(2.60), the
     * isochoric part (P_iso, A_iso, W_iso) and the volumetric potential
     * W_vol(Theta) with its derivatives are available separately.
     *
     * All functions of F throw if J <= 0 (an inverted element), those of
     * Theta if Theta <= 0.
     */
    template <int dim>
    class IsochoricVolumetricNeoHooke : public Material<dim>,
                                        public JacobianVolumetricSplit<dim>
    {
    public:
      /**
       * Store the moduli of @p parameters (mu, and K = lambda + 2/3 mu).
       * Throws for 2-D plane stress, which this model does not support.
       */
      IsochoricVolumetricNeoHooke(const Parameters::Material &parameters);

      void
      evaluate(const Tensor<2, dim> &F,
               Tensor<2, dim>       &P,
               Tensor<4, dim>       &A) const final;

      Tensor<2, dim>
      first_piola_stress(const Tensor<2, dim> &F) const final;

      /**
       * sigma = tau / J embedded in 3x3; in 2-D plane strain
       * sigma_33 = [mu J^{-2/3} (1 - I_1/3) + K/2 (J^2 - 1)] / J.
       */
      Tensor<2, 3>
      cauchy_stress(const Tensor<2, dim> &F) const final;

      double
      strain_energy_density(const Tensor<2, dim> &F) const final;

      /**
       * @name The split, for the mixed formulations (eqs. 2.59, 2.60)
       */
      /** @{ */

      /** W_iso = mu/2 (J^{-2/3} I_1 - 3), energy per reference volume. */
      double
      isochoric_strain_energy_density(const Tensor<2, dim> &F) const final;

      /** P_iso = dW_iso/dF = mu J^{-2/3} (F - I_1/3 F^{-T}). */
      Tensor<2, dim>
      isochoric_first_piola_stress(const Tensor<2, dim> &F) const final;

      /** P_iso and the tangent A_iso = dP_iso/dF (see the class doc). */
      void
      evaluate_isochoric(const Tensor<2, dim> &F,
                         Tensor<2, dim>       &P_iso,
                         Tensor<4, dim>       &A_iso) const final;

      // theta = J and W_vol(Theta) = K/4 (Theta^2 - 1 - 2 ln Theta):
      // JacobianVolumetricSplit.

      /** The bulk modulus K = lambda + 2/3 mu. */
      double
      bulk_modulus() const;

      /** The shear modulus mu. */
      double
      shear_modulus() const;
      /** @} */

    private:
      /** Bulk modulus K = lambda + 2/3 mu. */
      const double kappa;
      /** Shear modulus. */
      const double mu;
    };
  } // namespace Materials
} // namespace pg

#endif
