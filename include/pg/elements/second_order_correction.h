#ifndef pg_elements_second_order_correction_h
#define pg_elements_second_order_correction_h

#include <pg/base/global.h>
#include <pg/elements/family_elements.h>
#include <pg/families/family_set.h>
#include <pg/mesh/particle_set.h>

#include <deal.II/base/tensor.h>

#include <vector>

namespace pg
{
  /**
   * The second-order variational-consistency correction "VC2" of PPG2
   * (pg-methods.md section 11.6, eqs. 5.17, 5.25): test gradients
   *   t^{kj} = g^{kkj} + phi^{kj} (alpha_1^k + alpha_2^k dX^{kj}),
   * with the factors chosen so that at every particle k that is not fixed
   *   d^k = sum_{f} sum_{q} w_q T^{qk} = 0                   (first order),
   *   D^k = V^k 1 - sum_{j != k} V^j dX^{kj} (x) t^{kj} = 0   (second order).
   * d^k is the unit-stress residual; D^k is the same test-function integral
   * for the stress P = (X - X^k) (x) e_J, plus the volume term: with both
   * zero the discrete weak form integrates every linear stress field
   * exactly (the quadratic patch test). D^k involves family k's factors
   * only; d^k couples neighbours.
   *
   * The test-vector component J decouples: for each J one sparse system
   * with d + 1 unknowns (alpha_1J, alpha_2J.) and d + 1 equations per
   * particle, the same matrix for every J, solved by UMFPACK. Fixed
   * particles (boundary option s: every surface particle) keep zero
   * factors and drop their equations.
   */
  template <int dim>
  struct SecondOrderCorrection
  {
    /** alpha_1^k per particle. */
    std::vector<Tensor<1, dim>> alpha;
    /** alpha_2^k per particle. */
    std::vector<Tensor<2, dim>> second_order_alpha;
    /**
     * max over free particles of |d^k| / h^(d-1) and |D^k| / h^d before
     * and after the correction (h the particle spacing): the second ones
     * are round-off after a successful solve.
     */
    double max_first_order_residual_before, max_second_order_residual_before;
    double max_first_order_residual_after, max_second_order_residual_after;
  };

  /**
   * Solve the VC2 system for a PPG2 discretisation whose VC correction
   * function values are set (FamilyElements::initialize()). @p fixed marks
   * the particles whose factors stay zero. Throws with advice if the system
   * is singular.
   */
  template <int dim>
  SecondOrderCorrection<dim>
  solve_second_order_correction(const ParticleSet<dim>    &particles,
                                const FamilySet<dim>      &families,
                                const FamilyElements<dim> &elements,
                                const std::vector<bool>   &fixed);
} // namespace pg

#endif
