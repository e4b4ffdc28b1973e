#ifndef pg_materials_linear_elastic_h
#define pg_materials_linear_elastic_h

#include <pg/materials/material.h>
#include <pg/materials/volumetric_split.h>

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
     *
     * For the mixed formulations (plane strain and 3-D) it splits into the
     * deviatoric energy W_iso = mu (eps : eps - tr(eps)^2 / 3) (the 3-D
     * deviator, eps_33 = 0 in plane strain) and W_vol = K/2 theta^2 of the
     * volume measure theta = tr(eps), K = lambda + 2/3 mu.
     */
    template <int dim>
    class LinearElastic : public Material<dim>, public VolumetricSplit<dim>
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

      /**
       * @name The split for the mixed formulations (plane strain, 3-D;
       * each function throws in plane stress)
       */
      /** @{ */
      double
      isochoric_strain_energy_density(const Tensor<2, dim> &F) const final;

      /** P_iso = 2 mu (eps - tr(eps)/3 1). */
      Tensor<2, dim>
      isochoric_first_piola_stress(const Tensor<2, dim> &F) const final;

      void
      evaluate_isochoric(const Tensor<2, dim> &F,
                         Tensor<2, dim>       &P_iso,
                         Tensor<4, dim>       &A_iso) const final;

      /** theta = tr(eps) = tr(F) - dim. */
      double
      volume_measure(const Tensor<2, dim> &F) const final;

      /** d theta / dF = 1. */
      Tensor<2, dim>
      volume_measure_derivative(const Tensor<2, dim> &F) const final;

      /** theta is linear in F: nothing to add. */
      void
      add_volume_measure_second_derivative(const Tensor<2, dim> &F,
                                           const double          factor,
                                           Tensor<4, dim>       &A) const final;

      /** K/2 Theta^2. */
      double
      volumetric_strain_energy_density(const double Theta) const final;

      /** K Theta. */
      double
      volumetric_strain_energy_derivative(const double Theta) const final;

      /** K. */
      double
      volumetric_strain_energy_second_derivative(
        const double Theta) const final;
      /** @} */

    private:
      /** Throws in plane stress, where the split is not defined. */
      void
      check_split() const;

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
