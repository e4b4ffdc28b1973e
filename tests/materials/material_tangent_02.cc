// The isochoric-volumetric neo-Hooke material (eqs. 2.43-2.44) in 2-D plane
// strain and 3-D, with K and mu given: the tangent A against central finite
// differences of P, P against those of W, the stress free reference state,
// frame invariance and symmetric Cauchy stress, the small strain limit
// (linear elasticity with lambda = K - 2/3 mu, mu, and A(I) equal to its
// elasticity tensor), the split (P_iso + P_vol = P, P_vol = 0 for det F = 1,
// P_iso = 0 for a 3-D dilatation, A_iso and P_iso against finite differences
// of P_iso and W_iso, W_vol' and W_vol'' against finite differences), exact
// values at given F computed by hand, and the error messages. Then the
// elastic constants given as 'Bulk modulus' and 'Shear modulus' in
// subsection 'Material': lambda(), mu(), E and nu, the defaults unchanged,
// and the messages for a single modulus, impossible values and both pairs.

#include <pg/base/parameters.h>
#include <pg/materials/isochoric_volumetric_neo_hooke.h>
#include <pg/materials/material.h>

#include "../tests.h"
#include "tensor_tools.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <sstream>
#include <string>

using namespace pg;

const std::string model        = "isochoric-volumetric neo-Hooke";
const double      bulk_modulus = 100.;
const double      shear        = 30.;



Parameters::Material
make_parameters(const std::string &name, const std::string &plane)
{
  Parameters::Material parameters;
  parameters.model = name;
  parameters.youngs_modulus =
    9. * bulk_modulus * shear / (3. * bulk_modulus + shear); // for output only
  parameters.poissons_ratio =
    (3. * bulk_modulus - 2. * shear) / (2. * (3. * bulk_modulus + shear));
  parameters.bulk_modulus  = bulk_modulus;
  parameters.shear_modulus = shear;
  parameters.density       = 1.;
  parameters.plane         = plane;
  return parameters;
}



// max |dP/dF - A| / max |A| by central differences of @p stress.
template <int dim>
double
tangent_error(
  const std::function<Tensor<2, dim>(const Tensor<2, dim> &)> &stress,
  const Tensor<2, dim>                                        &F,
  const Tensor<4, dim>                                        &A)
{
  const double   h = 1e-6;
  Tensor<4, dim> dP;
  for (unsigned int c = 0; c < dim; ++c)
    for (unsigned int d = 0; d < dim; ++d)
      {
        Tensor<2, dim> F_plus = F, F_minus = F;
        F_plus[c][d] += h;
        F_minus[c][d] -= h;
        const Tensor<2, dim> column =
          (stress(F_plus) - stress(F_minus)) / (2. * h);
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            dP[a][b][c][d] = column[a][b];
      }
  return max_abs(dP - A) / max_abs(A);
}



// max |dW/dF - P| / max |P| by central differences of @p energy.
template <int dim>
double
stress_error(const std::function<double(const Tensor<2, dim> &)> &energy,
             const Tensor<2, dim>                                &F,
             const Tensor<2, dim>                                &P)
{
  const double   h = 1e-6;
  Tensor<2, dim> dW;
  for (unsigned int c = 0; c < dim; ++c)
    for (unsigned int d = 0; d < dim; ++d)
      {
        Tensor<2, dim> F_plus = F, F_minus = F;
        F_plus[c][d] += h;
        F_minus[c][d] -= h;
        dW[c][d] = (energy(F_plus) - energy(F_minus)) / (2. * h);
      }
  return max_abs(dW - P) / max_abs(P);
}



