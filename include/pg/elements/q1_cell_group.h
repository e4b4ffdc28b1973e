#ifndef pg_elements_q1_cell_group_h
#define pg_elements_q1_cell_group_h

#include <pg/assembly/loads.h>
#include <pg/elements/element_group.h>
#include <pg/materials/material.h>
#include <pg/materials/volumetric_split.h>
#include <pg/mesh/linear_cells.h>

#include <deal.II/dofs/dof_handler.h>

#include <vector>

namespace pg
{
  /**
   * The linear finite element cells of this rank, of the kind of
   * @p kind: Q1 quadrilaterals/hexahedra with 2^dim Gauss points, or P1
   * triangles/tetrahedra with one point (their gradient is constant, so
   * one point integrates the internal force and tangent of any material
   * exactly). The common kernel (assemble_element) on the cell's
   * quadrature table, plus the body force (QGaussSimplex(2) on P1 cells)
   * and the FE-consistent traction of their Neumann faces.
   */
  template <int dim>
  class Q1CellGroup : public ElementGroup<dim>
  {
  public:
    using CellIterator = typename DoFHandler<dim>::active_cell_iterator;

    /**
     * With a @p condensed_pressure material the cells are Q1P0 (2-D) /
     * H1P0 (3-D): p and Theta constant per cell and condensed
     * (assemble_condensed_pressure_element(), deal.II's step-44).
     */
    Q1CellGroup(
      const std::vector<CellIterator>       &cells,
      const LinearCells<dim>                &kind,
      const Materials::Material<dim>        &material,
      const Loads<dim>                      &loads,
      const Materials::VolumetricSplit<dim> *condensed_pressure = nullptr);

    std::string
    name() const override;

    unsigned int
    n_elements() const override;

    void
    get_dof_indices(const unsigned int                    e,
                    std::vector<types::global_dof_index> &dofs) const override;

    unsigned int
    n_evaluation_points(const unsigned int e) const override;

    /** JxW of every cell's Gauss points. */
    std::vector<double>
    evaluation_point_weights() const override;

    std::unique_ptr<GroupScratch>
    create_scratch() const override;

    void
    assemble(const unsigned int           e,
             const LinearAlgebra::Vector &u,
             const ElementHistory        &history,
             GroupScratch                &scratch,
             LocalSystem                 &local) const override;

    std::string
    element_name(const unsigned int e) const override;

    Point<dim>
    element_position(const unsigned int e) const override;

    std::string
    non_finite_hint() const override;

  private:
    const std::vector<CellIterator>       &cells;
    const LinearCells<dim>                 kind;
    const Materials::Material<dim>        &material;
    const Loads<dim>                      &loads;
    const Materials::VolumetricSplit<dim> *condensed_pressure;
    /** The number of Gauss points of a cell (2^dim, or 1 on P1 cells). */
    const unsigned int n_points;
  };
} // namespace pg

#endif
