// The condensed-pressure elements (UnlP0 for PBG and PPG, Q1P0 / H1P0, and
// U2P1 with linear p and Theta) of assemble_condensed_pressure_element(),
// pg-methods.md sections 12.2.1 and 12.2.2:
// - the residual is the gradient of the condensed potential
//   Pi = sum_q w_q W_iso(F_q) + W W_vol(J-bar) (P0), or
//   sum_q w_q [W_iso(F_q) + W_vol(Theta_q)] with Theta the weighted L2
//   projection of J onto linear functions (P1) (central differences of Pi,
//   computed here independently of the kernel, with another basis of the
//   linear functions), for PBG and Q1P0 (the Bubnov-Galerkin elements that
//   have a potential);
// - the tangent agrees with central differences of the residual (every
//   element, PPG's non-symmetric one included);
// - rigid motions give zero residual;
// - under a homogeneous deformation J-bar = J, and the element equals the
//   displacement element of the isochoric-volumetric material;
// for the isochoric-volumetric neo-Hooke (theta = J) and linear
// elasticity (theta = tr(eps), the B-bar method; rigid translations only,
// the model is not rotation invariant) at nu = 0.3 and nu = 0.4999, on an
// interior and a corner family of a distorted particle set (BCPBG, BCPPG,
// PBG U2P1), and on Q1 cells, in 2-D and 3-D.

#include <pg/elements/condensed_pressure.h>
#include <pg/materials/material.h>

#include "../tests.h"
#include "mixed_elements.h"

using namespace pg;

template <int dim>
std::unique_ptr<Materials::Material<dim>>
make_split_material(const std::string &model, const double nu)
{
  Parameters::Material parameters;
  parameters.model          = model;
  parameters.youngs_modulus = 100.;
  parameters.poissons_ratio = nu;
  parameters.density        = 1.;
  parameters.plane          = "strain";
  return Materials::create_material<dim>(parameters);
}



/**
 * The condensed potential, written out independently of the kernel: P0
 * (@p degree 0) with the mean of theta, P1 with the weighted least-squares
 * fit of theta by a + b . X (deal.II's FullMatrix, monomials about the
 * origin; the kernel uses Eigen and a centred, scaled basis).
 */
template <int dim>
double
potential(const QuadratureTable<dim>            &table,
          const QuadratureTable<dim>            &volumetric,
          const std::vector<Tensor<1, dim>>     &y,
          const Materials::VolumetricSplit<dim> &material,
          const unsigned int                     degree)
{
  double Pi = 0;
  for (unsigned int q = 0; q < table.n_points(); ++q)
    Pi += table.weights[q] * material.isochoric_strain_energy_density(
                               deformation_gradient(table, q, y));
  const unsigned int m = (degree == 0 ? 1 : dim + 1);
  FullMatrix<double> M(m, m);
  Vector<double>     b(m), c(m), phi(m);
  const auto         basis = [&](const unsigned int q) {
    phi[0] = 1.;
    for (unsigned int i = 1; i < m; ++i)
      phi[i] = volumetric.points[q][i - 1];
  };
  for (unsigned int q = 0; q < volumetric.n_points(); ++q)
    {
      basis(q);
      const double theta =
        material.volume_measure(deformation_gradient(volumetric, q, y));
      for (unsigned int i = 0; i < m; ++i)
        {
          b[i] += volumetric.weights[q] * theta * phi[i];
          for (unsigned int j = 0; j < m; ++j)
            M(i, j) += volumetric.weights[q] * phi[i] * phi[j];
        }
    }
  M.gauss_jordan();
  M.vmult(c, b);
  for (unsigned int q = 0; q < volumetric.n_points(); ++q)
    {
      basis(q);
      Pi += volumetric.weights[q] *
            material.volumetric_strain_energy_density(phi * c);
    }
  return Pi;
}



struct Errors
{
  double tangent     = 0;  // |K - FD(r)| / |K|
  double potential   = -1; // |r - FD(Pi)| / |r| (Bubnov-Galerkin only)
  double rigid       = 0;  // |r(rigid)| / force scale
  double homogeneous = 0;  // |r - r_displacement| / |r| at a homogeneous F

  void
  max(const Errors &e)
  {
    tangent     = std::max(tangent, e.tangent);
    potential   = std::max(potential, e.potential);
    rigid       = std::max(rigid, e.rigid);
    homogeneous = std::max(homogeneous, e.homogeneous);
  }
};



/**
 * Checks one element (isochoric points @p table, volumetric points
 * @p volumetric, nullptr: the same) at the relative nodal positions @p X.
 */
