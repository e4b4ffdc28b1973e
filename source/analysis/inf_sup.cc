#include <pg/analysis/inf_sup.h>
#include <pg/base/exceptions.h>
#include <pg/elements/condensed_pressure.h>
#include <pg/materials/linear_elastic.h>

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/lapack_support.h>
#include <deal.II/lac/lapack_templates.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pg
{
  namespace Analysis
  {
    namespace InfSup
    {
      template <int dim>
      void
      PressureProjectionMaterial<dim>::evaluate(const Tensor<2, dim> &F,
                                                Tensor<2, dim>       &P,
                                                Tensor<4, dim>       &A) const
      {
        P = first_piola_stress(F);
        A = 0;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int k = 0; k < dim; ++k)
            A[i][i][k][k] = 1.;
      }



      template <int dim>
      Tensor<2, dim>
      PressureProjectionMaterial<dim>::first_piola_stress(
        const Tensor<2, dim> &F) const
      {
        return (trace(F) - dim) * Tensor<2, dim>(unit_symmetric_tensor<dim>());
      }



      template <int dim>
      Tensor<2, 3>
      PressureProjectionMaterial<dim>::cauchy_stress(
        const Tensor<2, dim> &F) const
      {
        // Linear: sigma = P (only used by output, which the test has none).
        Tensor<2, 3>         sigma;
        const Tensor<2, dim> P = first_piola_stress(F);
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            sigma[i][j] = P[i][j];
        return sigma;
      }



      template <int dim>
      double
      PressureProjectionMaterial<dim>::strain_energy_density(
        const Tensor<2, dim> &F) const
      {
        return 0.5 * std::pow(trace(F) - dim, 2);
      }



      template <int dim>
      void
      H1Material<dim>::evaluate(const Tensor<2, dim> &F,
                                Tensor<2, dim>       &P,
                                Tensor<4, dim>       &A) const
      {
        P = F;
        A = 0;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int J = 0; J < dim; ++J)
            A[i][J][i][J] = 1.;
      }



      template <int dim>
      Tensor<2, dim>
      H1Material<dim>::first_piola_stress(const Tensor<2, dim> &F) const
      {
        return F;
      }



      template <int dim>
      Tensor<2, 3>
      H1Material<dim>::cauchy_stress(const Tensor<2, dim> &F) const
      {
        Tensor<2, 3> sigma;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            sigma[i][j] = F[i][j];
        return sigma;
      }



      template <int dim>
      double
      H1Material<dim>::strain_energy_density(const Tensor<2, dim> &F) const
      {
        // W = mu/2 (tr(F^T F) - d) with mu = 1, eq. (7.12) read with the
        // parentheses (d = 3 in the dissertation's 3-D notation).
        return 0.5 * (scalar_product(F, F) - dim);
      }



      template <int dim>
      void
      pressure_projection(const QuadratureTable<dim>        &table,
                          const std::vector<Tensor<1, dim>> &y,
                          const unsigned int                 degree,
                          FullMatrix<double>                &matrix)
      {
        AssertThrow(table.test_is_trial,
                    ExcMessage("The condensed pressure projection of the "
                               "inf-sup test needs a Bubnov-Galerkin table "
                               "(test = trial)."));
        // linear elasticity with K = 1, mu = 0: W = W_vol = (tr eps)^2 / 2
        // (built once, not per element)
        static const Materials::LinearElastic<dim> divergence_only = [] {
          Parameters::Material parameters;
          parameters.model         = "linear elastic";
          parameters.plane         = "strain";
          parameters.bulk_modulus  = 1.;
          parameters.shear_modulus = 0.;
          return Materials::LinearElastic<dim>(parameters);
        }();
        Vector<double> residual;
        assemble_condensed_pressure_element<dim>(table,
                                                 nullptr,
                                                 y,
                                                 divergence_only,
                                                 residual,
                                                 &matrix,
                                                 degree);
      }



      Value
      compute_value(const LinearAlgebra::SparseMatrix &T,
                    const LinearAlgebra::SparseMatrix &S,
                    const AffineConstraints<double>   &constraints,
                    const double                       relative_tolerance,
                    const unsigned int                 max_size)
      {
        AssertThrow(Utilities::MPI::n_mpi_processes(T.get_mpi_communicator()) ==
                      1,
                    ExcMessage("The inf-sup test runs on one MPI rank "
                               "only: start pg_solve without mpirun."));
        // The free (unconstrained) DoFs and their dense index.
        const unsigned int        n_all = T.m();
        std::vector<int>          dense_index(n_all, -1);
        std::vector<unsigned int> free;
        for (unsigned int i = 0; i < n_all; ++i)
          if (!constraints.is_constrained(i))
            {
              dense_index[i] = free.size();
              free.push_back(i);
            }
        const unsigned int n = free.size();
        AssertThrow(
          n <= max_size,
          ExcBadParameter("Analysis/Inf-sup subdivisions",
                          std::to_string(n) + " free unknowns",
                          "the dense generalised eigensolver handles at most " +
                            std::to_string(max_size) +
                            " unknowns: use fewer subdivisions."));
        AssertThrow(n > 0,
                    ExcMessage("The inf-sup test has no free unknowns: every "
                               "DoF is constrained; use more subdivisions."));

        LAPACKFullMatrix<double> t(n, n), s(n, n);
        const auto copy = [&](const LinearAlgebra::SparseMatrix &m,
                              LAPACKFullMatrix<double>          &dense) {
          for (const unsigned int i : free)
            for (auto entry = m.begin(i); entry != m.end(i); ++entry)
              if (dense_index[entry->column()] >= 0)
                dense(dense_index[i], dense_index[entry->column()]) =
                  entry->value();
        };
        copy(T, t);
        copy(S, s);
        return compute_value(t, s, relative_tolerance);
      }



      Value
      compute_value(LAPACKFullMatrix<double> &t,
                    LAPACKFullMatrix<double> &s,
                    const double              relative_tolerance)
      {
        const unsigned int n = t.m();
        AssertThrow(n > 0,
                    ExcMessage("The inf-sup test has no free unknowns: every "
                               "DoF is constrained; use more subdivisions."));

        // S must be positive definite, else (7.11) is not a generalised
        // symmetric-definite problem: check by a Cholesky factorisation
        // (xPOTRF) of a copy, as xSYGV would only report an error code.
        {
          std::vector<double> cholesky(static_cast<std::size_t>(n) * n);
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              cholesky[static_cast<std::size_t>(j) * n + i] = s(i, j);
          const types::blas_int size = n;
          types::blas_int       info = 0;
          potrf(&LAPACKSupport::L, &size, cholesky.data(), &size, &info);
          // A singular S (a free body: the constants are in its kernel)
          // may pass the factorisation with a round-off pivot, or fail with
          // a negative one: also refuse pivots below 1e-10 of S's largest
          // diagonal entry.
          double largest_diagonal = 0, smallest_pivot = 0;
          if (info == 0)
            {
              smallest_pivot = std::numeric_limits<double>::max();
              for (unsigned int i = 0; i < n; ++i)
                {
                  const double l =
                    cholesky[static_cast<std::size_t>(i) * n + i];
                  largest_diagonal = std::max(largest_diagonal, s(i, i));
                  smallest_pivot   = std::min(smallest_pivot, l * l);
                }
            }
          AssertThrow(info == 0 && smallest_pivot > 1e-10 * largest_diagonal,
                      ExcBadParameter(
                        "Boundary conditions/Dirichlet",
                        "(as given)",
                        "the H1 form S_h of the inf-sup test is not positive "
                        "definite on the free unknowns: the body is not held. "
                        "Clamp the boundary, e.g. 'Dirichlet = 0: xy, 1: xy, "
                        "2: xy, 3: xy' for the unit square."));
        }

        std::vector<Vector<double>> no_eigenvectors;
        t.compute_generalized_eigenvalues_symmetric(s, no_eigenvectors);
        std::vector<double> lambda(n);
        for (unsigned int i = 0; i < n; ++i)
          lambda[i] = t.eigenvalue(i).real();
        std::sort(lambda.begin(), lambda.end());

        Value value;
        value.n_free     = n;
        value.lambda_max = lambda.back();
        for (const double l : lambda)
          if (l < relative_tolerance * value.lambda_max)
            {
              ++value.n_zero;
              value.largest_zero = std::max(value.largest_zero, std::abs(l));
            }
        AssertThrow(value.n_zero < n,
                    ExcMessage("The inf-sup test found only zero "
                               "eigenvalues (T_h = 0)."));
        value.lambda_k = lambda[value.n_zero];
        value.beta     = std::sqrt(value.lambda_k);
        return value;
      }



      double
      loglog_slope(const unsigned int N_0,
                   const double       beta_0,
                   const unsigned int N_1,
                   const double       beta_1)
      {
        return -std::log(beta_1 / beta_0) /
               std::log(static_cast<double>(N_1) / N_0);
      }



      template class PressureProjectionMaterial<2>;
      template class PressureProjectionMaterial<3>;
      template class H1Material<2>;
      template class H1Material<3>;
      template void
      pressure_projection<2>(const QuadratureTable<2> &,
                             const std::vector<Tensor<1, 2>> &,
                             const unsigned int,
                             FullMatrix<double> &);
      template void
      pressure_projection<3>(const QuadratureTable<3> &,
                             const std::vector<Tensor<1, 3>> &,
                             const unsigned int,
                             FullMatrix<double> &);
    } // namespace InfSup
  }   // namespace Analysis
} // namespace pg
