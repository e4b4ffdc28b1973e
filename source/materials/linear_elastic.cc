#include <pg/materials/linear_elastic.h>
#include <pg/materials/material_registry.h>

namespace pg
{
  namespace Materials
  {
    template <int dim>
    LinearElastic<dim>::LinearElastic(const Parameters::Material &parameters)
      : lambda(dim == 2 && parameters.plane == "stress" ?
                 2. * parameters.lambda() * parameters.mu() /
                   (parameters.lambda() + 2. * parameters.mu()) :
                 parameters.lambda())
      , mu(parameters.mu())
      , plane_stress(dim == 2 && parameters.plane == "stress")
    {
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          for (unsigned int c = 0; c < dim; ++c)
            for (unsigned int d = 0; d < dim; ++d)
              tangent[a][b][c][d] = (a == b && c == d ? lambda : 0.) +
                                    (a == c && b == d ? mu : 0.) +
                                    (a == d && b == c ? mu : 0.);
    }



    template <int dim>
    void
    LinearElastic<dim>::evaluate(const Tensor<2, dim> &F,
                                 Tensor<2, dim>       &P,
                                 Tensor<4, dim>       &A) const
    {
      P = LinearElastic<dim>::first_piola_stress(F);
      A = tangent;
    }



    template <int dim>
    Tensor<2, dim>
    LinearElastic<dim>::first_piola_stress(const Tensor<2, dim> &F) const
    {
      // sigma = lambda tr(eps) 1 + 2 mu eps, eps = sym(F - I).
      double trace_eps = 0.;
      for (unsigned int a = 0; a < dim; ++a)
        trace_eps += F[a][a] - 1.;

      Tensor<2, dim> P;
      for (unsigned int a = 0; a < dim; ++a)
        {
          for (unsigned int b = 0; b < dim; ++b)
            P[a][b] = mu * (F[a][b] + F[b][a]);
          P[a][a] += lambda * trace_eps - 2. * mu;
        }
      return P;
    }



    template <int dim>
    Tensor<2, 3>
    LinearElastic<dim>::cauchy_stress(const Tensor<2, dim> &F) const
    {
      const Tensor<2, dim> P = LinearElastic<dim>::first_piola_stress(F);

      Tensor<2, 3> sigma;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          sigma[a][b] = P[a][b];

      if (dim == 2 && !plane_stress)
        {
          double trace_eps = 0.;
          for (unsigned int a = 0; a < dim; ++a)
            trace_eps += F[a][a] - 1.;
          sigma[2][2] = lambda * trace_eps;
        }
      return sigma;
    }



    template <int dim>
    double
    LinearElastic<dim>::strain_energy_density(const Tensor<2, dim> &F) const
    {
      // W = 1/2 sigma : eps.
      const Tensor<2, dim> P = LinearElastic<dim>::first_piola_stress(F);

      double W = 0.;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          W += P[a][b] * (0.5 * (F[a][b] + F[b][a]) - (a == b ? 1. : 0.));
      return 0.5 * W;
    }



    template class LinearElastic<2>;
    template class LinearElastic<3>;

    // Listed in this order in 'Model': linear elastic (10), saint venant
    // kirchhoff (20), neo-Hooke (30).
    PG_REGISTER_MATERIAL(LinearElastic,
                         "linear elastic",
                         "small strain, P = sigma(eps)",
                         10)
  } // namespace Materials
} // namespace pg
