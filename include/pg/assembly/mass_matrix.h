#ifndef pg_assembly_mass_matrix_h
#define pg_assembly_mass_matrix_h

#include <pg/base/global.h>
#include <pg/base/linear_algebra.h>
#include <pg/solvers/mechanical_system.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>

#include <vector>

namespace pg
{
  /**
   * The masses of the time integrators: the lumped mass rho_0 int N_k of
   * every DoF over all cells (masses.lumped; rho_0 V^k at a particle) and
   * its diagonal condensed with @p zero_constraints (masses.inverse: 1/m at
   * free DoFs, 0 at constrained ones); if @p consistent, also the Newmark
   * mass matrices in the sparsity of @p pattern: the consistent Q1 mass on
   * finite element cells and the lumped one on meshfree cells (@p meshfree
   * per active cell), unconstrained (masses.consistent) and condensed
   * (masses.condensed). Only the displacement components 0 ... dim-1 have
   * mass; the DoFs of the extra nodal fields (FieldLayout) go to
   * masses.massless. Throws if @p rho is not positive.
   */
  template <int dim>
  void
  assemble_masses(const DoFHandler<dim>             &dof_handler,
                  const std::vector<bool>           &meshfree,
                  const AffineConstraints<double>   &zero_constraints,
                  const LinearAlgebra::SparseMatrix &pattern,
                  const double                       rho,
                  const bool                         consistent,
                  MassMatrices                      &masses);
} // namespace pg

#endif
