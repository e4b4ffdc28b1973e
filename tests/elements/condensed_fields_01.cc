// The condensed fields as Newton iterates (CondensedFieldIterate,
// pg-methods.md section 12.2: the local update after each global solve):
// - at local equilibrium the iterate gives the closed form's residual and
//   tangent (P0 and P1);
// - away from it (Theta and p perturbed), for P0: the kernel's residual and
//   tangent are the static condensation of the three-field (u, p, Theta)
//   system, and update_condensed_fields() is its local update. The three
//   residuals
//     R_u = sum_q w_q P_iso(F_q) T^q + sum_{q in vol} w_q p dtheta/dF T^q,
//     R_p = sum_{q in vol} w_q (theta_q - Theta),
//     R_Theta = W (W_vol'(Theta) - p)
//   are written here with add_stress_residual(), their Jacobian is taken
//   by central differences, and the condensation is done densely;
// for the isochoric-volumetric neo-Hooke at nu = 0.4999, on an interior and
// a corner family of a distorted particle set (BCPBG UnlP0, BCPPG UnlP0,
// PBG U2P1) and on Q1P0 / H1P0 cells, in 2-D and 3-D.

#include <pg/elements/condensed_pressure.h>
#include <pg/materials/material.h>

#include <deal.II/lac/full_matrix.h>

#include "../tests.h"
#include "mixed_elements.h"

using namespace pg;

struct Errors
{
  double equilibrium = 0; // |closed form - iterate at equilibrium|
  double residual    = 0; // |r - condensed three-field r| / |r|
  double tangent     = 0; // |K - condensed three-field K| / |K|
  double update      = 0; // |local update - three-field update| / |update|

  void
  max(const Errors &e)
  {
    equilibrium = std::max(equilibrium, e.equilibrium);
    residual    = std::max(residual, e.residual);
    tangent     = std::max(tangent, e.tangent);
    update      = std::max(update, e.update);
  }
};



double
relative_difference(const FullMatrix<double> &A, const FullMatrix<double> &B)
{
  FullMatrix<double> D(A);
  D.add(-1., B);
  return D.linfty_norm() / std::max(B.linfty_norm(), 1e-300);
}



double
relative_difference(const Vector<double> &a, const Vector<double> &b)
{
  Vector<double> d(a);
  d -= b;
  return d.linfty_norm() / std::max(b.linfty_norm(), 1e-300);
}



/**
 * The three residuals (R_u, R_p, R_Theta) of a P0 element, stacked, at the
 * nodal positions @p y and the fields @p Theta, @p p.
 */
template <int dim>
Vector<double>
three_field_residual(const QuadratureTable<dim>            &table,
                     const QuadratureTable<dim>            &volumetric,
                     const std::vector<Tensor<1, dim>>     &y,
                     const double                           Theta,
                     const double                           p,
                     const Materials::VolumetricSplit<dim> &split)
{
  const unsigned int          n = y.size();
  std::vector<Tensor<1, dim>> d(n);
  add_stress_residual<dim>(
    table,
    [&](const unsigned int q) {
      return split.isochoric_first_piola_stress(
        deformation_gradient(table, q, y));
    },
    d);
  add_stress_residual<dim>(
    volumetric,
    [&](const unsigned int q) {
      return p * split.volume_measure_derivative(
                   deformation_gradient(volumetric, q, y));
    },
    d);
  Vector<double> R(n * dim + 2);
  for (unsigned int a = 0; a < n; ++a)
    for (unsigned int c = 0; c < dim; ++c)
      R[a * dim + c] = d[a][c];
  double W = 0;
  for (unsigned int q = 0; q < volumetric.n_points(); ++q)
    {
      W += volumetric.weights[q];
      R[n * dim] +=
        volumetric.weights[q] *
        (split.volume_measure(deformation_gradient(volumetric, q, y)) - Theta);
    }
  R[n * dim + 1] = W * (split.volumetric_strain_energy_derivative(Theta) - p);
  return R;
}



