// J2 plasticity (eqs. 2.46-2.54, 4.41, 4.62) at a material point, 2-D plane
// strain and 3-D, with the necking material of §7.3.5: the algorithmic
// tangent A = dP/dF against central finite differences of P (at fixed
// committed state) in the elastic range, at first yield, in further
// hardening and in elastic unloading, for a uniaxial F (two equal principal
// stretches) and a general F (rotation and shear); the isochoric split
// (evaluate_isochoric_with_state + the volumetric part = evaluate_with_state,
// and A_iso against differences); the state contract (two evaluations are
// identical, the trial state depends on (F, committed) only, the P-only
// path equals the tangent path); the elastic range equals the
// isochoric-volumetric neo-Hooke; the plastic update keeps det C_p^{-1} = 1
// and ends on the yield surface; and the error messages.

#include <pg/materials/isochoric_volumetric_neo_hooke.h>
#include <pg/materials/j2_plasticity.h>
#include <pg/materials/material.h>

#include "../tests.h"
#include "necking_material.h"
#include "tensor_tools.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

using namespace pg;

constexpr unsigned int n_state = Materials::J2Plasticity<3>::n_state;
using State                    = std::vector<double>;



bool
bitwise_equal(const State &a, const State &b)
{
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}



template <int dim>
bool
bitwise_equal(const Tensor<2, dim> &a, const Tensor<2, dim> &b)
{
  return std::memcmp(&a, &b, sizeof(a)) == 0;
}



template <int dim>
bool
bitwise_equal(const Tensor<4, dim> &a, const Tensor<4, dim> &b)
{
  return std::memcmp(&a, &b, sizeof(a)) == 0;
}



/** The initial state. */
template <int dim>
State
initial_state(const Materials::J2Plasticity<dim> &material)
{
  State state(n_state);
  material.initialize_state(make_array_view(state));
  return state;
}



/** Tensor<4, dim> in a non-deduced context (so that nullptr binds). */
template <int dim>
struct TangentType
{
  using type = Tensor<4, dim>;
};



/** P, A and the trial state at F from @p committed. */
template <int dim>
State
evaluate(const Materials::J2Plasticity<dim> &material,
         const Tensor<2, dim>               &F,
         const State                        &committed,
         Tensor<2, dim>                     &P,
         typename TangentType<dim>::type    *A,
         const bool                          isochoric = false)
{
  State trial(n_state, std::numeric_limits<double>::quiet_NaN());
  if (isochoric)
    material.evaluate_isochoric_with_state(F,
                                           make_array_view(committed),
                                           make_array_view(trial),
                                           P,
                                           A);
  else
    material.evaluate_with_state(F,
                                 make_array_view(committed),
                                 make_array_view(trial),
                                 P,
                                 A);
  return trial;
}



/**
 * max |A - A_FD| / max |A| with central differences of P (step h) at fixed
 * @p committed.
 */
template <int dim>
double
tangent_error(const Materials::J2Plasticity<dim> &material,
              const Tensor<2, dim>               &F,
              const State                        &committed,
              const bool                          isochoric)
{
  Tensor<2, dim> P;
  Tensor<4, dim> A;
  evaluate(material, F, committed, P, &A, isochoric);
  const double   h = 1e-6;
  Tensor<4, dim> A_fd;
  for (unsigned int c = 0; c < dim; ++c)
    for (unsigned int d = 0; d < dim; ++d)
      {
        Tensor<2, dim> F_plus = F, F_minus = F, P_plus, P_minus;
        F_plus[c][d] += h;
        F_minus[c][d] -= h;
        evaluate(material, F_plus, committed, P_plus, nullptr, isochoric);
        evaluate(material, F_minus, committed, P_minus, nullptr, isochoric);
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            A_fd[a][b][c][d] = (P_plus[a][b] - P_minus[a][b]) / (2. * h);
      }
  return max_abs(Tensor<4, dim>(A - A_fd)) / max_abs(A);
}



