#include <pg/materials/material_registry.h>
#include <pg/materials/saint_venant_kirchhoff.h>

namespace pg
{
  namespace Materials
  {
    template <int dim>
    SaintVenantKirchhoff<dim>::SaintVenantKirchhoff(
      const Parameters::Material &parameters)
      : lambda(dim == 2 && parameters.plane == "stress" ?
                 2. * parameters.lambda() * parameters.mu() /
                   (parameters.lambda() + 2. * parameters.mu()) :
                 parameters.lambda())
      , mu(parameters.mu())
      , plane_stress(dim == 2 && parameters.plane == "stress")
    {}



    template <int dim>
    void
    SaintVenantKirchhoff<dim>::second_piola_stress(const Tensor<2, dim> &F,
                                                   Tensor<2, dim>       &S,
                                                   double &trace_E) const
    {
      // E = 1/2 (F^T F - I), S = lambda tr(E) 1 + 2 mu E.
      trace_E = 0.;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = a; b < dim; ++b)
          {
            double C_ab = 0.;
            for (unsigned int k = 0; k < dim; ++k)
              C_ab += F[k][a] * F[k][b];
            if (a == b)
              {
                trace_E += 0.5 * (C_ab - 1.);
                S[a][a] = mu * (C_ab - 1.);
              }
            else
              {
                S[a][b] = mu * C_ab;
                S[b][a] = S[a][b];
              }
          }
      for (unsigned int a = 0; a < dim; ++a)
        S[a][a] += lambda * trace_E;
    }



    template <int dim>
    void
    SaintVenantKirchhoff<dim>::evaluate(const Tensor<2, dim> &F,
                                        Tensor<2, dim>       &P,
                                        Tensor<4, dim>       &A) const
    {
      Tensor<2, dim> S;
      double         trace_E;
      second_piola_stress(F, S, trace_E);

      // P = F S, left Cauchy-Green tensor b = F F^T.
      Tensor<2, dim> left_cauchy_green;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int c = 0; c < dim; ++c)
          {
            double P_ac = 0.;
            double b_ac = 0.;
            for (unsigned int k = 0; k < dim; ++k)
              {
                P_ac += F[a][k] * S[k][c];
                b_ac += F[a][k] * F[c][k];
              }
            P[a][c]                 = P_ac;
            left_cauchy_green[a][c] = b_ac;
          }

      // A_ABCD = d_AC S_BD + F_AE C_EBGD F_CG
      //        = d_AC S_BD + lambda F_AB F_CD + mu b_AC d_BD + mu F_AD F_CB.
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          for (unsigned int c = 0; c < dim; ++c)
            for (unsigned int d = 0; d < dim; ++d)
              A[a][b][c][d] = lambda * F[a][b] * F[c][d] +
                              mu * F[a][d] * F[c][b] + (a == c ? S[b][d] : 0.) +
                              (b == d ? mu * left_cauchy_green[a][c] : 0.);
    }



    template <int dim>
    Tensor<2, dim>
    SaintVenantKirchhoff<dim>::first_piola_stress(const Tensor<2, dim> &F) const
    {
      Tensor<2, dim> S;
      double         trace_E;
      second_piola_stress(F, S, trace_E);

      Tensor<2, dim> P;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int c = 0; c < dim; ++c)
          for (unsigned int k = 0; k < dim; ++k)
            P[a][c] += F[a][k] * S[k][c];
      return P;
    }



    template <int dim>
    Tensor<2, 3>
    SaintVenantKirchhoff<dim>::cauchy_stress(const Tensor<2, dim> &F) const
    {
      Tensor<2, dim> S;
      double         trace_E;
      second_piola_stress(F, S, trace_E);
      const double J = determinant(F);

      // sigma = F S F^T / J.
      const Tensor<2, dim> P = F * S;
      Tensor<2, 3>         sigma;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int c = 0; c < dim; ++c)
          {
            for (unsigned int k = 0; k < dim; ++k)
              sigma[a][c] += P[a][k] * F[c][k];
            sigma[a][c] /= J;
          }

      // Plane strain: E_33 = 0, F_33 = 1, sigma_33 = S_33 / J.
      if (dim == 2 && !plane_stress)
        sigma[2][2] = lambda * trace_E / J;
      return sigma;
    }



    template <int dim>
    double
    SaintVenantKirchhoff<dim>::strain_energy_density(
      const Tensor<2, dim> &F) const
    {
      // W = mu tr(E^2) + lambda/2 (tr E)^2.
      double trace_E    = 0.;
      double trace_E_sq = 0.;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          {
            double C_ab = 0.;
            for (unsigned int k = 0; k < dim; ++k)
              C_ab += F[k][a] * F[k][b];
            const double E_ab = 0.5 * (C_ab - (a == b ? 1. : 0.));
            trace_E_sq += E_ab * E_ab;
            if (a == b)
              trace_E += E_ab;
          }
      return mu * trace_E_sq + 0.5 * lambda * trace_E * trace_E;
    }



    template class SaintVenantKirchhoff<2>;
    template class SaintVenantKirchhoff<3>;

    // Listed in this order in 'Model': linear elastic (10), saint venant
    // kirchhoff (20), neo-Hooke (30).
    PG_REGISTER_MATERIAL(SaintVenantKirchhoff,
                         "saint venant kirchhoff",
                         "S = lambda tr(E) 1 + 2 mu E, eq. 2.45",
                         20)
  } // namespace Materials
} // namespace pg
