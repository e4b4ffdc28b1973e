#include <pg/base/exceptions.h>
#include <pg/materials/isochoric_volumetric_neo_hooke.h>
#include <pg/materials/material_registry.h>

#include <deal.II/base/utilities.h>

#include <cmath>

namespace pg
{
  namespace Materials
  {
    // A named namespace: the unity build may compile this file together
    // with other materials' helpers.
    namespace IsoVol
    {
      /** The name in error messages. */
      constexpr const char *model_name = "isochoric-volumetric neo-Hooke";



      /**
       * I_1 = tr(F F^T) of the 3-D deformation gradient; in 2-D plane
       * strain F_33 = 1 adds 1 to the in-plane trace.
       */
      template <int dim>
      inline double
      first_invariant(const Tensor<2, dim> &F)
      {
        double I_1 = 3. - dim;
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            I_1 += F[a][b] * F[a][b];
        return I_1;
      }



      /**
       * P_iso = mu J^{-2/3} (F - I_1/3 F^-T) and, unless @p A is nullptr,
       * *A = A_iso, given J, F^-1 and I_1.
       */
      template <int dim>
      void
      isochoric_part(const double          mu,
                     const Tensor<2, dim> &F,
                     const double          J,
                     const Tensor<2, dim> &Finv,
                     const double          I_1,
                     Tensor<2, dim>       &P,
                     Tensor<4, dim>       *A)
      {
        const double mu_J = mu * std::pow(J, -2. / 3.);
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            P[a][b] = mu_J * (F[a][b] - I_1 / 3. * Finv[b][a]);
        if (A == nullptr)
          return;

        // A_ABCD = mu J^-2/3 [d_AC d_BD - 2/3 (F_AB Finv_DC + Finv_BA F_CD)
        //          + I_1/3 Finv_BC Finv_DA + 2 I_1/9 Finv_BA Finv_DC].
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int d = 0; d < dim; ++d)
                (*A)[a][b][k][d] =
                  mu_J *
                  ((a == k && b == d ? 1. : 0.) -
                   2. / 3. * (F[a][b] * Finv[d][k] + Finv[b][a] * F[k][d]) +
                   I_1 / 3. * Finv[b][k] * Finv[d][a] +
                   2. * I_1 / 9. * Finv[b][a] * Finv[d][k]);
      }



      /**
       * Add P_vol = K/2 (J^2 - 1) F^-T to @p P and, unless @p A is nullptr,
       * A_vol = K J^2 Finv_BA Finv_DC - K/2 (J^2 - 1) Finv_BC Finv_DA to *A.
       */
      template <int dim>
      void
      add_volumetric_part(const double          kappa,
                          const double          J,
                          const Tensor<2, dim> &Finv,
                          Tensor<2, dim>       &P,
                          Tensor<4, dim>       *A)
      {
        const double c        = 0.5 * kappa * (J * J - 1.);
        const double kappa_J2 = kappa * J * J;
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            {
              P[a][b] += c * Finv[b][a];
              if (A != nullptr)
                for (unsigned int k = 0; k < dim; ++k)
                  for (unsigned int d = 0; d < dim; ++d)
                    (*A)[a][b][k][d] += kappa_J2 * Finv[b][a] * Finv[d][k] -
                                        c * Finv[b][k] * Finv[d][a];
            }
      }
    } // namespace IsoVol



    template <int dim>
    IsochoricVolumetricNeoHooke<dim>::IsochoricVolumetricNeoHooke(
      const Parameters::Material &parameters)
      : JacobianVolumetricSplit<dim>(parameters.lambda() +
                                       2. / 3. * parameters.mu(),
                                     IsoVol::model_name)
      , kappa(parameters.lambda() + 2. / 3. * parameters.mu())
      , mu(parameters.mu())
    {
      AssertThrow(dim == 3 || parameters.plane == "strain",
                  ExcBadParameter("Material/Plane",
                                  parameters.plane,
                                  "plane stress is not available for 'Model "
                                  "= isochoric-volumetric neo-Hooke'; use "
                                  "'Plane = strain'."));
    }



    template <int dim>
    void
    IsochoricVolumetricNeoHooke<dim>::evaluate(const Tensor<2, dim> &F,
                                               Tensor<2, dim>       &P,
                                               Tensor<4, dim>       &A) const
    {
      const double         J    = checked_jacobian(F, IsoVol::model_name);
      const Tensor<2, dim> Finv = invert(F);
      IsoVol::isochoric_part(mu, F, J, Finv, IsoVol::first_invariant(F), P, &A);
      IsoVol::add_volumetric_part(kappa, J, Finv, P, &A);
    }



