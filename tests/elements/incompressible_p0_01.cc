// The IUnlP0 family element of assemble_incompressible_p0_element()
// (pg-methods.md section 12.2.1: Theta = 1, the family pressure p a global
// unknown), for PBG and PPG tables of an interior and a corner family of a
// distorted particle set (and Q1 cells, the same kernel on a cell table),
// in 2-D and 3-D, with the isochoric part of the isochoric-volumetric
// neo-Hooke (theta = J) and of linear elasticity (theta = tr eps):
// - the tangent, (n dim + 1) x (n dim + 1) with the p row and column,
//   agrees with central differences of the residual in u and in p (every
//   element, PPG's non-symmetric one included);
// - PBG (and Q1): the residual is the gradient of
//   Pi = sum_q w_q W_iso(F_q) + p sum_q w_q (theta_q - theta(I)), written
//   out here independently, and the tangent is symmetric;
// - rigid motions at p = 0 give a zero residual (rows u and p);
// - under a homogeneous F with J != 1 and p = W_vol'(J) of a bulk modulus
//   K, the u rows equal the displacement element of the full material
//   with that K (an independent kernel path), and r_p = W (theta - theta(I)).

#include <pg/elements/condensed_pressure.h>
#include <pg/materials/material.h>

#include "../tests.h"
#include "mixed_elements.h"

using namespace pg;

struct Errors
{
  double tangent     = 0;  // |K - FD(r)| / |K|
  double potential   = -1; // |r - FD(Pi)| / |r| (Bubnov-Galerkin only)
  double symmetry    = -1; // |K - K^T| / |K| (Bubnov-Galerkin only)
  double rigid       = 0;  // |r(rigid)| / force scale
  double homogeneous = 0;  // |r_u - r_displacement| / |r|, |r_p - W dtheta|

  void
  max(const Errors &e)
  {
    tangent     = std::max(tangent, e.tangent);
    potential   = std::max(potential, e.potential);
    symmetry    = std::max(symmetry, e.symmetry);
    rigid       = std::max(rigid, e.rigid);
    homogeneous = std::max(homogeneous, e.homogeneous);
  }
};



template <int dim>
double
potential(const QuadratureTable<dim>            &table,
          const std::vector<Tensor<1, dim>>     &y,
          const Materials::VolumetricSplit<dim> &material,
          const double                           p)
{
  const double theta_0 =
    material.volume_measure(Tensor<2, dim>(unit_symmetric_tensor<dim>()));
  double Pi = 0;
  for (unsigned int q = 0; q < table.n_points(); ++q)
    {
      const Tensor<2, dim> F = deformation_gradient(table, q, y);
      Pi += table.weights[q] * (material.isochoric_strain_energy_density(F) +
                                p * (material.volume_measure(F) - theta_0));
    }
  return Pi;
}



/**
 * Checks one element at the relative nodal positions @p X: @p isochoric
 * has K = 0 (the material of IUnlP0), @p full the same mu with a bulk
 * modulus.
 */
