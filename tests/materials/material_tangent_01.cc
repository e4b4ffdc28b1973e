// Check the three constitutive models: the tangent A against central finite
// differences of P, P against central finite differences of W, the stress
// free reference state, frame invariance and symmetric Cauchy stress of the
// finite strain models, the small strain limit (Lame constants and the plane
// stress lambda*), the out-of-plane Cauchy stress of a plane strain stretch,
// the von Mises stress, and the error messages.

#include <pg/base/parameters.h>
#include <pg/materials/material.h>

#include "../tests.h"
#include "tensor_tools.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <string>

using namespace pg;

const double youngs_modulus = 100.;



Parameters::Material
make_parameters(const std::string &model, const std::string &plane)
{
  Parameters::Material parameters;
  parameters.model          = model;
  parameters.youngs_modulus = youngs_modulus;
  parameters.poissons_ratio = 0.3;
  parameters.density        = 1.;
  parameters.plane          = plane;
  return parameters;
}



template <int dim>
void
check(const std::string &model, const std::string &plane)
{
  deallog.push(model + (dim == 2 ? ", 2-D plane " + plane : ", 3-D"));

  const Parameters::Material parameters = make_parameters(model, plane);
  const std::unique_ptr<Materials::Material<dim>> material =
    Materials::create_material<dim>(parameters);
  const bool finite_strain = (model != "linear elastic");

  std::mt19937         generator(42);
  const Tensor<2, dim> I = unit_symmetric_tensor<dim>();
  const Tensor<2, dim> F = I + 0.2 * random_tensor<dim>(generator);
  AssertThrow(determinant(F) > 0.2, ExcInternalError());

  Tensor<2, dim> P;
  Tensor<4, dim> A;
  material->evaluate(F, P, A);

  // 1. A = dP/dF by central differences.
  {
    const double h           = 1e-6;
    double       max_error   = 0.;
    double       max_tangent = 0.;
    for (unsigned int c = 0; c < dim; ++c)
      for (unsigned int d = 0; d < dim; ++d)
        {
          Tensor<2, dim> F_plus = F, F_minus = F;
          F_plus[c][d] += h;
          F_minus[c][d] -= h;
          const Tensor<2, dim> dP = (material->first_piola_stress(F_plus) -
                                     material->first_piola_stress(F_minus)) /
                                    (2. * h);
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              {
                max_error =
                  std::max(max_error, std::abs(dP[a][b] - A[a][b][c][d]));
                max_tangent = std::max(max_tangent, std::abs(A[a][b][c][d]));
              }
        }
    print_bound("tangent matches finite differences of P, relative error",
                max_error / max_tangent,
                1e-6);
  }

  // 2. P = dW/dF by central differences.
  {
    const double   h = 1e-6;
    Tensor<2, dim> dW;
    for (unsigned int c = 0; c < dim; ++c)
      for (unsigned int d = 0; d < dim; ++d)
        {
          Tensor<2, dim> F_plus = F, F_minus = F;
          F_plus[c][d] += h;
          F_minus[c][d] -= h;
          dW[c][d] = (material->strain_energy_density(F_plus) -
                      material->strain_energy_density(F_minus)) /
                     (2. * h);
        }
    print_bound("stress matches finite differences of W, relative error",
                max_abs(dW - P) / max_abs(P),
                1e-6);
    print_bound("first_piola_stress equals P of evaluate, relative error",
                max_abs(material->first_piola_stress(F) - P) / max_abs(P),
                1e-14);
  }

  // 3. The reference state is stress and energy free.
  {
    Tensor<2, dim> P_0;
    Tensor<4, dim> A_0;
    material->evaluate(I, P_0, A_0);
    print_bound("|P(I)| / E", max_abs(P_0) / youngs_modulus, 1e-14);
    print_bound("|sigma(I)| / E",
                max_abs(material->cauchy_stress(I)) / youngs_modulus,
                1e-14);
    print_bound("W(I) / E",
                material->strain_energy_density(I) / youngs_modulus,
                1e-14);
  }

  // 4. Frame invariance, and sigma = P F^T / J symmetric.
  {
    const Tensor<2, 3> sigma      = material->cauchy_stress(F);
    Tensor<2, 3>       asymmetric = sigma - transpose(sigma);
    print_bound("|sigma - sigma^T| / |sigma|",
                max_abs(asymmetric) / max_abs(sigma),
                1e-12);

    // In-plane Cauchy stress: P F^T / J, and P itself for linear elasticity.
    const Tensor<2, dim> expected =
      finite_strain ? Tensor<2, dim>(P * transpose(F) / determinant(F)) : P;
    double max_error = 0.;
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int b = 0; b < dim; ++b)
        max_error = std::max(max_error, std::abs(sigma[a][b] - expected[a][b]));
    print_bound("in-plane sigma - P F^T / J (P if linear elastic), relative",
                max_error / max_abs(sigma),
                1e-12);

    if (finite_strain)
      {
        const Tensor<2, dim> Q = rotation<dim>(0.9);
        print_bound("|Q Q^T - 1|", max_abs(Q * transpose(Q) - I), 1e-15);
        print_bound("|P(QF) - Q P(F)| / |P(F)|",
                    max_abs(material->first_piola_stress(Q * F) - Q * P) /
                      max_abs(P),
                    1e-12);
        print_bound("|W(QF) - W(F)| / W(F)",
                    (material->strain_energy_density(Q * F) -
                     material->strain_energy_density(F)) /
                      material->strain_energy_density(F),
                    1e-12);
      }
  }

  // 5. Small strain limit. Linear elasticity under uniaxial stress (lateral
  // strain -nu eps_11, or -nu / (1 - nu) eps_11 in plane strain) recovers E,
  // which checks the Lame constants and lambda* of plane stress; the finite
  // strain models reduce to linear elasticity.
  if (!finite_strain)
    {
      const double   nu         = parameters.poissons_ratio;
      const double   eps_11     = 1e-3;
      const bool     strain     = (dim == 2 && plane == "strain");
      const double   lateral    = (strain ? -nu / (1. - nu) : -nu) * eps_11;
      Tensor<2, dim> F_uniaxial = I;
      F_uniaxial[0][0] += eps_11;
      for (unsigned int a = 1; a < dim; ++a)
        F_uniaxial[a][a] += lateral;
      const Tensor<2, 3> sigma = material->cauchy_stress(F_uniaxial);

      double lateral_stress = 0.;
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          if (a != 0 || b != 0)
            lateral_stress = std::max(lateral_stress, std::abs(sigma[a][b]));
      print_bound("uniaxial stress: in-plane |sigma_ab|, ab != 11, / sigma_11",
                  lateral_stress / sigma[0][0],
                  1e-10);
      print_rounded("uniaxial stress: sigma_11 / (E eps_11)",
                    sigma[0][0] / (youngs_modulus * eps_11),
                    6);
      if (strain)
        print_rounded("uniaxial stress: sigma_33 / sigma_11",
                      sigma[2][2] / sigma[0][0],
                      6);
    }
  else if (finite_strain)
    {
      const std::unique_ptr<Materials::Material<dim>> linear =
        Materials::create_material<dim>(
          make_parameters("linear elastic", plane));
      const Tensor<2, dim> F_small  = I + 1e-7 * random_tensor<dim>(generator);
      const Tensor<2, dim> P_linear = linear->first_piola_stress(F_small);
      print_bound("small strain: |P - P_linear elastic| / |P_linear elastic|",
                  max_abs(material->first_piola_stress(F_small) - P_linear) /
                    max_abs(P_linear),
                  1e-5);
    }

  // 6. The out-of-plane stress of a uniaxial stretch.
  if (dim == 2)
    {
      Tensor<2, dim> F_stretch = I;
      F_stretch[0][0]          = 1.01;
      const Tensor<2, 3> sigma = material->cauchy_stress(F_stretch);
      print_rounded("sigma_33 / E at F = diag(1.01, 1)",
                    sigma[2][2] / youngs_modulus,
                    4);
    }

  deallog.pop();
}



