#include <pg/base/exceptions.h>
#include <pg/mesh/linear_cells.h>

#include <deal.II/base/quadrature_lib.h>
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
    // deal.II 9.4's QGaussSimplex(2) is a collapsed (Duffy) rule whose
    // points do not follow a permutation of the simplex's vertices, so a
    // mirrored P1 cell integrated a non-polynomial body force differently
    // (1e-6 between a quarter and the full body in
    // problem/simplex_mirror_symmetry_01); the Witherden-Vincent rules are
    // invariant under the permutations, of the same degree 2n - 1
    if (kind.is_simplex())
      return QWitherdenVincentSimplex<dim>(n);
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
    // triangles of tetrahedra: the symmetric rule, as in quadrature()
    if (kind.is_simplex() && dim == 3)
      return QWitherdenVincentSimplex<dim - 1>(n);
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
