// The two stabilisations of the underintegrated family U1
// (elements/u1_stabilisation.h), on an interior and a corner family of a
// distorted particle set, in 2-D and 3-D:
// - U1SUnl (eq. 6.18) with the neo-Hooke material at nu = 0.4999 and its
//   pseudo-material at nu~ = 0.49: the tangent agrees with central finite
//   differences of the residual, rigid motions (translation, rotation by
//   0.7 rad) give zero residual, and with pseudo-material = material the
//   family equals the Unl family exactly (the master terms cancel);
// - Peridigm's hourglass force: the residual equals an independent
//   transcription of Peridigm's loop (correspondence.cxx,
//   computeHourglassForce(): force density += magnitude Y V_j, the
//   neighbour's -= magnitude Y V_k), the tangent agrees with central
//   differences, the force vanishes for every affine field (a homogeneous
//   stretch and shear, rotated) and sums to zero, and the tangent is not
//   symmetric (the force has no energy);
// - U1SIG's implicit-gradient term (eqs. 6.25-6.28) with the MLS1 second
//   derivatives of an interior and a corner family and the tangent A~ of
//   the pseudo-material at a random F: the residual equals central
//   differences of the energy
//   1/2 M_xx sum_E G_E : A~ : G_E (G = sum_b y^b (x) h^b, written out
//   here), the tangent central differences of the residual and is
//   symmetric, and affine fields give zero; M_xx is the second moment of
//   a ball (3-D) or disc (2-D) of the particle's volume, checked against
//   V r^2 / 5 and A r^2 / 4.

#include <pg/base/formulation_code.h>
#include <pg/elements/family_elements.h>
#include <pg/elements/u1_stabilisation.h>
#include <pg/shape_functions/shape_functions.h>

#include "../particle_fixture.h"
#include "../tests.h"

using namespace pg;

/** max |A - B| / max |B| over the entries. */
double
relative_difference(const Vector<double> &a, const Vector<double> &b)
{
  Vector<double> d(a);
  d -= b;
  return d.linfty_norm() / std::max(b.linfty_norm(), 1e-300);
}



/**
 * The largest difference between @p tangent and central differences of
 * @p residual_of, relative to the largest tangent entry.
 */
template <int dim, typename ResidualOf>
double
tangent_error(std::vector<Tensor<1, dim>> y,
              const FullMatrix<double>   &tangent,
              const double                h,
              const ResidualOf           &residual_of)
{
  Vector<double> rp, rm;
  double         error = 0, scale = 0;
  const double   eps = 1e-6 * h;
  for (unsigned int b = 0; b < y.size(); ++b)
    for (unsigned int c = 0; c < dim; ++c)
      {
        y[b][c] += eps;
        residual_of(y, rp);
        y[b][c] -= 2 * eps;
        residual_of(y, rm);
        y[b][c] += eps;
        for (unsigned int i = 0; i < rp.size(); ++i)
          {
            const double fd = (rp[i] - rm[i]) / (2 * eps);
            error = std::max(error, std::abs(fd - tangent(i, b * dim + c)));
            scale = std::max(scale, std::abs(tangent(i, b * dim + c)));
          }
      }
  return error / scale;
}



/** Peridigm's loop for one master (node 0), as in correspondence.cxx. */
template <int dim>
Vector<double>
peridigm_hourglass_force_density(const Tensor<2, dim>              &F,
                                 const std::vector<Tensor<1, dim>> &xi,
                                 const std::vector<Tensor<1, dim>> &y,
                                 const std::vector<double>         &volume,
                                 const double                       alpha,
                                 const double                       K,
                                 const double                       delta)
{
  const unsigned int n = xi.size();
  Vector<double>     force_density(n * dim);
  const double       constant =
    18.0 * alpha * K / 3.1415926535897932 / std::pow(delta, 4);
  for (unsigned int j = 1; j < n; ++j)
    {
      Tensor<1, dim> deformed_bond = y[j] - y[0];
      Tensor<1, dim> expected      = y[0] + F * xi[j];
      Tensor<1, dim> hourglass     = expected - y[j];
      double         dot           = -(hourglass * deformed_bond);
      double magnitude = constant * (dot / xi[j].norm()) / deformed_bond.norm();
      for (unsigned int c = 0; c < dim; ++c)
        {
          force_density[c] += magnitude * deformed_bond[c] * volume[j];
          force_density[j * dim + c] -=
            magnitude * deformed_bond[c] * volume[0];
        }
    }
  return force_density;
}



