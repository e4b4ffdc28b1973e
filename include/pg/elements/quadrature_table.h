#ifndef pg_elements_quadrature_table_h
#define pg_elements_quadrature_table_h

#include <pg/base/global.h>
#include <pg/materials/material.h>

#include <deal.II/base/array_view.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <vector>

namespace pg
{
  /**
   * The element view shared by Q1 cells and PG families (architecture.md
   * section 2, pg-methods.md section 7.4): local nodes b, evaluation points q
   * with weights w_q, trial vectors B^{qb} with F_q = sum_b x^b (x) B^{qb},
   * and test vectors T^{qa}. Test vectors are stored sparsely (a PPG point
   * has two, a PBG point has one per node); for Bubnov-Galerkin tables the
   * test vectors are the trial vectors and are not stored twice.
   */
  template <int dim>
  struct QuadratureTable
  {
    /** Start an empty table for @p n_nodes local nodes. */
    void
    reinit(const unsigned int n_nodes, const bool test_is_trial);

    /**
     * Append an evaluation point at @p point with weight @p weight (volume
     * units) and the trial vectors of all nodes (n_nodes entries).
     */
    void
    add_point(const double                       weight,
              const std::vector<Tensor<1, dim>> &trial,
              const Point<dim>                  &point);

    /** Add a test vector of node @p a to the point added last. */
    void
    add_test_vector(const unsigned int a, const Tensor<1, dim> &test);

    unsigned int
    n_points() const;

    unsigned int                n_nodes;
    bool                        test_is_trial;
    std::vector<double>         weights;
    std::vector<Point<dim>>     points; //!< X_q, reference configuration
    std::vector<Tensor<1, dim>> trial;  //!< n_points x n_nodes, row by row
    std::vector<unsigned int>   test_offsets;
    std::vector<unsigned int>   test_nodes;
    std::vector<Tensor<1, dim>> test_vectors;
  };

  /**
   * The weights of @p tables[0], ..., @p tables[n - 1], one table after the
   * other (ElementGroup::evaluation_point_weights()).
   */
  template <int dim>
  std::vector<double>
  concatenated_weights(const std::vector<QuadratureTable<dim>> &tables,
                       const unsigned int                       n)
  {
    AssertIndexRange(n, tables.size() + 1);
    std::vector<double> weights;
    for (unsigned int e = 0; e < n; ++e)
      weights.insert(weights.end(),
                     tables[e].weights.begin(),
                     tables[e].weights.end());
    return weights;
  }

  /**
   * The one kernel (pg-methods.md section 14.1): for the local nodal
   * positions relative to node 0, @p y^b = X^b - X^0 + u^b (using relative
   * positions keeps F accurate; the trial vectors sum to zero, so F does
   * not depend on the origin),
   *   F_q = sum_b y^b (x) B^{qb},
   *   r_{aA} = sum_q w_q P_AB(F_q) T^{qa}_B,
   *   K_{aA,bC} = sum_q w_q T^{qa}_B A_ABCD(F_q) B^{qb}_D.
   * Local DoFs are node-major: index a*dim + A. If @p tangent is nullptr
   * only the residual is computed. @p residual and @p tangent are
   * overwritten.
   *
   * A material with state (n_state_variables() = m > 0) needs the element's
   * slices of a QuadraturePointHistory: @p committed_state and
   * @p trial_state with n_points() * m values, point q's at q * m. Point q
   * is evaluated by Material::evaluate_with_state() from its committed
   * values, which writes its trial values (also when @p tangent is
   * nullptr). A stateless material ignores them (default: empty), and the
   * kernel calls evaluate(F, P, A) or first_piola_stress(F) as before.
   */
  template <int dim>
  void
  assemble_element(const QuadratureTable<dim>        &table,
                   const std::vector<Tensor<1, dim>> &y,
                   const Materials::Material<dim>    &material,
                   Vector<double>                    &residual,
                   FullMatrix<double>                *tangent,
                   const ArrayView<const double>     &committed_state = {},
                   const ArrayView<double>           &trial_state     = {});

  /**
   * The deformation gradient at point @p q of @p table.
   */
  template <int dim>
  Tensor<2, dim>
  deformation_gradient(const QuadratureTable<dim>        &table,
                       const unsigned int                 q,
                       const std::vector<Tensor<1, dim>> &y);

  /**
   * The unit-stress residual of the element (P = 1 at every point):
   * d_a += sum_q w_q T^{qa}, pg-methods.md section 8.2. Assembled over all
   * families it is the discrete Gauss theorem of the test functions:
   * zero at interior particles exactly when the first-order integration
   * constraint holds, the nodal area vector at the surface.
   */
  template <int dim>
  void
  add_unit_stress_residual(const QuadratureTable<dim>  &table,
                           std::vector<Tensor<1, dim>> &d);

  /**
   * The internal force of a prescribed stress field: d_a += sum_q w_q
   * P_q T^{qa} with P_q = @p stress(q) (first Piola-Kirchhoff, force per
   * reference area). add_unit_stress_residual() is the case P = 1.
   */
  template <int dim>
  void
  add_stress_residual(const QuadratureTable<dim>                    &table,
                      const std::function<Tensor<2, dim>(unsigned)> &stress,
                      std::vector<Tensor<1, dim>>                   &d);
} // namespace pg

#endif
