#ifndef pg_elements_condensed_pressure_h
#define pg_elements_condensed_pressure_h

#include <pg/base/global.h>
#include <pg/elements/quadrature_table.h>
#include <pg/materials/volumetric_split.h>

#include <deal.II/base/array_view.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace pg
{
  /**
   * The pressure p and the dilatation Theta of an element whose p and Theta
   * are condensed: constant (P0) in the mixed PG UnlP0 (eq. 6.9, per family)
   * and the mixed finite elements Q1P0 (2-D) and H1P0 (3-D) (per cell,
   * deal.II's step-44); linear (P1) in U2P1 (eq. 6.10, per family). For P1
   * the values at the first volumetric point (a family's master).
   */
  struct CondensedPressure
  {
    /**
     * Theta: the L2 projection of the volume measure theta (J, or tr(eps)
     * for linear elasticity) over the volumetric points onto constants
     * (theta-bar, the weighted mean) or linear functions.
     */
    double dilatation;
    /** p: the projection of W_vol'(Theta) (force per area). */
    double pressure;
  };

  /**
   * The condensed fields of one element as a Newton iterate (the
   * dissertation's local update after each global solve, pg-methods.md
   * section 12.2): the coefficients of Theta and p in the element's basis
   * phi (P0: (1); P1: (1, (X - X_c) / L)), m values each, and the
   * linearisation of the local equations at the last tangent assembly,
   *   d Theta = a + S du,   d p = b + T d Theta
   * (a = M^-1 R_p, b = M^-1 R_Theta, S = M^-1 G, T = M^-1 H in the notation
   * of assemble_condensed_pressure_element()). Unlike the closed form, p is
   * then not recomputed from the displacement at every iterate, so Newton's
   * method works on the three-field system: its convergence radius does not
   * shrink with K/mu, where the closed form's (a penalty method) does.
   */
  struct CondensedFieldIterate
  {
    /**
     * True until the first assembly sets the coefficients to local
     * equilibrium (the closed form) at the displacement it sees; set it
     * again whenever the displacement is changed outside Newton's method.
     */
    bool at_equilibrium = true;
    /** c_Theta and c_p (m values each). */
    std::vector<double> dilatation, pressure;
    /**
     * a, b (m values each), S (m x n_dofs, row by row) and T (m x m) of the
     * last assembly with a tangent; empty before it.
     */
    std::vector<double> a, b, S, T;
    /**
     * Unl+P1C (eqs. 6.12-6.16): the family's bubble coefficients u_b (dim
     * values, displacement per length) and the linearisation of its local
     * equation r_b = 0 at the last tangent assembly,
     *   d u_b = bubble_a + bubble_S du
     * (bubble_a = -K_bb^-1 r_b, bubble_S = -K_bb^-1 K_bg, dim x n_dofs row
     * by row); empty for the other elements.
     */
    std::vector<double> bubble, bubble_a, bubble_S;

    /**
     * Whether an assembly with a tangent stored a linearisation since the
     * last update, i.e. whether update_condensed_fields() has anything to
     * do.
     */
    bool
    linearised() const
    {
      return !S.empty() || !bubble_S.empty();
    }
  };

  /**
   * The local update after a Newton update: @p iterate's coefficients +=
   * (a + S du, b + T (a + S du)) and its bubble += bubble_a + bubble_S du,
   * with the element's update @p du (local DoFs, in the order of the
   * element's get_dof_indices()). Nothing if no tangent has been assembled
   * at this iterate.
   */
  void
  update_condensed_fields(CondensedFieldIterate     &iterate,
                          const std::vector<double> &du);

  /**
   * The condensed fields at the local positions @p y: the volumetric
   * points are those of @p volumetric_table (pg-methods.md section 12.2.1:
   * every point of a PBG family or a Q1 cell, the master of a PPG family).
   * Throws if J <= 0 at a volumetric point (finite strain). @p degree: 0
   * (P0) or 1 (P1).
   */
  template <int dim>
  CondensedPressure
  condensed_pressure(const QuadratureTable<dim>            &volumetric_table,
                     const std::vector<Tensor<1, dim>>     &y,
                     const Materials::VolumetricSplit<dim> &material,
                     const unsigned int                     degree = 0);

  /**
   * The element residual and tangent of the three-field (u, p, Theta)
   * Hu-Washizu potential (eqs. 6.2, 6.3) with p and Theta constant per
   * element and condensed in closed form (pg-methods.md section 12.2.1):
   * with W = sum_q w_q over the volumetric points and the volume measure
   * theta(F) of the material's split (J = det F; tr(eps) for linear
   * elasticity, where this is the B-bar method),
   * @f[ \Theta = \bar\theta = \frac1W \sum_q w_q \theta_q, \qquad
   *     p = W_{vol}'(\Theta), @f]
   * @f[ r_{aA} = \sum_{q} w_q P^{iso}_{AB}(F_q) T^{qa}_B
   *     + p\, g_{aA}, \qquad
   *     g_{aA} = \sum_{q\,\in\,vol} w_q
   *       \frac{\partial\theta_q}{\partial F_{AB}} T^{qa}_B, @f]
   * @f[ k_{aA,bC} = (\text{isochoric tangent})
   *     + \frac{W_{vol}''(\Theta)}{W} g_{aA} \bar g_{bC}
   *     + p \sum_{q\,\in\,vol} w_q T^{qa}_B
   *       \frac{\partial^2 \theta}{\partial F_{AB} \partial F_{CD}}
   *       B^{qb}_D, @f]
   * with test vectors T in g and trial vectors B in g-bar. This equals
   * the static condensation (6.6) at local equilibrium, and the
   * mean-dilatation form of step-44's condensed Q1P0.
   *
   * The isochoric part is evaluated at every point of @p table; the
   * volumetric part at the points of @p volumetric_table, which is
   * @p table itself (nullptr) for PBG families and Q1 cells, or the
   * one-point master table of a PPG family. Units: force (residual),
   * force per length (tangent). Overwrites @p residual and @p tangent
   * (nullptr: residual only) and returns the condensed fields.
   *
   * With @p iterate, p and Theta are its coefficients c_p, c_Theta instead
   * of the closed form (three fields; the closed form when
   * iterate->at_equilibrium, which it then stores). With the basis phi,
   * M = sum w phi phi^T, H = sum w W_vol''(Theta_q) phi phi^T, the moments
   * G = d/du sum w phi theta_q and the local residuals
   *   R_p = sum_q w_q phi_q theta_q - M c_Theta,
   *   R_Theta = sum_q w_q phi_q W_vol'(Theta_q) - M c_p,
   * the element's condensed residual and tangent are
   *   r = r_u(p_q) + G_test^T M^-1 (R_Theta + H M^-1 R_p),
   *   k = k_u(p_q) + G_test^T M^-1 H M^-1 G_trial,
   * which at local equilibrium (R_p = R_Theta = 0) are the closed form's.
   * An assembly with a tangent stores the linearisation that
   * update_condensed_fields() applies.
   *
   * A material with history: the isochoric part carries it
   * (VolumetricSplit::evaluate_isochoric_with_state() at every point of
   * @p table, from @p committed_state, writing @p trial_state: the
   * element's slices of the material's state, n_state_variables() values
   * per point of @p table); the volumetric part W_vol(Theta) stays
   * elastic. Empty slices: a stateless material.
   */
  template <int dim>
  CondensedPressure
  assemble_condensed_pressure_element(
    const QuadratureTable<dim>            &table,
    const QuadratureTable<dim>            *volumetric_table,
    const std::vector<Tensor<1, dim>>     &y,
    const Materials::VolumetricSplit<dim> &material,
    Vector<double>                        &residual,
    FullMatrix<double>                    *tangent,
    const unsigned int                     degree          = 0,
    CondensedFieldIterate                 *iterate         = nullptr,
    const ArrayView<const double>         &committed_state = {},
    const ArrayView<double>               &trial_state     = {});

  /**
   * The family residual and tangent of IUnlP0, the incompressible UnlP0
   * (pg-methods.md section 12.2.1, Table 7.1): Theta = 1 and the family's
   * pressure p^k, constant, a global unknown (K_pp = 0, so it cannot be
   * condensed). With the potential
   * @f[ \Pi^k = \sum_q w_q W_{iso}(\mathbf F_q)
   *     + p^k \sum_{q\,\in\,vol} w_q (\theta_q - \theta(\mathbf I)), @f]
   * the blocks are
   * @f[ r_{aA} = \sum_q w_q P^{iso}_{AB} T^{qa}_B + p^k g_{aA}, \qquad
   *     r_p = \sum_{q\,\in\,vol} w_q (\theta_q - \theta(\mathbf I)), @f]
   * @f[ k_{aA,bC} = (\text{isochoric tangent}) + p^k \sum_{q\,\in\,vol}
   *     w_q T^{qa}_B \frac{\partial^2\theta}{\partial F_{AB}\partial
   *     F_{CD}} B^{qb}_D, \quad k_{aA,p} = g_{aA}, \quad
   *     k_{p,bC} = \bar g_{bC}, \quad k_{pp} = 0, @f]
   * with g (test vectors) and g-bar (trial vectors) as in
   * assemble_condensed_pressure_element(): a saddle point, symmetric for PBG.
   * The volumetric points are those of @p table (PBG, nullptr) or of the
   * one-point master table @p volumetric_table (PPG, eq. 6.7). theta is the
   * split's volume measure (J; tr eps for linear elasticity) and its
   * volumetric energy is not used.
   *
   * Local DoFs: u of the n nodes node-major (a * dim + A), then p^k (n *
   * dim). Units: force (u rows), volume (p row). Overwrites @p residual and
   * @p tangent (nullptr: residual only). Throws if J <= 0 at a point.
   * Returns the mean volume measure theta-bar of the volumetric points
   * (1 when the constraint holds). The material's state as in
   * assemble_condensed_pressure_element() (the isochoric part carries it).
   */
  template <int dim>
  double
  assemble_incompressible_p0_element(
    const QuadratureTable<dim>            &table,
    const QuadratureTable<dim>            *volumetric_table,
    const std::vector<Tensor<1, dim>>     &y,
    const Materials::VolumetricSplit<dim> &material,
    const double                           pressure,
    Vector<double>                        &residual,
    FullMatrix<double>                    *tangent,
    const ArrayView<const double>         &committed_state = {},
    const ArrayView<double>               &trial_state     = {});
} // namespace pg

#endif
