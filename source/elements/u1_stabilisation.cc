#include <pg/elements/u1_stabilisation.h>

#include <deal.II/base/numbers.h>

#include <cmath>

namespace pg
{
  template <int dim>
  void
  assemble_u1s_unl_element(const QuadratureTable<dim>        &u1_table,
                           const QuadratureTable<dim>        &unl_table,
                           const std::vector<Tensor<1, dim>> &y,
                           const Materials::Material<dim>    &material,
                           const Materials::Material<dim>    &pseudo_material,
                           Vector<double>                    &residual,
                           FullMatrix<double>                *tangent,
                           U1SUnlScratch                     &scratch)
  {
    AssertDimension(u1_table.n_nodes, unl_table.n_nodes);
    FullMatrix<double> *term_tangent =
      (tangent != nullptr ? &scratch.tangent : nullptr);
    const auto add = [&](const double sign) {
      residual.add(sign, scratch.residual);
      if (tangent != nullptr)
        tangent->add(sign, scratch.tangent);
    };
    // V^k W(F^{kk}), then - V^k W~(F^{kk}) + sum_j w^{kj} W~(F^{kj})
    assemble_element(u1_table, y, material, residual, tangent);
    assemble_element(u1_table,
                     y,
                     pseudo_material,
                     scratch.residual,
                     term_tangent);
    add(-1.);
    assemble_element(unl_table,
                     y,
                     pseudo_material,
                     scratch.residual,
                     term_tangent);
    add(1.);
  }



  double
  hourglass_constant(const double alpha,
                     const double bulk_modulus,
                     const double horizon)
  {
    return 18. * alpha * bulk_modulus / (numbers::PI * std::pow(horizon, 4));
  }



  template <int dim>
  void
  add_hourglass_force(const QuadratureTable<dim>        &u1_table,
                      const std::vector<Tensor<1, dim>> &xi,
                      const std::vector<Tensor<1, dim>> &y,
                      const std::vector<double>         &volumes,
                      const double                       constant,
                      Vector<double>                    &residual,
                      FullMatrix<double>                *tangent)
  {
    const unsigned int n = u1_table.n_nodes;
    AssertDimension(u1_table.n_points(), 1);
    AssertDimension(xi.size(), n);
    AssertDimension(y.size(), n);
    AssertDimension(volumes.size(), n);
    const Tensor<2, dim> F = deformation_gradient(u1_table, 0, y);
    for (unsigned int j = 1; j < n; ++j)
      {
        const Tensor<1, dim> Y         = y[j] - y[0];
        const double         length    = Y.norm();
        const double         xi_length = xi[j].norm();
        const Tensor<1, dim> z         = F * xi[j] - Y;
        const double         phi       = z * Y;
        const double         c         = constant / xi_length;
        const double         weight    = volumes[0] * volumes[j];
        // t = -c phi Y / |Y|; internal force: -t at the master, +t at j
        const Tensor<1, dim> t = -c * phi / length * Y;
        for (unsigned int A = 0; A < dim; ++A)
          {
            residual[A] -= weight * t[A];
            residual[j * dim + A] += weight * t[A];
          }
        if (tangent == nullptr)
          continue;
        // with F xi = sum_b (B^b . xi) y^b:
        // dt = -c [ M dY + |Y| e (x) e sum_b (B^b . xi) dy^b ],
        // M = e (x) z - |Y| e (x) e + phi/|Y| (1 - e (x) e), dY = dy^j - dy^0
        const Tensor<1, dim> e = Y / length;
        Tensor<2, dim>       M, ee;
        for (unsigned int A = 0; A < dim; ++A)
          for (unsigned int C = 0; C < dim; ++C)
            {
              ee[A][C] = e[A] * e[C];
              M[A][C]  = e[A] * z[C] - length * ee[A][C] +
                        phi / length * ((A == C ? 1. : 0.) - ee[A][C]);
            }
        const unsigned int    point = 0;
        const Tensor<1, dim> *B     = &u1_table.trial[point * n];
        for (unsigned int b = 0; b < n; ++b)
          {
            // dt/dy^b (a dim x dim block)
            Tensor<2, dim> dt = -c * length * (B[b] * xi[j]) * ee;
            if (b == j)
              dt -= c * M;
            if (b == 0)
              dt += c * M;
            for (unsigned int A = 0; A < dim; ++A)
              for (unsigned int C = 0; C < dim; ++C)
                {
                  (*tangent)(A, b * dim + C) -= weight * dt[A][C];
                  (*tangent)(j * dim + A, b * dim + C) += weight * dt[A][C];
                }
          }
      }
  }



  template void
  assemble_u1s_unl_element(const QuadratureTable<2> &,
                           const QuadratureTable<2> &,
                           const std::vector<Tensor<1, 2>> &,
                           const Materials::Material<2> &,
                           const Materials::Material<2> &,
                           Vector<double> &,
                           FullMatrix<double> *,
                           U1SUnlScratch &);
  template void
  assemble_u1s_unl_element(const QuadratureTable<3> &,
                           const QuadratureTable<3> &,
                           const std::vector<Tensor<1, 3>> &,
                           const Materials::Material<3> &,
                           const Materials::Material<3> &,
                           Vector<double> &,
                           FullMatrix<double> *,
                           U1SUnlScratch &);
  template void
  add_hourglass_force(const QuadratureTable<2> &,
                      const std::vector<Tensor<1, 2>> &,
                      const std::vector<Tensor<1, 2>> &,
                      const std::vector<double> &,
                      const double,
                      Vector<double> &,
                      FullMatrix<double> *);
  template void
  add_hourglass_force(const QuadratureTable<3> &,
                      const std::vector<Tensor<1, 3>> &,
                      const std::vector<Tensor<1, 3>> &,
                      const std::vector<double> &,
                      const double,
                      Vector<double> &,
                      FullMatrix<double> *);
} // namespace pg
