#include <pg/base/global_reader.h>
#include <pg/elements/condensed_pressure.h>
#include <pg/elements/q1_cell.h>
#include <pg/elements/q1_cell_group.h>
#include <pg/elements/quadrature_table.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

namespace pg
{
  namespace
  {
    template <int dim>
    struct Q1Scratch : public GroupScratch
    {
      explicit Q1Scratch(const LinearCells<dim> &kind)
        : kind(kind)
        , fe_values(kind.mapping(),
                    kind.scalar_element(),
                    kind.fe_cell_quadrature(),
                    update_gradients | update_values |
                      update_quadrature_points | update_JxW_values)
        , fe_face_values(kind.mapping(),
                         kind.scalar_element(),
                         kind.face_quadrature(2),
                         update_values | update_quadrature_points |
                           update_normal_vectors | update_JxW_values)
      {
        // the body force on P1 cells: QGaussSimplex(2), exact for a
        // linear force times the linear shape functions (as QGauss(2) on
        // Q1 cells)
        if (kind.is_simplex())
          load_values =
            std::make_unique<FEValues<dim>>(kind.mapping(),
                                            kind.scalar_element(),
                                            kind.quadrature(2),
                                            update_values |
                                              update_quadrature_points |
                                              update_JxW_values);
      }

      std::unique_ptr<GroupScratch>
      clone() const override
      {
        return std::make_unique<Q1Scratch>(kind);
      }

      const LinearCells<dim>         kind;
      FEValues<dim>                  fe_values;
      std::unique_ptr<FEValues<dim>> load_values;
      FEFaceValues<dim>              fe_face_values;
      QuadratureTable<dim>           table;
      std::vector<Tensor<1, dim>>    y;
    };
  } // namespace



  template <int dim>
  Q1CellGroup<dim>::Q1CellGroup(
    const std::vector<CellIterator>       &cells,
    const LinearCells<dim>                &kind,
    const Materials::Material<dim>        &material,
    const Loads<dim>                      &loads,
    const Materials::VolumetricSplit<dim> *condensed_pressure)
    : cells(cells)
    , kind(kind)
    , material(material)
    , loads(loads)
    , condensed_pressure(condensed_pressure)
    , n_points(kind.fe_cell_quadrature().size())
  {}



  template <int dim>
  std::string
  Q1CellGroup<dim>::name() const
  {
    if (kind.is_simplex())
      return condensed_pressure == nullptr ? "P1 cells" : "P1P0 cells";
    if (condensed_pressure == nullptr)
      return "Q1 cells";
    return dim == 2 ? "Q1P0 cells" : "H1P0 cells";
  }



  template <int dim>
  unsigned int
  Q1CellGroup<dim>::n_elements() const
  {
    return cells.size();
  }



  template <int dim>
  void
  Q1CellGroup<dim>::get_dof_indices(
    const unsigned int                    e,
    std::vector<types::global_dof_index> &dofs) const
  {
    dofs.resize(cells[e]->get_fe().n_dofs_per_cell());
    cells[e]->get_dof_indices(dofs);
  }



  template <int dim>
  unsigned int
  Q1CellGroup<dim>::n_evaluation_points(const unsigned int) const
  {
    return n_points;
  }



  template <int dim>
  std::vector<double>
  Q1CellGroup<dim>::evaluation_point_weights() const
  {
    FEValues<dim>       fe_values(kind.mapping(),
                            kind.scalar_element(),
                            kind.fe_cell_quadrature(),
                            update_JxW_values);
    std::vector<double> weights;
    weights.reserve(cells.size() * n_points);
    for (const auto &cell : cells)
      {
        fe_values.reinit(
          typename Triangulation<dim>::active_cell_iterator(cell));
        for (const unsigned int q : fe_values.quadrature_point_indices())
          weights.push_back(fe_values.JxW(q));
      }
    return weights;
  }



  template <int dim>
  std::unique_ptr<GroupScratch>
  Q1CellGroup<dim>::create_scratch() const
  {
    return std::make_unique<Q1Scratch<dim>>(kind);
  }



  template <int dim>
  void
  Q1CellGroup<dim>::assemble(const unsigned int           e,
                             const LinearAlgebra::Vector &u,
                             const ElementHistory        &history,
                             GroupScratch                &scratch_base,
                             LocalSystem                 &local) const
  {
    auto       &scratch = static_cast<Q1Scratch<dim> &>(scratch_base);
    const auto &cell    = cells[e];
    scratch.fe_values.reinit(
      typename Triangulation<dim>::active_cell_iterator(cell));
    fill_q1_table(scratch.fe_values, scratch.table);
    const unsigned int n = cell->n_vertices();
    local.dofs.resize(n * dim);
    cell->get_dof_indices(local.dofs);
    scratch.y.resize(n);
    const LinearAlgebra::GlobalReader u_at(u);
    for (unsigned int b = 0; b < n; ++b)
      for (unsigned int c = 0; c < dim; ++c)
        scratch.y[b][c] = cell->vertex(b)[c] - cell->vertex(0)[c] +
                          u_at[local.dofs[b * dim + c]];
    // the material's part of the point history (U1SIG keeps its own
    // entries after it in the same store)
    MaterialStateSlices state(history,
                              scratch.table.n_points(),
                              material.n_state_variables());
    if (condensed_pressure != nullptr)
      assemble_condensed_pressure_element<dim>(scratch.table,
                                               nullptr,
                                               scratch.y,
                                               *condensed_pressure,
                                               local.residual,
                                               local.with_matrix ?
                                                 &local.matrix :
                                                 nullptr,
                                               0,
                                               this->condensed_field_iterate(e),
                                               state.committed(),
                                               state.trial());
    else
      assemble_element(scratch.table,
                       scratch.y,
                       material,
                       local.residual,
                       local.with_matrix ? &local.matrix : nullptr,
                       state.committed(),
                       state.trial());
    state.write_back();
    if (scratch.load_values != nullptr)
      {
        scratch.load_values->reinit(
          typename Triangulation<dim>::active_cell_iterator(cell));
        loads.add_body_force(*scratch.load_values, local.residual);
      }
    else
      loads.add_body_force(scratch.fe_values, local.residual);
    loads.add_face_tractions(cell, scratch.fe_face_values, local.residual);
  }



  template <int dim>
  std::string
  Q1CellGroup<dim>::element_name(const unsigned int e) const
  {
    return (kind.is_simplex() ? "P1 cell " : "Q1 cell ") +
           std::to_string(cells[e]->active_cell_index());
  }



  template <int dim>
  Point<dim>
  Q1CellGroup<dim>::element_position(const unsigned int e) const
  {
    return cells[e]->center();
  }



  template <int dim>
  std::string
  Q1CellGroup<dim>::non_finite_hint() const
  {
    return "Check the 'Traction', 'Body force' and 'Prescribed displacement' "
           "functions, the material, and the cell (degenerate or inverted).";
  }



  template class Q1CellGroup<2>;
  template class Q1CellGroup<3>;
} // namespace pg
