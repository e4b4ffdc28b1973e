// cauchy_stress_or_nan() (postprocess/output.h): the material's Cauchy
// stress where it is defined, NaN in every entry where the material throws
// (J <= 0). The nodal stresses and the point stresses of summary.json use
// it, so that an inverted correspondence F of a CPD particle (a visual aid:
// CPD has no stress tensor) no longer stops a run after its solution is
// computed (found on PETSc's square_quad.msh with a mirrored CPD strip:
// exit 1 after the converged step; now 'null' in summary.json, exit 0).

#include <pg/materials/neo_hooke.h>
#include <pg/postprocess/output.h>

#include "../tests.h"

using namespace pg;

int
main()
{
  initlog();
  Parameters::Material parameters;
  parameters.model          = "neo-Hooke";
  parameters.youngs_modulus = 100;
  parameters.poissons_ratio = 0.3;
  parameters.density        = 1;
  parameters.plane          = "strain";
  const Materials::NeoHooke<2> material(parameters);

  Tensor<2, 2> F;
  F[0][0]                    = 1.1;
  F[0][1]                    = 0.2;
  F[1][1]                    = 0.9;
  const Tensor<2, 3> defined = cauchy_stress_or_nan(material, F);
  print_bound("defined F: |sigma - cauchy_stress(F)|",
              (defined - material.cauchy_stress(F)).norm(),
              1e-14);

  F[0][0]                     = -1.1;
  const Tensor<2, 3> inverted = cauchy_stress_or_nan(material, F);
  bool               all_nan  = true;
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      all_nan = all_nan && std::isnan(inverted[i][j]);
  deallog << "inverted F (J < 0): every entry NaN: " << (all_nan ? "yes" : "no")
          << std::endl;

  std::vector<double> values;
  stress_field_values(material, F, values);
  deallog << "stress_field_values: F kept, the " << values.size() - 4
          << " stress values NaN: "
          << (std::all_of(values.begin() + 4,
                          values.end(),
                          [](const double v) { return std::isnan(v); }) ?
                "yes" :
                "no")
          << std::endl;
}