template <int dim>
Errors
check_element(const QuadratureTable<dim>            &table,
              const QuadratureTable<dim>            *volumetric,
              const std::vector<Tensor<1, dim>>     &X,
              const Materials::VolumetricSplit<dim> &split,
              const double                           mu,
              const double                           h,
              std::mt19937                          &rng,
              const unsigned int                     degree)
{
  std::uniform_real_distribution<double> random(-1., 1.);
  const unsigned int                     n  = X.size();
  const unsigned int                     nu = n * dim;
  std::vector<Tensor<1, dim>>            y(X);
  for (auto &v : y)
    for (unsigned int c = 0; c < dim; ++c)
      v[c] += 0.05 * h * random(rng);
  Errors errors;

  // equilibrium: the iterate's first assembly is the closed form
  Vector<double>        r_closed, r;
  FullMatrix<double>    K_closed, K;
  CondensedFieldIterate iterate;
  assemble_condensed_pressure_element(table,
                                      volumetric,
                                      y,
                                      split,
                                      r_closed,
                                      &K_closed,
                                      degree);
  assemble_condensed_pressure_element(table,
                                      volumetric,
                                      y,
                                      split,
                                      r,
                                      &K,
                                      degree,
                                      &iterate);
  errors.equilibrium = std::max(relative_difference(r, r_closed),
                                relative_difference(K, K_closed));
  // ... and stays so at the same displacement
  assemble_condensed_pressure_element(table,
                                      volumetric,
                                      y,
                                      split,
                                      r,
                                      &K,
                                      degree,
                                      &iterate);
  errors.equilibrium = std::max({errors.equilibrium,
                                 relative_difference(r, r_closed),
                                 relative_difference(K, K_closed)});
  if (degree > 0)
    return errors;

  // away from equilibrium
  const double Theta = iterate.dilatation[0] + 1e-3 * random(rng);
  const double p     = iterate.pressure[0] + mu * random(rng);
  iterate.dilatation = {Theta};
  iterate.pressure   = {p};
  assemble_condensed_pressure_element(table,
                                      volumetric,
                                      y,
                                      split,
                                      r,
                                      &K,
                                      degree,
                                      &iterate);

  const QuadratureTable<dim> &vol = (volumetric ? *volumetric : table);
  const auto                  R =
    [&](const std::vector<Tensor<1, dim>> &at, const double T, const double P) {
      return three_field_residual(table, vol, at, T, P, split);
    };
  const Vector<double> R0 = R(y, Theta, p);
  // the Jacobian of (R_u, R_p, R_Theta) in (u, Theta, p), by columns
  FullMatrix<double> J(nu + 2, nu + 2);
  for (unsigned int j = 0; j < nu + 2; ++j)
    {
      const double   eps = (j < nu ? 1e-6 * h : j == nu ? 1e-8 : 1e-6 * mu);
      Vector<double> plus, minus;
      if (j < nu)
        {
          y[j / dim][j % dim] += eps;
          plus = R(y, Theta, p);
          y[j / dim][j % dim] -= 2 * eps;
          minus = R(y, Theta, p);
          y[j / dim][j % dim] += eps;
        }
      else if (j == nu)
        {
          plus  = R(y, Theta + eps, p);
          minus = R(y, Theta - eps, p);
        }
      else
        {
          plus  = R(y, Theta, p + eps);
          minus = R(y, Theta, p - eps);
        }
      for (unsigned int i = 0; i < nu + 2; ++i)
        J(i, j) = (plus[i] - minus[i]) / (2 * eps);
    }
  // static condensation of (Theta, p)
  FullMatrix<double> K_cc(2, 2), K_uc(nu, 2), K_cu(2, nu), K_uu(nu, nu);
  for (unsigned int i = 0; i < nu + 2; ++i)
    for (unsigned int j = 0; j < nu + 2; ++j)
      {
        if (i < nu && j < nu)
          K_uu(i, j) = J(i, j);
        else if (i < nu)
          K_uc(i, j - nu) = J(i, j);
        else if (j < nu)
          K_cu(i - nu, j) = J(i, j);
        else
          K_cc(i - nu, j - nu) = J(i, j);
      }
  FullMatrix<double> K_cc_inverse(2, 2);
  K_cc_inverse.invert(K_cc);
  FullMatrix<double> C(2, nu), K_condensed(K_uu);
  K_cc_inverse.mmult(C, K_cu);
  FullMatrix<double> K_uc_C(nu, nu);
  K_uc.mmult(K_uc_C, C);
  K_condensed.add(-1., K_uc_C);
  Vector<double> R_c(2), K_inverse_R_c(2), r_condensed(nu);
  R_c[0] = R0[nu];
  R_c[1] = R0[nu + 1];
  K_cc_inverse.vmult(K_inverse_R_c, R_c);
  K_uc.vmult(r_condensed, K_inverse_R_c);
  r_condensed *= -1.;
  for (unsigned int i = 0; i < nu; ++i)
    r_condensed[i] += R0[i];
  errors.residual = relative_difference(r, r_condensed);
  errors.tangent  = relative_difference(K, K_condensed);

  // the local update after an update du: d(Theta, p) = -K_cc^-1 (R_c +
  // K_cu du)
  std::vector<double> du(nu);
  Vector<double>      du_vector(nu), K_cu_du(2), dc(2);
  for (unsigned int i = 0; i < nu; ++i)
    du[i] = du_vector[i] = 0.01 * h * random(rng);
  K_cu.vmult(K_cu_du, du_vector);
  K_cu_du += R_c;
  K_cc_inverse.vmult(dc, K_cu_du);
  dc *= -1.;
  update_condensed_fields(iterate, du);
  Vector<double> dc_kernel(2);
  dc_kernel[0]  = iterate.dilatation[0] - Theta;
  dc_kernel[1]  = iterate.pressure[0] - p;
  errors.update = std::max(std::abs(dc_kernel[0] - dc[0]) / std::abs(dc[0]),
                           std::abs(dc_kernel[1] - dc[1]) / std::abs(dc[1]));
  return errors;
}



