#ifndef pg_shape_functions_shape_functions_h
#define pg_shape_functions_shape_functions_h

#include <pg/base/global.h>

#include <deal.II/base/array_view.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <string>
#include <vector>

namespace pg
{
  /**
   * Meshfree shape-function gradients of one family (pg-methods.md
   * section 6, Table 5.1): the first-order bases and the quadratic WTE2 of
   * the U2 formulations. All functions take the family in
   * local numbering: member 0 is the master k, members 1..N its neighbours.
   */
  namespace ShapeFunctions
  {
    /** The bases of Table 5.1. */
    enum class Base
    {
      mte1, //!< moving Taylor expansion, eq. (5.52)
      mls1, //!< moving least squares with full derivative, eqs. (5.43)-(5.47)
      wls1, //!< weighted least squares, eq. (5.45)
      wte1, //!< weighted Taylor expansion (classical correspondence, 4.3)
      wte2  //!< quadratic weighted Taylor expansion (U2, section 6.4)
    };

    /** "MTE1" -> Base::mte1, etc. */
    Base
    parse_base(const std::string &name);

    /** Input of the shape-function routines for one family. */
    template <int dim>
    struct FamilyGeometry
    {
      /** X^i - X^k for every member i (entry 0 is zero). */
      std::vector<Tensor<1, dim>> bonds;
      /** V^i for every member i. */
      std::vector<double> volumes;
      /** n in omega = |dX|^(-2n). */
      double weight_exponent;
    };

    /**
     * Raw gradients g^{kji} (i = 0..N) of the base @p base of family k at
     * the evaluation point j = @p point (a local index). For every base the
     * gradients satisfy sum_i g^{kji} = 0 and sum_i dX^{ki} (x) g^{kji} = 1
     * (linear consistency, eqs. 5.8, 5.9); WTE2 also reproduces the
     * gradient of every quadratic field at every point.
     *
     * Returns the condition number of the moment matrix (basis scaled to
     * the family size, so the number is dimensionless); the caller decides
     * what is too large. A singular matrix returns infinity.
     */
    template <int dim>
    double
    raw_gradients(const Base                   base,
                  const FamilyGeometry<dim>   &family,
                  const unsigned int           point,
                  std::vector<Tensor<1, dim>> &gradients);

    /**
     * The bond correction (eq. 5.55) of the gradients at evaluation point
     * @p point != 0: g <- (1 - n (x) n) g + delta_ji dX^{kj} / |dX^{kj}|^2,
     * with n the unit bond from the master to the point. Afterwards the
     * deformation gradient maps the bond k-j exactly (eq. 5.12).
     */
    template <int dim>
    void
    apply_bond_correction(const FamilyGeometry<dim>   &family,
                          const unsigned int           point,
                          std::vector<Tensor<1, dim>> &gradients);

    /**
     * The second derivatives h^i = d^2 N^{kki}_MLS1 / dX dX (symmetric,
     * 1/length^2) of the MLS1 shape functions of family k at its master
     * (eq. 6.28, pg-methods.md sections 6.3 and 12.3.3), from the full
     * derivative of N_i(X) = V^i omega_i(X) p^{ki} . M(X)^{-1} p(X - X^k)
     * with the moving weights omega_i(X) = |X^i - X|^(-2n). The master's
     * own weight is not the exception 0 but the finite constant
     * @p self_weight (times V^k; its derivatives are zero): the "modified
     * weight function exception" of eq. (6.28), doc/ambiguities.md. The
     * second derivatives reproduce those of every linear field, i.e.
     * sum_i h^i = 0 and sum_i dX^{ki} (x) h^i = 0. With n = 0 the weights
     * are constant and every h^i is zero. Returns the condition number of
     * the moment matrix at the master (infinite if singular).
     */
    template <int dim>
    double
    mls1_second_derivatives(const FamilyGeometry<dim>   &family,
                            const double                 self_weight,
                            std::vector<Tensor<2, dim>> &second_derivatives);

    /**
     * Effective (difference-form) gradients, pg-methods.md section 1.1:
     * B^i = g^i for i != 0 and B^0 = -sum_{i != 0} g^i.
     */
    template <int dim>
    void
    make_effective(std::vector<Tensor<1, dim>> &gradients);
  } // namespace ShapeFunctions
} // namespace pg

#endif
