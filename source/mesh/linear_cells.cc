#include <pg/base/exceptions.h>
#include <pg/mesh/linear_cells.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>

namespace pg
{
  template <int dim>
  LinearCells<dim>::LinearCells()
    : kind(ReferenceCells::get_hypercube<dim>())
    , element(std::make_shared<FE_Q<dim>>(1))
  {}



  template <int dim>
  LinearCells<dim>::LinearCells(const Triangulation<dim> &triangulation)
    : LinearCells()
  {
    const std::vector<ReferenceCell> kinds =
      triangulation.get_reference_cells();
    AssertThrow(kinds.size() == 1 &&
                  (kinds[0].is_hyper_cube() || kinds[0].is_simplex()),
                ExcMessage("pg's meshes hold cells of one kind: "
                           "quadrilaterals or triangles in 2-D, hexahedra or "
                           "tetrahedra in 3-D."));
    kind = kinds[0];
    if (kind.is_simplex())
      element = std::make_shared<FE_SimplexP<dim>>(1);
  }



  template <int dim>
  const ReferenceCell &
  LinearCells<dim>::reference_cell() const
  {
    return kind;
  }



  template <int dim>
  bool
  LinearCells<dim>::is_simplex() const
  {
    return kind.is_simplex();
  }



  template <int dim>
  const FiniteElement<dim> &
  LinearCells<dim>::scalar_element() const
  {
    return *element;
  }



  template <int dim>
  const Mapping<dim> &
  LinearCells<dim>::mapping() const
  {
    return kind.template get_default_linear_mapping<dim>();
  }



  template <int dim>
  Quadrature<dim>
  LinearCells<dim>::quadrature(const unsigned int n) const
  {
    return kind.template get_gauss_type_quadrature<dim>(n);
  }



  template <int dim>
  Quadrature<dim>
  LinearCells<dim>::fe_cell_quadrature() const
  {
    return quadrature(kind.is_simplex() ? 1 : 2);
  }



  template <int dim>
  Quadrature<dim - 1>
  LinearCells<dim>::face_quadrature(const unsigned int n) const
  {
    return kind.face_reference_cell(0)
      .template get_gauss_type_quadrature<dim - 1>(n);
  }



  template <int dim>
  std::string
  LinearCells<dim>::name() const
  {
    if (kind.is_simplex())
      return dim == 2 ? "triangles" : "tetrahedra";
    return dim == 2 ? "quadrilaterals" : "hexahedra";
  }



  template class LinearCells<2>;
  template class LinearCells<3>;
} // namespace pg
