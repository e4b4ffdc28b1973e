#ifndef pg_mesh_simplex_split_h
#define pg_mesh_simplex_split_h

#include <pg/base/global.h>
#include <pg/mesh/mesh_generator.h>

#include <deal.II/grid/tria.h>

#include <vector>

namespace pg
{
  namespace Mesh
  {
    /**
     * 'Cells = simplices' in subsection 'Geometry' (create_mesh()): split the
     * quadrilaterals (hexahedra) of @p hypercubes into 8 triangles (24
     * tetrahedra) each, into the empty @p triangulation, with the new
     * vertices of curved boundaries on them (simplex_split.cc says how).
     */
    template <int dim>
    void
    split_into_simplices(const Triangulation<dim> &hypercubes,
                         Triangulation<dim>       &triangulation);

    /**
     * Set the cells, vertices, spacing and simplex fields of @p size to
     * those of @p n hypercube cells per direction of total @p measure split
     * into simplices.
     */
    template <int dim>
    void
    predict_split_size(const std::vector<double> &n,
                       const double               measure,
                       MeshSize                  &size);
  } // namespace Mesh
} // namespace pg

#endif
