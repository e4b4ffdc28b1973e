#include <pg/shape_functions/correction_functions.h>

#include <Eigen/Dense>

#include <cmath>

namespace pg
{
  namespace ShapeFunctions
  {
    template <int dim>
    std::vector<double>
    correction_function(const FormulationCode::CorrectionFunction function,
                        const FamilyGeometry<dim>                &family)
    {
      const unsigned int  n = family.bonds.size();
      std::vector<double> phi(n, 0.);
      if (function == FormulationCode::CorrectionFunction::v1)
        for (unsigned int i = 1; i < n; ++i)
          phi[i] = 1.;
      else
        {
          // N^{kki}_MLS1 = omega^{ki} V^i p^{ki} . M^{-1} . p(0), with the
          // linear basis p = (1, dX / h) and the self-weight omega^{kk} = 0.
          using Vec = Eigen::Matrix<double, dim + 1, 1>;
          using Mat = Eigen::Matrix<double, dim + 1, dim + 1>;
          double h  = 0;
          for (const auto &b : family.bonds)
            h = std::max(h, b.norm());
          std::vector<Vec>    p(n);
          std::vector<double> w(n, 0.);
          Mat                 M = Mat::Zero();
          for (unsigned int i = 1; i < n; ++i)
            {
              p[i](0) = 1.;
              for (unsigned int a = 0; a < dim; ++a)
                p[i](a + 1) = family.bonds[i][a] / h;
              w[i] = std::pow(family.bonds[i].norm_square(),
                              -family.weight_exponent) *
                     family.volumes[i];
              M += w[i] * p[i] * p[i].transpose();
            }
          Vec e0          = Vec::Zero();
          e0(0)           = 1.;
          const Vec gamma = M.fullPivLu().solve(e0);
          for (unsigned int i = 1; i < n; ++i)
            phi[i] = w[i] * p[i].dot(gamma);
        }
      double sum = 0;
      for (unsigned int i = 1; i < n; ++i)
        sum += phi[i];
      phi[0] = -sum;
      return phi;
    }



    template std::vector<double>
    correction_function<2>(const FormulationCode::CorrectionFunction,
                           const FamilyGeometry<2> &);
    template std::vector<double>
    correction_function<3>(const FormulationCode::CorrectionFunction,
                           const FamilyGeometry<3> &);
  } // namespace ShapeFunctions
} // namespace pg
