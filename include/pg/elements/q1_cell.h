#ifndef pg_elements_q1_cell_h
#define pg_elements_q1_cell_h

#include <pg/base/global.h>
#include <pg/elements/quadrature_table.h>

#include <deal.II/fe/fe_values.h>

namespace pg
{
  /**
   * The quadrature table of a Q1 cell: Gauss points with weights JxW and
   * trial = test vectors grad N_b (Bubnov-Galerkin). @p fe_values belongs
   * to the scalar FE_Q(1) and has been reinit()ed on the cell, with
   * update_gradients | update_JxW_values. Node b is vertex b, which matches
   * the node-major DoF order of FESystem(FE_Q(1), dim) on a cell.
   */
  template <int dim>
  void
  fill_q1_table(const FEValues<dim> &fe_values, QuadratureTable<dim> &table);
} // namespace pg

#endif
