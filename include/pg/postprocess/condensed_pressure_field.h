#ifndef pg_postprocess_condensed_pressure_field_h
#define pg_postprocess_condensed_pressure_field_h

#include <pg/base/global.h>
#include <pg/postprocess/problem_view.h>

#include <deal.II/lac/vector.h>

#include <vector>

namespace pg
{
  namespace Postprocess
  {
    /**
     * The condensed pressure p = W_vol'(Theta) (stress units, positive in
     * tension) and dilatation Theta of a mixed formulation (UnlP0, U2P1,
     * Q1P0/H1P0), which the element kernel computes from u but the solution
     * vector does not hold (assemble_condensed_pressure_element()).
     */
    struct CondensedPressureField
    {
      /**
       * By particle index, on every rank: the value of the particle's
       * family (P0: the family's constant; U2P1: the linear field at the
       * master). 0 for particles without a family.
       */
      std::vector<double> particle_pressure, particle_dilatation;
      /**
       * By active cell index: a Q1P0/H1P0 cell's own value (cells of this
       * rank), a meshfree cell's mean over its particles (every cell).
       */
      Vector<float> cell_pressure, cell_dilatation;
      /** Smallest and largest p over all elements (families and cells). */
      double min_pressure, max_pressure;
    };

    /**
     * The condensed fields of @p view's mixed formulation at the
     * displacement @p u_all (the full vector, on every rank). Collective.
     * The formulation must be mixed (FormulationCode::mixed()).
     */
    template <int dim>
    CondensedPressureField
    condensed_pressure_field(const ProblemView<dim> &view,
                             const Vector<double>   &u_all);
  } // namespace Postprocess
} // namespace pg

#endif
