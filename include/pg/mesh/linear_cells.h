#ifndef pg_mesh_linear_cells_h
#define pg_mesh_linear_cells_h

#include <pg/base/global.h>

#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/reference_cell.h>
#include <deal.II/grid/tria.h>

#include <memory>

namespace pg
{
  /**
   * The linear element, mapping and Gauss quadratures of a mesh whose cells
   * are all of one kind: FE_Q(1), MappingQ1 and QGauss on quadrilaterals
   * and hexahedra; FE_SimplexP(1), MappingFE(FE_SimplexP(1)) and
   * QGaussSimplex on triangles and tetrahedra (deal.II's ReferenceCell
   * facilities). Everything on the meshfree path that integrates over
   * cells or faces (lumped volumes, boundary area vectors, face loads,
   * output) takes them from here instead of assuming hypercubes.
   */
  template <int dim>
  class LinearCells
  {
  public:
    /** Quadrilaterals (hexahedra). */
    LinearCells();

    /**
     * The kind of the cells of @p triangulation; throws if it holds more
     * than one kind (mesh files refuse such meshes first, with a message
     * naming the file).
     */
    explicit LinearCells(const Triangulation<dim> &triangulation);

    /** The reference cell of every cell. */
    const ReferenceCell &
    reference_cell() const;

    /** True for triangles and tetrahedra. */
    bool
    is_simplex() const;

    /** FE_Q(1) or FE_SimplexP(1): shape function i belongs to vertex i. */
    const FiniteElement<dim> &
    scalar_element() const;

    /** MappingQ1, or MappingFE with FE_SimplexP(1). */
    const Mapping<dim> &
    mapping() const;

    /**
     * QGauss(n) or QGaussSimplex(n) (n = 2 integrates products of two
     * linear functions exactly).
     */
    Quadrature<dim>
    quadrature(const unsigned int n) const;

    /**
     * The rule of a finite element cell's internal force and tangent:
     * QGauss(2) on Q1 cells, QGaussSimplex(1) on P1 cells (their gradient
     * is constant: one point is exact for any material).
     */
    Quadrature<dim>
    fe_cell_quadrature() const;

    /** The same rule on a face (all faces of a cell are of one kind). */
    Quadrature<dim - 1>
    face_quadrature(const unsigned int n) const;

    /** "quadrilaterals", "triangles", "hexahedra" or "tetrahedra". */
    std::string
    name() const;

  private:
    ReferenceCell                             kind;
    std::shared_ptr<const FiniteElement<dim>> element;
  };
} // namespace pg

#endif
