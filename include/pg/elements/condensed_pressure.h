#ifndef pg_elements_condensed_pressure_h
#define pg_elements_condensed_pressure_h

#include <pg/base/global.h>
#include <pg/elements/quadrature_table.h>
#include <pg/materials/volumetric_split.h>

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
    const unsigned int                     degree = 0);
} // namespace pg

#endif