template <int dim>
Errors
check_element(const QuadratureTable<dim>            &table,
              const QuadratureTable<dim>            *volumetric,
              const std::vector<Tensor<1, dim>>     &X,
              const Materials::VolumetricSplit<dim> &isochoric,
              const Materials::VolumetricSplit<dim> &full,
              const double                           h,
              const bool                             rotate,
              std::mt19937                          &rng)
{
  std::uniform_real_distribution<double> random(-1., 1.);
  const unsigned int                     n   = X.size();
  const unsigned int                     n_u = n * dim;
  std::vector<Tensor<1, dim>>            y(X);
  for (auto &v : y)
    for (unsigned int c = 0; c < dim; ++c)
      v[c] += 0.05 * h * random(rng);
  double     p        = 3. * random(rng);
  const auto residual = [&](const std::vector<Tensor<1, dim>>     &at,
                            const double                           pressure,
                            const Materials::VolumetricSplit<dim> &material,
                            Vector<double>                        &r,
                            FullMatrix<double>                    *K) {
    return assemble_incompressible_p0_element(table,
                                              volumetric,
                                              at,
                                              material,
                                              pressure,
                                              r,
                                              K);
  };

  Errors             errors;
  Vector<double>     r, rp, rm;
  FullMatrix<double> K;
  residual(y, p, isochoric, r, &K);
  AssertDimension(r.size(), n_u + 1);
  double       scale = 0, r_error = 0;
  const double eps            = 1e-6 * h;
  const auto   compare_column = [&](const unsigned int j, const double step) {
    for (unsigned int i = 0; i <= n_u; ++i)
      {
        const double fd = (rp[i] - rm[i]) / (2 * step);
        errors.tangent  = std::max(errors.tangent, std::abs(fd - K(i, j)));
        scale           = std::max(scale, std::abs(K(i, j)));
      }
  };
  for (unsigned int b = 0; b < n; ++b)
    for (unsigned int c = 0; c < dim; ++c)
      {
        y[b][c] += eps;
        residual(y, p, isochoric, rp, nullptr);
        const double Pi_p = potential(table, y, isochoric, p);
        y[b][c] -= 2 * eps;
        residual(y, p, isochoric, rm, nullptr);
        const double Pi_m = potential(table, y, isochoric, p);
        y[b][c] += eps;
        compare_column(b * dim + c, eps);
        r_error =
          std::max(r_error,
                   std::abs((Pi_p - Pi_m) / (2 * eps) - r[b * dim + c]));
      }
  const double dp = 1e-6;
  residual(y, p + dp, isochoric, rp, nullptr);
  residual(y, p - dp, isochoric, rm, nullptr);
  compare_column(n_u, dp);
  r_error = std::max(r_error,
                     std::abs((potential(table, y, isochoric, p + dp) -
                               potential(table, y, isochoric, p - dp)) /
                                (2 * dp) -
                              r[n_u]));
  errors.tangent /= scale;
  if (volumetric == nullptr)
    {
      errors.potential = r_error / r.linfty_norm();
      errors.symmetry  = 0;
      for (unsigned int i = 0; i <= n_u; ++i)
        for (unsigned int j = 0; j <= n_u; ++j)
          errors.symmetry =
            std::max(errors.symmetry, std::abs(K(i, j) - K(j, i)) / scale);
    }

  // rigid translation and rotation at p = 0
  const double                force_scale = 100. * std::pow(h, dim - 1);
  std::vector<Tensor<1, dim>> moved(n);
  const Tensor<2, dim>        R =
    rotate ? rotation<dim>(0.7) : unit_symmetric_tensor<dim>();
  for (unsigned int b = 0; b < n; ++b)
    for (unsigned int c = 0; c < dim; ++c)
      moved[b][c] = (R * X[b])[c] + 0.3 * (c + 1) * h;
  residual(moved, 0., isochoric, r, nullptr);
  errors.rigid = r.linfty_norm() / force_scale;

  // a homogeneous F: p = W_vol'(theta) of the full material makes the u
  // rows the displacement element of the full material (Bubnov-Galerkin
  // tables: the same points for both parts)
  if (volumetric == nullptr)
    {
      Tensor<2, dim> F = unit_symmetric_tensor<dim>();
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          F[i][j] += 0.1 * random(rng);
      for (unsigned int b = 0; b < n; ++b)
        moved[b] = F * X[b];
      const double theta = full.volume_measure(F);
      const double theta_0 =
        full.volume_measure(Tensor<2, dim>(unit_symmetric_tensor<dim>()));
      p = full.volumetric_strain_energy_derivative(theta);
      const double   mean_theta = residual(moved, p, isochoric, r, nullptr);
      Vector<double> r_displacement;
      assemble_element(table,
                       moved,
                       dynamic_cast<const Materials::Material<dim> &>(full),
                       r_displacement,
                       nullptr);
      double volume = 0;
      for (const double w : table.weights)
        volume += w;
      double difference = std::abs(r[n_u] - volume * (theta - theta_0)) /
                          (volume * std::abs(theta - theta_0));
      difference = std::max(difference, std::abs(mean_theta - theta));
      for (unsigned int i = 0; i < n_u; ++i)
        difference = std::max(difference,
                              std::abs(r[i] - r_displacement[i]) /
                                r_displacement.linfty_norm());
      errors.homogeneous = difference;
    }
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

  const auto report = [&](const std::string &name, const Errors &worst) {
    deallog << dim << "d " << name
            << ": tangent = FD(r): " << verdict(worst.tangent, 1e-6)
            << ", r = FD(Pi): " << verdict(worst.potential, 1e-6)
            << ", symmetric: " << verdict(worst.symmetry, 1e-13)
            << ", rigid: " << verdict(worst.rigid, 1e-11)
            << ", homogeneous = displacement: "
            << verdict(worst.homogeneous, 1e-12) << std::endl;
  };

  for (const std::string model :
       {"isochoric-volumetric neo-Hooke", "linear elastic"})
    {
      Parameters::Material parameters;
      parameters.model          = model;
      parameters.youngs_modulus = 100.;
      parameters.poissons_ratio = 0.45;
      parameters.density        = 1.;
      parameters.plane          = "strain";
      const auto full_owner     = Materials::create_material<dim>(parameters);
      const auto isochoric_owner =
        Materials::create_material<dim>(parameters.without_volumetric_energy());
      const auto &full =
        dynamic_cast<const Materials::VolumetricSplit<dim> &>(*full_owner);
      const auto &isochoric =
        dynamic_cast<const Materials::VolumetricSplit<dim> &>(*isochoric_owner);
      const bool rotate = (model != "linear elastic");
      Errors     worst;
      for_each_mixed_element<dim>(
        fixture,
        [&](const QuadratureTable<dim>        &table,
            const QuadratureTable<dim>        *volumetric,
            const std::vector<Tensor<1, dim>> &X,
            const unsigned int                 degree) {
          // (the P1 fields of U2P1 are not IUnlP0's)
          if (degree == 0)
            worst.max(check_element(table,
                                    volumetric,
                                    X,
                                    isochoric,
                                    full,
                                    h,
                                    rotate,
                                    rng));
        },
        [&](const std::string &element) {
          if (element.find("U2P1") != std::string::npos)
            return;
          // (IUnlP0 has the tables of UnlP0)
          std::string code = element;
          if (code.find("UnlP0") != std::string::npos)
            code.replace(code.find("UnlP0"), 5, "IUnlP0");
          std::ostringstream name;
          name << code << ", " << model;
          report(name.str(), worst);
          worst = Errors();
        });
    }
}



int
main()
{
  initlog();
  test<2>();
  test<3>();
}
