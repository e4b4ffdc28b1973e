// The VC correction functions V1 ... V5 (eqs. 5.60-5.64,
// shape_functions/correction_functions.h) keep what pg-methods.md section
// 11.2 says they keep, on every family of a distorted particle set in 2-D
// and 3-D (horizon 3.01 h, so that the WLS2 fits of V2 and V4 have enough
// neighbours at the corners):
//   zeroth order  sum_i Phi^i = 0                       (all),
//   first order   sum_i dX^i (x) Phi^i = 0               (V2 ... V5),
//   second order  sum_i dX^i (x) dX^i (x) Phi^i = 0      (V4),
// and V2, the diagonal of the WLS2 Hessian, differentiates every quadratic
// field exactly: sum_i dX^i_a dX^i_b Phi^i_d = 2 delta_ad delta_bd.
// V1 keeps only zeroth order, V3 and V5 not the second.

#include <pg/shape_functions/correction_functions.h>

#include "../particle_fixture.h"
#include "../tests.h"

using namespace pg;

template <int dim>
void
test()
{
  const ParticleFixture<dim> fixture(dim == 2 ? 6 : 3, 0.25, 3.01);
  using CF = FormulationCode::CorrectionFunction;
  for (const auto [function, name] : {std::pair{CF::v1, "V1"},
                                      std::pair{CF::v2, "V2"},
                                      std::pair{CF::v3, "V3"},
                                      std::pair{CF::v4, "V4"},
                                      std::pair{CF::v5, "V5"}})
    {
      double zeroth = 0, first = 0, second = 0, hessian = 0, cond = 0;
      for (unsigned int k = 0; k < fixture.particles.n_particles(); ++k)
        {
          const ShapeFunctions::FamilyGeometry<dim> family =
            fixture.family_geometry(k);
          std::vector<Tensor<1, dim>> phi;
          cond     = std::max(cond,
                          ShapeFunctions::correction_function(function,
                                                              family,
                                                              phi));
          double h = 0;
          for (const auto &b : family.bonds)
            h = std::max(h, b.norm());
          // scaled by the size of Phi (1 for V1 ... V5, 1/h^2 for V2)
          double scale = 0;
          for (const auto &p : phi)
            scale = std::max(scale, p.norm());
          Tensor<1, dim> s0;
          Tensor<2, dim> s1;
          Tensor<3, dim> s2;
          for (unsigned int i = 0; i < phi.size(); ++i)
            {
              const Tensor<1, dim> &x = family.bonds[i];
              s0 += phi[i];
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    s1[a][d] += x[a] * phi[i][d];
                    for (unsigned int b = 0; b < dim; ++b)
                      s2[a][b][d] += x[a] * x[b] * phi[i][d];
                  }
            }
          zeroth = std::max(zeroth, s0.norm() / scale);
          first  = std::max(first, s1.norm() / (scale * h));
          if (function == CF::v2)
            {
              Tensor<3, dim> exact;
              for (unsigned int d = 0; d < dim; ++d)
                exact[d][d][d] = 2.;
              hessian = std::max(hessian, (s2 - exact).norm() / 2.);
            }
          else
            second = std::max(second, s2.norm() / (scale * h * h));
        }
      const auto kept = [](const double v) {
        return v < 1e-12 ? std::string("kept") : std::string("not kept");
      };
      deallog << dim << "d " << name << ": zeroth order " << kept(zeroth)
              << ", first order " << kept(first);
      if (function == CF::v2)
        deallog << ", quadratic Hessian exact: "
                << (hessian < 1e-10 ? "yes" : "NO");
      else
        deallog << ", second order " << kept(second);
      deallog << ", condition number below 1e6: " << (cond < 1e6 ? "yes" : "NO")
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
