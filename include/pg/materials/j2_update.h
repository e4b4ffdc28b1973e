#ifndef pg_materials_j2_update_h
#define pg_materials_j2_update_h

#include <deal.II/base/config.h>

#include <pg/base/global.h>
#include <pg/materials/small_matrix.h>

#include <deal.II/base/tensor.h>

#ifndef DEAL_II_TRILINOS_WITH_SACADO
#  error "J2 plasticity needs deal.II with Trilinos' Sacado (forward AD)."
#endif

#include <Sacado.hpp>

#include <array>
#include <cmath>

namespace pg
{
  namespace Materials
  {
    /**
     * The local update of J2Plasticity (eq. 4.41) at one evaluation point,
     * in any number type: the residual R(x; b_e^tr, J) of the unknowns
     * x = (b_e, Delta alpha), its Newton solution with the local Jacobian
     * (4.42) by forward AD, the stresses, and the correction step that
     * carries the derivatives dx/dF of the implicit function (4.62). See
     * the documentation of J2Plasticity for the equations. b_e is 3x3 (the
     * plane strain state is 3-D); stresses and moduli are force per area,
     * b_e, C_p^{-1} and alpha dimensionless.
     */
    namespace J2
    {
      using namespace SmallMatrix;

      /** Unknowns of the local problem: b_e (6 components), Delta alpha. */
      inline constexpr unsigned int n_unknowns = 7;

      /** Forward AD numbers for the local Jacobian (derivatives by x). */
      using LocalAD = Sacado::Fad::SFad<double, n_unknowns>;

      /** Forward AD numbers for the tangent (derivatives by the F_AB). */
      template <int dim>
      using TangentAD = Sacado::Fad::SFad<double, dim * dim>;

      /** Rows and columns of the 6 symmetric components, in state order. */
      inline constexpr unsigned int voigt_row[6]    = {0, 1, 2, 0, 0, 1};
      inline constexpr unsigned int voigt_column[6] = {0, 1, 2, 1, 2, 2};

      /** The material constants the local functions need. */
      struct Constants
      {
        double mu, kappa;
        double sigma_y0, sigma_y_inf, H, delta;

        /** sigma_y(alpha) of eq. (2.49). */
        template <typename Number>
        Number
        yield_stress(const Number &alpha) const
        {
          using std::exp;
          return sigma_y0 + H * alpha +
                 (sigma_y_inf - sigma_y0) * (1. - exp(-delta * alpha));
        }
      };

      /** The symmetric matrix of the 6 components @p v (state order). */
      template <typename Number>
      Matrix3<Number>
      symmetric_matrix(const Number *v)
      {
        Matrix3<Number> M;
        for (unsigned int i = 0; i < 6; ++i)
          {
            M[voigt_row[i]][voigt_column[i]] = v[i];
            M[voigt_column[i]][voigt_row[i]] = v[i];
          }
        return M;
      }

      /** The 3x3 F of the in-plane @p F (plane strain: F_33 = 1). */
      template <int dim>
      Matrix3<double>
      embed(const Tensor<2, dim> &F)
      {
        Matrix3<double> F3 = identity<double>();
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            F3[a][b] = F[a][b];
        return F3;
      }

      /**
       * The 3x3 F in AD numbers whose derivative directions are the
       * in-plane components F_ab (direction a dim + b).
       */
      template <int dim>
      Matrix3<TangentAD<dim>>
      embed_ad(const Tensor<2, dim> &F)
      {
        Matrix3<TangentAD<dim>> F3 = identity<TangentAD<dim>>();
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            F3[a][b] = TangentAD<dim>(dim * dim, a * dim + b, F[a][b]);
        return F3;
      }

      /** A matrix of doubles as constants of type Number. */
      template <typename Number>
      Matrix3<Number>
      convert(const Matrix3<double> &M)
      {
        Matrix3<Number> R;
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = 0; b < 3; ++b)
            R[a][b] = M[a][b];
        return R;
      }

      /** tau_iso = mu dev(J^{-2/3} b_e). */
      template <typename Number>
      Matrix3<Number>
      isochoric_kirchhoff_stress(const Constants       &c,
                                 const Matrix3<Number> &b_e,
                                 const Number          &J)
      {
        using std::pow;
        const Number    factor = c.mu * pow(J, -2. / 3.);
        const Number    mean   = trace(b_e) / 3.;
        Matrix3<Number> tau;
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = 0; b < 3; ++b)
            tau[a][b] = factor * (b_e[a][b] - (a == b ? mean : Number(0.)));
        return tau;
      }

      /** sigma_vM = sqrt(3/2 tau_iso : tau_iso) (tau_iso is deviatoric). */
      template <typename Number>
      Number
      von_mises(const Matrix3<Number> &tau_iso)
      {
        using std::sqrt;
        return sqrt(1.5 * squared_norm(tau_iso));
      }

