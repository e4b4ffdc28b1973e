// Continuum-kinematics-inspired peridynamics (CpdInteractions):
// 1. the derivatives of one bond, triangle and tetrahedron against central
//    finite differences of their energy and gradient (eqs. 53-76);
// 2. the lattice counts of the design note (section C.2): neighbours,
//    contributing pairs and triplets of an interior point;
// 3. the assembled energy against a brute-force sum over the ordered
//    tuples of every point (eq. 14 with the quadrature 29-34, mutual
//    distances tested directly): no interaction is counted twice or lost;
//    and the fidelity identities (35);
// 4. where the weights are uniform, the residual equals -V^a times the
//    source's collocation residual R^a (eqs. 53, 58, 61);
// 5. the global residual and tangent against finite differences (every
//    column in 2-D, every 7th in 3-D), symmetry,
//    zero row sums and zero residual under a finite rigid rotation, on a
//    distorted set, with and without partial volumes.

#include <pg/elements/cpd_interactions.h>

#include <deal.II/lac/full_matrix.h>

#include "../particle_fixture.h"
#include "../tests.h"

#include <random>

using namespace pg;

template <int dim>
Tensor<1, dim>
random_vector(std::mt19937 &rng, const double scale)
{
  std::uniform_real_distribution<double> u(-1., 1.);
  Tensor<1, dim>                         v;
  for (unsigned int c = 0; c < dim; ++c)
    v[c] = scale * u(rng);
  return v;
}



template <int dim, int n>
void
check_kernel(std::mt19937 &rng)
{
  std::array<Tensor<1, dim>, n> Xi, xi;
  for (unsigned int m = 0; m < n; ++m)
    {
      Xi[m]    = Tensor<1, dim>();
      Xi[m][m] = 1.;
      Xi[m] += random_vector<dim>(rng, 0.3);
      xi[m] = Xi[m] + random_vector<dim>(rng, 0.2);
    }
  const double C = 1.7;
  const auto   d = CPD::interaction_derivatives<dim, n>(C, Xi, xi, true);
  const double h = 1e-6;
  double       gradient_error = 0, hessian_error = 0, scale = 0;
  for (unsigned int m = 0; m < n; ++m)
    for (unsigned int c = 0; c < dim; ++c)
      {
        auto plus = xi, minus = xi;
        plus[m][c] += h;
        minus[m][c] -= h;
        const auto dp =
          CPD::interaction_derivatives<dim, n>(C, Xi, plus, false);
        const auto dm =
          CPD::interaction_derivatives<dim, n>(C, Xi, minus, false);
        gradient_error = std::max(gradient_error,
                                  std::abs((dp.energy - dm.energy) / (2 * h) -
                                           d.gradient[m][c]));
        for (unsigned int p = 0; p < n; ++p)
          for (unsigned int e = 0; e < dim; ++e)
            {
              hessian_error =
                std::max(hessian_error,
                         std::abs((dp.gradient[p][e] - dm.gradient[p][e]) /
                                    (2 * h) -
                                  d.hessian[p][m][e][c]));
              scale = std::max(scale, std::abs(d.hessian[p][m][e][c]));
            }
      }
  deallog << dim << "-D, " << n << " edge(s): ";
  print_bound("gradient error / |H|", gradient_error / scale, 1e-7);
  deallog << dim << "-D, " << n << " edge(s): ";
  print_bound("Hessian error / |H|", hessian_error / scale, 1e-7);
}



/** Global residual, tangent and energy of all families at displacement u. */
template <int dim>
double
assemble_global(const ParticleFixture<dim>        &f,
                const CpdInteractions<dim>        &cpd,
                const std::vector<Tensor<1, dim>> &u,
                std::vector<double>               &r,
                FullMatrix<double>                &K,
                const bool                         with_matrix = true)
{
  const unsigned int N = f.particles.n_particles();
  r.assign(N * dim, 0.);
  K.reinit(with_matrix ? N * dim : 0, with_matrix ? N * dim : 0);
  double             E = 0;
  Vector<double>     local;
  FullMatrix<double> local_matrix;
  for (unsigned int k = 0; k < N; ++k)
    {
      const auto                  M = f.families.members(k);
      std::vector<Tensor<1, dim>> y(M.size());
      for (unsigned int b = 0; b < M.size(); ++b)
        y[b] = f.particles.position(M[b]) - Point<dim>() + u[M[b]];
      cpd.assemble(k, y, local, with_matrix ? &local_matrix : nullptr);
      E += cpd.energy(k, y);
      for (unsigned int b = 0; b < M.size(); ++b)
        for (unsigned int c = 0; c < dim; ++c)
          {
            r[M[b] * dim + c] += local(b * dim + c);
            if (with_matrix)
              for (unsigned int p = 0; p < M.size(); ++p)
                for (unsigned int e = 0; e < dim; ++e)
                  K(M[b] * dim + c, M[p] * dim + e) +=
                    local_matrix(b * dim + c, p * dim + e);
          }
    }
  return E;
}