template <int dim>
void
check(const std::string &plane)
{
  deallog.push(dim == 2 ? "2-D plane " + plane : "3-D");

  const Parameters::Material parameters = make_parameters(model, plane);
  const std::unique_ptr<Materials::Material<dim>> material =
    Materials::create_material<dim>(parameters);
  const auto *split =
    dynamic_cast<const Materials::IsochoricVolumetricNeoHooke<dim> *>(
      material.get());
  AssertThrow(split != nullptr, ExcInternalError());
  AssertThrow(split->bulk_modulus() == bulk_modulus &&
                split->shear_modulus() == shear,
              ExcInternalError());

  std::mt19937         generator(42);
  const Tensor<2, dim> I = unit_symmetric_tensor<dim>();
  const Tensor<2, dim> F = I + 0.2 * random_tensor<dim>(generator);
  AssertThrow(determinant(F) > 0.2, ExcInternalError());

  Tensor<2, dim> P;
  Tensor<4, dim> A;
  material->evaluate(F, P, A);

  // 1. A = dP/dF and P = dW/dF by central differences.
  print_bound("tangent matches finite differences of P, relative error",
              tangent_error<dim>(
                [&](const Tensor<2, dim> &G) {
                  return material->first_piola_stress(G);
                },
                F,
                A),
              1e-7);
  print_bound("stress matches finite differences of W, relative error",
              stress_error<dim>(
                [&](const Tensor<2, dim> &G) {
                  return material->strain_energy_density(G);
                },
                F,
                P),
              1e-7);
  print_bound("first_piola_stress equals P of evaluate, relative error",
              max_abs(material->first_piola_stress(F) - P) / max_abs(P),
              1e-14);

  // 2. The reference state is stress and energy free.
  {
    Tensor<2, dim> P_0;
    Tensor<4, dim> A_0;
    material->evaluate(I, P_0, A_0);
    print_bound("|P(I)| / mu", max_abs(P_0) / shear, 1e-14);
    print_bound("|sigma(I)| / mu",
                max_abs(material->cauchy_stress(I)) / shear,
                1e-14);
    print_bound("W(I) / mu", material->strain_energy_density(I) / shear, 1e-14);

    // The small strain limit: A(I) is the elasticity tensor of linear
    // elasticity with lambda = K - 2/3 mu (plane strain in 2-D).
    Tensor<4, dim> C;
    const double   lambda = bulk_modulus - 2. / 3. * shear;
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int b = 0; b < dim; ++b)
        for (unsigned int c = 0; c < dim; ++c)
          for (unsigned int d = 0; d < dim; ++d)
            C[a][b][c][d] = (a == b && c == d ? lambda : 0.) +
                            (a == c && b == d ? shear : 0.) +
                            (a == d && b == c ? shear : 0.);
    print_bound("|A(I) - C(lambda = K - 2/3 mu, mu)| / |C|",
                max_abs(A_0 - C) / max_abs(C),
                1e-14);
  }

  // 3. Frame invariance, and sigma = P F^T / J symmetric.
  {
    const Tensor<2, 3> sigma = material->cauchy_stress(F);
    print_bound("|sigma - sigma^T| / |sigma|",
                max_abs(sigma - transpose(sigma)) / max_abs(sigma),
                1e-14);
    const Tensor<2, dim> expected  = P * transpose(F) / determinant(F);
    double               max_error = 0.;
    for (unsigned int a = 0; a < dim; ++a)
      for (unsigned int b = 0; b < dim; ++b)
        max_error = std::max(max_error, std::abs(sigma[a][b] - expected[a][b]));
    print_bound("in-plane sigma - P F^T / J, relative",
                max_error / max_abs(sigma),
                1e-13);

    const Tensor<2, dim> Q = rotation<dim>(0.9);
    print_bound("|Q Q^T - 1|", max_abs(Q * transpose(Q) - I), 1e-15);
    print_bound("|P(QF) - Q P(F)| / |P(F)|",
                max_abs(material->first_piola_stress(Q * F) - Q * P) /
                  max_abs(P),
                1e-13);
    print_bound("|W(QF) - W(F)| / W(F)",
                (material->strain_energy_density(Q * F) -
                 material->strain_energy_density(F)) /
                  material->strain_energy_density(F),
                1e-13);
  }

  // 4. The small strain limit: linear elasticity with the same parameters
  // (lambda() = K - 2/3 mu, mu()).
  {
    const std::unique_ptr<Materials::Material<dim>> linear =
      Materials::create_material<dim>(make_parameters("linear elastic", plane));
    const Tensor<2, dim> F_small  = I + 1e-7 * random_tensor<dim>(generator);
    const Tensor<2, dim> P_linear = linear->first_piola_stress(F_small);
    print_bound("small strain: |P - P_linear elastic| / |P_linear elastic|",
                max_abs(material->first_piola_stress(F_small) - P_linear) /
                  max_abs(P_linear),
                1e-6);
  }

  // 5. The split: P_iso + P_vol = P with P_vol = J W_vol'(J) F^-T, and
  // A_iso, P_iso against finite differences.
  {
    const double   J = determinant(F);
    Tensor<2, dim> P_iso;
    Tensor<4, dim> A_iso;
    split->evaluate_isochoric(F, P_iso, A_iso);
    const Tensor<2, dim> P_vol =
      J * split->volumetric_strain_energy_derivative(J) * transpose(invert(F));
    print_bound("|P_iso + J W_vol'(J) F^-T - P| / |P|",
                max_abs(P_iso + P_vol - P) / max_abs(P),
                1e-14);
    print_bound("isochoric_first_piola_stress equals P_iso of "
                "evaluate_isochoric",
                max_abs(split->isochoric_first_piola_stress(F) - P_iso) /
                  max_abs(P_iso),
                1e-15);
    print_bound("|W_iso(F) + W_vol(J) - W(F)| / W(F)",
                (split->isochoric_strain_energy_density(F) +
                 split->volumetric_strain_energy_density(J) -
                 material->strain_energy_density(F)) /
                  material->strain_energy_density(F),
                1e-14);
    print_bound("A_iso matches finite differences of P_iso, relative error",
                tangent_error<dim>(
                  [&](const Tensor<2, dim> &G) {
                    return split->isochoric_first_piola_stress(G);
                  },
                  F,
                  A_iso),
                1e-7);
    print_bound("P_iso matches finite differences of W_iso, relative error",
                stress_error<dim>(
                  [&](const Tensor<2, dim> &G) {
                    return split->isochoric_strain_energy_density(G);
                  },
                  F,
                  P_iso),
                1e-7);
  }

  // 6. An isochoric F (det F = 1): no volumetric part, and the Cauchy stress
  // (3x3, with sigma_33 in plane strain) is deviatoric.
  {
    const Tensor<2, dim> F_iso = F / std::pow(determinant(F), 1. / dim);
    print_bound("|det F_iso - 1|", determinant(F_iso) - 1., 1e-15);
    const Tensor<2, dim> P_iso = material->first_piola_stress(F_iso);
    print_bound("det F = 1: |P - P_iso| / |P|",
                max_abs(P_iso - split->isochoric_first_piola_stress(F_iso)) /
                  max_abs(P_iso),
                1e-14);
    print_bound("det F = 1: |W - W_iso| / W",
                (material->strain_energy_density(F_iso) -
                 split->isochoric_strain_energy_density(F_iso)) /
                  material->strain_energy_density(F_iso),
                1e-14);
    const Tensor<2, 3> sigma = material->cauchy_stress(F_iso);
    print_bound("det F = 1: tr sigma (3x3) / |sigma|",
                trace(sigma) / max_abs(sigma),
                1e-14);
  }

  // 7. A dilatation F = s 1 (s = 1.1). In 3-D b_iso = 1 and the isochoric
  // stress vanishes. In plane strain F = diag(s, s, 1) is no 3-D
  // dilatation: I_1 = 2 s^2 + 1, and P_iso = mu s^(-4/3) (s^2 - 1)/(3 s) 1
  // (balanced by tau_iso,33 = 2 mu s^(-4/3) (1 - s^2)/3).
  {
    const double         s     = 1.1;
    const Tensor<2, dim> F_dil = s * I;
    const Tensor<2, dim> P_iso = split->isochoric_first_piola_stress(F_dil);
    if (dim == 3)
      print_bound("F = s 1: |P_iso| / mu", max_abs(P_iso) / shear, 1e-15);
    else
      {
        const double expected =
          shear * std::pow(s, -4. / 3.) * (s * s - 1.) / (3. * s);
        print_bound("F = s 1: |P_iso - mu s^(-4/3) (s^2 - 1)/(3 s) 1| / mu",
                    max_abs(P_iso - expected * I) / shear,
                    1e-15);
      }
    // Then P = P_iso + K/2 (s^dim - 1/s^dim) s^(dim-1) 1 (J = s^dim).
    const double J = std::pow(s, dim);
    print_bound("F = s 1: |P - P_iso - K/2 (J^2 - 1)/s 1| / |P|",
                max_abs(material->first_piola_stress(F_dil) - P_iso -
                        0.5 * bulk_modulus * (J * J - 1.) / s * I) /
                  max_abs(material->first_piola_stress(F_dil)),
                1e-14);
  }

  // 8. Values computed by hand (rounded to 6 digits), so that a wrong
  // formula that is still a consistent potential is caught: the simple
  // shear F = 1 + 0.3 e_1 (x) e_2 (J = 1, I_1 = 3.09) gives
  // W = mu/2 0.09 = 1.35, P_12 = mu 0.3 = 9, P_11 = -mu I_1/3 F^-T_11 +
  // mu = mu (1 - 1.03) = -0.9, P_21 = -mu I_1/3 F^-T_21 = 0.3 mu 1.03 =
  // 9.27; the stretch F = diag(1.2, 1, 1) gives W below and P_11.
  {
    Tensor<2, dim> F_shear       = I;
    F_shear[0][1]                = 0.3;
    const Tensor<2, dim> P_shear = material->first_piola_stress(F_shear);
    print_rounded("simple shear 0.3: W",
                  material->strain_energy_density(F_shear),
                  6);
    print_rounded("simple shear 0.3: P_11", P_shear[0][0], 6);
    print_rounded("simple shear 0.3: P_12", P_shear[0][1], 6);
    print_rounded("simple shear 0.3: P_21", P_shear[1][0], 6);

    Tensor<2, dim> F_stretch = I;
    F_stretch[0][0]          = 1.2;
    const Tensor<2, 3> sigma = material->cauchy_stress(F_stretch);
    print_rounded("stretch diag(1.2, 1, 1): W",
                  material->strain_energy_density(F_stretch),
                  6);
    print_rounded("stretch diag(1.2, 1, 1): P_11",
                  material->first_piola_stress(F_stretch)[0][0],
                  6);
    print_rounded("stretch diag(1.2, 1, 1): sigma_22", sigma[1][1], 6);
    print_rounded("stretch diag(1.2, 1, 1): sigma_33", sigma[2][2], 6);
  }

  deallog.pop();
}



