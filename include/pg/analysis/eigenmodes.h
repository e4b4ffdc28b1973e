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
     * are real (pg-methods.md "Verified numerically", 3.).
     *
     * With @p is_displacement (one flag per row, empty: all rows are
     * displacements) the other unknowns q (the nodal p and Theta of U2P1C
     * and Unl+P1C, the family pressure of IUnlP0) are eliminated first, and
     * the eigenvalues are those of the stiffness the displacements see,
     * comparable with the displacement formulations':
     * - K_qq regular (U2P1C, Unl+P1C): the Schur complement
     *   K_uu - K_uq K_qq^{-1} K_qu;
     * - K_qq = 0 (IUnlP0, a constraint without penalty): K_uu on the
     *   displacements that satisfy the constraint, ker K_qu. With Z the
     *   orthonormal basis of ker K_qu and W the one of ker K_uq^T (= Z for a
     *   symmetric tangent), the finite eigenvalues of the saddle-point
     *   pencil (K, diag(I, 0)) are those of (W^T Z)^{-1} W^T K_uu Z. The
     *   kernels are found by SVD (singular values below 1e-10 of the
     *   largest count as zero); @p n_constraint_modes returns how many
     *   pressure modes do not constrain the displacement (rank deficiency
     *   of K_qu: spurious pressure modes).
     *
     * Throws if the matrix has more than @p max_size rows (the dense solver
     * would be too slow), if it is distributed over several MPI ranks, or
     * if K_qq is neither regular nor zero.
     */
    std::vector<double>
    dense_eigenvalues(const LinearAlgebra::SparseMatrix &matrix,
                      const std::vector<bool>           &is_displacement = {},
                      unsigned int      *n_constraint_modes = nullptr,
                      const unsigned int max_size           = 6000);
  } // namespace Analysis
} // namespace pg

#endif
