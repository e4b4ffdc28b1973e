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
                           U1SUnlScratch                     &scratch,
                           const ArrayView<const double>     &committed_state,
                           const ArrayView<double>           &trial_state)
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
    assemble_element(u1_table,
                     y,
                     material,
                     residual,
                     tangent,
                     committed_state,
                     trial_state);
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



  template <int dim>
  double
  particle_second_moment(const double volume)
  {
    if (dim == 3)
      return std::pow(3. / numbers::PI, 2. / 3.) /
             (10. * std::pow(2., 1. / 3.)) * std::pow(volume, 5. / 3.);
    return volume * volume / (4. * numbers::PI);
  }



  template <int dim>
  void
  add_implicit_gradient_stabilisation(const std::vector<Tensor<2, dim>> &h,
                                      const double          second_moment,
                                      const Tensor<4, dim> &A,
                                      const std::vector<Tensor<1, dim>> &y,
                                      Vector<double>     &residual,
                                      FullMatrix<double> *tangent)
  {
    const unsigned int n = h.size();
    AssertDimension(y.size(), n);
    AssertDimension(residual.size(), n * dim);
    // G_{CDE} = sum_b y^b_C h^b_{DE}, and S_{ABE} = M A_{ABCD} G_{CDE}
    Tensor<3, dim> G;
    for (unsigned int b = 0; b < n; ++b)
      for (unsigned int C = 0; C < dim; ++C)
        for (unsigned int D = 0; D < dim; ++D)
          for (unsigned int E = 0; E < dim; ++E)
            G[C][D][E] += y[b][C] * h[b][D][E];
    Tensor<3, dim> S;
    for (unsigned int A_ = 0; A_ < dim; ++A_)
      for (unsigned int B = 0; B < dim; ++B)
        for (unsigned int E = 0; E < dim; ++E)
          {
            double value = 0;
            for (unsigned int C = 0; C < dim; ++C)
              for (unsigned int D = 0; D < dim; ++D)
                value += A[A_][B][C][D] * G[C][D][E];
            S[A_][B][E] = second_moment * value;
          }
    for (unsigned int a = 0; a < n; ++a)
      for (unsigned int A_ = 0; A_ < dim; ++A_)
        {
          double value = 0;
          for (unsigned int B = 0; B < dim; ++B)
            for (unsigned int E = 0; E < dim; ++E)
              value += h[a][B][E] * S[A_][B][E];
          residual[a * dim + A_] += value;
        }
    if (tangent == nullptr)
      return;
    // K_{aA,bC} = M h^a_{BE} A_{ABCD} h^b_{DE}: first T^b_{ABCE} =
    // A_{ABCD} h^b_{DE}
    Tensor<4, dim> T;
    for (unsigned int b = 0; b < n; ++b)
      {
        for (unsigned int A_ = 0; A_ < dim; ++A_)
          for (unsigned int B = 0; B < dim; ++B)
            for (unsigned int C = 0; C < dim; ++C)
              for (unsigned int E = 0; E < dim; ++E)
                {
                  double value = 0;
                  for (unsigned int D = 0; D < dim; ++D)
                    value += A[A_][B][C][D] * h[b][D][E];
                  T[A_][B][C][E] = second_moment * value;
                }
        for (unsigned int a = 0; a < n; ++a)
          for (unsigned int A_ = 0; A_ < dim; ++A_)
            for (unsigned int C = 0; C < dim; ++C)
              {
                double value = 0;
                for (unsigned int B = 0; B < dim; ++B)
                  for (unsigned int E = 0; E < dim; ++E)
                    value += h[a][B][E] * T[A_][B][C][E];
                (*tangent)(a * dim + A_, b * dim + C) += value;
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
                           U1SUnlScratch &,
                           const ArrayView<const double> &,
                           const ArrayView<double> &);
  template void
  assemble_u1s_unl_element(const QuadratureTable<3> &,
                           const QuadratureTable<3> &,
                           const std::vector<Tensor<1, 3>> &,
                           const Materials::Material<3> &,
                           const Materials::Material<3> &,
                           Vector<double> &,
                           FullMatrix<double> *,
                           U1SUnlScratch &,
                           const ArrayView<const double> &,
                           const ArrayView<double> &);
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
  template double
  particle_second_moment<2>(const double);
  template double
  particle_second_moment<3>(const double);
  template void
  add_implicit_gradient_stabilisation<2>(const std::vector<Tensor<2, 2>> &,
                                         const double,
                                         const Tensor<4, 2> &,
                                         const std::vector<Tensor<1, 2>> &,
                                         Vector<double> &,
                                         FullMatrix<double> *);
  template void
  add_implicit_gradient_stabilisation<3>(const std::vector<Tensor<2, 3>> &,
                                         const double,
                                         const Tensor<4, 3> &,
                                         const std::vector<Tensor<1, 3>> &,
                                         Vector<double> &,
                                         FullMatrix<double> *);
} // namespace pg
