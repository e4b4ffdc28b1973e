#ifndef pg_dofs_relevant_dofs_h
#define pg_dofs_relevant_dofs_h

#include <pg/base/global.h>
#include <pg/base/linear_algebra.h>
#include <pg/families/family_set.h>
#include <pg/mesh/particle_set.h>

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace pg
{
  /**
   * The DoFs that this rank reads (the ghosted IndexSet of the solution, of
   * the constraints and of the sparsity pattern's rows):
   * - its locally owned DoFs,
   * - the DoFs of every member of its owned families (the PG and CPD
   *   groups gather y^b = X^b - X^k + u^b over the members b of a family),
   * - the DoFs of its locally owned cells (the Q1 group, the face loads,
   *   and the points and line samples inside these cells).
   *
   * One horizon is enough for the solution: a family reads only its own
   * members. The VC correction system couples two horizons (a member's row
   * couples to the masters of the families it belongs to), but it works in
   * the reference configuration and builds its own row set
   * (CorrectionSystem::make_sparsity_pattern), so it needs no entry here.
   *
   * @p owned_families are the particle indices k of the families whose
   * master DoFs this rank owns.
   */
  template <int dim>
  IndexSet
  compute_relevant_dofs(const DoFHandler<dim>           &dof_handler,
                        const ParticleSet<dim>          &particles,
                        const FamilySet<dim>            &families,
                        const std::vector<unsigned int> &owned_families);

  /**
   * All entries of the distributed vector @p v on every rank, gathered
   * from the owners' entries (bit for bit; collective: every rank of the
   * vector's communicator must call it). For the postprocessors that write
   * or reduce over all particles; O(n_dofs) memory and traffic per call, so
   * call it once per output, not per Newton update.
   */
  Vector<double>
  gather_to_all(const LinearAlgebra::Vector &v);
} // namespace pg

#endif
