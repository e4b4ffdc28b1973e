#ifndef pg_elements_kernel_cost_h
#define pg_elements_kernel_cost_h

#include <pg/base/global.h>
#include <pg/elements/quadrature_table.h>

namespace pg
{
  /**
   * The size of the local tangent of @p table: (n_nodes dim)^2 entries.
   */
  template <int dim>
  double
  tangent_entries(const QuadratureTable<dim> &table);

  /**
   * The floating point operations (a multiply-add counts 2) that
   * assemble_element() performs for the residual and tangent of @p table,
   * the material law excluded: the arithmetic of the kernel, counted from
   * its loops. Used to report flop rates of Q1 cells and families in the
   * same normalisation (doc/benchmarks/plate_with_hole.md).
   */
  template <int dim>
  double
  tangent_flops(const QuadratureTable<dim> &table);
} // namespace pg

#endif
