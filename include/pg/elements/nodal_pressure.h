#ifndef pg_elements_nodal_pressure_h
#define pg_elements_nodal_pressure_h

#include <pg/base/global.h>
#include <pg/elements/condensed_pressure.h>
#include <pg/elements/quadrature_table.h>
#include <pg/materials/volumetric_split.h>

#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace pg
{
  /**
   * The interpolation of a family's nodal pressure and dilatation to its
   * evaluation points (eq. 6.11, pg-methods.md section 12.2.2): the field
   * is linear in the family, with the value of the master and the gradient
   * of the family's displacement functions at the master,
   * @f[ p^{kq} = \sum_a p^a \pi^{qa}, \qquad
   *     \pi^{qa} = \delta_{a0} + \mathbf B^{0a}\cdot(\mathbf X^q - \mathbf
   *     X^0), @f]
   * with B^{0a} the trial vectors of the table's point 0, the master (as
   * FamilyElements builds PBG tables). Returns pi, n_points x n_nodes, row
   * by row. Its rows sum to 1 (the trial vectors sum to zero), so constant
   * fields are exact; linear ones are exact where the trial vectors are
   * linearly consistent.
   */
  template <int dim>
  std::vector<double>
  nodal_field_interpolation(const QuadratureTable<dim> &table);

  /**
   * theta(I), the volume measure of the undeformed state: 1 for J, 0 for
   * tr eps. The nodal dilatation unknown is vartheta = Theta - theta(I), so
   * that the zero vector is the undeformed state.
   */
  template <int dim>
  double
  rest_volume_measure(const Materials::VolumetricSplit<dim> &material);

  /**
   * @p table with the bubble of Unl+P1C as one more node, n_nodes (eqs.
   * 6.13, 6.15, 6.16): its trial vectors are X_q - X_c, X_c the weighted
   * centroid of the points, so that sum_q w_q (X_q - X_c) = 0 (eq. 6.14).
   */
  template <int dim>
  QuadratureTable<dim>
  with_bubble_node(const QuadratureTable<dim> &table);

  /**
   * The family residual and tangent of the mixed PBG formulations with
   * nodal pressure and dilatation, U2P1C (eq. 6.11) and Unl+P1C (eqs.
   * 6.12-6.16), pg-methods.md sections 12.2.2-12.2.3. With the point values
   * p_q = sum_a pi^{qa} p^a, Theta_q = theta_0 + sum_a pi^{qa} vartheta^a
   * (theta_0 = theta(I): 1 for J, 0 for tr eps, so that the nodal unknown
   * vartheta = Theta - theta_0 is 0 at rest) and the family potential
   * @f[ \Pi^k = \sum_q w_q \big[W_{iso}(\mathbf F_q) + W_{vol}(\Theta_q)
   *     + p_q(\theta(\mathbf F_q) - \Theta_q)\big], @f]
   * the residual blocks are
   * @f[ r_{aA} = \sum_q w_q (P^{iso} + p_q\,\partial\theta/\partial\mathbf
   *     F)_{AB} B^{qa}_B, \quad
   *     r_{p,a} = \sum_q w_q(\theta_q - \Theta_q)\pi^{qa}, \quad
   *     r_{\Theta,a} = \sum_q w_q(W_{vol}'(\Theta_q) - p_q)\pi^{qa}, @f]
   * and the tangent is their exact derivative (symmetric: Bubnov-Galerkin).
   *
   * With @p bubble (Unl+P1C) F_q gains u_b (x) (X_q - X_c), X_c the
   * weighted centroid of the points (eqs. 6.13, 6.15, 6.16), and the bubble
   * u_b is condensed: r = r_g - K_gb K_bb^-1 r_b, K = K_gg - K_gb K_bb^-1
   * K_bg. u_b is @p iterate's (a Newton iterate, recovered after each global
   * solve by update_condensed_fields()); with no @p iterate or one
   * at_equilibrium it is solved from r_b = 0 first (local Newton, started
   * from the iterate's last bubble if it has one, else from 0), and
   * stored in the iterate. An assembly with a tangent stores the
   * linearisation of u_b in the iterate. Without a bubble the iterate is
   * not used.
   *
   * Local DoFs: u of the n nodes node-major (a * dim + A), then p^a (n *
   * dim + a), then vartheta^a (n * dim + n + a): @p p and @p vartheta hold
   * the nodal values. Throws if theta(F_q) is undefined (J <= 0). Units:
   * force (u rows), volume (p and Theta rows); @p residual and @p tangent
   * (nullptr: residual only) are overwritten.
   *
   * A material with history: the isochoric part carries it
   * (VolumetricSplit::evaluate_isochoric_with_state() at every point, from
   * @p committed_state, writing @p trial_state: the family's slices of the
   * material's state, n_state_variables() per point of @p table; empty:
   * stateless); W_vol stays elastic. The bubble's local Newton iteration
   * evaluates from the committed state and discards its trial states; the
   * final assembly writes @p trial_state at the converged bubble.
   */
  template <int dim>
  void
  assemble_nodal_pressure_family(
    const QuadratureTable<dim>            &table,
    const std::vector<Tensor<1, dim>>     &y,
    const std::vector<double>             &p,
    const std::vector<double>             &vartheta,
    const Materials::VolumetricSplit<dim> &material,
    const bool                             bubble,
    Vector<double>                        &residual,
    FullMatrix<double>                    *tangent,
    CondensedFieldIterate                 *iterate         = nullptr,
    const ArrayView<const double>         &committed_state = {},
    const ArrayView<double>               &trial_state     = {});
} // namespace pg

#endif
