#ifndef pg_materials_saint_venant_kirchhoff_h
#define pg_materials_saint_venant_kirchhoff_h

#include <pg/materials/material.h>

namespace pg
{
  namespace Materials
  {
    /**
     * The Saint Venant-Kirchhoff material, eq. (2.45). With the Green-Lagrange
     * strain
     * @f[ E = \frac12 (F^T F - I) @f]
     * the second Piola-Kirchhoff stress is
     * @f[ S = \lambda \, \mathrm{tr}(E) \, 1 + 2 \mu E, @f]
     * the first Piola-Kirchhoff stress P = F S, and the tangent
     * @f[ A_{ABCD} = \delta_{AC} S_{BD} + F_{AE} \mathbb{C}_{EBGD} F_{CG},
     *     \quad \mathbb{C}_{EBGD} = \lambda \delta_{EB} \delta_{GD}
     *       + \mu (\delta_{EG} \delta_{BD} + \delta_{ED} \delta_{BG}), @f]
     * which is evaluated as
     * @f$ A_{ABCD} = \delta_{AC} S_{BD} + \lambda F_{AB} F_{CD}
     *     + \mu b_{AC} \delta_{BD} + \mu F_{AD} F_{CB} @f$ with
     * @f$ b = F F^T @f$. The strain energy density is
     * @f$ W = \mu \, \mathrm{tr}(E^2) + \frac{\lambda}{2} (\mathrm{tr} E)^2
     * @f$. Stresses and moduli are in units of force per area, W in energy
     * per volume.
     *
     * In 2-D plane strain (E_33 = 0) the 3-D lambda is used, S_33 =
     * lambda tr(E), and the Cauchy stress sigma = F S F^T / J has sigma_33 =
     * S_33 / J. In 2-D plane stress, S_33 = 0 eliminates E_33 exactly (S is
     * linear in E), which replaces lambda by
     * @f$ \lambda^* = 2 \lambda \mu / (\lambda + 2 \mu) @f$ in both S and W;
     * then sigma_33 = 0, and the J of the Cauchy stress is the in-plane
     * determinant: the thickness change F_33 is not tracked for output.
     */
    template <int dim>
    class SaintVenantKirchhoff : public Material<dim>
    {
    public:
      /**
       * Store the Lame constants of @p parameters (lambda replaced by
       * lambda* in 2-D plane stress).
       */
      SaintVenantKirchhoff(const Parameters::Material &parameters);

      void
      evaluate(const Tensor<2, dim> &F,
               Tensor<2, dim>       &P,
               Tensor<4, dim>       &A) const final;

      Tensor<2, dim>
      first_piola_stress(const Tensor<2, dim> &F) const final;

      /**
       * sigma = F S F^T / J embedded in 3x3, with sigma_33 = S_33 / J in
       * plane strain and 0 in plane stress (J is the in-plane determinant).
       */
      Tensor<2, 3>
      cauchy_stress(const Tensor<2, dim> &F) const final;

      double
      strain_energy_density(const Tensor<2, dim> &F) const final;

    private:
      /** S and tr(E) at @p F. */
      void
      second_piola_stress(const Tensor<2, dim> &F,
                          Tensor<2, dim>       &S,
                          double               &trace_E) const;

      /** Lame's first parameter (lambda* in plane stress). */
      const double lambda;
      /** Shear modulus. */
      const double mu;
      /** 2-D plane stress rather than plane strain. */
      const bool plane_stress;
    };
  } // namespace Materials
} // namespace pg

#endif
