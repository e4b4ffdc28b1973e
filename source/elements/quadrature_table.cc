#include <pg/elements/quadrature_table.h>

#include <Eigen/Dense>

#include <array>
#include <string>

namespace pg
{
  template <int dim>
  void
  QuadratureTable<dim>::reinit(const unsigned int n, const bool test_trial)
  {
    n_nodes       = n;
    test_is_trial = test_trial;
    weights.clear();
    points.clear();
    trial.clear();
    test_offsets.assign(1, 0);
    test_nodes.clear();
    test_vectors.clear();
  }



  template <int dim>
  void
  QuadratureTable<dim>::add_point(const double                       weight,
                                  const std::vector<Tensor<1, dim>> &row,
                                  const Point<dim>                  &point)
  {
    AssertDimension(row.size(), n_nodes);
    weights.push_back(weight);
    points.push_back(point);
    trial.insert(trial.end(), row.begin(), row.end());
    test_offsets.push_back(test_offsets.back());
  }



  template <int dim>
  void
  QuadratureTable<dim>::add_test_vector(const unsigned int    a,
                                        const Tensor<1, dim> &test)
  {
    Assert(!test_is_trial, ExcInternalError());
    AssertIndexRange(a, n_nodes);
    test_nodes.push_back(a);
    test_vectors.push_back(test);
    ++test_offsets.back();
  }



  template <int dim>
  unsigned int
  QuadratureTable<dim>::n_points() const
  {
    return weights.size();
  }



  template <int dim>
  Tensor<2, dim>
  deformation_gradient(const QuadratureTable<dim>        &table,
                       const unsigned int                 q,
                       const std::vector<Tensor<1, dim>> &y)
  {
    const Tensor<1, dim> *B = &table.trial[q * table.n_nodes];
    Tensor<2, dim>        F;
    for (unsigned int b = 0; b < table.n_nodes; ++b)
      for (unsigned int A = 0; A < dim; ++A)
        for (unsigned int D = 0; D < dim; ++D)
          F[A][D] += y[b][A] * B[b][D];
    return F;
  }



  namespace
  {
    /**
     * The tangent of a Bubnov-Galerkin table (test = trial) as dim^2 dense
     * products: for every pair of components (i, k),
     *   K^{ik} = sum_q B_q C_q^{ik} B_q^T = X^{ik} Y^T,
     * with B_q the n x dim matrix of trial vectors at point q,
     * C_q^{ik}_{jl} = w_q A_q,ijkl, X^{ik} = [B_1 C_1^{ik} | ... | B_Q
     * C_Q^{ik}] and Y = [B_1 | ... | B_Q]. The inner dimension Q dim makes the
     * product efficient, and the major symmetry A_ijkl = A_klij gives
     * K^{ki} = (K^{ik})^T, so only i <= k is computed; without it
     * (@p major_symmetry false, e.g. a damage tangent) every (i, k) is.
     */
    template <int dim>
    void
    bubnov_galerkin_tangent(const QuadratureTable<dim> &table,
                            const std::vector<double>  &weighted_tangents,
                            const bool                  major_symmetry,
                            FullMatrix<double>         &tangent)
    {
      using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic>;
      constexpr unsigned int d4 = dim * dim * dim * dim;
      const unsigned int     n  = table.n_nodes;
      const unsigned int     nq = table.n_points();
      Matrix                 Y(n, nq * dim), X(n, nq * dim), Kik(n, n);
      for (unsigned int q = 0; q < nq; ++q)
        for (unsigned int b = 0; b < n; ++b)
          for (unsigned int l = 0; l < dim; ++l)
            Y(b, q * dim + l) = table.trial[q * n + b][l];

      const unsigned int n_dofs = n * dim;
      double *const      K      = &tangent(0, 0);
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int k = (major_symmetry ? i : 0); k < dim; ++k)
          {
            for (unsigned int q = 0; q < nq; ++q)
              {
                const double *C = &weighted_tangents[q * d4];
                for (unsigned int b = 0; b < n; ++b)
                  for (unsigned int l = 0; l < dim; ++l)
                    {
                      double s = 0;
                      for (unsigned int j = 0; j < dim; ++j)
                        s += Y(b, q * dim + j) *
                             C[((i * dim + j) * dim + k) * dim + l];
                      X(b, q * dim + l) = s;
                    }
              }
            Kik.noalias() = X * Y.transpose();
            for (unsigned int a = 0; a < n; ++a)
              for (unsigned int b = 0; b < n; ++b)
                {
                  K[(a * dim + i) * n_dofs + b * dim + k] = Kik(a, b);
                  if (major_symmetry)
                    K[(b * dim + k) * n_dofs + a * dim + i] = Kik(a, b);
                }
          }
    }



