#ifndef pg_base_linear_algebra_h
#define pg_base_linear_algebra_h

#include <pg/base/global.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

namespace pg
{
  /**
   * The linear algebra backend of pg: Trilinos (Epetra) through deal.II.
   * Code elsewhere names these aliases, never the backend types.
   */
  namespace LinearAlgebra
  {
    using SparseMatrix    = TrilinosWrappers::SparseMatrix;
    using SparsityPattern = TrilinosWrappers::SparsityPattern;
    using Vector          = TrilinosWrappers::MPI::Vector;
  } // namespace LinearAlgebra
} // namespace pg

#endif