      /**
       * tau = tau_iso + K/2 (J^2 - 1) 1 (or tau_iso alone) and
       * P = tau F^{-T}.
       */
      template <typename Number>
      Matrix3<Number>
      piola_stress(const Constants       &c,
                   const Matrix3<Number> &b_e,
                   const Matrix3<Number> &F,
                   const Number          &J,
                   const bool             with_volumetric_part)
      {
        Matrix3<Number> tau = isochoric_kirchhoff_stress(c, b_e, J);
        if (with_volumetric_part)
          {
            const Number p = 0.5 * c.kappa * (J * J - 1.);
            for (unsigned int a = 0; a < 3; ++a)
              tau[a][a] += p;
          }
        return multiply(tau, transpose(invert(F)));
      }

      /**
       * The local residual of the update (class documentation):
       * R_1 = b_e - exp(-Delta alpha n) b_e^tr exp(-Delta alpha n) (6
       * components) and R_2 = [sigma_vM - sigma_y(alpha_n + Delta alpha)] /
       * mu, at the unknowns @p x = (b_e, Delta alpha).
       */
      template <typename Number>
      std::array<Number, n_unknowns>
      residual(const Constants                      &c,
               const std::array<Number, n_unknowns> &x,
               const Matrix3<Number>                &b_e_trial,
               const Number                         &J,
               const double                          alpha_n)
      {
        const Matrix3<Number> b_e      = symmetric_matrix(x.data());
        const Number         &dalpha   = x[6];
        const Matrix3<Number> tau_iso  = isochoric_kirchhoff_stress(c, b_e, J);
        const Number          sigma_vm = von_mises(tau_iso);

        // -Delta alpha n = -Delta alpha 3/2 tau_iso / sigma_vM.
        Matrix3<Number> X;
        const Number    factor = -1.5 * dalpha / sigma_vm;
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = 0; b < 3; ++b)
            X[a][b] = factor * tau_iso[a][b];
        const Matrix3<Number> E = exponential(X);
        const Matrix3<Number> M = multiply(multiply(E, b_e_trial), E);

        std::array<Number, n_unknowns> R;
        for (unsigned int i = 0; i < 6; ++i)
          R[i] = b_e[voigt_row[i]][voigt_column[i]] -
                 M[voigt_row[i]][voigt_column[i]];
        const Number alpha = alpha_n + dalpha;
        R[6]               = (sigma_vm - c.yield_stress(alpha)) / c.mu;
        return R;
      }

      /** The converged local solution and the inverse local Jacobian. */
      struct LocalSolution
      {
        std::array<double, n_unknowns>                         x;
        std::array<std::array<double, n_unknowns>, n_unknowns> jacobian_inverse;
      };

      /**
       * Newton's method for R(x) = 0 from x = (b_e^tr, 0), with a
       * backtracking line search on |R|^2 that keeps Delta alpha >= 0.
       * Converged when max |R_1| <= 1e-12 max(1, max |b_e^tr|) and
       * |f| <= 1e-11 sigma_y(alpha_n) + 1e-14 mu, or, within 1e3 times
       * these, when no step decreases |R| any more (round-off); the caller
       * then polishes x with corrected_unknowns(), one more Newton step.
       * Returns x and the inverse of dR/dx there; throws, with advice,
       * after 50 iterations or when the line search fails. Call it only if
       * the elastic predictor gives f > 0.
       */
      LocalSolution
      solve_update(const Constants       &c,
                   const Matrix3<double> &b_e_trial,
                   const double           J,
                   const double           alpha_n);

      /**
       * One more Newton correction x - (dR/dx)^{-1} R(x, F) in the number
       * type of @p F (double, or AD numbers whose derivatives then are the
       * exact dx/dF of the implicit function, eq. 4.62).
       */
      template <typename Number>
      std::array<Number, n_unknowns>
      corrected_unknowns(const Constants       &c,
                         const LocalSolution   &solution,
                         const Matrix3<Number> &b_e_trial,
                         const Number          &J,
                         const double           alpha_n)
      {
        std::array<Number, n_unknowns> x;
        for (unsigned int i = 0; i < n_unknowns; ++i)
          x[i] = solution.x[i];
        const std::array<Number, n_unknowns> R =
          residual<Number>(c, x, b_e_trial, J, alpha_n);
        std::array<Number, n_unknowns> corrected;
        for (unsigned int i = 0; i < n_unknowns; ++i)
          {
            Number correction = solution.jacobian_inverse[i][0] * R[0];
            for (unsigned int j = 1; j < n_unknowns; ++j)
              correction += solution.jacobian_inverse[i][j] * R[j];
            corrected[i] = x[i] - correction;
          }
        return corrected;
      }

    } // namespace J2
  }   // namespace Materials
} // namespace pg

#endif