// W_vol and its derivatives, against central differences and exact values.
void
check_volumetric()
{
  deallog.push("W_vol");
  const std::unique_ptr<Materials::Material<3>> material =
    Materials::create_material<3>(make_parameters(model, "strain"));
  const auto &split =
    dynamic_cast<const Materials::IsochoricVolumetricNeoHooke<3> &>(*material);

  const double h       = 1e-6;
  double       error_1 = 0., error_2 = 0.;
  for (const double Theta : {0.5, 0.9, 1., 1.3, 2.})
    {
      const double d1 = (split.volumetric_strain_energy_density(Theta + h) -
                         split.volumetric_strain_energy_density(Theta - h)) /
                        (2. * h);
      const double d2 = (split.volumetric_strain_energy_derivative(Theta + h) -
                         split.volumetric_strain_energy_derivative(Theta - h)) /
                        (2. * h);
      error_1 =
        std::max(error_1,
                 std::abs(d1 -
                          split.volumetric_strain_energy_derivative(Theta)) /
                   bulk_modulus);
      error_2 = std::max(
        error_2,
        std::abs(d2 - split.volumetric_strain_energy_second_derivative(Theta)) /
          bulk_modulus);
    }
  print_bound("W_vol' matches finite differences of W_vol, error / K",
              error_1,
              1e-8);
  print_bound("W_vol'' matches finite differences of W_vol', error / K",
              error_2,
              1e-8);
  print_bound("W_vol(1) / K",
              split.volumetric_strain_energy_density(1.) / bulk_modulus,
              1e-16);
  print_bound("W_vol'(1) / K",
              split.volumetric_strain_energy_derivative(1.) / bulk_modulus,
              1e-16);
  // Exact: W_vol''(1) = K; W_vol'(2) = K/2 (2 - 1/2) = 0.75 K;
  // W_vol(2) = K/4 (3 - 2 ln 2) = 0.403426 K.
  print_rounded("W_vol''(1) / K",
                split.volumetric_strain_energy_second_derivative(1.) /
                  bulk_modulus,
                6);
  print_rounded("W_vol'(2) / K",
                split.volumetric_strain_energy_derivative(2.) / bulk_modulus,
                6);
  print_rounded("W_vol(2) / K",
                split.volumetric_strain_energy_density(2.) / bulk_modulus,
                6);
  deallog.pop();
}



