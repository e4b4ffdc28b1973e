#ifndef pg_analysis_eigenmodes_h
#define pg_analysis_eigenmodes_h

#include <pg/base/global.h>
#include <pg/base/linear_algebra.h>

#include <vector>

namespace pg
{
  namespace Analysis
  {
    /**
     * All eigenvalues of the (serial) sparse matrix @p matrix, by LAPACK on
     * a dense copy, sorted by their real parts; the real parts are
     * returned. The PPG tangent is not symmetric, and its low eigenvalues
     * are real (pg-methods.md "Verified numerically", 3.). Throws if the
     * matrix has more than @p max_size rows (the dense solver would be too
     * slow) or if it is distributed over several MPI ranks.
     */
    std::vector<double>
    dense_eigenvalues(const LinearAlgebra::SparseMatrix &matrix,
                      const unsigned int                 max_size = 6000);
  } // namespace Analysis
} // namespace pg

#endif
