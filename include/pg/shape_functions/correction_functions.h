#ifndef pg_shape_functions_correction_functions_h
#define pg_shape_functions_correction_functions_h

#include <pg/base/formulation_code.h>
#include <pg/base/global.h>
#include <pg/shape_functions/shape_functions.h>

#include <vector>

namespace pg
{
  namespace ShapeFunctions
  {
    /**
     * The VC correction functions Phi^{kki} of family k into @p phi, one
     * per member i (pg-methods.md section 11.3), in effective form: the
     * master entry is minus the sum of the others, so that the correction
     * keeps the gradients in difference form. Component d of phi[i] is the
     * function of the correction in direction d (eq. 5.56); it is the same
     * scalar in every component except for V2.
     *
     * - V1 (5.60): phi = 1 for every neighbour.
     * - V3 (5.62) and V5 (5.64): phi = N^{kki}_MLS1, the MLS1 shape function
     *   value at the master with the moving weight centred there (omega^{kk}
     *   = 0). It is independent of the evaluation point, as printed. V5
     *   differs from V3 only by the bond projector, which the caller
     *   applies to the correction vector (reading [A] 4 of section 18).
     * - V4 (5.63): phi = N^{kki}_WLS2, the same with the quadratic basis:
     *   it also keeps second-order consistency (eq. 5.58).
     * - V2 (5.61): component d is d^2 N^{ki}_WLS2 / dX_d^2, the diagonal of
     *   the Hessian of the quadratic fit (reading [A] 7 of section 18): it
     *   keeps zeroth and first order.
     *
     * Returns the condition number of the moment matrix (1 for V1); the
     * caller decides what is too large (WLS2 needs at least 6 neighbours
     * in 2-D and 10 in 3-D, not on one conic).
     */
    template <int dim>
    double
    correction_function(const FormulationCode::CorrectionFunction function,
                        const FamilyGeometry<dim>                &family,
                        std::vector<Tensor<1, dim>>              &phi);
  } // namespace ShapeFunctions
} // namespace pg

#endif
