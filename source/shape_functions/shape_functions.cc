#include <pg/shape_functions/shape_functions.h>

#include <deal.II/base/exceptions.h>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <limits>

namespace pg
{
  namespace ShapeFunctions
  {
    namespace
    {
      /**
       * omega = |dX|^(-2n) (eqs. 4.5, 5.42); the self-weight is zero. The
       * default n = 1 is a division, the correctly rounded 1/r2: glibc's
       * std::pow(r2, -1.) costs about 100 instructions (MTE1 evaluates N^2
       * weights per family) and is one ulp off for about 0.08 % of the
       * arguments.
       */
      inline double
      weight(const double r2, const double n)
      {
        if (r2 == 0.)
          return 0.;
        return (n == 1.) ? 1. / r2 : std::pow(r2, -n);
      }



      /** Condition number of a symmetric positive (semi)definite matrix. */
      template <typename Matrix>
      double
      condition_number(const Matrix &m)
      {
        const Eigen::SelfAdjointEigenSolver<Matrix> eigen(
          m,
          Eigen::EigenvaluesOnly);
        const double lmin = eigen.eigenvalues().minCoeff();
        const double lmax = eigen.eigenvalues().maxCoeff();
        if (!(lmin > 0.) || !std::isfinite(lmax))
          return std::numeric_limits<double>::infinity();
        return lmax / lmin;
      }



      /**
       * The largest bond length of the family: the basis scale h. One square
       * root of the largest |dX|^2 (sqrt is monotone and correctly rounded,
       * so this is the largest of the norms, bit for bit).
       */
      template <int dim>
      double
      family_scale(const FamilyGeometry<dim> &family)
      {
        double h2 = 0;
        for (const auto &b : family.bonds)
          h2 = std::max(h2, b.norm_square());
        const double h = std::sqrt(h2);
        return (h > 0 ? h : 1.);
      }



      /**
       * Taylor bases (WTE1 about the master, MTE1 about the point):
       * g^i = omega^{ci} V^i M^{-1} dX^{ci} for i != c, g^c = -sum, with the
       * centre c and M = sum_{i != c} omega^{ci} V^i dX^{ci} (x) dX^{ci}.
       */
      template <int dim>
      double
      taylor_gradients(const FamilyGeometry<dim>   &family,
                       const unsigned int           centre,
                       std::vector<Tensor<1, dim>> &g)
      {
        const unsigned int              n = family.bonds.size();
        const double                    h = family_scale(family);
        Eigen::Matrix<double, dim, dim> M =
          Eigen::Matrix<double, dim, dim>::Zero();
        std::vector<Tensor<1, dim>> d(n);
        std::vector<double>         w(n);
        for (unsigned int i = 0; i < n; ++i)
          {
            d[i] = (family.bonds[i] - family.bonds[centre]) / h;
            w[i] = weight(d[i].norm_square(), family.weight_exponent) *
                   family.volumes[i];
            for (unsigned int a = 0; a < dim; ++a)
              for (unsigned int b = 0; b < dim; ++b)
                M(a, b) += w[i] * d[i][a] * d[i][b];
          }
        const double cond = condition_number(M);
        if (!std::isfinite(cond))
          return cond;
        const Eigen::Matrix<double, dim, dim> Minv = M.inverse();
        g.assign(n, Tensor<1, dim>());
        for (unsigned int i = 0; i < n; ++i)
          if (i != centre)
            {
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int b = 0; b < dim; ++b)
                  g[i][a] += w[i] * Minv(a, b) * d[i][b] / h;
              g[centre] -= g[i];
            }
        return cond;
      }