template <int dim>
void
test()
{
  const ParticleFixture<dim> fixture(dim == 2 ? 6 : 4,
                                     0.25,
                                     dim == 2 ? 2.51 : 2.01);
  const double                           h = 1. / (dim == 2 ? 6 : 4);
  std::mt19937                           rng(42);
  std::uniform_real_distribution<double> random(-1., 1.);

  Parameters::Material parameters;
  parameters.model          = "neo-Hooke";
  parameters.youngs_modulus = 100.;
  parameters.poissons_ratio = 0.4999;
  parameters.density        = 1.;
  parameters.plane          = "strain";
  const auto material       = Materials::create_material<dim>(parameters);
  const auto pseudo =
    Materials::create_material<dim>(parameters.with_poissons_ratio(0.49));

  const FormulationCode code = parse_formulation_code("PBG U1SUnl");
  FamilyElements<dim>   u1_elements(fixture.particles,
                                  fixture.families,
                                  code.underintegrated_part(),
                                  ShapeFunctions::Base::mte1,
                                  1.);
  FamilyElements<dim>   unl_elements(fixture.particles,
                                   fixture.families,
                                   code.stabilisation_part(),
                                   ShapeFunctions::Base::mte1,
                                   1.);
  u1_elements.initialize();
  unl_elements.initialize();

  double u1s_tangent = 0, u1s_rigid = 0, u1s_equal_unl = 0;
  double hg_peridigm = 0, hg_tangent = 0, hg_affine = 0, hg_sum = 0;
  double hg_asymmetry = 1;
  for (const unsigned int k : fixture.interior_and_corner())
    {
      QuadratureTable<dim> u1_table, unl_table;
      u1_elements.build(k, u1_table);
      unl_elements.build(k, unl_table);
      const auto                  geometry = u1_elements.geometry(k);
      const auto                 &X        = geometry.bonds;
      const unsigned int          n        = X.size();
      std::vector<Tensor<1, dim>> y(X);
      for (auto &v : y)
        for (unsigned int c = 0; c < dim; ++c)
          v[c] += 0.05 * h * random(rng);

      // U1SUnl
      U1SUnlScratch      scratch;
      Vector<double>     r, r_unl;
      FullMatrix<double> K;
      assemble_u1s_unl_element(u1_table,
                               unl_table,
                               y,
                               *material,
                               *pseudo,
                               r,
                               &K,
                               scratch);
      u1s_tangent = std::max(
        u1s_tangent,
        tangent_error<dim>(y, K, h, [&](const auto &yy, Vector<double> &rr) {
          U1SUnlScratch s;
          assemble_u1s_unl_element(u1_table,
                                   unl_table,
                                   yy,
                                   *material,
                                   *pseudo,
                                   rr,
                                   nullptr,
                                   s);
        }));
      const Tensor<2, dim>        R = rotation<dim>(0.7);
      std::vector<Tensor<1, dim>> rigid(n);
      for (unsigned int b = 0; b < n; ++b)
        rigid[b] = R * X[b] + Tensor<1, dim>(Point<dim>::unit_vector(0));
      assemble_u1s_unl_element(u1_table,
                               unl_table,
                               rigid,
                               *material,
                               *pseudo,
                               r,
                               nullptr,
                               scratch);
      u1s_rigid = std::max(u1s_rigid, r.linfty_norm() / (100. * h));
      assemble_u1s_unl_element(u1_table,
                               unl_table,
                               y,
                               *material,
                               *material,
                               r,
                               nullptr,
                               scratch);
      assemble_element(unl_table, y, *material, r_unl, nullptr);
      u1s_equal_unl = std::max(u1s_equal_unl, relative_difference(r, r_unl));

      // Peridigm's hourglass force, alpha = 0.02, K = 100, delta = 2.51 h
      const double        alpha = 0.02, bulk = 100., delta = 2.51 * h;
      const double        constant = hourglass_constant(alpha, bulk, delta);
      std::vector<double> volumes(n);
      for (unsigned int b = 0; b < n; ++b)
        volumes[b] = fixture.particles.volume(fixture.families.members(k)[b]);
      const auto hourglass = [&](const auto &yy, Vector<double> &rr) {
        rr.reinit(n * dim);
        add_hourglass_force(u1_table, X, yy, volumes, constant, rr, nullptr);
      };
      Vector<double> force;
      hourglass(y, force);
      const double   random_force = force.linfty_norm();
      Vector<double> peridigm =
        peridigm_hourglass_force_density(deformation_gradient(u1_table, 0, y),
                                         X,
                                         y,
                                         volumes,
                                         alpha,
                                         bulk,
                                         delta);
      // force = own volume x force density; the residual is minus it
      for (unsigned int b = 0; b < n; ++b)
        for (unsigned int c = 0; c < dim; ++c)
          peridigm[b * dim + c] *= -volumes[b];
      hg_peridigm = std::max(hg_peridigm, relative_difference(force, peridigm));
      double sum  = 0;
      for (unsigned int c = 0; c < dim; ++c)
        {
          double s = 0;
          for (unsigned int b = 0; b < n; ++b)
            s += force[b * dim + c];
          sum = std::max(sum, std::abs(s));
        }
      hg_sum = std::max(hg_sum, sum / force.linfty_norm());

      FullMatrix<double> Kh(n * dim, n * dim);
      force = 0;
      add_hourglass_force(u1_table, X, y, volumes, constant, force, &Kh);
      hg_tangent =
        std::max(hg_tangent, tangent_error<dim>(y, Kh, h, hourglass));
      double asymmetry = 0;
      for (unsigned int i = 0; i < n * dim; ++i)
        for (unsigned int j = 0; j < n * dim; ++j)
          asymmetry = std::max(asymmetry, std::abs(Kh(i, j) - Kh(j, i)));
      hg_asymmetry = std::min(hg_asymmetry, asymmetry / Kh.linfty_norm());

      // an affine field: stretch and shear, rotated, translated
      Tensor<2, dim> G = unit_symmetric_tensor<dim>();
      G[0][0]          = 1.2;
      G[0][1]          = 0.3;
      G[1][1]          = 0.9;
      G                = R * G;
      std::vector<Tensor<1, dim>> affine(n);
      for (unsigned int b = 0; b < n; ++b)
        affine[b] = G * X[b] + Tensor<1, dim>(Point<dim>::unit_vector(1));
      hourglass(affine, force);
      hg_affine = std::max(hg_affine, force.linfty_norm() / random_force);
    }

  deallog << dim << "d U1SUnl: tangent = FD: " << verdict(u1s_tangent, 1e-6)
          << ", rigid motions: " << verdict(u1s_rigid, 1e-12)
          << ", = Unl for W~ = W: " << verdict(u1s_equal_unl, 1e-13)
          << std::endl;
  deallog << dim
          << "d hourglass: = Peridigm's loop: " << verdict(hg_peridigm, 1e-13)
          << ", tangent = FD: " << verdict(hg_tangent, 1e-6)
          << ", affine fields: " << verdict(hg_affine, 1e-12)
          << ", sum of forces: " << verdict(hg_sum, 1e-13)
          << ", tangent not symmetric: " << (hg_asymmetry > 1e-3 ? "yes" : "NO")
          << std::endl;
}



