#include <pg/elements/q1_cell.h>

namespace pg
{
  template <int dim>
  void
  fill_q1_table(const FEValues<dim> &fe_values, QuadratureTable<dim> &table)
  {
    const unsigned int n = fe_values.dofs_per_cell;
    table.reinit(n, true);
    std::vector<Tensor<1, dim>> row(n);
    const bool                  have_points =
      (fe_values.get_update_flags() & update_quadrature_points);
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        for (unsigned int b = 0; b < n; ++b)
          row[b] = fe_values.shape_grad(b, q);
        table.add_point(fe_values.JxW(q),
                        row,
                        have_points ? fe_values.quadrature_point(q) :
                                      Point<dim>());
      }
  }



  template void
  fill_q1_table<2>(const FEValues<2> &, QuadratureTable<2> &);
  template void
  fill_q1_table<3>(const FEValues<3> &, QuadratureTable<3> &);
} // namespace pg
