// The second derivatives of the MLS1 shape functions at the master with a
// finite self-weight (ShapeFunctions::mls1_second_derivatives(), eq. 6.28,
// the implicit gradients of U1SIG), on every family of a distorted particle
// set in 2-D and 3-D, weight exponents n = 1 and 2, self-weights of a bond
// of 1e-3 and 1 times the nearest-neighbour distance:
// - they equal central second differences of N_i(X) =
//   V^i omega_i(X) p^{ki} . M(X)^{-1} p(X - X^k), written out here
//   independently (deal.II FullMatrix, unscaled basis), at X = X^k, with
//   the master's weight held at the self-weight;
// - they reproduce the zero second derivatives of linear fields:
//   sum_i h^i = 0 and sum_i dX^{ki} (x) h^i = 0;
// - with n = 0 (constant weights: a global linear fit) they vanish.

#include <pg/shape_functions/shape_functions.h>

#include "../particle_fixture.h"
#include "../tests.h"

using namespace pg;

/** N_i(X) at X = X^k + x, for all members i, written out directly. */
template <int dim>
std::vector<double>
mls1_values(const ShapeFunctions::FamilyGeometry<dim> &family,
            const double                               self_weight,
            const Tensor<1, dim>                      &x)
{
  const unsigned int  n = family.bonds.size();
  const unsigned int  m = dim + 1;
  FullMatrix<double>  M(m, m);
  std::vector<double> w(n);
  const auto          basis = [](const Tensor<1, dim> &d) {
    Vector<double> p(dim + 1);
    p[0] = 1.;
    for (unsigned int a = 0; a < dim; ++a)
      p[a + 1] = d[a];
    return p;
  };
  for (unsigned int i = 0; i < n; ++i)
    {
      w[i] = family.volumes[i] *
             (i == 0 ? self_weight :
                       std::pow((family.bonds[i] - x).norm_square(),
                                -family.weight_exponent));
      const Vector<double> p = basis(family.bonds[i]);
      for (unsigned int r = 0; r < m; ++r)
        for (unsigned int c = 0; c < m; ++c)
          M(r, c) += w[i] * p[r] * p[c];
    }
  M.gauss_jordan();
  Vector<double> gamma(m);
  M.vmult(gamma, basis(x));
  std::vector<double> N(n);
  for (unsigned int i = 0; i < n; ++i)
    N[i] = w[i] * (basis(family.bonds[i]) * gamma);
  return N;
}



template <int dim>
void
test()
{
  const ParticleFixture<dim> fixture(dim == 2 ? 6 : 3, 0.25, 2.51);
  for (const double exponent : {1., 2., 0.})
    for (const double self_distance : {1e-3, 1.})
      {
        double fd_error = 0, linear_error = 0, largest = 0;
        for (unsigned int k = 0; k < fixture.particles.n_particles(); ++k)
          {
            const ShapeFunctions::FamilyGeometry<dim> family =
              fixture.family_geometry(k, exponent);
            double s = std::numeric_limits<double>::max();
            for (unsigned int i = 1; i < family.bonds.size(); ++i)
              s = std::min(s, family.bonds[i].norm());
            const double self_weight =
              std::pow(self_distance * s, -2. * exponent);
            std::vector<Tensor<2, dim>> h;
            ShapeFunctions::mls1_second_derivatives(family, self_weight, h);
            double scale = 0;
            for (const auto &hi : h)
              scale = std::max(scale, hi.norm());
            largest = std::max(largest, scale * s * s);
            if (exponent == 0.)
              continue;

            // central second differences at X^k
            const double eps = 1e-3 * s;
            for (unsigned int a = 0; a < dim; ++a)
              for (unsigned int b = 0; b < dim; ++b)
                {
                  Tensor<1, dim> ea, eb;
                  ea[a]         = eps;
                  eb[b]         = eps;
                  const auto pp = mls1_values(family, self_weight, ea + eb);
                  const auto pm = mls1_values(family, self_weight, ea - eb);
                  const auto mp = mls1_values(family, self_weight, eb - ea);
                  const auto mm = mls1_values(family, self_weight, -ea - eb);
                  for (unsigned int i = 0; i < h.size(); ++i)
                    fd_error =
                      std::max(fd_error,
                               std::abs((pp[i] - pm[i] - mp[i] + mm[i]) /
                                          (4 * eps * eps) -
                                        h[i][a][b]) /
                                 scale);
                }
            // linear fields
            Tensor<2, dim> sum;
            Tensor<3, dim> first;
            for (unsigned int i = 0; i < h.size(); ++i)
              {
                sum += h[i];
                for (unsigned int c = 0; c < dim; ++c)
                  for (unsigned int a = 0; a < dim; ++a)
                    for (unsigned int b = 0; b < dim; ++b)
                      first[c][a][b] += family.bonds[i][c] * h[i][a][b];
              }
            linear_error =
              std::max(linear_error,
                       std::max(sum.norm(), first.norm() / s) / scale);
          }
        deallog << dim << "d, n = " << exponent << ", self-weight at "
                << self_distance << " x spacing: ";
        if (exponent == 0.)
          deallog << "all zero: " << (largest < 1e-12 ? "yes" : "NO")
                  << std::endl;
        else
          deallog << "= FD: " << (fd_error < 1e-5 ? "yes" : "NO")
                  << ", linear fields: "
                  << (linear_error < 1e-11 ? "yes" : "NO")
                  << ", nonzero: " << (largest > 1e-3 ? "yes" : "NO")
                  << std::endl;
      }
}



int
main()
{
  initlog();
  test<2>();
  test<3>();
}
