#include <pg/base/exceptions.h>
#include <pg/materials/j2_update.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace pg
{
  namespace Materials
  {
    namespace J2
    {
      // Helpers of solve_update() (a named namespace: the unity build may
      // compile this file together with others).
      namespace UpdateInternal
      {
        /**
         * Solve the 7x7 system @p K y = @p r in place (Gaussian elimination
         * with partial pivoting); returns false if K is singular.
         */
        bool
        solve(std::array<std::array<double, n_unknowns>, n_unknowns> K,
              std::array<double, n_unknowns>                        &r)
        {
          constexpr unsigned int n = n_unknowns;
          for (unsigned int k = 0; k < n; ++k)
            {
              unsigned int pivot = k;
              for (unsigned int i = k + 1; i < n; ++i)
                if (std::abs(K[i][k]) > std::abs(K[pivot][k]))
                  pivot = i;
              if (!(std::abs(K[pivot][k]) > 0.))
                return false;
              std::swap(K[k], K[pivot]);
              std::swap(r[k], r[pivot]);
              for (unsigned int i = k + 1; i < n; ++i)
                {
                  const double l = K[i][k] / K[k][k];
                  for (unsigned int j = k; j < n; ++j)
                    K[i][j] -= l * K[k][j];
                  r[i] -= l * r[k];
                }
            }
          for (unsigned int k = n; k-- > 0;)
            {
              for (unsigned int j = k + 1; j < n; ++j)
                r[k] -= K[k][j] * r[j];
              r[k] /= K[k][k];
            }
          return true;
        }

        /** Values and local Jacobian dR/dx of the residual at @p x. */
        void
        residual_and_jacobian(
          const Constants                                        &c,
          const std::array<double, n_unknowns>                   &x,
          const Matrix3<double>                                  &b_e_trial,
          const double                                            J,
          const double                                            alpha_n,
          std::array<double, n_unknowns>                         &R,
          std::array<std::array<double, n_unknowns>, n_unknowns> &K)
        {
          std::array<LocalAD, n_unknowns> x_ad;
          for (unsigned int i = 0; i < n_unknowns; ++i)
            x_ad[i] = LocalAD(n_unknowns, i, x[i]);
          const std::array<LocalAD, n_unknowns> R_ad =
            residual<LocalAD>(c,
                              x_ad,
                              convert<LocalAD>(b_e_trial),
                              LocalAD(J),
                              alpha_n);
          for (unsigned int i = 0; i < n_unknowns; ++i)
            {
              R[i] = R_ad[i].val();
              for (unsigned int j = 0; j < n_unknowns; ++j)
                K[i][j] = R_ad[i].dx(j);
            }
        }

        /** max |R_1|, and |R_2| mu (the yield function). */
        inline std::pair<double, double>
        residual_norms(const Constants &c, const std::array<double, 7> &R)
        {
          double r1 = 0.;
          for (unsigned int i = 0; i < 6; ++i)
            r1 = std::max(r1, std::abs(R[i]));
          return {r1, std::abs(R[6]) * c.mu};
        }

      } // namespace UpdateInternal



      LocalSolution
      solve_update(const Constants       &c,
                   const Matrix3<double> &b_e_trial,
                   const double           J,
                   const double           alpha_n)
      {
        LocalSolution solution;
        for (unsigned int i = 0; i < 6; ++i)
          solution.x[i] = b_e_trial[voigt_row[i]][voigt_column[i]];
        solution.x[6] = 0.;

        double b_max = 1.;
        for (unsigned int i = 0; i < 6; ++i)
          b_max = std::max(b_max, std::abs(solution.x[i]));
        const double tolerance_1 = 1e-12 * b_max;
        const double tolerance_2 =
          1e-11 * c.yield_stress(alpha_n) + 1e-14 * c.mu;
        const auto merit = [](const std::array<double, n_unknowns> &R) {
          double m = 0.;
          for (const double r : R)
            m += r * r;
          return m;
        };
        const auto failure = [](const double r1, const double r2) {
          return ExcMessage(
            "The local Newton iteration of the J2 plasticity update (eq. "
            "4.41) did not converge (|R_b| = " +
            Utilities::to_string(r1) + ", |f| = " + Utilities::to_string(r2) +
            "): the strain increment of the step is too large. Reduce the "
            "load step by increasing 'Load steps' in subsection 'Loading' "
            "(or the time step).");
        };

        std::array<double, n_unknowns>                         R;
        std::array<std::array<double, n_unknowns>, n_unknowns> K;
        constexpr unsigned int max_iterations = 50;
        for (unsigned int iteration = 0;; ++iteration)
          {
            UpdateInternal::residual_and_jacobian(c,
                                                  solution.x,
                                                  b_e_trial,
                                                  J,
                                                  alpha_n,
                                                  R,
                                                  K);
            const auto [r1, r2] = UpdateInternal::residual_norms(c, R);
            if (r1 <= tolerance_1 && r2 <= tolerance_2)
              break;
            // Within 1e3 of the tolerances a step that no longer decreases
            // |R| means round-off: accept (the caller's correction step
            // polishes x once more).
            const bool near_round_off =
              (r1 <= 1e3 * tolerance_1 && r2 <= 1e3 * tolerance_2);
            if (iteration == max_iterations)
              {
                AssertThrow(near_round_off, failure(r1, r2));
                break;
              }

            std::array<double, n_unknowns> dx = R;
            for (double &v : dx)
              v = -v;
            AssertThrow(UpdateInternal::solve(K, dx),
                        ExcMessage("The local Jacobian of the J2 plasticity "
                                   "update (eq. 4.42) is singular."));

            // Backtracking: the first of 1, 1/2, 1/4, ... that keeps
            // Delta alpha >= 0 and decreases |R|^2.
            const double merit_0   = merit(R);
            double       step      = 1.;
            bool         decreased = false;
            for (unsigned int halving = 0; halving < 30 && !decreased;
                 ++halving, step *= 0.5)
              {
                std::array<double, n_unknowns> x_new = solution.x;
                for (unsigned int i = 0; i < n_unknowns; ++i)
                  x_new[i] += step * dx[i];
                if (x_new[6] >= 0. &&
                    merit(residual<double>(c, x_new, b_e_trial, J, alpha_n)) <
                      merit_0)
                  {
                    solution.x = x_new;
                    decreased  = true;
                  }
              }
            if (!decreased)
              {
                AssertThrow(near_round_off, failure(r1, r2));
                break;
              }
          }

        // The inverse of the converged local Jacobian, column by column.
        for (unsigned int j = 0; j < n_unknowns; ++j)
          {
            std::array<double, n_unknowns> e{};
            e[j] = 1.;
            AssertThrow(UpdateInternal::solve(K, e),
                        ExcMessage("The local Jacobian of the J2 plasticity "
                                   "update (eq. 4.42) is singular."));
            for (unsigned int i = 0; i < n_unknowns; ++i)
              solution.jacobian_inverse[i][j] = e[i];
          }
        return solution;
      }

    } // namespace J2
  }   // namespace Materials
} // namespace pg
