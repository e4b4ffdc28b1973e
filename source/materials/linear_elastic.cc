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



    template <int dim>
    void
    LinearElastic<dim>::check_split() const
    {
      AssertThrow(!plane_stress,
                  ExcMessage("The mixed formulations (UnlP0, Q1P0) split the "
                             "linear elastic energy into its deviatoric and "
                             "volumetric parts, which plane stress does not "
                             "have (nor does it lock). Use 'Plane = strain' "
                             "in subsection 'Material' or a displacement "
                             "formulation."));
    }



    template <int dim>
    double
    LinearElastic<dim>::isochoric_strain_energy_density(
      const Tensor<2, dim> &F) const
    {
      check_split();
      const double tr      = volume_measure(F);
      double       eps_eps = 0.;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          {
            const double e = 0.5 * (F[a][b] + F[b][a]) - (a == b ? 1. : 0.);
            eps_eps += e * e;
          }
      return mu * (eps_eps - tr * tr / 3.);
    }



    template <int dim>
    Tensor<2, dim>
    LinearElastic<dim>::isochoric_first_piola_stress(
      const Tensor<2, dim> &F) const
    {
      check_split();
      const double   tr = volume_measure(F);
      Tensor<2, dim> P;
      for (unsigned int a = 0; a < dim; ++a)
        {
          for (unsigned int b = 0; b < dim; ++b)
            P[a][b] = mu * (F[a][b] + F[b][a]);
          P[a][a] -= 2. * mu * (1. + tr / 3.);
        }
      return P;
    }



    template <int dim>
    void
    LinearElastic<dim>::evaluate_isochoric(const Tensor<2, dim> &F,
                                           Tensor<2, dim>       &P_iso,
                                           Tensor<4, dim>       &A_iso) const
    {
      P_iso = isochoric_first_piola_stress(F);
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          for (unsigned int c = 0; c < dim; ++c)
            for (unsigned int d = 0; d < dim; ++d)
              A_iso[a][b][c][d] = (a == b && c == d ? -2. / 3. * mu : 0.) +
                                  (a == c && b == d ? mu : 0.) +
                                  (a == d && b == c ? mu : 0.);
    }



    template <int dim>
    double
    LinearElastic<dim>::volume_measure(const Tensor<2, dim> &F) const
    {
      double tr = 0.;
      for (unsigned int a = 0; a < dim; ++a)
        tr += F[a][a] - 1.;
      return tr;
    }



    template <int dim>
    Tensor<2, dim>
    LinearElastic<dim>::volume_measure_derivative(const Tensor<2, dim> &) const
    {
      return unit_symmetric_tensor<dim>();
    }



    template <int dim>
    void
    LinearElastic<dim>::add_volume_measure_second_derivative(
      const Tensor<2, dim> &,
      const double,
      Tensor<4, dim> &) const
    {}



    template <int dim>
    double
    LinearElastic<dim>::volumetric_strain_energy_density(
      const double Theta) const
    {
      check_split();
      return 0.5 * (lambda + 2. / 3. * mu) * Theta * Theta;
    }



    template <int dim>
    double
    LinearElastic<dim>::volumetric_strain_energy_derivative(
      const double Theta) const
    {
      check_split();
      return (lambda + 2. / 3. * mu) * Theta;
    }



    template <int dim>
    double
    LinearElastic<dim>::volumetric_strain_energy_second_derivative(
      const double) const
    {
      check_split();
      return lambda + 2. / 3. * mu;
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