// Call @p f and print the message of the exception it throws.
void
print_exception(const std::string &name, const std::function<void()> &f)
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



// subsection Material with @p entries, declared and parsed as pg_solve does.
Parameters::Material
parse(const std::string &entries)
{
  ParameterHandler prm;
  Parameters::Material::declare_parameters(prm);
  prm.parse_input_from_string("subsection Material\n" + entries + "end\n");
  Parameters::Material parameters;
  parameters.parse_parameters(prm);
  return parameters;
}



void
check_parameters()
{
  deallog.push("parameters");
  {
    const Parameters::Material p = parse("");
    AssertThrow(!p.bulk_modulus && !p.shear_modulus, ExcInternalError());
    deallog << "defaults: E = " << p.youngs_modulus
            << ", nu = " << p.poissons_ratio << ", no K and mu" << std::endl;
    // E = 1, nu = 0.3: lambda = 0.3 / (1.3 0.4), mu = 1 / 2.6.
    print_rounded("defaults: lambda", p.lambda(), 10);
    print_rounded("defaults: mu", p.mu(), 10);
  }
  {
    const Parameters::Material p =
      parse("  set Model = " + model +
            "\n  set Bulk modulus = 100\n  set Shear modulus = 30\n");
    AssertThrow(p.bulk_modulus && *p.bulk_modulus == 100. && p.shear_modulus &&
                  *p.shear_modulus == 30.,
                ExcInternalError());
    // lambda = K - 2/3 mu = 80, E = 9 K mu / (3 K + mu) = 27000/330,
    // nu = (3 K - 2 mu) / (2 (3 K + mu)) = 240/660.
    print_bound("K = 100, mu = 30: |lambda() - 80| / 80",
                (p.lambda() - 80.) / 80.,
                1e-15);
    print_bound("K = 100, mu = 30: mu() - 30", p.mu() - 30., 0.);
    print_rounded("K = 100, mu = 30: E", p.youngs_modulus, 10);
    print_rounded("K = 100, mu = 30: nu", p.poissons_ratio, 10);

    // The same material given by its E and nu.
    std::ostringstream E_nu;
    E_nu << std::setprecision(17)
         << "  set Young's modulus = " << p.youngs_modulus
         << "\n  set Poisson's ratio = " << p.poissons_ratio << "\n";
    const Parameters::Material q = parse(E_nu.str());
    print_bound("the same by E and nu: |lambda - 80| / 80",
                (q.lambda() - 80.) / 80.,
                1e-14);
    print_bound("the same by E and nu: |mu - 30| / 30",
                (q.mu() - 30.) / 30.,
                1e-14);

    // A nearly incompressible material keeps K exactly.
    const Parameters::Material r =
      parse("  set Bulk modulus = 1e8\n  set Shear modulus = 1\n");
    print_bound("K = 1e8, mu = 1: lambda() + 2/3 mu() - K",
                r.lambda() + 2. / 3. * r.mu() - 1e8,
                0.);
    print_rounded("K = 1e8, mu = 1: nu", r.poissons_ratio, 10);

    // Every material reads them, e.g. linear elastic: E and nu of the pair.
    const std::unique_ptr<Materials::Material<3>> linear =
      Materials::create_material<3>(
        parse("  set Model = linear elastic\n  set Bulk modulus = "
              "100\n  set Shear modulus = 30\n"));
    Tensor<2, 3> F = unit_symmetric_tensor<3>();
    F[0][0] += 1e-3;
    const Tensor<2, 3> sigma = linear->cauchy_stress(F);
    // sigma_11 = (lambda + 2 mu) 1e-3 = 0.14, sigma_22 = lambda 1e-3 = 0.08.
    print_rounded("linear elastic, K = 100, mu = 30, eps_11 = 1e-3: sigma_11",
                  sigma[0][0],
                  10);
    print_rounded("linear elastic, K = 100, mu = 30, eps_11 = 1e-3: sigma_22",
                  sigma[1][1],
                  10);
  }

  print_exception("Bulk modulus alone",
                  []() { parse("  set Bulk modulus = 100\n"); });
  print_exception("Shear modulus alone",
                  []() { parse("  set Shear modulus = 30\n"); });
  print_exception("negative Bulk modulus", []() {
    parse("  set Bulk modulus = -100\n  set Shear modulus = 30\n");
  });
  print_exception("zero Shear modulus", []() {
    parse("  set Bulk modulus = 100\n  set Shear modulus = 0\n");
  });
  print_exception("Bulk modulus not a number", []() {
    parse("  set Bulk modulus = 1e2x\n  set Shear modulus = 30\n");
  });
  print_exception("both pairs", []() {
    parse("  set Young's modulus = 80\n  set Bulk modulus = 100\n"
          "  set Shear modulus = 30\n");
  });
  print_exception("both pairs, Poisson's ratio", []() {
    parse("  set Poisson's ratio = 0.25\n  set Bulk modulus = 100\n"
          "  set Shear modulus = 30\n");
  });
  deallog.pop();
}



int
main()
{
  initlog();

  check<2>("strain");
  check<3>("strain");
  check_volumetric();

  print_exception(model + " at J < 0", []() {
    Tensor<2, 2> F;
    F[0][0] = -0.5;
    F[1][1] = 1.;
    Materials::create_material<2>(make_parameters(model, "strain"))
      ->first_piola_stress(F);
  });
  print_exception(model + " at Theta = 0", []() {
    dynamic_cast<const Materials::IsochoricVolumetricNeoHooke<3> &>(
      *Materials::create_material<3>(make_parameters(model, "strain")))
      .volumetric_strain_energy_derivative(0.);
  });
  print_exception(model + " in plane stress", []() {
    Materials::create_material<2>(make_parameters(model, "stress"));
  });

  check_parameters();
}