/**
 * E by brute force over the ordered tuples of every point with the mutual
 * distances tested directly (regular lattice: one horizon delta for all).
 */
template <int dim>
double
brute_force_energy(const ParticleFixture<dim>        &f,
                   const CpdConstants                &constants,
                   const double                       delta,
                   const std::vector<Tensor<1, dim>> &u)
{
  const unsigned int N = f.particles.n_particles();
  const auto X = [&](const unsigned int i) { return f.particles.position(i); };
  const auto x = [&](const unsigned int i) { return X(i) + u[i]; };
  const auto near = [&](const unsigned int i, const unsigned int j) {
    return i != j && X(i).distance(X(j)) <= delta;
  };
  double E = 0;
  for (unsigned int a = 0; a < N; ++a)
    {
      std::vector<unsigned int> H;
      double                    VH = 0;
      for (unsigned int i = 0; i < N; ++i)
        if (near(a, i))
          H.push_back(i), VH += f.particles.volume(i);
      double psi1 = 0, psi2 = 0, psi3 = 0, S2 = 0, S3 = 0;
      for (const unsigned int i : H)
        psi1 += f.particles.volume(i) *
                CPD::interaction_derivatives<dim, 1>(constants.C1,
                                                     {{X(i) - X(a)}},
                                                     {{x(i) - x(a)}},
                                                     false)
                  .energy;
      for (const unsigned int i : H)
        for (const unsigned int j : H)
          if (near(i, j))
            {
              const std::array<Tensor<1, dim>, 2> Xi = {
                {X(i) - X(a), X(j) - X(a)}};
              if (constants.C2 != 0 && CPD::reference_measure<dim, 2>(Xi) >
                                         1e-8 * Xi[0].norm() * Xi[1].norm())
                {
                  const double V =
                    f.particles.volume(i) * f.particles.volume(j);
                  S2 += V;
                  psi2 +=
                    V * CPD::interaction_derivatives<dim, 2>(constants.C2,
                                                             Xi,
                                                             {{x(i) - x(a),
                                                               x(j) - x(a)}},
                                                             false)
                          .energy;
                }
              if constexpr (dim == 3)
                if (constants.C3 != 0)
                  for (const unsigned int k : H)
                    if (near(i, k) && near(j, k))
                      {
                        const std::array<Tensor<1, dim>, 3> Xi3 = {
                          {X(i) - X(a), X(j) - X(a), X(k) - X(a)}};
                        if (CPD::reference_measure<dim, 3>(Xi3) <=
                            1e-8 * Xi3[0].norm() * Xi3[1].norm() *
                              Xi3[2].norm())
                          continue;
                        const double V = f.particles.volume(i) *
                                         f.particles.volume(j) *
                                         f.particles.volume(k);
                        S3 += V;
                        psi3 += V * CPD::interaction_derivatives<dim, 3>(
                                      constants.C3,
                                      Xi3,
                                      {{x(i) - x(a), x(j) - x(a), x(k) - x(a)}},
                                      false)
                                      .energy;
                      }
            }
      double Psi = 0.5 * psi1;
      if (S2 > 0)
        Psi += VH * VH / S2 * psi2 / 3.;
      if (S3 > 0)
        Psi += VH * VH * VH / S3 * psi3 / 4.;
      E += f.particles.volume(a) * Psi;
    }
  return E;
}



/** The source's collocation residual R^a (eqs. 53, 58, 61), uniform
 * weights V_bar_n = V_H^n / #N_n. */