    template <int dim>
    Tensor<2, dim>
    IsochoricVolumetricNeoHooke<dim>::first_piola_stress(
      const Tensor<2, dim> &F) const
    {
      const double         J    = checked_jacobian(F, IsoVol::model_name);
      const Tensor<2, dim> Finv = invert(F);
      Tensor<2, dim>       P;
      IsoVol::isochoric_part<dim>(mu,
                                  F,
                                  J,
                                  Finv,
                                  IsoVol::first_invariant(F),
                                  P,
                                  nullptr);
      IsoVol::add_volumetric_part<dim>(kappa, J, Finv, P, nullptr);
      return P;
    }



    template <int dim>
    Tensor<2, 3>
    IsochoricVolumetricNeoHooke<dim>::cauchy_stress(
      const Tensor<2, dim> &F) const
    {
      const double J    = checked_jacobian(F, IsoVol::model_name);
      const double I_1  = IsoVol::first_invariant(F);
      const double mu_J = mu * std::pow(J, -2. / 3.);
      const double c    = 0.5 * kappa * (J * J - 1.);

      // sigma = [mu J^-2/3 (b - I_1/3 1) + K/2 (J^2 - 1) 1] / J, b = F F^T.
      Tensor<2, 3> sigma;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          {
            double b_ab = 0.;
            for (unsigned int k = 0; k < dim; ++k)
              b_ab += F[a][k] * F[b][k];
            sigma[a][b] =
              (mu_J * (b_ab - (a == b ? I_1 / 3. : 0.)) + (a == b ? c : 0.)) /
              J;
          }

      // Plane strain: b_33 = 1.
      if (dim == 2)
        sigma[2][2] = (mu_J * (1. - I_1 / 3.) + c) / J;
      return sigma;
    }



    template <int dim>
    double
    IsochoricVolumetricNeoHooke<dim>::strain_energy_density(
      const Tensor<2, dim> &F) const
    {
      return isochoric_strain_energy_density(F) +
             this->volumetric_strain_energy_density(
               checked_jacobian(F, IsoVol::model_name));
    }



    template <int dim>
    double
    IsochoricVolumetricNeoHooke<dim>::isochoric_strain_energy_density(
      const Tensor<2, dim> &F) const
    {
      const double J = checked_jacobian(F, IsoVol::model_name);
      return 0.5 * mu *
             (std::pow(J, -2. / 3.) * IsoVol::first_invariant(F) - 3.);
    }



    template <int dim>
    Tensor<2, dim>
    IsochoricVolumetricNeoHooke<dim>::isochoric_first_piola_stress(
      const Tensor<2, dim> &F) const
    {
      const double   J = checked_jacobian(F, IsoVol::model_name);
      Tensor<2, dim> P_iso;
      IsoVol::isochoric_part<dim>(mu,
                                  F,
                                  J,
                                  invert(F),
                                  IsoVol::first_invariant(F),
                                  P_iso,
                                  nullptr);
      return P_iso;
    }



    template <int dim>
    void
    IsochoricVolumetricNeoHooke<dim>::evaluate_isochoric(
      const Tensor<2, dim> &F,
      Tensor<2, dim>       &P_iso,
      Tensor<4, dim>       &A_iso) const
    {
      const double J = checked_jacobian(F, IsoVol::model_name);
      IsoVol::isochoric_part(mu,
                             F,
                             J,
                             invert(F),
                             IsoVol::first_invariant(F),
                             P_iso,
                             &A_iso);
    }



    template <int dim>
    double
    IsochoricVolumetricNeoHooke<dim>::bulk_modulus() const
    {
      return kappa;
    }



    template <int dim>
    double
    IsochoricVolumetricNeoHooke<dim>::shear_modulus() const
    {
      return mu;
    }



    template class IsochoricVolumetricNeoHooke<2>;
    template class IsochoricVolumetricNeoHooke<3>;

    // Listed after neo-Hooke (30).
    PG_REGISTER_MATERIAL(IsochoricVolumetricNeoHooke,
                         "isochoric-volumetric neo-Hooke",
                         "mu/2 (tr b_iso - 3) + K/4 (J^2 - 1 - 2 ln J), "
                         "eqs. 2.43-2.44",
                         40)
  } // namespace Materials
} // namespace pg