      /**
       * WTE2 (pg-methods.md section 6.4): static weight about the master,
       * difference basis p = (x_a, x_a x_b (a <= b)) with x = (X - X^k)/h;
       * g^i = omega^{ki} V^i p^{ki} . M^{-1} . dp/dX(X^j) for i != 0 and
       * g^0 = -sum, M = sum_i omega^{ki} V^i p^{ki} (x) p^{ki}. The
       * gradients are linear in X^j - X^k, exact for quadratic fields.
       */
      template <int dim>
      double
      quadratic_taylor_gradients(const FamilyGeometry<dim>   &family,
                                 const unsigned int           point,
                                 std::vector<Tensor<1, dim>> &g)
      {
        constexpr int n_basis    = dim + dim * (dim + 1) / 2;
        using Vec                = Eigen::Matrix<double, n_basis, 1>;
        using Mat                = Eigen::Matrix<double, n_basis, n_basis>;
        const unsigned int n     = family.bonds.size();
        const double       h     = family_scale(family);
        const auto         basis = [](const Tensor<1, dim> &x) {
          Vec p;
          int m = 0;
          for (int a = 0; a < dim; ++a)
            p(m++) = x[a];
          for (int a = 0; a < dim; ++a)
            for (int b = a; b < dim; ++b)
              p(m++) = x[a] * x[b];
          return p;
        };

        std::vector<Vec>    p(n);
        std::vector<double> w(n);
        Mat                 M = Mat::Zero();
        for (unsigned int i = 1; i < n; ++i)
          {
            p[i] = basis(family.bonds[i] / h);
            w[i] = weight(family.bonds[i].norm_square() / (h * h),
                          family.weight_exponent) *
                   family.volumes[i];
            M += w[i] * p[i] * p[i].transpose();
          }
        const double cond = condition_number(M);
        if (!std::isfinite(cond))
          return cond;
        const Mat Minv = M.inverse();

        // dp/dX_c at the point: e_c for the linear monomials, the product
        // rule for the quadratic ones (each divided by h)
        const Tensor<1, dim>                x = family.bonds[point] / h;
        Eigen::Matrix<double, n_basis, dim> dp =
          Eigen::Matrix<double, n_basis, dim>::Zero();
        int m = 0;
        for (int a = 0; a < dim; ++a)
          dp(m++, a) = 1. / h;
        for (int a = 0; a < dim; ++a)
          for (int b = a; b < dim; ++b, ++m)
            {
              dp(m, a) += x[b] / h;
              dp(m, b) += x[a] / h;
            }
        const Eigen::Matrix<double, n_basis, dim> gamma = Minv * dp;

        g.assign(n, Tensor<1, dim>());
        for (unsigned int i = 1; i < n; ++i)
          {
            for (int c = 0; c < dim; ++c)
              g[i][c] = w[i] * p[i].dot(gamma.col(c));
            g[0] -= g[i];
          }
        return cond;
      }



      /**
       * Least-squares bases with the linear basis p = (1, (X - X^k)/h).
       * WLS1: static weight about the master, gradient dN_i/dX =
       * omega^{ki} V^i p^{ki} . M^{-1} . dp/dX (eq. 5.45).
       * MLS1: moving weight about the point j with omega^{jj} = 0 held fixed;
       * the full derivative of the moment matrix (pg-methods.md section
       * 6.3), since the shortcut (5.46) is invalid with the self-weight
       * exception.
       */
      template <int dim>
      double
      least_squares_gradients(const FamilyGeometry<dim>   &family,
                              const unsigned int           point,
                              const bool                   moving,
                              std::vector<Tensor<1, dim>> &g)
      {
        using Vec                 = Eigen::Matrix<double, dim + 1, 1>;
        using Mat                 = Eigen::Matrix<double, dim + 1, dim + 1>;
        const unsigned int n      = family.bonds.size();
        const double       h      = family_scale(family);
        const double       e      = family.weight_exponent;
        const unsigned int centre = moving ? point : 0;

        std::vector<Vec>            p(n);
        std::vector<double>         w(n);
        std::vector<Tensor<1, dim>> dw(n); // d omega_i / dX at the point
        Mat                         M = Mat::Zero();
        for (unsigned int i = 0; i < n; ++i)
          {
            p[i](0) = 1.;
            for (unsigned int a = 0; a < dim; ++a)
              p[i](a + 1) = family.bonds[i][a] / h;
            const Tensor<1, dim> r  = family.bonds[i] - family.bonds[centre];
            const double         r2 = r.norm_square();
            w[i]                    = weight(r2, e) * family.volumes[i];
            // d|X^i - X|^(-2n)/dX = 2n (X^i - X) |X^i - X|^(-2n-2)
            if (moving && i != centre)
              dw[i] = 2. * e * r * std::pow(r2, -e - 1.) * family.volumes[i];
            M += w[i] * p[i] * p[i].transpose();
          }
        // conditioning of the scaled matrix (basis normalised by h)
        Mat          Ms   = M / M.norm();
        const double cond = condition_number(Ms);
        if (!std::isfinite(cond))
          return cond;
        const Mat Minv = M.inverse();

        Vec px;
        px(0) = 1.;
        for (unsigned int a = 0; a < dim; ++a)
          px(a + 1) = family.bonds[point][a] / h;
        const Vec gamma = Minv * px;

        g.assign(n, Tensor<1, dim>());
        for (unsigned int a = 0; a < dim; ++a)
          {
            Vec dp    = Vec::Zero();
            dp(a + 1) = 1. / h;
            Mat dM    = Mat::Zero();
            if (moving)
              for (unsigned int l = 0; l < n; ++l)
                dM += dw[l][a] * p[l] * p[l].transpose();
            const Vec dgamma = Minv * (dp - dM * gamma);
            for (unsigned int i = 0; i < n; ++i)
              g[i][a] = dw[i][a] * p[i].dot(gamma) + w[i] * p[i].dot(dgamma);
          }
        return cond;
      }
    } // namespace