// Call @p f and print the message of the ExcMessage or ExcBadParameter it
// throws.
template <typename Function>
void
print_exception(const std::string &name, const Function &f)
{
  try
    {
      f();
      deallog << name << ": no exception" << std::endl;
    }
  catch (const ExceptionBase &e)
    {
      std::string text = exception_message(e);
      text.erase(0, text.find_first_not_of(" \n"));
      deallog << name << ": " << text << std::endl;
    }
}



int
main()
{
  initlog();

  for (const std::string model :
       {"linear elastic", "saint venant kirchhoff", "neo-Hooke"})
    {
      check<2>(model, "strain");
      if (model != "neo-Hooke")
        check<2>(model, "stress");
      check<3>(model, "strain");
    }

  Tensor<2, 3> uniaxial;
  uniaxial[0][0] = 1.;
  print_rounded("von Mises stress of diag(1, 0, 0)",
                Materials::von_mises_stress(uniaxial),
                4);

  print_exception("neo-Hooke at J < 0", []() {
    Tensor<2, 2> F;
    F[0][0] = -0.5;
    F[1][1] = 1.;
    Materials::create_material<2>(make_parameters("neo-Hooke", "strain"))
      ->first_piola_stress(F);
  });
  print_exception("neo-Hooke in plane stress", []() {
    Materials::create_material<2>(make_parameters("neo-Hooke", "stress"));
  });
  print_exception("plane stress in 3-D", []() {
    Materials::create_material<3>(make_parameters("linear elastic", "stress"));
  });
  print_exception("unknown model", []() {
    Materials::create_material<2>(make_parameters("mooney rivlin", "strain"));
  });
}
