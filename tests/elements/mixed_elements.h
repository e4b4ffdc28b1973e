#ifndef pg_tests_elements_mixed_elements_h
#define pg_tests_elements_mixed_elements_h

// The mixed elements that the condensed-pressure tests check, on a
// ParticleFixture: the families of interior_and_corner() for BCPBG UnlP0,
// BCPPG UnlP0 and PBG U2P1, then every 7th cell as a Q1P0 (2-D) / H1P0
// (3-D) element.

#include <pg/base/formulation_code.h>
#include <pg/elements/family_elements.h>
#include <pg/elements/q1_cell.h>
#include <pg/elements/quadrature_table.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include "../particle_fixture.h"

#include <functional>
#include <string>
#include <vector>

/**
 * Calls @p check(table, volumetric table (nullptr: the table itself), X,
 * degree) for each element, with X the nodal positions relative to node 0
 * and degree that of the condensed fields (0: P0, 1: P1), and @p done(name)
 * after each kind of element: the formulation text, or "Q1P0 cell" /
 * "H1P0 cell".
 */
template <int dim>
void
for_each_mixed_element(
  const ParticleFixture<dim>                     &fixture,
  const std::function<void(const pg::QuadratureTable<dim> &,
                           const pg::QuadratureTable<dim> *,
                           const std::vector<dealii::Tensor<1, dim>> &,
                           unsigned int)>        &check,
  const std::function<void(const std::string &)> &done)
{
  using namespace pg;
  for (const std::string code : {"BCPBG UnlP0", "BCPPG UnlP0", "PBG U2P1"})
    {
      const FormulationCode formulation = parse_formulation_code(code);
      FamilyElements<dim>   elements(fixture.particles,
                                   fixture.families,
                                   formulation,
                                   ShapeFunctions::parse_base("MTE1"),
                                   1.);
      elements.initialize();
      const bool pbg = (formulation.method == FormulationCode::Method::pbg);
      for (const unsigned int k : fixture.interior_and_corner())
        {
          QuadratureTable<dim> table, master_table;
          elements.build(k, table);
          elements.build_master_table(k, master_table);
          check(table,
                pbg ? nullptr : &master_table,
                elements.geometry(k).bonds,
                formulation.condensed_pressure_degree());
        }
      done(formulation.text);
    }

  const dealii::FE_Q<dim>     fe(1);
  dealii::FEValues<dim>       fe_values(fe,
                                  dealii::QGauss<dim>(2),
                                  dealii::update_gradients |
                                    dealii::update_JxW_values);
  std::vector<Tensor<1, dim>> X;
  for (const auto &cell : fixture.tria.active_cell_iterators())
    if (cell->active_cell_index() % 7 == 0)
      {
        fe_values.reinit(cell);
        QuadratureTable<dim> table;
        fill_q1_table(fe_values, table);
        X.resize(cell->n_vertices());
        for (const unsigned int v : cell->vertex_indices())
          X[v] = cell->vertex(v) - cell->vertex(0);
        check(table, nullptr, X, 0);
      }
  done(dim == 2 ? "Q1P0 cell" : "H1P0 cell");
}

#endif
