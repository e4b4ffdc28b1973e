#ifndef pg_materials_linear_elastic_h
#define pg_materials_linear_elastic_h

#include <pg/materials/material.h>

namespace pg
{
  namespace Materials
  {
    /**
     * Isotropic linear elasticity (small strain). With the infinitesimal
     * strain
     * @f[ \varepsilon = \mathrm{sym}(F - I) @f]
     * the stress is
     * @f[ P = \sigma = \lambda \, \mathrm{tr}(\varepsilon) \, 1
     *       + 2 \mu \varepsilon, @f]
     * the (constant) tangent
     * @f[ A_{ABCD} = \lambda \delta_{AB} \delta_{CD}
     *       + \mu (\delta_{AC} \delta_{BD} + \delta_{AD} \delta_{BC}) @f]
     * and the strain energy density
     * @f$ W = \frac12 \sigma : \varepsilon @f$.
     * Stresses and moduli are in units of force per area, W in energy per
     * volume.
     *
     * In 2-D plane strain (eps_33 = 0) the 3-D lambda is used and the
     * out-of-plane stress is sigma_33 = lambda tr(eps). In 2-D plane stress
     * (sigma_33 = 0, eps_33 eliminated) lambda is replaced by
     * @f$ \lambda^* = 2 \lambda \mu / (\lambda + 2 \mu) @f$.
     *
     * The model is not frame invariant: it is meant for small displacements
     * and rotations only.
     */
    template <int dim>
    class LinearElastic : public Material<dim>
    {
    public:
      /**
       * Store the Lame constants of @p parameters (lambda replaced by
       * lambda* in 2-D plane stress).
       */
      LinearElastic(const Parameters::Material &parameters);

      void
      evaluate(const Tensor<2, dim> &F,
               Tensor<2, dim>       &P,
               Tensor<4, dim>       &A) const final;

      Tensor<2, dim>
      first_piola_stress(const Tensor<2, dim> &F) const final;

      /**
       * sigma embedded in 3x3, with sigma_33 = lambda tr(eps) in plane strain
       * and 0 in plane stress.
       */
      Tensor<2, 3>
      cauchy_stress(const Tensor<2, dim> &F) const final;

      double
      strain_energy_density(const Tensor<2, dim> &F) const final;

    private:
      /** Lame's first parameter (lambda* in plane stress). */
      const double lambda;
      /** Shear modulus. */
      const double mu;
      /** 2-D plane stress rather than plane strain. */
      const bool plane_stress;
      /** The constant tangent A. */
      Tensor<4, dim> tangent;
    };
  } // namespace Materials
} // namespace pg

#endif
