// Checks of the Mooney-Rivlin material of mooney_rivlin.cc, through pg's
// registry as pg_solve sees it: the tangent against central differences of
// P, P against differences of W, P(I) = 0, and c2 = 0 against pg's
// neo-Hooke, in 2-D plane strain and 3-D. Prints the largest relative
// deviations and exits with 1 if one is above its bound.

#include <pg/materials/material.h>
#include <pg/materials/material_registry.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <algorithm>
#include <cmath>
#include <iostream>

using namespace dealii;

namespace
{
  pg::Parameters::Material
  parameters(const std::string &model, const double c2)
  {
    ParameterHandler prm;
    pg::Parameters::Material::declare_parameters(prm);
    prm.parse_input_from_string(
      "subsection Material\n  set Model = " + model +
      "\n  set Young's modulus = 100\n  set Poisson's ratio = 0.3\n"
      "  subsection Mooney-Rivlin\n    set Second constant = " +
      std::to_string(c2) + "\n  end\nend\n");
    pg::Parameters::Material p;
    p.parse_parameters(prm);
    return p;
  }



  template <int dim>
  bool
  check()
  {
    const auto material =
      pg::Materials::create_material<dim>(parameters("Mooney-Rivlin", 7.5));
    const auto neo_hooke =
      pg::Materials::create_material<dim>(parameters("neo-Hooke", 0));
    const auto mr_c2_zero =
      pg::Materials::create_material<dim>(parameters("Mooney-Rivlin", 0));

    Tensor<2, dim> F;
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int b = 0; b < dim; ++b)
        F[a][b] = (a == b ? 1.1 : 0.) + 0.07 * (a + 1) - 0.05 * b;
    Tensor<2, dim> P;
    Tensor<4, dim> A;
    material->evaluate(F, P, A);

    const double h             = 1e-6;
    double       tangent_error = 0, stress_error = 0;
    for (unsigned int c = 0; c < dim; ++c)
      for (unsigned int d = 0; d < dim; ++d)
        {
          Tensor<2, dim> Fp = F, Fm = F;
          Fp[c][d] += h;
          Fm[c][d] -= h;
          const Tensor<2, dim> dP = (material->first_piola_stress(Fp) -
                                     material->first_piola_stress(Fm)) /
                                    (2. * h);
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              tangent_error =
                std::max(tangent_error, std::abs(dP[a][b] - A[a][b][c][d]));
          const double dW = (material->strain_energy_density(Fp) -
                             material->strain_energy_density(Fm)) /
                            (2. * h);
          stress_error = std::max(stress_error, std::abs(dW - P[c][d]));
        }
    tangent_error /= A.norm();
    stress_error /= P.norm();
    const double at_identity =
      material->first_piola_stress(unit_symmetric_tensor<dim>()).norm();
    const double neo_hooke_error =
      (mr_c2_zero->first_piola_stress(F) - neo_hooke->first_piola_stress(F))
        .norm() /
      neo_hooke->first_piola_stress(F).norm();

    std::cout << dim << "-D: tangent vs differences of P " << tangent_error
              << ", P vs differences of W " << stress_error << ", |P(I)| "
              << at_identity << ", c2 = 0 vs neo-Hooke " << neo_hooke_error
              << std::endl;
    return tangent_error < 1e-7 && stress_error < 1e-7 && at_identity < 1e-12 &&
           neo_hooke_error < 1e-14;
  }
} // namespace



int
main()
{
  const bool ok = check<2>() && check<3>();
  std::cout << (ok ? "all checks passed" : "a check FAILED") << std::endl;
  return ok ? 0 : 1;
}
