#ifndef pg_tests_materials_necking_material_h
#define pg_tests_materials_necking_material_h

// The J2 plasticity material of the dissertation's necking bar (§7.3.5,
// B-13), kN and mm: E 206.9, nu 0.29, sigma_y0 0.45, sigma_inf 1.165, H
// 0.13, delta 16.93; plane strain in 2-D (j2_plasticity_01, _02).

#include <pg/materials/material_parameters.h>

inline pg::Parameters::Material
necking_material()
{
  pg::Parameters::Material parameters;
  parameters.model                    = "J2 plasticity";
  parameters.youngs_modulus           = 206.9;
  parameters.poissons_ratio           = 0.29;
  parameters.density                  = 1.;
  parameters.plane                    = "strain";
  parameters.initial_yield_stress     = 0.45;
  parameters.saturation_yield_stress  = 1.165;
  parameters.linear_hardening_modulus = 0.13;
  parameters.saturation_exponent      = 16.93;
  return parameters;
}

#endif