template <int dim>
Errors
check_element(const QuadratureTable<dim>            &table,
              const QuadratureTable<dim>            *volumetric,
              const std::vector<Tensor<1, dim>>     &X,
              const Materials::VolumetricSplit<dim> &material,
              const double                           h,
              const bool                             rotate,
              std::mt19937                          &rng,
              const unsigned int                     degree = 0)
{
  std::uniform_real_distribution<double> random(-1., 1.);
  const unsigned int                     n = X.size();
  std::vector<Tensor<1, dim>>            y(X);
  for (auto &v : y)
    for (unsigned int c = 0; c < dim; ++c)
      v[c] += 0.05 * h * random(rng);
  const auto residual = [&](const std::vector<Tensor<1, dim>> &at,
                            Vector<double>                    &r,
                            FullMatrix<double>                *K) {
    assemble_condensed_pressure_element(table,
                                        volumetric,
                                        at,
                                        material,
                                        r,
                                        K,
                                        degree);
  };

  Errors             errors;
  Vector<double>     r, rp, rm;
  FullMatrix<double> K;
  residual(y, r, &K);
  double       scale = 0, r_error = 0;
  const double eps = 1e-6 * h;
  for (unsigned int b = 0; b < n; ++b)
    for (unsigned int c = 0; c < dim; ++c)
      {
        y[b][c] += eps;
        residual(y, rp, nullptr);
        const double Pi_p = potential(table,
                                      volumetric ? *volumetric : table,
                                      y,
                                      material,
                                      degree);
        y[b][c] -= 2 * eps;
        residual(y, rm, nullptr);
        const double Pi_m = potential(table,
                                      volumetric ? *volumetric : table,
                                      y,
                                      material,
                                      degree);
        y[b][c] += eps;
        for (unsigned int i = 0; i < n * dim; ++i)
          {
            const double fd = (rp[i] - rm[i]) / (2 * eps);
            errors.tangent =
              std::max(errors.tangent, std::abs(fd - K(i, b * dim + c)));
            scale = std::max(scale, std::abs(K(i, b * dim + c)));
          }
        r_error =
          std::max(r_error,
                   std::abs((Pi_p - Pi_m) / (2 * eps) - r[b * dim + c]));
      }
  errors.tangent /= scale;
  // (a Petrov-Galerkin element has no potential: -1, printed n/a)
  errors.potential = (volumetric == nullptr ? r_error / r.linfty_norm() : -1.);

  // rigid translation and rotation
  const double                force_scale = 100. * std::pow(h, dim - 1);
  std::vector<Tensor<1, dim>> moved(n);
  const Tensor<2, dim>        R =
    rotate ? rotation<dim>(0.7) : unit_symmetric_tensor<dim>();
  for (unsigned int b = 0; b < n; ++b)
    for (unsigned int c = 0; c < dim; ++c)
      moved[b][c] = (R * X[b])[c] + 0.3 * (c + 1) * h;
  residual(moved, r, nullptr);
  errors.rigid = r.linfty_norm() / force_scale;

  // a homogeneous deformation: the displacement element of the same
  // material (Bubnov-Galerkin tables: same points for both parts)
  if (volumetric == nullptr)
    {
      Tensor<2, dim> F = unit_symmetric_tensor<dim>();
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          F[i][j] += 0.1 * random(rng);
      for (unsigned int b = 0; b < n; ++b)
        moved[b] = F * X[b];
      Vector<double> r_displacement;
      residual(moved, r, nullptr);
      assemble_element(table,
                       moved,
                       dynamic_cast<const Materials::Material<dim> &>(material),
                       r_displacement,
                       nullptr);
      r_displacement -= r;
      errors.homogeneous = r_displacement.linfty_norm() / r.linfty_norm();
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
  std::mt19937 rng(7);

  const auto report = [&](const std::string &name, const Errors &worst) {
    deallog << dim << "d " << name
            << ": tangent = FD(r): " << verdict(worst.tangent, 1e-6)
            << ", r = FD(Pi): " << verdict(worst.potential, 1e-6)
            << ", rigid: " << verdict(worst.rigid, 1e-11)
            << ", homogeneous = displacement: "
            << verdict(worst.homogeneous, 1e-12) << std::endl;
  };

  for (const std::string model :
       {"isochoric-volumetric neo-Hooke", "linear elastic"})
    for (const double nu : {0.3, 0.4999})
      {
        const auto  material_owner = make_split_material<dim>(model, nu);
        const auto &material =
          dynamic_cast<const Materials::VolumetricSplit<dim> &>(
            *material_owner);
        const bool rotate = (model != "linear elastic");
        Errors     worst;
        for_each_mixed_element<dim>(
          fixture,
          [&](const QuadratureTable<dim>        &table,
              const QuadratureTable<dim>        *volumetric,
              const std::vector<Tensor<1, dim>> &X,
              const unsigned int                 degree) {
            worst.max(check_element(table,
                                    volumetric,
                                    X,
                                    material,
                                    h,
                                    rotate,
                                    rng,
                                    degree));
          },
          [&](const std::string &element) {
            std::ostringstream name;
            name << element << ", " << model << ", nu = " << nu;
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
