#ifndef pg_materials_jacobian_volumetric_split_h
#define pg_materials_jacobian_volumetric_split_h

#include <pg/base/global.h>
#include <pg/materials/volumetric_split.h>

#include <string>

namespace pg
{
  namespace Materials
  {
    /**
     * The volumetric half of VolumetricSplit that the isochoric-volumetric
     * neo-Hooke and J2 plasticity share (eq. 2.44): the volume measure
     * theta(F) = J = det F and W_vol(Theta) = K/4 (Theta^2 - 1 - 2 ln
     * Theta), so that p = W_vol' = K/2 (Theta - 1/Theta). A model derives
     * from it and implements the isochoric functions. Errors name the model
     * (J <= 0, Theta <= 0: an inverted element). Units: K force per area.
     */
    template <int dim>
    class JacobianVolumetricSplit : public VolumetricSplit<dim>
    {
    public:
      /** For the bulk modulus @p K of the model named @p model. */
      JacobianVolumetricSplit(const double K, const std::string &model);

      /** J = det F. */
      double
      volume_measure(const Tensor<2, dim> &F) const final;

      /** dJ/dF = J F^{-T}. */
      Tensor<2, dim>
      volume_measure_derivative(const Tensor<2, dim> &F) const final;

      /** A += factor J (F^{-T} (x) F^{-T} - F^{-T} [x] F^{-1}). */
      void
      add_volume_measure_second_derivative(const Tensor<2, dim> &F,
                                           const double          factor,
                                           Tensor<4, dim>       &A) const final;

      /** K/4 (Theta^2 - 1 - 2 ln Theta). */
      double
      volumetric_strain_energy_density(const double Theta) const final;

      /** K/2 (Theta - 1/Theta). */
      double
      volumetric_strain_energy_derivative(const double Theta) const final;

      /** K/2 (1 + 1/Theta^2). */
      double
      volumetric_strain_energy_second_derivative(
        const double Theta) const final;

    private:
      /** Theta, or throw with advice if Theta <= 0. */
      double
      checked_volume_ratio(const double Theta) const;

      const double      volumetric_bulk_modulus;
      const std::string model;
    };
  } // namespace Materials
} // namespace pg

#endif
