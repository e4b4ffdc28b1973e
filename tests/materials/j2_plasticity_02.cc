// J2 plasticity (eqs. 2.46-2.54, 4.41) along homogeneous load paths at a
// material point, with the necking material of §7.3.5 (kN, mm):
// * uniaxial tension in 3-D with free lateral faces (the lateral stretches
//   solved by Newton's method with the algorithmic tangent so that
//   P_22 = P_33 = 0): the Kirchhoff stress tau_11 = J sigma_11 equals
//   sigma_y(alpha) at every plastic step (the closed form of uniaxial
//   stress: sigma_vM = tau_11), the Newton iterations converge
//   quadratically, and the Cauchy stress differs from tau_11 by J - 1;
// * elastic unloading to zero stress: the residual stretch is exp(alpha)
//   and the lateral ones exp(-alpha/2) (uniaxial isochoric plastic flow,
//   C_p = diag(e^{2 alpha}, e^{-alpha}, e^{-alpha})), with no change of
//   alpha;
// * simple shear F = 1 + gamma e_1 (x) e_2 in 2-D plane strain and 3-D:
//   alpha and the shear stress grow monotonically, the yield function stays
//   <= 0 (to round-off), tau_12 <= sigma_y / sqrt(3), and the Cauchy stress
//   is symmetric;
// * single large steps from the initial state (simple shear gamma = 0.5, 2,
//   5 and uniaxial stretch 2, 6), also for perfect plasticity: the local
//   Newton iteration converges and ends on the yield surface.

#include <pg/materials/j2_plasticity.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include "../tests.h"
#include "necking_material.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <utility>
#include <vector>

using namespace pg;

constexpr unsigned int n_state = Materials::J2Plasticity<3>::n_state;
using State                    = std::vector<double>;



std::string
fixed(const double value, const int digits)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << value;
  return s.str();
}



/**
 * Solve P_rr(F) = 0 for the diagonal entries F_rr, r in @p free, of a
 * diagonal F (the other entries fixed) from @p committed, by Newton's method
 * with the algorithmic tangent. Returns the trial state; @p worst_rate is
 * the largest r_{k+1} / r_k^2 (times sigma_y0) seen while r_k > 1e-9.
 */
State
solve_free(const Materials::J2Plasticity<3> &material,
           Tensor<2, 3>                     &F,
           const std::vector<unsigned int>  &free,
           const State                      &committed,
           double                           &worst_rate,
           unsigned int                     &iterations)
{
  const double sigma_y0 = 0.45;
  State        trial(n_state);
  double       previous = -1.;
  for (iterations = 0; iterations < 20; ++iterations)
    {
      Tensor<2, 3> P;
      Tensor<4, 3> A;
      material.evaluate_with_state(F,
                                   make_array_view(committed),
                                   make_array_view(trial),
                                   P,
                                   &A);
      double r = 0.;
      for (const unsigned int i : free)
        r = std::max(r, std::abs(P[i][i]));
      if (previous > 1e-9 * sigma_y0)
        worst_rate = std::max(worst_rate, r * sigma_y0 / (previous * previous));
      previous = r;
      if (r <= 1e-13 * sigma_y0)
        return trial;

      // J dF = -P on the free diagonal entries.
      const unsigned int n = free.size();
      FullMatrix<double> K(n, n);
      Vector<double>     rhs(n), dF(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          rhs[i] = -P[free[i]][free[i]];
          for (unsigned int j = 0; j < n; ++j)
            K(i, j) = A[free[i]][free[i]][free[j]][free[j]];
        }
      K.gauss_jordan();
      K.vmult(dF, rhs);
      for (unsigned int i = 0; i < n; ++i)
        F[free[i]][free[i]] += dF[i];
    }
  AssertThrow(false, ExcMessage("The lateral Newton iteration failed."));
  return trial;
}



