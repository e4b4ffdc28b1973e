// Linear consistency and bond mapping of the trial functions.
//
// 1. For a linear displacement field the deformation gradient at every
//    evaluation point of every family equals the exact one to round-off,
//    for every base (WTE1, WLS1, MLS1, MTE1), with and without the bond
//    correction (eq. 5.9, which BC preserves: section 10).
// 2. With BC the deformation gradient at point j maps the bond k-j exactly
//    for any (non-affine) positions, eq. (5.12); without BC it does not
//    (except for WTE1/WLS1 at the master, which is no bond).
// 3. U2 (WTE2, section 6.4): for a quadratic displacement field the
//    deformation gradient at every evaluation point equals the exact one
//    at that point to round-off (the trial space of a quadratic simplex).
// Checked on a distorted particle set in 2-D and 3-D, on all families.

#include <pg/base/formulation_code.h>
#include <pg/elements/family_elements.h>

#include "../particle_fixture.h"
#include "../tests.h"

using namespace pg;

template <int dim>
void
test()
{
  const ParticleFixture<dim> fixture(dim == 2 ? 8 : 4,
                                     0.3,
                                     dim == 2 ? 2.51 : 2.01);
  std::mt19937                           rng(3);
  std::uniform_real_distribution<double> random(-1., 1.);
  Tensor<2, dim>                         H;
  for (unsigned int i = 0; i < dim; ++i)
    for (unsigned int j = 0; j < dim; ++j)
      H[i][j] = 0.3 * random(rng);
  const Tensor<2, dim> F_exact = unit_symmetric_tensor<dim>() + H;

  for (const std::string bc : {"", "BC"})
    for (const std::string base : {"WTE1", "WLS1", "MLS1", "MTE1"})
      {
        FamilyElements<dim> elements(fixture.particles,
                                     fixture.families,
                                     parse_formulation_code(bc.empty() ?
                                                              "PBG Unl noBC" :
                                                              "BCPBG Unl"),
                                     ShapeFunctions::parse_base(base),
                                     1.);
        elements.initialize();
        double consistency = 0, mapping = 0;
        for (unsigned int k = 0; k < fixture.families.n_families(); ++k)
          {
            QuadratureTable<dim> table;
            elements.build(k, table);
            const auto                  geometry = elements.geometry(k);
            const auto                 &X        = geometry.bonds;
            std::vector<Tensor<1, dim>> y(X.size()), x(X.size());
            for (unsigned int b = 0; b < X.size(); ++b)
              {
                y[b] = F_exact * X[b];
                x[b] = X[b];
                for (unsigned int c = 0; c < dim; ++c)
                  x[b][c] += 0.2 * X[b].norm() * random(rng);
              }
            // PBG Unl: point q is member j (q = 0 is the master)
            for (unsigned int q = 0; q < table.n_points(); ++q)
              {
                consistency = std::max(
                  consistency,
                  (deformation_gradient(table, q, y) - F_exact).norm());
                if (q > 0)
                  mapping = std::max(mapping,
                                     (deformation_gradient(table, q, x) * X[q] -
                                      (x[q] - x[0]))
                                         .norm() /
                                       X[q].norm());
              }
          }
        deallog << dim << "d " << (bc.empty() ? "   " : "BC ") << base
                << ": F exact for linear fields: "
                << (consistency < 1e-12 ? "yes" : "NO") << ", bond mapping: "
                << (mapping < 1e-12 ? "exact" : "not exact") << std::endl;
        if (consistency >= 1e-12)
          deallog << "  max |F - F_exact| = " << consistency << std::endl;
      }

  // u_i = H_ij X_j + C_ijk X_j X_k with C symmetric in j, k
  Tensor<3, dim> C;
  for (unsigned int i = 0; i < dim; ++i)
    for (unsigned int j = 0; j < dim; ++j)
      for (unsigned int k = j; k < dim; ++k)
        C[i][j][k] = C[i][k][j] = 0.2 * random(rng);
  const auto position = [&](const Point<dim> &X) {
    Tensor<1, dim> x = X + H * X;
    for (unsigned int i = 0; i < dim; ++i)
      x[i] += X * (C[i] * X);
    return x;
  };
  FamilyElements<dim> elements(fixture.particles,
                               fixture.families,
                               parse_formulation_code("PBG U2"),
                               ShapeFunctions::Base::mte1,
                               1.);
  elements.initialize();
  double consistency = 0;
  for (unsigned int k = 0; k < fixture.families.n_families(); ++k)
    {
      QuadratureTable<dim> table;
      elements.build(k, table);
      const auto                  members = fixture.families.members(k);
      std::vector<Tensor<1, dim>> y(members.size());
      for (unsigned int b = 0; b < members.size(); ++b)
        y[b] = position(fixture.particles.position(members[b])) -
               position(fixture.particles.position(members[0]));
      for (unsigned int q = 0; q < table.n_points(); ++q)
        {
          Tensor<2, dim> F = F_exact;
          for (unsigned int i = 0; i < dim; ++i)
            F[i] += 2. * (C[i] * table.points[q]);
          consistency =
            std::max(consistency,
                     (deformation_gradient(table, q, y) - F).norm());
        }
    }
  deallog << dim << "d U2 (WTE2): F exact for quadratic fields: "
          << (consistency < 1e-11 ? "yes" : "NO") << std::endl;
  if (consistency >= 1e-11)
    deallog << "  max |F - F_exact| = " << consistency << std::endl;
}



int
main()
{
  initlog();
  test<2>();
  test<3>();
}