template <int dim>
void
test_implicit_gradients()
{
  const ParticleFixture<dim> fixture(dim == 2 ? 6 : 4,
                                     0.25,
                                     dim == 2 ? 2.51 : 2.01);
  const double                           h = 1. / (dim == 2 ? 6 : 4);
  std::mt19937                           rng(7);
  std::uniform_real_distribution<double> random(-1., 1.);
  Parameters::Material                   parameters;
  parameters.model          = "neo-Hooke";
  parameters.youngs_modulus = 100.;
  parameters.poissons_ratio = 0.49;
  parameters.density        = 1.;
  parameters.plane          = "strain";
  const auto     pseudo     = Materials::create_material<dim>(parameters);
  Tensor<2, dim> F_frozen   = unit_symmetric_tensor<dim>();
  for (unsigned int i = 0; i < dim; ++i)
    for (unsigned int j = 0; j < dim; ++j)
      F_frozen[i][j] += 0.1 * random(rng);
  Tensor<2, dim> P;
  Tensor<4, dim> A;
  pseudo->evaluate(F_frozen, P, A);

  double tangent = 0, energy = 0, symmetry = 0, affine = 0;
  for (const unsigned int k : fixture.interior_and_corner())
    {
      const ShapeFunctions::FamilyGeometry<dim> family =
        fixture.family_geometry(k);
      std::vector<Tensor<2, dim>> second;
      ShapeFunctions::mls1_second_derivatives(family,
                                              std::pow(1e-3 * h, -2.),
                                              second);
      const double M = particle_second_moment<dim>(fixture.particles.volume(k));
      const unsigned int n           = second.size();
      const auto         residual_of = [&](const std::vector<Tensor<1, dim>> &y,
                                   Vector<double>                    &r) {
        r.reinit(n * dim);
        add_implicit_gradient_stabilisation(second, M, A, y, r, nullptr);
      };
      const auto energy_of = [&](const std::vector<Tensor<1, dim>> &y) {
        double Pi = 0;
        for (unsigned int E = 0; E < dim; ++E)
          {
            Tensor<2, dim> G;
            for (unsigned int b = 0; b < n; ++b)
              for (unsigned int C = 0; C < dim; ++C)
                for (unsigned int D = 0; D < dim; ++D)
                  G[C][D] += y[b][C] * second[b][D][E];
            Pi +=
              0.5 * M * scalar_product(G, double_contract<2, 0, 3, 1>(A, G));
          }
        return Pi;
      };
      std::vector<Tensor<1, dim>> y(family.bonds);
      for (auto &v : y)
        for (unsigned int c = 0; c < dim; ++c)
          v[c] += 0.05 * h * random(rng);
      Vector<double>     r(n * dim);
      FullMatrix<double> K(n * dim, n * dim);
      add_implicit_gradient_stabilisation(second, M, A, y, r, &K);
      tangent = std::max(tangent, tangent_error<dim>(y, K, h, residual_of));
      double       fd_error = 0;
      const double eps      = 1e-6 * h;
      for (unsigned int b = 0; b < n; ++b)
        for (unsigned int c = 0; c < dim; ++c)
          {
            y[b][c] += eps;
            const double plus = energy_of(y);
            y[b][c] -= 2 * eps;
            const double minus = energy_of(y);
            y[b][c] += eps;
            fd_error =
              std::max(fd_error,
                       std::abs((plus - minus) / (2 * eps) - r[b * dim + c]));
          }
      energy = std::max(energy, fd_error / r.linfty_norm());
      for (unsigned int i = 0; i < n * dim; ++i)
        for (unsigned int j = 0; j < n * dim; ++j)
          symmetry =
            std::max(symmetry, std::abs(K(i, j) - K(j, i)) / K.linfty_norm());
      // an affine field (a random F and translation): zero
      Tensor<2, dim> G = unit_symmetric_tensor<dim>();
      G[0][1]          = 0.3;
      G[1][0]          = -0.2;
      std::vector<Tensor<1, dim>> moved(n);
      for (unsigned int b = 0; b < n; ++b)
        moved[b] =
          G * family.bonds[b] + Tensor<1, dim>(Point<dim>::unit_vector(0));
      Vector<double> zero(n * dim);
      add_implicit_gradient_stabilisation(second, M, A, moved, zero, nullptr);
      affine = std::max(affine, zero.linfty_norm() / r.linfty_norm());
    }
  // M_xx of a ball / disc of volume 2
  const double V      = 2.;
  const double radius = dim == 3 ? std::cbrt(3. * V / (4. * numbers::PI)) :
                                   std::sqrt(V / numbers::PI);
  const double exact =
    (dim == 3 ? V * radius * radius / 5. : V * radius * radius / 4.);
  deallog << dim << "d U1SIG: r = FD(energy): " << verdict(energy, 1e-7)
          << ", tangent = FD: " << verdict(tangent, 1e-6)
          << ", symmetric: " << verdict(symmetry, 1e-13)
          << ", affine fields: " << verdict(affine, 1e-11) << ", M_xx: "
          << verdict(std::abs(particle_second_moment<dim>(V) - exact) / exact,
                     1e-14)
          << std::endl;
}



int
main()
{
  initlog();
  test<2>();
  test<3>();
  test_implicit_gradients<2>();
  test_implicit_gradients<3>();
}