void
uniaxial_tension()
{
  deallog.push("uniaxial tension, 3-D");
  const Materials::J2Plasticity<3> material(necking_material());
  State                            committed(n_state);
  material.initialize_state(make_array_view(committed));

  // Four elastic steps, first yield at 0.25 %, then steps of 1 % to 30 %.
  std::vector<double> stretches = {1.0005, 1.001, 1.0015, 1.002, 1.0025};
  for (unsigned int k = 1; k <= 30; ++k)
    stretches.push_back(1. + 0.01 * k);

  Tensor<2, 3> F           = unit_symmetric_tensor<3>();
  double       worst_yield = 0., worst_rate = 0., worst_cauchy = 0.;
  unsigned int n_plastic = 0, n_elastic = 0, max_iterations = 0;
  deallog << "stretch  alpha  tau_11  sigma_11  J  yield" << std::endl;
  for (unsigned int step = 0; step < stretches.size(); ++step)
    {
      F[0][0] = stretches[step];
      unsigned int iterations;
      const State  trial =
        solve_free(material, F, {1, 2}, committed, worst_rate, iterations);
      max_iterations = std::max(max_iterations, iterations);
      committed      = trial;

      const double       J = determinant(F);
      const Tensor<2, 3> sigma =
        material.cauchy_stress_with_state(F,
                                          make_array_view(
                                            std::as_const(committed)));
      const double tau_11 = J * sigma[0][0];
      const double alpha  = committed[Materials::J2Plasticity<3>::alpha_index];
      const bool   plastic =
        committed[Materials::J2Plasticity<3>::yield_flag_index] == 1.;
      if (plastic)
        {
          ++n_plastic;
          worst_yield =
            std::max(worst_yield,
                     std::abs(tau_11 - material.yield_stress(alpha)) /
                       material.yield_stress(alpha));
          // sigma_11 = tau_11 / J: the Cauchy stress differs by J - 1.
          worst_cauchy =
            std::max(worst_cauchy, std::abs(sigma[0][0] / tau_11 - 1. / J));
        }
      else
        ++n_elastic;
      if (step < 6 || (step + 1) % 5 == 0)
        deallog << fixed(stretches[step], 4) << "  " << fixed(alpha, 6) << "  "
                << fixed(tau_11, 6) << "  " << fixed(sigma[0][0], 6) << "  "
                << fixed(J, 6) << "  " << (plastic ? 1 : 0) << std::endl;
    }
  deallog << "elastic steps: " << n_elastic << ", plastic steps: " << n_plastic
          << std::endl;
  print_bound("every plastic step: |tau_11 - sigma_y(alpha)| / sigma_y",
              worst_yield,
              1e-8);
  print_bound("every plastic step: |sigma_11 / tau_11 - 1 / J|",
              worst_cauchy,
              1e-14);
  deallog << "lateral Newton: quadratic (r_k+1 <= 1e3 r_k^2 / sigma_y0): "
          << (worst_rate <= 1e3 ? "yes" : "NO") << ", at most "
          << (max_iterations <= 5 ? "5" : "NO: more than 5")
          << " iterations per step" << std::endl;

  // Unload to zero stress: P_11 = P_22 = P_33 = 0, elastic.
  const double alpha = committed[Materials::J2Plasticity<3>::alpha_index];
  unsigned int iterations;
  const State  unloaded =
    solve_free(material, F, {0, 1, 2}, committed, worst_rate, iterations);
  deallog << "unloaded: elastic: "
          << (unloaded[Materials::J2Plasticity<3>::yield_flag_index] == 0. &&
                  unloaded[Materials::J2Plasticity<3>::alpha_index] == alpha ?
                "yes" :
                "NO")
          << ", alpha = " << fixed(alpha, 6)
          << ", residual stretch = " << fixed(F[0][0], 6) << std::endl;
  print_bound("unloaded: |lambda_1 - exp(alpha)| / exp(alpha)",
              (F[0][0] - std::exp(alpha)) / std::exp(alpha),
              1e-8);
  print_bound("unloaded: |lambda_2,3 - exp(-alpha/2)| / exp(-alpha/2)",
              std::max(std::abs(F[1][1] - std::exp(-alpha / 2.)),
                       std::abs(F[2][2] - std::exp(-alpha / 2.))) /
                std::exp(-alpha / 2.),
              1e-8);
  deallog.pop();
}



