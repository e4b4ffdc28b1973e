#include <pg/analysis/eigenmodes.h>
#include <pg/base/exceptions.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>

namespace pg
{
  namespace Analysis
  {
    namespace
    {
      using Dense = LAPACKFullMatrix<double>;

      /** The block (rows, columns) of @p a. */
      Dense
      block(const Dense                     &a,
            const std::vector<unsigned int> &rows,
            const std::vector<unsigned int> &columns)
      {
        Dense b(rows.size(), columns.size());
        for (unsigned int i = 0; i < rows.size(); ++i)
          for (unsigned int j = 0; j < columns.size(); ++j)
            b(i, j) = a(rows[i], columns[j]);
        return b;
      }

      /**
       * An orthonormal basis (the columns) of the kernel of @p a (m x n,
       * m < n), by SVD: the right singular vectors of the singular values
       * below 1e-10 of the largest, and those beyond m. @p rank returns
       * n - (number of columns).
       */
      Dense
      kernel(Dense a, unsigned int &rank)
      {
        const unsigned int m = a.m(), n = a.n();
        a.compute_svd();
        const double largest = (m > 0 ? a.singular_value(0) : 0.);
        rank                 = 0;
        for (unsigned int i = 0; i < std::min(m, n); ++i)
          rank += (a.singular_value(i) > 1e-10 * largest);
        const Dense &vt = a.get_svd_vt();
        Dense        z(n, n - rank);
        for (unsigned int k = rank; k < n; ++k)
          for (unsigned int i = 0; i < n; ++i)
            z(i, k - rank) = vt(k, i);
        return z;
      }

      std::vector<double>
      sorted_real_eigenvalues(Dense &a)
      {
        a.compute_eigenvalues();
        std::vector<double> values(a.m());
        for (unsigned int i = 0; i < a.m(); ++i)
          values[i] = a.eigenvalue(i).real();
        std::sort(values.begin(), values.end());
        return values;
      }
    } // namespace



    std::vector<double>
    dense_eigenvalues(const LinearAlgebra::SparseMatrix &matrix,
                      const std::vector<bool>           &is_displacement,
                      unsigned int                      *n_constraint_modes,
                      const unsigned int                 max_size)
    {
      const unsigned int n = matrix.m();
      AssertThrow(Utilities::MPI::n_mpi_processes(
                    matrix.get_mpi_communicator()) == 1,
                  ExcMessage("The eigenmode analysis runs on one MPI rank "
                             "only: start pg_solve without mpirun."));
      AssertThrow(n <= max_size,
                  ExcBadParameter("Analysis/Type",
                                  "eigenmodes",
                                  "the dense eigensolver handles at most " +
                                    std::to_string(max_size) +
                                    " unknowns, and this problem has " +
                                    std::to_string(n) +
                                    ": use a coarser mesh."));
      Assert(is_displacement.empty() || is_displacement.size() == n,
             ExcDimensionMismatch(is_displacement.size(), n));
      Dense dense(n, n);
      for (unsigned int i = 0; i < n; ++i)
        for (auto entry = matrix.begin(i); entry != matrix.end(i); ++entry)
          dense(i, entry->column()) = entry->value();
      if (n_constraint_modes != nullptr)
        *n_constraint_modes = 0;

      std::vector<unsigned int> u, q;
      for (unsigned int i = 0; i < n; ++i)
        (is_displacement.empty() || is_displacement[i] ? u : q).push_back(i);
      if (q.empty())
        return sorted_real_eigenvalues(dense);

      Dense k_uu = block(dense, u, u), k_uq = block(dense, u, q),
            k_qu = block(dense, q, u), k_qq = block(dense, q, q);
      const double scale = k_uu.linfty_norm();
      if (k_qq.linfty_norm() > 1e-14 * scale)
        {
          // Schur complement: K_uu - K_uq K_qq^{-1} K_qu
          Dense svd = k_qq;
          svd.compute_svd();
          const double ratio =
            svd.singular_value(q.size() - 1) / svd.singular_value(0);
          AssertThrow(ratio > 1e-13,
                      ExcMessage(
                        "The eigenmode analysis eliminates the pressure and "
                        "dilatation unknowns, but their block of the tangent "
                        "is singular (smallest/largest singular value " +
                        std::to_string(ratio) +
                        "). Check the mixed formulation's horizon (each "
                        "family needs a regular moment matrix)."));
          k_qq.compute_lu_factorization();
          k_qq.solve(k_qu);
          Dense correction(u.size(), u.size());
          k_uq.mmult(correction, k_qu);
          k_uu.add(-1., correction);
          return sorted_real_eigenvalues(k_uu);
        }

      // K_qq = 0: the displacement stiffness on ker K_qu
      unsigned int rank_right = 0, rank_left = 0;
      const Dense  z = kernel(k_qu, rank_right);
      Dense        k_qu_left(q.size(), u.size());
      for (unsigned int i = 0; i < u.size(); ++i)
        for (unsigned int j = 0; j < q.size(); ++j)
          k_qu_left(j, i) = k_uq(i, j);
      const Dense w = kernel(k_qu_left, rank_left);
      AssertThrow(rank_left == rank_right,
                  ExcMessage("The eigenmode analysis found the constraint of "
                             "the incompressible formulation with rank " +
                             std::to_string(rank_right) + " in its rows and " +
                             std::to_string(rank_left) +
                             " in its columns; it cannot reduce it."));
      if (n_constraint_modes != nullptr)
        *n_constraint_modes = q.size() - rank_right;
      Dense kz(u.size(), z.n()), wtkz(w.n(), z.n()), wtz(w.n(), z.n());
      k_uu.mmult(kz, z);
      w.Tmmult(wtkz, kz);
      w.Tmmult(wtz, z);
      wtz.compute_lu_factorization();
      wtz.solve(wtkz);
      return sorted_real_eigenvalues(wtkz);
    }
  } // namespace Analysis
} // namespace pg