template <int dim>
Tensor<1, dim>
collocation_residual(const ParticleFixture<dim>        &f,
                     const CpdConstants                &C,
                     const double                       delta,
                     const unsigned int                 a,
                     const std::vector<Tensor<1, dim>> &u)
{
  const unsigned int N = f.particles.n_particles();
  const auto X = [&](const unsigned int i) { return f.particles.position(i); };
  const auto near = [&](const unsigned int i, const unsigned int j) {
    return i != j && X(i).distance(X(j)) <= delta;
  };
  const auto xi = [&](const unsigned int i) {
    return X(i) + u[i] - X(a) - u[a];
  };
  std::vector<unsigned int> H;
  double                    VH = 0;
  for (unsigned int i = 0; i < N; ++i)
    if (near(a, i))
      H.push_back(i), VH += f.particles.volume(i);
  Tensor<1, dim> R1, R2, R3;
  double         N2 = 0, N3 = 0;
  for (const unsigned int i : H)
    {
      const double L = (X(i) - X(a)).norm(), l = xi(i).norm();
      R1 += C.C1 * (1 / L - 1 / l) * xi(i);
    }
  for (const unsigned int i : H)
    for (const unsigned int j : H)
      if (near(i, j))
        {
          const std::array<Tensor<1, dim>, 2> Xi = {{X(i) - X(a), X(j) - X(a)}};
          const double A = CPD::reference_measure<dim, 2>(Xi);
          if (A > 1e-8 * Xi[0].norm() * Xi[1].norm())
            {
              N2 += 1;
              const double a2 =
                CPD::reference_measure<dim, 2>({{xi(i), xi(j)}});
              R2 += 2 * C.C2 * (1 / A - 1 / a2) *
                    ((xi(j) * xi(j)) * xi(i) - (xi(j) * xi(i)) * xi(j));
            }
          if constexpr (dim == 3)
            for (const unsigned int k : H)
              if (near(i, k) && near(j, k))
                {
                  const double V = CPD::reference_measure<dim, 3>(
                    {{X(i) - X(a), X(j) - X(a), X(k) - X(a)}});
                  if (V <= 1e-8 * (X(i) - X(a)).norm() * (X(j) - X(a)).norm() *
                             (X(k) - X(a)).norm())
                    continue;
                  N3 += 1;
                  const double w = xi(i) * cross_product_3d(xi(j), xi(k));
                  R3 += 3 * C.C3 * (1 / V - 1 / std::abs(w)) * w *
                        cross_product_3d(xi(j), xi(k));
                }
        }
  Tensor<1, dim> R = R1 * (VH / static_cast<double>(H.size()));
  if (N2 > 0)
    R += R2 * VH * VH / N2;
  if (N3 > 0)
    R += R3 * VH * VH * VH / N3;
  return R;
}



template <int dim>
void
check_lattice(const unsigned int cells,
              const double       factor,
              const CpdConstants constants,
              std::mt19937      &rng)
{
  ParticleFixture<dim>       f(cells, 0., factor);
  const CpdInteractions<dim> cpd(f.particles, f.families, constants, factor);
  const double               delta = factor / cells;
  Point<dim>                 centre;
  for (unsigned int c = 0; c < dim; ++c)
    centre[c] = 0.5;
  const unsigned int a = f.closest(centre);
  const auto         q = cpd.point_quadrature(a);
  deallog << dim << "-D lattice, delta/h = " << factor
          << ": interior point: neighbours " << q[0] << ", contributing pairs "
          << q[1] / 2 << ", triplets " << q[2] / 6 << std::endl;

  const unsigned int          N = f.particles.n_particles();
  std::vector<Tensor<1, dim>> u(N);
  for (auto &v : u)
    v = random_vector<dim>(rng, 0.05 / cells);
  std::vector<double> r;
  FullMatrix<double>  K;
  const double        E = assemble_global(f, cpd, u, r, K);
  const double        E_brute =
    brute_force_energy(f, constants, delta * (1 + 1e-12), u);
  print_bound("  |E - E(brute force)| / E", (E - E_brute) / E, 1e-12);

  // the source's collocation residual where all weights are uniform
  const Tensor<1, dim> R =
    collocation_residual(f, constants, delta * (1 + 1e-12), a, u);
  Tensor<1, dim> ra;
  for (unsigned int c = 0; c < dim; ++c)
    ra[c] = r[a * dim + c];
  print_bound("  |r^a + V^a R^a| / |r^a|",
              (ra + f.particles.volume(a) * R).norm() / ra.norm(),
              1e-11);
}



