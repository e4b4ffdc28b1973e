#include <pg/materials/jacobian_volumetric_split.h>
#include <pg/materials/material.h>

#include <deal.II/base/utilities.h>

#include <cmath>

namespace pg
{
  namespace Materials
  {
    template <int dim>
    JacobianVolumetricSplit<dim>::JacobianVolumetricSplit(
      const double       K,
      const std::string &model)
      : volumetric_bulk_modulus(K)
      , model(model)
    {}



    template <int dim>
    double
    JacobianVolumetricSplit<dim>::checked_volume_ratio(const double Theta) const
    {
      AssertThrow(Theta > 0.,
                  ExcMessage(
                    "The volume ratio Theta = " + Utilities::to_string(Theta) +
                    " <= 0: the volumetric potential W_vol of the " + model +
                    " material is undefined there. Reduce the load "
                    "step by increasing 'Load steps' in subsection "
                    "'Loading'."));
      return Theta;
    }



    template <int dim>
    double
    JacobianVolumetricSplit<dim>::volume_measure(const Tensor<2, dim> &F) const
    {
      return checked_jacobian(F, model);
    }



    template <int dim>
    Tensor<2, dim>
    JacobianVolumetricSplit<dim>::volume_measure_derivative(
      const Tensor<2, dim> &F) const
    {
      return checked_jacobian(F, model) * transpose(invert(F));
    }



    template <int dim>
    void
    JacobianVolumetricSplit<dim>::add_volume_measure_second_derivative(
      const Tensor<2, dim> &F,
      const double          factor,
      Tensor<4, dim>       &A) const
    {
      const double         fJ    = factor * checked_jacobian(F, model);
      const Tensor<2, dim> F_inv = invert(F);
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          for (unsigned int c = 0; c < dim; ++c)
            for (unsigned int d = 0; d < dim; ++d)
              A[a][b][c][d] +=
                fJ * (F_inv[b][a] * F_inv[d][c] - F_inv[b][c] * F_inv[d][a]);
    }



    template <int dim>
    double
    JacobianVolumetricSplit<dim>::volumetric_strain_energy_density(
      const double Theta) const
    {
      checked_volume_ratio(Theta);
      return 0.25 * volumetric_bulk_modulus *
             (Theta * Theta - 1. - 2. * std::log(Theta));
    }



    template <int dim>
    double
    JacobianVolumetricSplit<dim>::volumetric_strain_energy_derivative(
      const double Theta) const
    {
      checked_volume_ratio(Theta);
      return 0.5 * volumetric_bulk_modulus * (Theta - 1. / Theta);
    }



    template <int dim>
    double
    JacobianVolumetricSplit<dim>::volumetric_strain_energy_second_derivative(
      const double Theta) const
    {
      checked_volume_ratio(Theta);
      return 0.5 * volumetric_bulk_modulus * (1. + 1. / (Theta * Theta));
    }



    template class JacobianVolumetricSplit<2>;
    template class JacobianVolumetricSplit<3>;
  } // namespace Materials
} // namespace pg
