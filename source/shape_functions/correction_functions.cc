#include <pg/shape_functions/correction_functions.h>

#include <Eigen/Dense>

#include <cmath>
#include <limits>

namespace pg
{
  namespace ShapeFunctions
  {
    template <int dim>
    double
    correction_function(const FormulationCode::CorrectionFunction function,
                        const FamilyGeometry<dim>                &family,
                        std::vector<Tensor<1, dim>>              &phi)
    {
      using CF             = FormulationCode::CorrectionFunction;
      const unsigned int n = family.bonds.size();
      phi.assign(n, Tensor<1, dim>());
      const auto every_component = [](const double value) {
        Tensor<1, dim> t;
        for (unsigned int d = 0; d < dim; ++d)
          t[d] = value;
        return t;
      };
      double condition_number = 1.;
      if (function == CF::v1)
        for (unsigned int i = 1; i < n; ++i)
          phi[i] = every_component(1.);
      else
        {
          // The least-squares fit about the master with the weights
          // omega^{ki} V^i and the self-weight omega^{kk} = 0: the basis
          // p = (1, dX / h) (MLS1 = WLS1 at the master: V3, V5) or with the
          // quadratic monomials dX_a dX_b / h^2, a <= b (WLS2: V2, V4).
          // N^{kki} = w_i p_i . M^{-1} p(0), and for V2 the second
          // derivative d2N^i/dX_d^2 = (2 / h^2) w_i p_i . M^{-1} e_(dd).
          const bool quadratic = (function == CF::v2 || function == CF::v4);
          const unsigned int m =
            1 + dim + (quadratic ? dim * (dim + 1) / 2 : 0);
          double h = 0;
          for (const auto &b : family.bonds)
            h = std::max(h, b.norm());
          std::vector<Eigen::VectorXd> p(n, Eigen::VectorXd::Zero(m));
          std::vector<double>          w(n, 0.);
          std::vector<unsigned int>    square(dim); // index of dX_d^2
          Eigen::MatrixXd              M = Eigen::MatrixXd::Zero(m, m);
          for (unsigned int i = 1; i < n; ++i)
            {
              const Tensor<1, dim> x = family.bonds[i] / h;
              p[i](0)                = 1.;
              unsigned int index     = 1;
              for (unsigned int a = 0; a < dim; ++a)
                p[i](index++) = x[a];
              if (quadratic)
                for (unsigned int a = 0; a < dim; ++a)
                  for (unsigned int b = a; b < dim; ++b)
                    {
                      if (a == b)
                        square[a] = index;
                      p[i](index++) = x[a] * x[b];
                    }
              w[i] = std::pow(family.bonds[i].norm_square(),
                              -family.weight_exponent) *
                     family.volumes[i];
              M += w[i] * p[i] * p[i].transpose();
            }
          const Eigen::JacobiSVD<Eigen::MatrixXd> svd(M);
          const auto                             &sigma = svd.singularValues();
          condition_number                              = sigma(m - 1) > 0. ?
                                                            sigma(0) / sigma(m - 1) :
                                                            std::numeric_limits<double>::infinity();
          const Eigen::FullPivLU<Eigen::MatrixXd> lu(M);
          const auto solve = [&](const unsigned int j) {
            Eigen::VectorXd e = Eigen::VectorXd::Zero(m);
            e(j)              = 1.;
            return Eigen::VectorXd(lu.solve(e));
          };
          if (function == CF::v2)
            for (unsigned int d = 0; d < dim; ++d)
              {
                const Eigen::VectorXd gamma = solve(square[d]);
                for (unsigned int i = 1; i < n; ++i)
                  phi[i][d] = 2. / (h * h) * w[i] * p[i].dot(gamma);
              }
          else
            {
              const Eigen::VectorXd gamma = solve(0);
              for (unsigned int i = 1; i < n; ++i)
                phi[i] = every_component(w[i] * p[i].dot(gamma));
            }
        }
      Tensor<1, dim> sum;
      for (unsigned int i = 1; i < n; ++i)
        sum += phi[i];
      phi[0] = -sum;
      return condition_number;
    }



    template double
    correction_function<2>(const FormulationCode::CorrectionFunction,
                           const FamilyGeometry<2> &,
                           std::vector<Tensor<1, 2>> &);
    template double
    correction_function<3>(const FormulationCode::CorrectionFunction,
                           const FamilyGeometry<3> &,
                           std::vector<Tensor<1, 3>> &);
  } // namespace ShapeFunctions
} // namespace pg