/** max |A_ABCD - A_CDAB| / max |A|. */
template <int dim>
double
major_asymmetry(const Tensor<4, dim> &A)
{
  double m = 0.;
  for (unsigned int a = 0; a < dim; ++a)
    for (unsigned int b = 0; b < dim; ++b)
      for (unsigned int c = 0; c < dim; ++c)
        for (unsigned int d = 0; d < dim; ++d)
          m = std::max(m, std::abs(A[a][b][c][d] - A[c][d][a][b]));
  return m / max_abs(A);
}



/** det C_p^{-1} of a state. */
double
plastic_determinant(const State &s)
{
  Tensor<2, 3>       C;
  const unsigned int row[6]    = {0, 1, 2, 0, 0, 1},
                     column[6] = {0, 1, 2, 1, 2, 2};
  for (unsigned int i = 0; i < 6; ++i)
    C[row[i]][column[i]] = C[column[i]][row[i]] = s[i];
  return determinant(C);
}



template <int dim>
Tensor<2, dim>
uniaxial(const double stretch)
{
  // Lateral contraction nu = 0.29 roughly: in 3-D the two lateral stretches
  // are equal; in 2-D plane strain lambda_2 = 1 = lambda_3.
  Tensor<2, dim> F = unit_symmetric_tensor<dim>();
  F[0][0]          = stretch;
  if (dim == 3)
    F[1][1] = F[2][2] = 1. - 0.45 * (stretch - 1.);
  return F;
}



/** Q (I + g H) with a fixed pseudo-random H (entries in [-1, 1]). */
template <int dim>
Tensor<2, dim>
general(const double g)
{
  std::mt19937   generator(7);
  Tensor<2, dim> H;
  for (unsigned int a = 0; a < dim; ++a)
    for (unsigned int b = 0; b < dim; ++b)
      H[a][b] = 2. * (generator() / 4294967295.) - 1.;
  H[0][1] += 1.; // a dominant shear
  return rotation<dim>(0.7) * (unit_symmetric_tensor<dim>() + g * H);
}



template <int dim>
void
check_tangents()
{
  const std::string name = (dim == 2 ? "2-D plane strain" : "3-D");
  deallog.push(name);
  const Materials::J2Plasticity<dim> material(necking_material());
  const State                        initial = initial_state(material);

  // The load paths: (label, F of step 1, F of step 2, F of step 3), each
  // step from the committed state of the one before; step 3 unloads.
  struct Path
  {
    std::string    label;
    Tensor<2, dim> F[3];
  };
  const std::vector<Path> paths = {
    {"uniaxial",
     {uniaxial<dim>(1.01), uniaxial<dim>(1.03), uniaxial<dim>(1.028)}},
    {"general", {general<dim>(0.01), general<dim>(0.03), general<dim>(0.029)}}};
  // Elastic strains of the same kind.
  const Tensor<2, dim> F_elastic[2] = {uniaxial<dim>(1.001),
                                       general<dim>(0.0004)};

  double worst_error = 0.;
  for (unsigned int i = 0; i < paths.size(); ++i)
    {
      const Path &path = paths[i];
      // Elastic: a small strain from the initial state.
      {
        const Tensor<2, dim> F = F_elastic[i];
        Tensor<2, dim>       P;
        const State          trial = evaluate(material, F, initial, P, nullptr);
        AssertThrow(trial[7] == 0., ExcInternalError());
        const double error = tangent_error(material, F, initial, false);
        worst_error        = std::max(worst_error, error);
        print_bound(path.label + ", elastic: |A - A_FD| / |A|", error, 1e-8);
      }

      State             committed    = initial;
      const std::string step_name[3] = {"first yield",
                                        "further hardening",
                                        "elastic unloading"};
      for (unsigned int step = 0; step < 3; ++step)
        {
          Tensor<2, dim> P;
          Tensor<4, dim> A;
          const State    trial =
            evaluate(material, path.F[step], committed, P, &A);
          const bool plastic = (trial[7] == 1.);
          AssertThrow(plastic == (step < 2), ExcInternalError());
          const double error =
            tangent_error(material, path.F[step], committed, false);
          worst_error = std::max(worst_error, error);
          print_bound(path.label + ", " + step_name[step] +
                        ": |A - A_FD| / |A|",
                      error,
                      1e-8);
          if (plastic)
            {
              // On the yield surface, with det C_p^{-1} = 1.
              const double f =
                material.yield_function(path.F[step], make_array_view(trial));
              print_bound(path.label + ", " + step_name[step] +
                            ": |f| / sigma_y",
                          f / material.yield_stress(trial[6]),
                          1e-12);
              print_bound(path.label + ", " + step_name[step] +
                            ": |det C_p^-1 - 1|",
                          plastic_determinant(trial) - 1.,
                          1e-13);
              deallog << path.label << ", " << step_name[step]
                      << ": Delta alpha > 0: "
                      << (trial[6] > committed[6] ? "yes" : "NO")
                      << ", A major-symmetric (to 1e-12): "
                      << (major_asymmetry(A) <= 1e-12 ? "yes" : "NO")
                      << std::endl;
            }
          else
            AssertThrow(bitwise_equal(State(trial.begin(), trial.begin() + 7),
                                      State(committed.begin(),
                                            committed.begin() + 7)),
                        ExcInternalError());
          committed = trial;
        }
    }
  deallog << "largest FD tangent error < 1e-9: "
          << (worst_error < 1e-9 ? "yes" : "no") << std::endl;
  deallog.pop();
}