template <int dim>
void
simple_shear()
{
  deallog.push(dim == 2 ? "simple shear, 2-D plane strain" :
                          "simple shear, 3-D");
  const Materials::J2Plasticity<dim> material(necking_material());
  State                              committed(n_state), trial(n_state);
  material.initialize_state(make_array_view(committed));

  double       previous_alpha = 0., previous_shear = 0.;
  bool         monotone    = true;
  double       worst_yield = 0., worst_shear = 0., worst_symmetry = 0.;
  unsigned int n_plastic = 0;
  deallog << "gamma  alpha  sigma_12  sigma_vM / sigma_y" << std::endl;
  for (unsigned int step = 1; step <= 100; ++step)
    {
      const double   gamma = 0.01 * step;
      Tensor<2, dim> F     = unit_symmetric_tensor<dim>();
      F[0][1]              = gamma;
      Tensor<2, dim> P;
      material.evaluate_with_state(F,
                                   make_array_view(committed),
                                   make_array_view(trial),
                                   P,
                                   nullptr);
      committed = trial;
      n_plastic += (committed[7] == 1. ? 1 : 0);

      const Tensor<2, 3> sigma =
        material.cauchy_stress_with_state(F,
                                          make_array_view(
                                            std::as_const(committed)));
      const double alpha   = committed[6];
      const double sigma_y = material.yield_stress(alpha);
      const double f =
        material.yield_function(F, make_array_view(std::as_const(committed)));
      worst_yield = std::max(worst_yield, f / sigma_y);
      // J = 1: tau = sigma.
      worst_shear =
        std::max(worst_shear, sigma[0][1] / (sigma_y / std::sqrt(3.)) - 1.);
      double asymmetry = 0., size = 0.;
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = 0; b < 3; ++b)
          {
            asymmetry =
              std::max(asymmetry, std::abs(sigma[a][b] - sigma[b][a]));
            size = std::max(size, std::abs(sigma[a][b]));
          }
      worst_symmetry = std::max(worst_symmetry, asymmetry / size);
      monotone =
        monotone && alpha >= previous_alpha && sigma[0][1] > previous_shear;
      previous_alpha = alpha;
      previous_shear = sigma[0][1];
      if (step % 20 == 0 || step == 1)
        deallog << fixed(gamma, 2) << "  " << fixed(alpha, 6) << "  "
                << fixed(sigma[0][1], 6) << "  "
                << fixed((f + sigma_y) / sigma_y, 6) << std::endl;
    }
  deallog << "plastic steps: " << n_plastic << " of 100" << std::endl;
  deallog << "alpha and sigma_12 grow monotonically: "
          << (monotone ? "yes" : "NO") << std::endl;
  print_bound("max f / sigma_y (f <= 0 up to round-off)",
              std::max(worst_yield, 0.),
              1e-11);
  print_bound("max sigma_12 / (sigma_y / sqrt 3) - 1 (bounded)",
              std::max(worst_shear, 0.),
              1e-11);
  print_bound("max |sigma - sigma^T| / |sigma|", worst_symmetry, 1e-14);
  deallog.pop();
}



void
large_steps()
{
  deallog.push("single large steps");
  Parameters::Material perfect     = necking_material();
  perfect.saturation_yield_stress  = perfect.initial_yield_stress;
  perfect.linear_hardening_modulus = 0.;
  perfect.saturation_exponent      = 0.;
  for (const Parameters::Material &parameters : {necking_material(), perfect})
    {
      const Materials::J2Plasticity<3> material(parameters);
      State                            initial(n_state), trial(n_state);
      material.initialize_state(make_array_view(initial));
      double       worst     = 0.;
      unsigned int n_plastic = 0;
      for (const double g : {0.5, 2., 5.})
        for (const bool shear : {true, false})
          {
            Tensor<2, 3> F = unit_symmetric_tensor<3>();
            if (shear)
              F[0][1] = g;
            else
              {
                F[0][0] = 1. + g;
                F[1][1] = F[2][2] = 1. / std::sqrt(1. + g);
              }
            Tensor<2, 3> P;
            Tensor<4, 3> A;
            material.evaluate_with_state(F,
                                         make_array_view(
                                           std::as_const(initial)),
                                         make_array_view(trial),
                                         P,
                                         &A);
            n_plastic += (trial[7] == 1. ? 1 : 0);
            worst = std::max(worst,
                             std::abs(material.yield_function(
                               F,
                               make_array_view(std::as_const(trial)))) /
                               material.yield_stress(trial[6]));
          }
      deallog << (parameters.linear_hardening_modulus > 0. ? "hardening" :
                                                             "perfect")
              << ": plastic " << n_plastic << " of 6" << std::endl;
      print_bound("|f| / sigma_y", worst, 1e-12);
    }
  deallog.pop();
}



int
main()
{
  initlog();
  uniaxial_tension();
  simple_shear<2>();
  simple_shear<3>();
  large_steps();
}