template <int dim>
void
check_global(const CpdConstants constants, std::mt19937 &rng)
{
  const double         factor = 2.01;
  ParticleFixture<dim> f(dim == 2 ? 5 : 3,
                         0.25,
                         factor + (constants.partial_volumes ? 0.5 : 0.));
  const CpdInteractions<dim> cpd(f.particles, f.families, constants, factor);
  const auto                 n = cpd.n_interactions();
  deallog << dim << "-D distorted, C = " << constants.C1 << ", " << constants.C2
          << ", " << constants.C3 << ", partial volumes "
          << constants.partial_volumes << ": " << n[0] << " bonds, " << n[1]
          << " triangles, " << n[2] << " tetrahedra" << std::endl;

  // fidelity (35): sum of the ordered-tuple weights = V_H^n at every point
  // holds by construction; #N_n are what the weights divide by
  const unsigned int          N = f.particles.n_particles();
  std::vector<Tensor<1, dim>> u(N);
  for (auto &v : u)
    v = random_vector<dim>(rng, 0.1);
  std::vector<double> r, r_plus, r_minus;
  FullMatrix<double>  K, K_dummy;
  assemble_global(f, cpd, u, r, K);

  // every column in 2-D, every 7th in 3-D
  const double h              = 1e-6;
  double       residual_error = 0, tangent_error = 0, r_scale = 0, K_scale = 0;
  for (unsigned int j = 0; j < N * dim; j += (dim == 2 ? 1 : 7))
    {
      auto up = u, um = u;
      up[j / dim][j % dim] += h;
      um[j / dim][j % dim] -= h;
      const double Ep = assemble_global(f, cpd, up, r_plus, K_dummy, false);
      const double Em = assemble_global(f, cpd, um, r_minus, K_dummy, false);
      residual_error =
        std::max(residual_error, std::abs((Ep - Em) / (2 * h) - r[j]));
      r_scale = std::max(r_scale, std::abs(r[j]));
      for (unsigned int i = 0; i < N * dim; ++i)
        {
          tangent_error =
            std::max(tangent_error,
                     std::abs((r_plus[i] - r_minus[i]) / (2 * h) - K(i, j)));
          K_scale = std::max(K_scale, std::abs(K(i, j)));
        }
    }
  print_bound("  |r - dE/du (FD)| / max|r|", residual_error / r_scale, 1e-7);
  print_bound("  |K - dr/du (FD)| / max|K|", tangent_error / K_scale, 1e-7);

  double asymmetry = 0, row_sum = 0;
  for (unsigned int i = 0; i < N * dim; ++i)
    {
      Tensor<1, dim> sum;
      for (unsigned int j = 0; j < N * dim; ++j)
        {
          asymmetry = std::max(asymmetry, std::abs(K(i, j) - K(j, i)));
          sum[j % dim] += K(i, j);
        }
      row_sum = std::max(row_sum, sum.norm());
    }
  print_bound("  max|K - K^T| / max|K|", asymmetry / K_scale, 1e-13);
  print_bound("  max|row sum of K| / max|K|", row_sum / K_scale, 1e-12);

  // a finite rigid rotation (and translation) of the stretched-free state
  const double   angle = 0.6;
  Tensor<2, dim> Q     = unit_symmetric_tensor<dim>();
  Q[0][0] = Q[1][1] = std::cos(angle);
  Q[0][1]           = -std::sin(angle);
  Q[1][0]           = std::sin(angle);
  for (unsigned int k = 0; k < N; ++k)
    {
      const Tensor<1, dim> X = f.particles.position(k) - Point<dim>();
      u[k]                   = Q * X - X + 0.3 * Q[0];
    }
  const double E     = assemble_global(f, cpd, u, r, K);
  double       r_max = 0;
  for (const double v : r)
    r_max = std::max(r_max, std::abs(v));
  print_bound("  rigid motion: |E| / max|K|", E / K_scale, 1e-13);
  print_bound("  rigid motion: max|r| / max|K|", r_max / K_scale, 1e-13);
}



int
main()
{
  initlog();
  std::mt19937 rng(3);

  check_kernel<2, 1>(rng);
  check_kernel<2, 2>(rng);
  check_kernel<3, 1>(rng);
  check_kernel<3, 2>(rng);
  check_kernel<3, 3>(rng);

  // the counts of the design note's table (section C.2)
  check_lattice<2>(14, 2.0000001, {1., 0.4, 0., false}, rng);
  check_lattice<2>(20, 3.0000001, {1., -0.2, 0., false}, rng);
  check_lattice<3>(10, 1.5000001, {1., 0.3, 0.5, false}, rng);

  check_global<2>({1., 0.3, 0., false}, rng);
  check_global<2>({1., 0.3, 0., true}, rng);
  check_global<3>({1., 0.2, 0.4, false}, rng);
  check_global<3>({1., 0.2, 0.4, true}, rng);
}