template <int dim>
void
test()
{
  const ParticleFixture<dim> fixture(dim == 2 ? 6 : 4,
                                     0.25,
                                     dim == 2 ? 2.51 : 2.01);
  const double h = 1. / (dim == 2 ? 6 : 4);
  std::mt19937 rng(11);

  Parameters::Material parameters;
  parameters.model          = "isochoric-volumetric neo-Hooke";
  parameters.youngs_modulus = 100.;
  parameters.poissons_ratio = 0.4999;
  parameters.density        = 1.;
  parameters.plane          = "strain";
  const auto  material      = Materials::create_material<dim>(parameters);
  const auto &split =
    dynamic_cast<const Materials::VolumetricSplit<dim> &>(*material);
  const double mu = parameters.mu();

  const auto report = [&](const std::string &name, const Errors &worst) {
    deallog << dim << "d " << name << ": at equilibrium = closed form: "
            << verdict(worst.equilibrium, 1e-12);
    if (name.find("U2P1") == std::string::npos)
      deallog << ", r = condensed: " << verdict(worst.residual, 1e-6)
              << ", K = condensed: " << verdict(worst.tangent, 1e-6)
              << ", local update: " << verdict(worst.update, 1e-6);
    deallog << std::endl;
  };

  Errors worst;
  for_each_mixed_element<dim>(
    fixture,
    [&](const QuadratureTable<dim>        &table,
        const QuadratureTable<dim>        *volumetric,
        const std::vector<Tensor<1, dim>> &X,
        const unsigned int                 degree) {
      worst.max(check_element(table, volumetric, X, split, mu, h, rng, degree));
    },
    [&](const std::string &element) {
      report(element, worst);
      worst = Errors();
    });
}



int
main()
{
  initlog();
  test<2>();
  test<3>();
}