    Base
    parse_base(const std::string &name)
    {
      if (name == "MTE1")
        return Base::mte1;
      if (name == "MLS1")
        return Base::mls1;
      if (name == "WLS1")
        return Base::wls1;
      AssertThrow(name == "WTE1",
                  ExcMessage("The entry 'Shape functions' in subsection "
                             "'Discretization' has the value <" +
                             name + ">; valid are MTE1, MLS1, WLS1, WTE1."));
      return Base::wte1;
    }



    template <int dim>
    double
    raw_gradients(const Base                   base,
                  const FamilyGeometry<dim>   &family,
                  const unsigned int           point,
                  std::vector<Tensor<1, dim>> &gradients)
    {
      AssertIndexRange(point, family.bonds.size());
      switch (base)
        {
          case Base::mte1:
            return taylor_gradients(family, point, gradients);
          case Base::wte1:
            return taylor_gradients(family, 0, gradients);
          case Base::mls1:
            return least_squares_gradients(family, point, true, gradients);
          case Base::wls1:
            return least_squares_gradients(family, point, false, gradients);
          case Base::wte2:
            return quadratic_taylor_gradients(family, point, gradients);
        }
      Assert(false, ExcInternalError());
      return 0;
    }



    template <int dim>
    void
    apply_bond_correction(const FamilyGeometry<dim>   &family,
                          const unsigned int           point,
                          std::vector<Tensor<1, dim>> &gradients)
    {
      Assert(point != 0, ExcInternalError());
      const Tensor<1, dim> &bond = family.bonds[point];
      const double          b2   = bond.norm_square();
      for (unsigned int i = 0; i < gradients.size(); ++i)
        {
          // (1 - n (x) n) g = g - bond (bond . g) / |bond|^2
          gradients[i] -= bond * ((bond * gradients[i]) / b2);
          if (i == point)
            gradients[i] += bond / b2;
        }
    }



    template <int dim>
    void
    make_effective(std::vector<Tensor<1, dim>> &gradients)
    {
      Tensor<1, dim> sum;
      for (unsigned int i = 1; i < gradients.size(); ++i)
        sum += gradients[i];
      gradients[0] = -sum;
    }



