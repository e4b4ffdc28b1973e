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
     * The scalar VC correction functions phi^{kki} of family k, one per
     * member i (pg-methods.md section 11.3), in effective form: the master
     * entry is minus the sum of the others, so that the correction keeps
     * the gradients in difference form.
     *
     * - V1 (5.60): phi = 1 for every neighbour.
     * - V3 (5.62) and V5 (5.64): phi = N^{kki}_MLS1, the MLS1 shape function
     *   value at the master with the moving weight centred there (omega^{kk}
     *   = 0). It is independent of the evaluation point, as printed. V5
     *   differs from V3 only by the bond projector, which the caller
     *   applies to the correction vector (reading [A] 4 of section 18).
     */
    template <int dim>
    std::vector<double>
    correction_function(const FormulationCode::CorrectionFunction function,
                        const FamilyGeometry<dim>                &family);
  } // namespace ShapeFunctions
} // namespace pg

#endif
