#ifndef pg_elements_u1_stabilisation_h
#define pg_elements_u1_stabilisation_h

#include <pg/base/global.h>
#include <pg/elements/quadrature_table.h>
#include <pg/materials/material.h>

#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace pg
{
  /**
   * The two stabilisations of the underintegrated family U1 (one point at
   * the master, the classical correspondence): rank deficient on its own
   * (pg-methods.md section 12.3.1, cpd-and-correspondence.md).
   */

  /**
   * Work arrays of assemble_u1s_unl_element(), kept by the caller (one per
   * thread) so that the assembly does not allocate.
   */
  struct U1SUnlScratch
  {
    Vector<double>     residual;
    FullMatrix<double> tangent;
  };

  /**
   * The U1SUnl family (eq. 6.18, pg-methods.md section 12.3.2):
   *   V^k (W - W~)(F^{kk}) + sum_j w^{kj} W~(F^{kj}),
   * the real material @p material on the one-point table @p u1_table minus
   * the pseudo-material @p pseudo_material on the same table plus the
   * pseudo-material on the Unl table @p unl_table (both tables of the same
   * family, nodes in the same order). The pseudo-material has the constants
   * of eq. (6.20). Residual and tangent as assemble_element(), which they
   * combine; both are overwritten. The real material carries the
   * history at the point of @p u1_table (@p committed_state,
   * @p trial_state: its slices, n_state_variables() values; empty if
   * stateless); the pseudo-material is elastic (stateless).
   */
  template <int dim>
  void
  assemble_u1s_unl_element(const QuadratureTable<dim>        &u1_table,
                           const QuadratureTable<dim>        &unl_table,
                           const std::vector<Tensor<1, dim>> &y,
                           const Materials::Material<dim>    &material,
                           const Materials::Material<dim>    &pseudo_material,
                           Vector<double>                    &residual,
                           FullMatrix<double>                *tangent,
                           U1SUnlScratch                     &scratch,
                           const ArrayView<const double> &committed_state = {},
                           const ArrayView<double>       &trial_state     = {});

  /**
   * The constant C = 18 alpha K / (pi delta^4) of Peridigm's hourglass
   * force (force / length^6): the bond-based
   * (PMB) micromodulus times the 'Hourglass coefficient' @p alpha, with the
   * bulk modulus @p bulk_modulus and the horizon @p horizon of the family.
   */
  double
  hourglass_constant(const double alpha,
                     const double bulk_modulus,
                     const double horizon);

  /**
   * Add Peridigm's hourglass (penalty) force of the family of a master
   * particle, as Peridigm's correspondence materials compute it
   * (src/materials/correspondence.cxx, computeHourglassForce()), and its
   * consistent tangent. For every bond of the master (node 0) to member j
   * (reference bond xi = X^j - X^0, current bond Y = y^j - y^0), with the
   * master's deformation gradient F = sum_b y^b (x) B^b from the trial
   * vectors of @p u1_table (its one point):
   *   z = F xi - Y (the expected minus the actual neighbour position),
   *   t = -C (z . Y) Y / (|xi| |Y|),
   *   force on the master += V^0 V^j t, on member j -= V^0 V^j t.
   * The residual is the internal force, so @p residual gets -V^0 V^j t at
   * the master and +V^0 V^j t at j; @p tangent (if not nullptr) its
   * derivative with respect to all nodes of the family (t depends on every
   * node through F). @p y are positions relative to the master (y^0 = 0
   * or any common origin), @p xi the reference positions relative to the
   * master, @p volumes V^b, all in the node order of @p u1_table. The force
   * vanishes for every affine field, is not derived from an energy (the
   * tangent is not symmetric), and keeps Peridigm's factor |Y|: in
   * Peridigm's units the effective penalty depends on the unit of length.
   * Adds to @p residual and @p tangent.
   */
  template <int dim>
  void
  add_hourglass_force(const QuadratureTable<dim>        &u1_table,
                      const std::vector<Tensor<1, dim>> &xi,
                      const std::vector<Tensor<1, dim>> &y,
                      const std::vector<double>         &volumes,
                      const double                       constant,
                      Vector<double>                    &residual,
                      FullMatrix<double>                *tangent);

  /**
   * The second moment M_xx = int_{V^k} x^2 dV of a particle volume taken as
   * a ball (eq. 6.27, [checked]: V r^2 / 5 of a sphere, V^{5/3} (3/pi)^{2/3}
   * / (10 2^{1/3})) or, in 2-D, a disc of area V per unit thickness:
   * V^2 / (4 pi) (pg-methods.md section 12.3.3, [D]; the source gives 3-D
   * only). Units: length^(dim + 2).
   */
  template <int dim>
  double
  particle_second_moment(const double volume);

  /**
   * Add U1SIG's implicit-gradient stabilisation of a U1 family (eqs.
   * 6.25, 6.26, 6.28; pg-methods.md section 12.3.3): with the second
   * derivatives @p h (h^b_{DE}, ShapeFunctions::mls1_second_derivatives(),
   * in the node order of @p y) the gradient of the deformation gradient at
   * the master is G_{CDE} = sum_b y^b_C h^b_{DE}, and the quadratic energy
   * 1/2 M_xx sum_E G_{..E} : A : G_{..E} with the frozen tangent @p A
   * (force / area) gives
   *   r_aA += M_xx h^a_{BE} A_{ABCD} G_{CDE},
   *   K_{aA,bC} += M_xx h^a_{BE} A_{ABCD} h^b_{DE}.
   * Both vanish for every affine field; the tangent is symmetric when A
   * has the major symmetry. @p tangent may be nullptr. Adds.
   */
  template <int dim>
  void
  add_implicit_gradient_stabilisation(const std::vector<Tensor<2, dim>> &h,
                                      const double          second_moment,
                                      const Tensor<4, dim> &A,
                                      const std::vector<Tensor<1, dim>> &y,
                                      Vector<double>     &residual,
                                      FullMatrix<double> *tangent);
} // namespace pg

#endif
