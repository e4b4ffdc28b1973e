#ifndef pg_materials_volumetric_split_h
#define pg_materials_volumetric_split_h

#include <pg/base/global.h>

#include <deal.II/base/array_view.h>
#include <deal.II/base/tensor.h>

namespace pg
{
  namespace Materials
  {
    /**
     * The split W(F) = W_iso(F) + W_vol(theta(F)) that the mixed
     * (Hu-Washizu) formulations need (eqs. 2.59-2.60, 6.1-6.3): they
     * replace the volume measure theta(F) by an independent dilatation
     * Theta and enforce theta = Theta weakly with a pressure p = W_vol'.
     * A material that offers it derives from this interface besides
     * Material:
     *
     * | model | theta(F) | W_vol(Theta) |
     * |---|---|---|
     * | isochoric-volumetric neo-Hooke | J = det F | K/4 (Theta^2 - 1 - 2 ln
     * Theta) | | linear elastic (plane strain, 3-D) | tr(F - I) | K/2 Theta^2 |
     *
     * Units: energies per reference volume, stresses and moduli force per
     * area; theta and Theta are dimensionless.
     */
    template <int dim>
    class VolumetricSplit
    {
    public:
      virtual ~VolumetricSplit() = default;

      /** W_iso(F). */
      virtual double
      isochoric_strain_energy_density(const Tensor<2, dim> &F) const = 0;

      /** P_iso = dW_iso/dF. */
      virtual Tensor<2, dim>
      isochoric_first_piola_stress(const Tensor<2, dim> &F) const = 0;

      /** P_iso and A_iso = dP_iso/dF. */
      virtual void
      evaluate_isochoric(const Tensor<2, dim> &F,
                         Tensor<2, dim>       &P_iso,
                         Tensor<4, dim>       &A_iso) const = 0;

      /**
       * The isochoric part with history (plasticity: the deviatoric
       * response carries the plastic flow, the volumetric part stays
       * elastic), under the contract of Material::evaluate_with_state():
       * P_iso and, unless @p A_iso is nullptr, A_iso = dP_iso/dF at @p F
       * from @p committed_state; writes the whole @p trial_state. The
       * state is the Material's (n_state_variables() entries). The
       * default, for stateless materials, forwards to evaluate_isochoric()
       * or isochoric_first_piola_stress().
       */
      virtual void
      evaluate_isochoric_with_state(
        const Tensor<2, dim>          &F,
        const ArrayView<const double> &committed_state,
        const ArrayView<double>       &trial_state,
        Tensor<2, dim>                &P_iso,
        Tensor<4, dim>                *A_iso) const
      {
        (void)committed_state;
        (void)trial_state;
        if (A_iso != nullptr)
          evaluate_isochoric(F, P_iso, *A_iso);
        else
          P_iso = isochoric_first_piola_stress(F);
      }

      /** The volume measure theta(F); throws where it is undefined. */
      virtual double
      volume_measure(const Tensor<2, dim> &F) const = 0;

      /** d theta / dF. */
      virtual Tensor<2, dim>
      volume_measure_derivative(const Tensor<2, dim> &F) const = 0;

      /**
       * A_ABCD += @p factor d^2 theta / dF_AB dF_CD (the part of the
       * tangent of p d theta/dF at fixed p).
       */
      virtual void
      add_volume_measure_second_derivative(const Tensor<2, dim> &F,
                                           const double          factor,
                                           Tensor<4, dim>       &A) const = 0;

      /** W_vol(Theta). */
      virtual double
      volumetric_strain_energy_density(const double Theta) const = 0;

      /** W_vol'(Theta), the pressure of eq. (2.60). */
      virtual double
      volumetric_strain_energy_derivative(const double Theta) const = 0;

      /** W_vol''(Theta). */
      virtual double
      volumetric_strain_energy_second_derivative(const double Theta) const = 0;
    };
  } // namespace Materials
} // namespace pg

#endif