    template <int dim>
    double
    mls1_second_derivatives(const FamilyGeometry<dim>   &family,
                            const double                 self_weight,
                            std::vector<Tensor<2, dim>> &h)
    {
      using Vec            = Eigen::Matrix<double, dim + 1, 1>;
      using Mat            = Eigen::Matrix<double, dim + 1, dim + 1>;
      const unsigned int n = family.bonds.size();
      const double       L = family_scale(family); // basis scaling only
      const double       e = family.weight_exponent;

      // At X = X^k: omega_i, d omega_i / dX_A, d^2 omega_i / dX_A dX_B of
      // omega = |d|^(-2e), d = X^i - X (pg-methods.md section 6.3), times V^i
      std::vector<Vec>                      p(n);
      std::vector<double>                   w(n);
      std::vector<Tensor<1, dim>>           dw(n);
      std::vector<Tensor<2, dim>>           ddw(n);
      Mat                                   M = Mat::Zero();
      std::array<Mat, dim>                  dM;
      std::array<std::array<Mat, dim>, dim> ddM;
      for (unsigned int a = 0; a < dim; ++a)
        {
          dM[a] = Mat::Zero();
          for (unsigned int b = 0; b < dim; ++b)
            ddM[a][b] = Mat::Zero();
        }
      for (unsigned int i = 0; i < n; ++i)
        {
          p[i](0) = 1.;
          for (unsigned int a = 0; a < dim; ++a)
            p[i](a + 1) = family.bonds[i][a] / L;
          const Tensor<1, dim> &d  = family.bonds[i];
          const double          r2 = d.norm_square();
          const double          V  = family.volumes[i];
          if (i == 0)
            w[i] = self_weight * V;
          else
            {
              w[i]            = weight(r2, e) * V;
              const double c1 = 2. * e * std::pow(r2, -e - 1.) * V;
              const double c2 =
                2. * e * (2. * e + 2.) * std::pow(r2, -e - 2.) * V;
              dw[i] = c1 * d;
              for (unsigned int a = 0; a < dim; ++a)
                for (unsigned int b = 0; b < dim; ++b)
                  ddw[i][a][b] = -c1 * (a == b) + c2 * d[a] * d[b];
            }
          const Mat pp = p[i] * p[i].transpose();
          M += w[i] * pp;
          for (unsigned int a = 0; a < dim; ++a)
            {
              dM[a] += dw[i][a] * pp;
              for (unsigned int b = 0; b < dim; ++b)
                ddM[a][b] += ddw[i][a][b] * pp;
            }
        }
      const double cond = condition_number(Mat(M / M.norm()));
      h.assign(n, Tensor<2, dim>());
      if (!std::isfinite(cond))
        return cond;
      const Mat Minv = M.inverse();

      // gamma = M^{-1} p(X - X^k) at X = X^k, and its derivatives
      // (d p / dX_A = e_{A+1} / L, d^2 p = 0)
      Vec p0                     = Vec::Zero();
      p0(0)                      = 1.;
      const Vec            gamma = Minv * p0;
      std::array<Vec, dim> dgamma;
      for (unsigned int a = 0; a < dim; ++a)
        {
          Vec dp    = Vec::Zero();
          dp(a + 1) = 1. / L;
          dgamma[a] = Minv * (dp - dM[a] * gamma);
        }
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = a; b < dim; ++b)
          {
            const Vec ddgamma = Minv * (-ddM[a][b] * gamma - dM[a] * dgamma[b] -
                                        dM[b] * dgamma[a]);
            for (unsigned int i = 0; i < n; ++i)
              {
                const double value = ddw[i][a][b] * p[i].dot(gamma) +
                                     dw[i][a] * p[i].dot(dgamma[b]) +
                                     dw[i][b] * p[i].dot(dgamma[a]) +
                                     w[i] * p[i].dot(ddgamma);
                h[i][a][b] = value;
                h[i][b][a] = value;
              }
          }
      return cond;
    }



    template double
    mls1_second_derivatives<2>(const FamilyGeometry<2> &,
                               const double,
                               std::vector<Tensor<2, 2>> &);
    template double
    mls1_second_derivatives<3>(const FamilyGeometry<3> &,
                               const double,
                               std::vector<Tensor<2, 3>> &);
    template double
    raw_gradients<2>(const Base,
                     const FamilyGeometry<2> &,
                     const unsigned int,
                     std::vector<Tensor<1, 2>> &);
    template double
    raw_gradients<3>(const Base,
                     const FamilyGeometry<3> &,
                     const unsigned int,
                     std::vector<Tensor<1, 3>> &);
    template void
    apply_bond_correction<2>(const FamilyGeometry<2> &,
                             const unsigned int,
                             std::vector<Tensor<1, 2>> &);
    template void
    apply_bond_correction<3>(const FamilyGeometry<3> &,
                             const unsigned int,
                             std::vector<Tensor<1, 3>> &);
    template void
    make_effective<2>(std::vector<Tensor<1, 2>> &);
    template void
    make_effective<3>(std::vector<Tensor<1, 3>> &);
  } // namespace ShapeFunctions
} // namespace pg