    /**
     * The Bubnov-Galerkin tangent when every point has the same material
     * tangent A (a linear elastic material; any material at F = I):
     *   K^{ik} = sum_jl A_ijkl S^{jl},   S^{jl} = sum_q w_q B_q,j B_q,l^T
     *          = (Y_j W) Y_l^T,
     * with Y_j the n x Q matrix of the j-th components of the trial vectors
     * and W = diag(w_q). The dim (dim + 1) / 2 products S^{jl}, j <= l
     * (S^{lj} = (S^{jl})^T), have the inner dimension Q instead of Q dim:
     * a third of the flops of bubnov_galerkin_tangent() in 3-D, half in 2-D.
     */
    template <int dim>
    void
    uniform_bubnov_galerkin_tangent(const QuadratureTable<dim> &table,
                                    const Tensor<4, dim>       &A,
                                    FullMatrix<double>         &tangent)
    {
      using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic>;
      using RowMajorMatrix =
        Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
      const unsigned int      n  = table.n_nodes;
      const unsigned int      nq = table.n_points();
      std::array<Matrix, dim> Y, WY;
      for (unsigned int j = 0; j < dim; ++j)
        {
          Y[j].resize(n, nq);
          WY[j].resize(n, nq);
        }
      for (unsigned int q = 0; q < nq; ++q)
        for (unsigned int b = 0; b < n; ++b)
          for (unsigned int j = 0; j < dim; ++j)
            {
              Y[j](b, q)  = table.trial[q * n + b][j];
              WY[j](b, q) = table.weights[q] * table.trial[q * n + b][j];
            }
      // S[j][l] for all j, l (row-major: row a of S is contiguous)
      std::array<std::array<RowMajorMatrix, dim>, dim> S;
      for (unsigned int j = 0; j < dim; ++j)
        for (unsigned int l = j; l < dim; ++l)
          {
            S[j][l].noalias() = WY[j] * Y[l].transpose();
            if (l != j)
              S[l][j] = S[j][l].transpose();
          }

      const unsigned int n_dofs = n * dim;
      double *const      K      = &tangent(0, 0);
      for (unsigned int a = 0; a < n; ++a)
        for (unsigned int i = 0; i < dim; ++i)
          {
            double *const row = K + (a * dim + i) * n_dofs;
            for (unsigned int j = 0; j < dim; ++j)
              for (unsigned int l = 0; l < dim; ++l)
                {
                  const double *const s = &S[j][l](a, 0);
                  for (unsigned int k = 0; k < dim; ++k)
                    {
                      const double c = A[i][j][k][l];
                      if (c == 0)
                        continue;
                      for (unsigned int b = 0; b < n; ++b)
                        row[b * dim + k] += c * s[b];
                    }
                }
          }
    }
  } // namespace



  template <int dim>
  void
  assemble_element(const QuadratureTable<dim>        &table,
                   const std::vector<Tensor<1, dim>> &y,
                   const Materials::Material<dim>    &material,
                   Vector<double>                    &residual,
                   FullMatrix<double>                *tangent,
                   const ArrayView<const double>     &committed_state,
                   const ArrayView<double>           &trial_state)
  {
    constexpr unsigned int d3     = dim * dim * dim;
    constexpr unsigned int d4     = dim * d3;
    const unsigned int     n      = table.n_nodes;
    const unsigned int     n_dofs = n * dim;
    AssertDimension(y.size(), n);
    residual.reinit(n_dofs);
    if (tangent != nullptr)
      tangent->reinit(n_dofs, n_dofs);
    // FullMatrix and Vector store their entries contiguously (row-major);
    // raw pointers keep the innermost loops free of index checks.
    double *const K =
      (tangent != nullptr && n_dofs > 0) ? &(*tangent)(0, 0) : nullptr;
    double *const r = residual.data();
    // Bubnov-Galerkin tables get their tangent from dense products after
    // the loop over the points; the others (PPG: two test vectors per
    // point) contract point by point.
    const bool dense_tangent = (K != nullptr && table.test_is_trial);

    // A material with state evaluates point q from its committed slice and
    // writes its trial slice; a stateless one takes the calls of before.
    const unsigned int n_state = material.n_state_variables();
    if (n_state > 0)
      AssertThrow(committed_state.size() == table.n_points() * n_state &&
                    trial_state.size() == table.n_points() * n_state,
                  ExcMessage(
                    "The material has " + std::to_string(n_state) +
                    " state variables per point, so assemble_element() "
                    "needs state slices of " +
                    std::to_string(table.n_points() * n_state) +
                    " values (committed: " +
                    std::to_string(committed_state.size()) +
                    ", trial: " + std::to_string(trial_state.size()) +
                    "). Pass the element's slices of the "
                    "QuadraturePointHistory."));
    const auto evaluate = [&](const unsigned int    q,
                              const Tensor<2, dim> &F,
                              Tensor<2, dim>       &P,
                              Tensor<4, dim>       *A) {
      if (n_state == 0)
        {
          if (A != nullptr)
            material.evaluate(F, P, *A);
          else
            P = material.first_piola_stress(F);
        }
      else
        material.evaluate_with_state(
          F,
          make_array_view(committed_state.begin() + q * n_state,
                          committed_state.begin() + (q + 1) * n_state),
          make_array_view(trial_state.begin() + q * n_state,
                          trial_state.begin() + (q + 1) * n_state),
          P,
          A);
    };

    Tensor<2, dim> P;
    Tensor<4, dim> A;
    // the material tangent of the first point, and whether every point has
    // exactly that one (then uniform_bubnov_galerkin_tangent())
    Tensor<4, dim> first_tangent;
    bool           uniform_tangent = true;
    // ab[b][i][j][k] = w_q A_ijkl B^{qb}_l, reused for every test node
    std::vector<double> ab((K != nullptr && !dense_tangent) ? n * d3 : 0);
    // w_q A_q of every point, for the dense products
    std::vector<double> weighted_tangents(
      dense_tangent ? table.n_points() * d4 : 0);

    for (unsigned int q = 0; q < table.n_points(); ++q)
      {
        const double          w = table.weights[q];
        const Tensor<1, dim> *B = &table.trial[q * n];
        const Tensor<2, dim>  F = deformation_gradient(table, q, y);
        if (dense_tangent)
          {
            evaluate(q, F, P, &A);
            if (q == 0)
              first_tangent = A;
            else if (uniform_tangent && A != first_tangent)
              uniform_tangent = false;
            double *C = &weighted_tangents[q * d4];
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                for (unsigned int k = 0; k < dim; ++k)
                  for (unsigned int l = 0; l < dim; ++l)
                    C[((i * dim + j) * dim + k) * dim + l] = w * A[i][j][k][l];
          }
        else if (K != nullptr)
          {
            evaluate(q, F, P, &A);
            double a_raw[dim][dim][dim][dim];
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                for (unsigned int k = 0; k < dim; ++k)
                  for (unsigned int l = 0; l < dim; ++l)
                    a_raw[i][j][k][l] = w * A[i][j][k][l];
            for (unsigned int b = 0; b < n; ++b)
              {
                double Bb[dim];
                for (unsigned int l = 0; l < dim; ++l)
                  Bb[l] = B[b][l];
                double *out = &ab[b * d3];
                for (unsigned int i = 0; i < dim; ++i)
                  for (unsigned int j = 0; j < dim; ++j)
                    for (unsigned int k = 0; k < dim; ++k)
                      {
                        double s = 0;
                        for (unsigned int l = 0; l < dim; ++l)
                          s += a_raw[i][j][k][l] * Bb[l];
                        out[(i * dim + j) * dim + k] = s;
                      }
              }
          }
        else
          evaluate(q, F, P, nullptr);

        // The (sparse) test vectors of this point.
        const unsigned int t_begin =
          table.test_is_trial ? 0 : table.test_offsets[q];
        const unsigned int t_end =
          table.test_is_trial ? n : table.test_offsets[q + 1];
        for (unsigned int t = t_begin; t < t_end; ++t)
          {
            const unsigned int a =
              table.test_is_trial ? t : table.test_nodes[t];
            const Tensor<1, dim> &T =
              table.test_is_trial ? B[t] : table.test_vectors[t];
            for (unsigned int i = 0; i < dim; ++i)
              {
                double s = 0;
                for (unsigned int j = 0; j < dim; ++j)
                  s += P[i][j] * T[j];
                r[a * dim + i] += w * s;
              }
            if (K == nullptr || dense_tangent)
              continue;
            double Ta[dim];
            for (unsigned int j = 0; j < dim; ++j)
              Ta[j] = T[j];
            for (unsigned int i = 0; i < dim; ++i)
              {
                double *row = K + (a * dim + i) * n_dofs;
                for (unsigned int b = 0; b < n; ++b)
                  {
                    const double *in = &ab[b * d3 + i * dim * dim];
                    for (unsigned int k = 0; k < dim; ++k)
                      {
                        double s = 0;
                        for (unsigned int j = 0; j < dim; ++j)
                          s += Ta[j] * in[j * dim + k];
                        row[b * dim + k] += s;
                      }
                  }
              }
          }
      }
    if (dense_tangent && table.n_points() > 0)
      {
        if (uniform_tangent)
          uniform_bubnov_galerkin_tangent(table, first_tangent, *tangent);
        else
          bubnov_galerkin_tangent(table,
                                  weighted_tangents,
                                  material.tangent_has_major_symmetry(),
                                  *tangent);
      }
  }



  template <int dim>
  void
  add_stress_residual(const QuadratureTable<dim>                    &table,
                      const std::function<Tensor<2, dim>(unsigned)> &stress,
                      std::vector<Tensor<1, dim>>                   &d)
  {
    AssertDimension(d.size(), table.n_nodes);
    for (unsigned int q = 0; q < table.n_points(); ++q)
      {
        const Tensor<2, dim> wP = table.weights[q] * stress(q);
        if (table.test_is_trial)
          for (unsigned int a = 0; a < table.n_nodes; ++a)
            d[a] += wP * table.trial[q * table.n_nodes + a];
        else
          for (unsigned int t = table.test_offsets[q];
               t < table.test_offsets[q + 1];
               ++t)
            d[table.test_nodes[t]] += wP * table.test_vectors[t];
      }
  }



  template <int dim>
  void
  add_unit_stress_residual(const QuadratureTable<dim>  &table,
                           std::vector<Tensor<1, dim>> &d)
  {
    add_stress_residual<dim>(
      table,
      [](unsigned int) -> Tensor<2, dim> {
        return unit_symmetric_tensor<dim>();
      },
      d);
  }



  template struct QuadratureTable<2>;
  template struct QuadratureTable<3>;
  template void
  assemble_element<2>(const QuadratureTable<2> &,
                      const std::vector<Tensor<1, 2>> &,
                      const Materials::Material<2> &,
                      Vector<double> &,
                      FullMatrix<double> *,
                      const ArrayView<const double> &,
                      const ArrayView<double> &);
  template void
  assemble_element<3>(const QuadratureTable<3> &,
                      const std::vector<Tensor<1, 3>> &,
                      const Materials::Material<3> &,
                      Vector<double> &,
                      FullMatrix<double> *,
                      const ArrayView<const double> &,
                      const ArrayView<double> &);
  template Tensor<2, 2>
  deformation_gradient<2>(const QuadratureTable<2> &,
                          const unsigned int,
                          const std::vector<Tensor<1, 2>> &);
  template Tensor<2, 3>
  deformation_gradient<3>(const QuadratureTable<3> &,
                          const unsigned int,
                          const std::vector<Tensor<1, 3>> &);
  template void
  add_stress_residual<2>(const QuadratureTable<2> &,
                         const std::function<Tensor<2, 2>(unsigned)> &,
                         std::vector<Tensor<1, 2>> &);
  template void
  add_stress_residual<3>(const QuadratureTable<3> &,
                         const std::function<Tensor<2, 3>(unsigned)> &,
                         std::vector<Tensor<1, 3>> &);
  template void
  add_unit_stress_residual<2>(const QuadratureTable<2> &,
                              std::vector<Tensor<1, 2>> &);
  template void
  add_unit_stress_residual<3>(const QuadratureTable<3> &,
                              std::vector<Tensor<1, 3>> &);
} // namespace pg