template <int dim>
void
check_split_and_contract()
{
  const std::string name = (dim == 2 ? "2-D plane strain" : "3-D");
  deallog.push(name);
  const Materials::J2Plasticity<dim> material(necking_material());
  const State                        initial = initial_state(material);

  // A plastic state from a general F, then a further plastic step.
  Tensor<2, dim> P0;
  const State    committed =
    evaluate(material, general<dim>(0.02), initial, P0, nullptr);
  const Tensor<2, dim> F = general<dim>(0.035);

  Tensor<2, dim> P, P_iso;
  Tensor<4, dim> A, A_iso;
  const State    trial  = evaluate(material, F, committed, P, &A);
  const State trial_iso = evaluate(material, F, committed, P_iso, &A_iso, true);
  AssertThrow(trial[7] == 1., ExcInternalError());

  // The volumetric part of the isochoric-volumetric split:
  // P_vol = J W_vol'(J) F^-T, A_vol = d P_vol / dF.
  const double         J    = determinant(F);
  const Tensor<2, dim> Finv = invert(F);
  const double         p    = material.volumetric_strain_energy_derivative(J);
  const double   ddW   = material.volumetric_strain_energy_second_derivative(J);
  Tensor<2, dim> P_sum = P_iso;
  Tensor<4, dim> A_sum = A_iso;
  for (unsigned int a = 0; a < dim; ++a)
    for (unsigned int b = 0; b < dim; ++b)
      {
        P_sum[a][b] += J * p * Finv[b][a];
        for (unsigned int c = 0; c < dim; ++c)
          for (unsigned int d = 0; d < dim; ++d)
            A_sum[a][b][c][d] +=
              (J * p + J * J * ddW) * Finv[b][a] * Finv[d][c] -
              J * p * Finv[b][c] * Finv[d][a];
      }
  print_bound("split: |P_iso + P_vol - P| / |P|",
              max_abs(Tensor<2, dim>(P_sum - P)) / max_abs(P),
              1e-13);
  print_bound("split: |A_iso + A_vol - A| / |A|",
              max_abs(Tensor<4, dim>(A_sum - A)) / max_abs(A),
              1e-12);
  deallog << "split: the same trial state: "
          << (bitwise_equal(trial, trial_iso) ? "yes" : "NO") << std::endl;
  print_bound("split: plastic step, |A_iso - A_iso,FD| / |A_iso|",
              tangent_error(material, F, committed, true),
              1e-8);
  print_bound("split: elastic, |A_iso - A_iso,FD| / |A_iso|",
              tangent_error(material, general<dim>(0.0004), initial, true),
              1e-8);

  // The state contract: twice the same (bitwise), whatever the trial slice
  // held before; the P-only path equals the tangent path.
  {
    Tensor<2, dim> P2;
    Tensor<4, dim> A2;
    State          trial2(n_state, 12345.);
    material.evaluate_with_state(F,
                                 make_array_view(committed),
                                 make_array_view(trial2),
                                 P2,
                                 &A2);
    deallog << "contract: second evaluation identical (P, A, trial state): "
            << (bitwise_equal(P, P2) && bitwise_equal(A, A2) &&
                    bitwise_equal(trial, trial2) ?
                  "yes" :
                  "NO")
            << std::endl;
    Tensor<2, dim> P3;
    const State    trial3 = evaluate(material, F, committed, P3, nullptr);
    print_bound("contract: |P(no tangent) - P| / |P|",
                max_abs(Tensor<2, dim>(P3 - P)) / max_abs(P),
                1e-14);
    double state_difference = 0.;
    for (unsigned int i = 0; i < n_state; ++i)
      state_difference =
        std::max(state_difference, std::abs(trial3[i] - trial[i]));
    print_bound("contract: |trial(no tangent) - trial|",
                state_difference,
                1e-14);
  }

  // The elastic range is the isochoric-volumetric neo-Hooke.
  {
    Parameters::Material parameters = necking_material();
    parameters.model                = "isochoric-volumetric neo-Hooke";
    const Materials::IsochoricVolumetricNeoHooke<dim> neo_hooke(parameters);
    const Tensor<2, dim> F_e = general<dim>(0.0004);
    Tensor<2, dim>       P_j2, P_nh;
    Tensor<4, dim>       A_j2, A_nh;
    material.evaluate(F_e, P_j2, A_j2);
    neo_hooke.evaluate(F_e, P_nh, A_nh);
    const double mu = material.shear_modulus();
    print_bound("elastic range = isochoric-volumetric neo-Hooke: |dP| / mu",
                max_abs(Tensor<2, dim>(P_j2 - P_nh)) / mu,
                1e-14);
    print_bound("elastic range = isochoric-volumetric neo-Hooke: |dA| / mu",
                max_abs(Tensor<4, dim>(A_j2 - A_nh)) / mu,
                1e-14);
    const Tensor<2, 3> sigma_j2 = material.cauchy_stress(F_e);
    const Tensor<2, 3> sigma_nh = neo_hooke.cauchy_stress(F_e);
    print_bound("elastic range: |sigma - sigma_neo-Hooke| / mu",
                max_abs(Tensor<2, 3>(sigma_j2 - sigma_nh)) / mu,
                1e-14);
  }

  // The outputs.
  {
    std::vector<double> values(2);
    material.state_outputs(make_array_view(trial), make_array_view(values));
    const std::vector<std::string> names = material.state_output_names();
    deallog << "outputs: " << names[0]
            << " = alpha: " << (values[0] == trial[6] ? "yes" : "NO") << ", "
            << names[1] << " = " << values[1] << std::endl;
  }
  deallog.pop();
}



void
check_errors()
{
  const auto message = [](const Parameters::Material &parameters) {
    try
      {
        Materials::create_material<2>(parameters);
      }
    catch (const ExceptionBase &e)
      {
        return exception_message(e);
      }
    return std::string("no error");
  };
  Parameters::Material parameters = necking_material();
  parameters.plane                = "stress";
  deallog << "plane stress: " << message(parameters) << std::endl;

  parameters                      = necking_material();
  parameters.initial_yield_stress = 0.;
  deallog << "sigma_y0 = 0: " << message(parameters) << std::endl;
  parameters                         = necking_material();
  parameters.saturation_yield_stress = 0.4;
  deallog << "sigma_yinf < sigma_y0: " << message(parameters) << std::endl;
  parameters                          = necking_material();
  parameters.linear_hardening_modulus = -0.1;
  deallog << "H < 0: " << message(parameters) << std::endl;
  parameters                     = necking_material();
  parameters.saturation_exponent = -1.;
  deallog << "delta < 0: " << message(parameters) << std::endl;
}



int
main()
{
  initlog();
  check_tangents<2>();
  check_tangents<3>();
  check_split_and_contract<2>();
  check_split_and_contract<3>();
  check_errors();
}
