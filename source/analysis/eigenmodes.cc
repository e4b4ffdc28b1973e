#include <pg/analysis/eigenmodes.h>
#include <pg/base/exceptions.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>

namespace pg
{
  namespace Analysis
  {
    std::vector<double>
    dense_eigenvalues(const LinearAlgebra::SparseMatrix &matrix,
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
      LAPACKFullMatrix<double> dense(n, n);
      for (unsigned int i = 0; i < n; ++i)
        for (auto entry = matrix.begin(i); entry != matrix.end(i); ++entry)
          dense(i, entry->column()) = entry->value();
      dense.compute_eigenvalues();
      std::vector<double> values(n);
      for (unsigned int i = 0; i < n; ++i)
        values[i] = dense.eigenvalue(i).real();
      std::sort(values.begin(), values.end());
      return values;
    }
  } // namespace Analysis
} // namespace pg
