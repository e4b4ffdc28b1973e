#include <pg/base/exceptions.h>
#include <pg/materials/material_registry.h>
#include <pg/materials/neo_hooke.h>

#include <deal.II/base/utilities.h>

#include <cmath>

namespace pg
{
  namespace Materials
  {



    template <int dim>
    NeoHooke<dim>::NeoHooke(const Parameters::Material &parameters)
      : lambda(parameters.lambda())
      , mu(parameters.mu())
    {
      AssertThrow(dim == 3 || parameters.plane == "strain",
                  ExcBadParameter("Material/Plane",
                                  parameters.plane,
                                  "plane stress is not yet available for "
                                  "'Model = neo-Hooke'; use 'Plane = "
                                  "strain'."));
    }



    template <int dim>
    void
    NeoHooke<dim>::evaluate(const Tensor<2, dim> &F,
                            Tensor<2, dim>       &P,
                            Tensor<4, dim>       &A) const
    {
      const double         J    = checked_jacobian(F, "neo-Hooke");
      const Tensor<2, dim> Finv = invert(F);
      const double         c    = 0.5 * lambda * (J * J - 1.);

      // P = mu (F - F^-T) + lambda/2 (J^2 - 1) F^-T.
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          P[a][b] = mu * F[a][b] + (c - mu) * Finv[b][a];

      // A_ABCD = mu d_AC d_BD + [mu - lambda/2 (J^2 - 1)] Finv_BC Finv_DA
      //        + lambda J^2 Finv_BA Finv_DC.
      const double lambda_J2 = lambda * J * J;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int d = 0; d < dim; ++d)
              A[a][b][k][d] = (mu - c) * Finv[b][k] * Finv[d][a] +
                              lambda_J2 * Finv[b][a] * Finv[d][k] +
                              (a == k && b == d ? mu : 0.);
    }



    template <int dim>
    Tensor<2, dim>
    NeoHooke<dim>::first_piola_stress(const Tensor<2, dim> &F) const
    {
      const double         J    = checked_jacobian(F, "neo-Hooke");
      const Tensor<2, dim> Finv = invert(F);
      const double         c    = 0.5 * lambda * (J * J - 1.);

      Tensor<2, dim> P;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          P[a][b] = mu * F[a][b] + (c - mu) * Finv[b][a];
      return P;
    }



    template <int dim>
    Tensor<2, 3>
    NeoHooke<dim>::cauchy_stress(const Tensor<2, dim> &F) const
    {
      const double J = checked_jacobian(F, "neo-Hooke");
      const double c = 0.5 * lambda * (J * J - 1.);

      // sigma = [mu (b - 1) + lambda/2 (J^2 - 1) 1] / J, b = F F^T.
      Tensor<2, 3> sigma;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          {
            double b_ab = 0.;
            for (unsigned int k = 0; k < dim; ++k)
              b_ab += F[a][k] * F[b][k];
            sigma[a][b] =
              (mu * (b_ab - (a == b ? 1. : 0.)) + (a == b ? c : 0.)) / J;
          }

      // Plane strain: b_33 = 1, so tau_33 = lambda/2 (J^2 - 1).
      if (dim == 2)
        sigma[2][2] = c / J;
      return sigma;
    }



    template <int dim>
    double
    NeoHooke<dim>::strain_energy_density(const Tensor<2, dim> &F) const
    {
      const double J     = checked_jacobian(F, "neo-Hooke");
      const double log_J = std::log(J);

      // tr C - 3; in 2-D plane strain C_33 = 1, so this is the in-plane trace
      // minus 2, i.e. minus dim in both cases.
      double trace_C_minus_3 = -static_cast<double>(dim);
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          trace_C_minus_3 += F[a][b] * F[a][b];

      return 0.5 * mu * (trace_C_minus_3 - 2. * log_J) +
             0.25 * lambda * (J * J - 1. - 2. * log_J);
    }



    template class NeoHooke<2>;
    template class NeoHooke<3>;

    // Listed in this order in 'Model': linear elastic (10), saint venant
    // kirchhoff (20), neo-Hooke (30).
    PG_REGISTER_MATERIAL(NeoHooke, "neo-Hooke", "compressible, eq. 2.42", 30)
  } // namespace Materials
} // namespace pg
