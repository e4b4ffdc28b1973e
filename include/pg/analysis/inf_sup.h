#ifndef pg_analysis_inf_sup_h
#define pg_analysis_inf_sup_h

#include <pg/base/global.h>
#include <pg/base/linear_algebra.h>
#include <pg/elements/quadrature_table.h>
#include <pg/materials/material.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <string>
#include <vector>

namespace pg
{
  namespace Analysis
  {
    /**
     * The numerical inf-sup test of Chapelle & Bathe (1993), dissertation
     * section 7.2.5: the generalised symmetric eigenproblem
     *   T_h U_h = lambda S_h U_h   (7.11)
     * with S_h the H1 form, ||u_h||^2_H1 = U_h . S_h U_h (7.12), and T_h the
     * pressure projection, ||p_h||^2_L2 = U_h . T_h U_h (7.13). The inf-sup
     * value is beta~ = sqrt(lambda_k) (7.14), lambda_k the smallest non-zero
     * eigenvalue (k - 1 zero eigenvalues), and the number of spurious
     * pressure modes k_pm = k - (n_u - n_p + 1) (7.15).
     *
     * Both matrices come from the element view (QuadratureTable and
     * assemble_element) with two linear "materials" in the undeformed
     * state: K = 1, mu = 0 for T_h and K = 0, mu = 1 for S_h.
     */
    namespace InfSup
    {
      /**
       * The material of T_h with a displacement-based (or full-integrated
       * per point) pressure: K = 1, mu = 0, linearised at F = 1,
       * W = 1/2 (tr F - d)^2, P = (tr F - d) 1, A_iJkL = delta_iJ delta_kL.
       * The element tangent is sum_q w_q (Div N_a)(Div N_b), the bilinear
       * form int div u div v.
       */
      template <int dim>
      class PressureProjectionMaterial : public Materials::Material<dim>
      {
      public:
        void
        evaluate(const Tensor<2, dim> &F,
                 Tensor<2, dim>       &P,
                 Tensor<4, dim>       &A) const override;
        Tensor<2, dim>
        first_piola_stress(const Tensor<2, dim> &F) const override;
        Tensor<2, 3>
        cauchy_stress(const Tensor<2, dim> &F) const override;
        double
        strain_energy_density(const Tensor<2, dim> &F) const override;
      };

      /**
       * The material of S_h (7.12): K = 0, mu = 1 with
       * W = mu/2 (tr(F^T F) - d), P = mu F, A_iJkL = mu delta_ik delta_JL.
       * The element tangent is sum_q w_q grad N_a . grad N_b (times the
       * identity in the components), the bilinear form int grad u : grad v.
       */
      template <int dim>
      class H1Material : public Materials::Material<dim>
      {
      public:
        void
        evaluate(const Tensor<2, dim> &F,
                 Tensor<2, dim>       &P,
                 Tensor<4, dim>       &A) const override;
        Tensor<2, dim>
        first_piola_stress(const Tensor<2, dim> &F) const override;
        Tensor<2, 3>
        cauchy_stress(const Tensor<2, dim> &F) const override;
        double
        strain_energy_density(const Tensor<2, dim> &F) const override;
      };

      /**
       * The element matrix of T_h for a pressure per element that is
       * statically condensed exactly: constant (@p degree 0: Q1P0 for a Q1
       * cell, UnlP0 for a PBG family, pg-methods.md section 12.2.1) or
       * linear (@p degree 1: U2P1 for a PBG family, section 12.2.2). With
       * the basis phi_q of the pressure, its moment matrix M = sum_q w_q
       * phi_q phi_q^T and the integrated divergences b_{i,aA} = sum_q w_q
       * phi_{q,i} B^{qa}_A,
       *   T_e = b^T M^{-1} b
       * (for P0: b b^T / V_e). This is the tangent of the condensed mixed
       * element (assemble_condensed_pressure_element()) for linear
       * elasticity with K = 1 and mu = 0 at the undeformed positions @p y,
       * and is computed by it. Only Bubnov-Galerkin tables (test = trial)
       * are accepted.
       */
      template <int dim>
      void
      pressure_projection(const QuadratureTable<dim>        &table,
                          const std::vector<Tensor<1, dim>> &y,
                          const unsigned int                 degree,
                          FullMatrix<double>                &matrix);

      /** The result of one mesh of the test. */
      struct Value
      {
        /** Unknowns after removing the constrained DoFs (n_u). */
        unsigned int n_free = 0;
        /** Eigenvalues with lambda < tolerance * lambda_max (k - 1). */
        unsigned int n_zero     = 0;
        double       lambda_max = 0;
        /** The largest eigenvalue counted as zero (0 if none). */
        double largest_zero = 0;
        /** lambda_k, the smallest non-zero eigenvalue. */
        double lambda_k = 0;
        /** beta~ = sqrt(lambda_k), eq. (7.14). */
        double beta = 0;
      };

      /**
       * Solve (7.11) densely for the DoFs of @p T and @p S that are not
       * constrained in @p constraints (their rows and columns are dropped,
       * so S is positive definite for a body held by its Dirichlet
       * conditions), with LAPACK's xSYGV. Throws a clear message if S is
       * not positive definite (too few Dirichlet conditions), if the
       * problem has more than @p max_size free unknowns, or on more than one
       * MPI rank. Eigenvalues below @p relative_tolerance times the largest
       * count as zero.
       */
      Value
      compute_value(const LinearAlgebra::SparseMatrix &T,
                    const LinearAlgebra::SparseMatrix &S,
                    const AffineConstraints<double>   &constraints,
                    const double                       relative_tolerance,
                    const unsigned int                 max_size = 6000);

      /**
       * The same for dense @p t and @p s over the free unknowns (both are
       * overwritten): the pressure spaces P1C and P1C+bubble, whose T_h
       * couples all particles through the inverse pressure mass matrix.
       */
      Value
      compute_value(LAPACKFullMatrix<double> &t,
                    LAPACKFullMatrix<double> &s,
                    const double              relative_tolerance);

      /**
       * The log-log slope -d log(beta) / d log(N) between two meshes with
       * N_0 and N_1 subdivisions: 1 means beta ~ h (locking), 0 a bounded
       * inf-sup value.
       */
      double
      loglog_slope(const unsigned int N_0,
                   const double       beta_0,
                   const unsigned int N_1,
                   const double       beta_1);
    } // namespace InfSup
  }   // namespace Analysis
} // namespace pg

#endif
