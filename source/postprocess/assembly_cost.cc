#include <pg/elements/kernel_cost.h>
#include <pg/elements/q1_cell.h>
#include <pg/postprocess/postprocessors.h>
#include <pg/postprocess/run_summary.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_values.h>

namespace pg
{
  namespace Postprocess
  {
    template <int dim>
    void
    compute_assembly_cost(const ProblemView<dim> &view, RunSummary &summary)
    {
      auto &cost                 = summary.assembly_cost;
      cost.fe_entries            = 0;
      cost.fe_flops              = 0;
      cost.family_entries        = 0;
      cost.family_flops          = 0;
      const auto &owned_fe_cells = *view.owned_fe_cells;
      if (!owned_fe_cells.empty())
        {
          // every FE cell has the same table size; the FEValues of the
          // assembly (LinearCells::fe_cell_quadrature())
          FEValues<dim>        fe_values(view.cells->mapping(),
                                  *view.fe_scalar,
                                  view.cells->fe_cell_quadrature(),
                                  update_gradients | update_values |
                                    update_quadrature_points |
                                    update_JxW_values);
          QuadratureTable<dim> table;
          fe_values.reinit(typename Triangulation<dim>::active_cell_iterator(
            owned_fe_cells.front()));
          fill_q1_table(fe_values, table);
          cost.fe_entries = owned_fe_cells.size() * tangent_entries(table);
          cost.fe_flops   = owned_fe_cells.size() * tangent_flops(table);
        }
      if (view.cpd)
        for (const unsigned int k : *view.owned_families)
          {
            // an interaction of order n has (n + 1) dim rows and columns
            const auto n = view.cpd->n_interactions(k);
            for (unsigned int order = 0; order < 3; ++order)
              cost.family_entries +=
                n[order] * Utilities::fixed_power<2>((order + 2.) * dim);
          }
      else
        for (const auto &table : *view.family_tables)
          {
            cost.family_entries += tangent_entries(table);
            cost.family_flops += tangent_flops(table);
          }
      for (double *x : {&cost.fe_entries,
                        &cost.fe_flops,
                        &cost.family_entries,
                        &cost.family_flops})
        *x = Utilities::MPI::sum(*x, view.mpi_communicator);
    }



    template void
    compute_assembly_cost(const ProblemView<2> &, RunSummary &);
    template void
    compute_assembly_cost(const ProblemView<3> &, RunSummary &);
  } // namespace Postprocess
} // namespace pg
